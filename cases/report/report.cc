#include "report/report.h"

#include "report/table.h"

#include <algorithm>
#include <exception>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <limits>

#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <stdio.h> // renameat2, RENAME_EXCHANGE (glibc >= 2.28)
#include <unistd.h>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  std::string format(const double x)
  {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", x);
    return b;
  }

  std::string concise(const std::exception &e)
  {
    std::string text = e.what();
    const auto info = text.find("Additional information:");
    if (info != std::string::npos)
      {
        text = text.substr(info + 23);
        const auto trace = text.find("Stacktrace:");
        if (trace != std::string::npos)
          text = text.substr(0, trace);
      }
    std::string folded;
    bool space = false;
    for (const char c : text)
      {
        if (c == '\n' || c == ' ' || c == '\t' || c == '-')
          {
            space = space || c != '-' || folded.empty() || folded.back() == ' ';
            if (c != '-')
              continue;
          }
        if (space && !folded.empty())
          folded += ' ';
        space = false;
        folded += c;
      }
    return folded;
  }

  namespace
  {
    /// Between the target's name and the owner (host-pid) of a temporary sibling.
    const std::string temporary_marker = ".tmp-";

    std::string host_name()
    {
      char name[256] = {};
      if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0')
        return "localhost";
      return name;
    }

    bool process_exists(const long pid)
    {
      // kill with signal 0 only checks: EPERM means it exists under another user
      return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
    }

    bool ends_with(const std::string &s, const std::string &tail)
    {
      return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
    }

    /// Whether the hidden entry `name` of a reports folder is a temporary that no run will finish.
    bool stale_temporary(const std::string &name, const std::string &host)
    {
      if (name.size() < 2 || name[0] != '.')
        return false;
      const auto at = name.rfind(temporary_marker);
      if (at == std::string::npos)
        return ends_with(name, ".tmp"); // written before the owner was in the name
      const std::string owner = name.substr(at + temporary_marker.size());
      const auto dash = owner.rfind('-');
      if (dash == std::string::npos || owner.substr(0, dash) != host)
        return false;
      const std::string pid = owner.substr(dash + 1);
      if (pid.empty() || pid.size() > 18 || pid.find_first_not_of("0123456789") != std::string::npos)
        return false;
      return !process_exists(std::stol(pid));
    }
  } // namespace

  fs::path temporary_sibling(const fs::path &target, const long pid)
  {
    return target.parent_path() /
           ("." + target.filename().string() + temporary_marker + host_name() + "-" + std::to_string(pid));
  }

  fs::path temporary_sibling(const fs::path &target) { return temporary_sibling(target, ::getpid()); }

  void replace_folder(const fs::path &tmp, const fs::path &folder)
  {
    const auto fail = [&](const char *what) {
      throw fs::filesystem_error(std::string("cannot put the report in place (") + what + ")", tmp, folder,
                                 std::error_code(errno, std::generic_category()));
    };
    // Another run may put its report in place, or take the old one away, between two steps: retry.
    for (int attempt = 0; attempt < 100; ++attempt)
      {
        if (::rename(tmp.c_str(), folder.c_str()) == 0)
          return; // nothing (or an empty folder) was there
        if (errno != ENOTEMPTY && errno != EEXIST)
          fail("rename");
        if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) == 0)
          {
            fs::remove_all(tmp); // the earlier report
            return;
          }
        if (errno == EINVAL || errno == ENOSYS)
          {
            // A file system without exchange: move the old report aside under a name of this process.
            const fs::path aside = temporary_sibling(folder.parent_path() / (folder.filename().string() + ".old"));
            fs::remove_all(aside);
            if (::rename(folder.c_str(), aside.c_str()) == 0)
              fs::remove_all(aside);
            else if (errno != ENOENT)
              fail("rename aside");
            continue;
          }
        if (errno != ENOENT)
          fail("exchange");
      }
    errno = EBUSY;
    fail("another run replaced the folder 100 times in a row");
  }

  std::vector<fs::path> remove_stale_temporaries(const fs::path &folder)
  {
    std::vector<fs::path> removed;
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
      return removed;
    const std::string host = host_name();
    for (const auto &entry : fs::directory_iterator(folder, ec))
      if (stale_temporary(entry.path().filename().string(), host))
        {
          // another run may remove it at the same time: not an error
          std::error_code ignored;
          fs::remove_all(entry.path(), ignored);
          removed.push_back(entry.path());
        }
    return removed;
  }

  bool SceneResult::pass() const
  {
    return std::all_of(rows.begin(), rows.end(), [](const Row &r) { return r.pass; });
  }

  double SceneResult::worst_error() const
  {
    double worst = 0.;
    for (const Row &r : rows)
      worst = std::max(worst, r.error.empty() ? r.rel_error : std::numeric_limits<double>::infinity());
    return worst;
  }

  std::string csv_quote(const std::string &s)
  {
    std::string out = "\"";
    for (const char c : s)
      out += (c == '"') ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
  }

  namespace
  {
    /// The columns of errors.csv and errors.md; the FE contract's in the Markdown only when a row has one.
    std::vector<Column> error_columns(const bool contract)
    {
      const auto contract_column = [contract](const char *csv, const char *md) {
        return contract ? Column::both(csv, md) : Column::csv_only(csv);
      };
      return {Column::both("quantity", "quantity").quoted(),
              Column::both("metric", "metric").quoted(),
              Column::both("method", "checked").quoted(),
              Column::both("reference", "reference").quoted(),
              Column::both("reference_value", "reference value"),
              Column::both("value", "value"),
              Column::csv_only("abs_error"),
              Column::both("rel_error", "rel. error"),
              Column::both("tolerance", "tolerance"),
              Column::both("pass", "pass"),
              Column::both("dofs", "DoFs"),
              Column::both("seconds", "s"),
              Column::csv_only("error").quoted(),
              contract_column("fe_asked", "FE asked"),
              contract_column("fe_estimate", "FE estimate"),
              contract_column("fe_contract", "contract").quoted()};
    }

    std::vector<Cell> error_cells(const Row &r)
    {
      const bool failed = !r.error.empty();
      Cell reference_value(r.reference_value), value(r.value), dofs(r.dofs);
      return {r.quantity,
              r.metric,
              r.method,
              r.reference,
              failed ? reference_value.md_text("-") : reference_value,
              failed ? value.md_text("error: " + r.error) : value,
              r.abs_error,
              r.rel_error,
              r.tolerance,
              Cell(r.pass ? "pass" : "FAIL").md_text(r.pass ? "pass" : "**FAIL**"),
              r.dofs ? dofs : dofs.md_text("-"),
              r.seconds,
              r.error,
              r.asked > 0 ? Cell(r.asked) : Cell(r.asked).md_text("-"),
              r.estimate >= 0 ? Cell(r.estimate) : Cell(r.estimate).md_text("-"),
              r.contract.empty() ? Cell(r.contract).md_text("-") : Cell(r.contract)};
    }
  } // namespace

  void write_errors(const SceneResult &s, const fs::path &folder)
  {
    const bool contract = std::any_of(s.rows.begin(), s.rows.end(), [](const Row &r) { return r.asked > 0; });
    Table table(error_columns(contract), Number{'g', 17});
    for (const Row &r : s.rows)
      table.add(error_cells(r));
    table.write_csv(folder / "errors.csv");
    write_text(folder / "errors.md", "# " + s.name + "\n\n" + s.description + "\n\n" + table.md());
  }

  namespace
  {
    thread_local std::string plot_subtitle;
  }

  PlotSubtitle::PlotSubtitle(std::string line)
    : previous(std::move(plot_subtitle))
  {
    plot_subtitle = std::move(line);
  }

  PlotSubtitle::~PlotSubtitle() { plot_subtitle = std::move(previous); }

  bool write_plot(const fs::path &folder, const std::string &stem, const std::string &title, const std::string &xlabel,
                  const std::string &ylabel, const std::vector<Series> &series, const bool logx, const bool logy)
  {
    std::ofstream data(folder / (stem + ".dat"));
    data << std::setprecision(12);
    for (std::size_t i = 0; i < series.size(); ++i)
      {
        data << "# " << series[i].title << "\n";
        for (std::size_t j = 0; j < series[i].x.size(); ++j)
          data << series[i].x[j] << ' ' << series[i].y[j] << '\n';
        data << "\n\n"; // gnuplot data blocks: index i
      }
    data.close();
    std::ofstream gp(folder / (stem + ".gp"));
    gp << "# gnuplot script: `gnuplot " << stem << ".gp` in this folder remakes " << stem << ".png and " << stem
       << ".svg\n"
       << "set title \"" << title << (plot_subtitle.empty() ? "" : "\\n" + plot_subtitle)
       << "\" noenhanced\nset xlabel \"" << xlabel << "\" noenhanced\nset ylabel \"" << ylabel
       << "\" noenhanced\nset grid\n"
       // the legend outside the plot area, right of it: it cannot cover data
       << "set key outside right top vertical Left reverse\n"
       << (logx ? "set logscale x\nset format x \"%g\"\n" : "") << (logy ? "set logscale y\nset format y \"%.0e\"\n" : "");
    std::string plot = "plot ";
    // Each series of its own colour takes the next of gnuplot's 8 line types' colours; one with colour_of takes that
    // series' colour (FE points drawn in their curve's).
    std::vector<std::size_t> colour(series.size());
    std::size_t              own = 0;
    for (std::size_t i = 0; i < series.size(); ++i)
      colour[i] = series[i].colour_of >= 0 && std::size_t(series[i].colour_of) < i ? colour[series[i].colour_of] : own++;
    for (std::size_t i = 0; i < series.size(); ++i)
      {
        // from the 9th colour on, another point shape and dash tell the series apart
        const std::size_t round = colour[i] / 8;
        constexpr int     shapes[] = {7, 5, 9, 11, 13};
        const std::string shape    = std::to_string(shapes[round % 5]);
        const std::string dash  = " dt " + std::to_string(round % 5 + 1);
        plot += std::string(i ? ", " : "") + "'" + stem + ".dat' index " + std::to_string(i) + " with " +
                (series[i].linespoints ? "linespoints lw 2 pt " + shape + " ps 1" + dash
                 : series[i].points    ? "points pt " + shape + " ps 1.2"
                                       : "lines lw 2" + dash) +
                " lc " + std::to_string(colour[i] % 8 + 1) + " title \"" + series[i].title + "\" noenhanced";
      }
    gp << "set terminal pngcairo size 1100,600\nset output '" << stem << ".png'\n" << plot << "\n"
       << "set terminal svg size 1100,600\nset output '" << stem << ".svg'\n" << plot << "\n";
    gp.close();
    const std::string command = "cd '" + folder.string() + "' && gnuplot '" + stem + ".gp' > /dev/null 2>&1";
    return std::system(command.c_str()) == 0;
  }
  Row compare(const std::string &quantity, const std::string &metric, const std::string &checked,
              const std::string &reference, const double ref, const double value, const double scale,
              const double tolerance, const unsigned int dofs, const double seconds)
  {
    Row row;
    row.quantity = quantity;
    row.metric = metric;
    row.method = checked;
    row.reference = reference;
    row.reference_value = ref;
    row.value = value;
    row.abs_error = std::abs(value - ref);
    row.rel_error = row.abs_error / std::max(std::abs(scale), 1e-300);
    row.tolerance = tolerance;
    row.pass = row.rel_error <= tolerance;
    row.dofs = dofs;
    row.seconds = seconds;
    return row;
  }

  Row failed(const std::string &quantity, const std::string &checked, const std::string &reference,
             const std::string &what)
  {
    Row row;
    row.quantity = quantity;
    row.method = checked;
    row.reference = reference;
    row.error = what;
    row.rel_error = std::numeric_limits<double>::infinity();
    return row;
  }

} // namespace gradcontact::cases
