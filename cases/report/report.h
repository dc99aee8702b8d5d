// gradcontact/cases: comparison rows and the files of a report.
//
// A comparison is a value: quantity, metric, reference, values, errors, tolerance,
// DoFs, time. Tables (errors.csv / errors.md), convergence tables and gnuplot plots are made from rows.
#ifndef GRADCONTACT_CASES_REPORT_H
#define GRADCONTACT_CASES_REPORT_H

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  struct Row
  {
    std::string quantity;  ///< e.g. "force", "pressure"
    std::string metric;    ///< e.g. "relative", "r/a = 0.5, relative to max |p|"
    std::string reference; ///< "closed form", "numerical MDR", ...
    std::string method;    ///< what is checked: "FE", "closed form"
    double reference_value = 0., value = 0., abs_error = 0., rel_error = 0., tolerance = 0.;
    bool pass = false;
    unsigned int dofs = 0;  ///< 0 for analytic comparisons
    double seconds = 0.;    ///< time of the checked value
    std::string error;      ///< non-empty when a side failed to evaluate
    /// Under the accuracy contract (Discretization/accuracy = contract): the FE's asked relative tolerance, its
    /// relative error estimate and the verdict ("held", or "refused: " and the limit); 0, -1 and empty otherwise.
    double      asked    = 0.;
    double      estimate = -1.;
    std::string contract;
  };

  /// A comparison row: |value - ref| / |scale| against `tolerance`.
  Row compare(const std::string &quantity, const std::string &metric, const std::string &checked,
              const std::string &reference, double ref, double value, double scale, double tolerance,
              unsigned int dofs, double seconds);
  /// A row for a side that failed to evaluate (its relative error is infinite, so it fails).
  Row failed(const std::string &quantity, const std::string &checked, const std::string &reference,
             const std::string &what);

  struct SceneResult
  {
    std::string name, description, kind;
    std::vector<Row> rows;
    double seconds = 0.;
    bool pass() const;
    double worst_error() const; ///< the largest rel_error (inf where a side failed)
  };

  /// errors.csv and errors.md in `folder`.
  void write_errors(const SceneResult &s, const std::filesystem::path &folder);

  /// A line plot: curves (dense x, y) and point sets, written as data + gnuplot script, and rendered to
  /// PNG and SVG when gnuplot is installed. Returns false when gnuplot failed (the data and the
  /// script are kept, so the plot can be made by hand).
  struct Series
  {
    std::string title;
    std::vector<double> x, y;
    bool points = false;
    bool linespoints = false; ///< line through the points, each marked (a sweep of runs)
    /// The index of the series (before this one) whose colour it takes, e.g. FE points their closed-form curve's;
    /// -1: a colour of its own.
    int colour_of = -1;
  };

  /// While one lives, every plot of this thread carries `line` under its title (the parameters a scene ran with, so
  /// that a plot of a --set variant says what it shows).
  class PlotSubtitle
  {
  public:
    explicit PlotSubtitle(std::string line);
    ~PlotSubtitle();
    PlotSubtitle(const PlotSubtitle &) = delete;
    PlotSubtitle &operator=(const PlotSubtitle &) = delete;

  private:
    std::string previous;
  };
  bool write_plot(const std::filesystem::path &folder, const std::string &stem, const std::string &title,
                  const std::string &xlabel, const std::string &ylabel, const std::vector<Series> &series,
                  bool logx = false, bool logy = false);

  /// The hidden temporary sibling `.<name>.tmp-<host>-<pid>` under which `target` is written by process
  /// `pid` of this host: the owner in the name lets the next run tell a killed run's leftovers from the
  /// work of a run still going (several runs, e.g. --shard jobs, may share one reports folder).
  std::filesystem::path temporary_sibling(const std::filesystem::path &target, long pid);
  /// ... of this process.
  std::filesystem::path temporary_sibling(const std::filesystem::path &target);

  /// Removes from `folder` (not recursively) the temporaries that no run will finish: those of a process of
  /// this host that no longer exists, and the `.<name>.tmp` of versions before the owner was in the name.
  /// Those of other hosts are kept (their processes cannot be asked). Returns the removed paths.
  std::vector<std::filesystem::path> remove_stale_temporaries(const std::filesystem::path &folder);

  /// Moves the complete folder `tmp` to `folder`, replacing what is there in one step: rename(2) when
  /// `folder` is absent, else an atomic exchange of the two (renameat2 RENAME_EXCHANGE) and the old report,
  /// now at `tmp`, removed. Two runs that finish at once each leave a whole report behind (the later one
  /// stays); neither sees the other's folder vanish. Throws std::filesystem::error naming both paths.
  void replace_folder(const std::filesystem::path &tmp, const std::filesystem::path &folder);

  /// Writes `folder` through a temporary sibling and replaces the old report only when complete.
  template <class Writer>
  void atomic_folder(const std::filesystem::path &folder, const Writer &writer)
  {
    namespace fs = std::filesystem;
    const fs::path tmp = temporary_sibling(folder);
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    try
      {
        writer(tmp);
      }
    catch (...)
      {
        fs::remove_all(tmp);
        throw;
      }
    replace_folder(tmp, folder);
  }

  std::string format(double x);

  /// A CSV field: `s` in double quotes, inner quotes doubled.
  std::string csv_quote(const std::string &s);

  /// The message of an exception without deal.II's file, line and stack trace: for a deal.II
  /// exception the "Additional information" text, whitespace folded; otherwise what().
  std::string concise(const std::exception &e);
} // namespace gradcontact::cases

#endif
