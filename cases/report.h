// gradcontact/cases: comparison rows and the files of a report.
//
// A comparison is a value (STYLE rule 7): quantity, metric, reference, values, errors, tolerance,
// DoFs, time. Tables (errors.csv / errors.md), convergence tables and gnuplot plots are made from rows.
#pragma once

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

  /// One level of a refinement study.
  struct Level
  {
    unsigned int refinement;
    unsigned int dofs;
    double seconds;
    double value;
    double error; ///< relative, against the reference of the study
  };

  /// The observed order p of error ~ DoFs^(-p/2) (h ~ DoFs^(-1/2) in 2D), least squares over the last
  /// three levels (fewer if there are fewer); NaN with one level.
  double observed_order(const std::vector<Level> &levels);

  /// A line plot: curves (dense x, y) and point sets, written as data + gnuplot script, and rendered to
  /// PNG and SVG when gnuplot is installed. Returns false when gnuplot failed (the data and the
  /// script are kept, so the plot can be made by hand).
  struct Series
  {
    std::string title;
    std::vector<double> x, y;
    bool points = false;
    bool linespoints = false; ///< line through the points, each marked (a sweep of runs)
  };
  bool write_plot(const std::filesystem::path &folder, const std::string &stem, const std::string &title,
                  const std::string &xlabel, const std::string &ylabel, const std::vector<Series> &series,
                  bool logx = false, bool logy = false);

  /// Writes `folder` through a temporary sibling and replaces the old report only when complete.
  template <class Writer>
  void atomic_folder(const std::filesystem::path &folder, const Writer &writer)
  {
    namespace fs = std::filesystem;
    const fs::path tmp = folder.parent_path() / ("." + folder.filename().string() + ".tmp");
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
    fs::remove_all(folder);
    fs::rename(tmp, folder);
  }

  std::string format(double x);

  /// The message of an exception without deal.II's file, line and stack trace: for a deal.II
  /// exception the "Additional information" text, whitespace folded; otherwise what().
  std::string concise(const std::exception &e);
} // namespace gradcontact::cases
