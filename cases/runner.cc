#include "runner.h"

#include <analytic/batch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    struct Options
    {
      std::vector<fs::path> scenes;
      fs::path reports = "reports";
      bool quiet = false;
      bool verbose = false;
    };

    /// One comparison: a value against a reference, with its error and tolerance (STYLE rule 7).
    struct Row
    {
      std::string name, case_name, quantity;
      double reference = 0., value = 0., abs_error = 0., rel_error = 0., tolerance = 0.;
      bool pass = false;
      std::string error; // non-empty when either side failed to evaluate
      double milliseconds = 0.;
    };

    struct SceneResult
    {
      std::string name;
      std::vector<Row> rows;
      double seconds = 0.;
      bool pass() const
      {
        return std::all_of(rows.begin(), rows.end(), [](const Row &r) { return r.pass; });
      }
    };

    Options parse(const std::vector<std::string> &args)
    {
      Options o;
      for (std::size_t i = 0; i < args.size(); ++i)
        {
          const std::string &a = args[i];
          if (a == "--reports")
            {
              if (i + 1 == args.size())
                throw std::invalid_argument("run: --reports needs a folder");
              o.reports = args[++i];
            }
          else if (a == "--quiet")
            o.quiet = true;
          else if (a == "--verbose")
            o.verbose = true;
          else if (!a.empty() && a[0] == '-')
            throw std::invalid_argument("run: unknown option '" + a + "'");
          else
            {
              const fs::path p(a);
              if (fs::is_directory(p))
                {
                  std::vector<fs::path> found;
                  for (const auto &entry : fs::directory_iterator(p))
                    if (entry.path().extension() == ".jsonl")
                      found.push_back(entry.path());
                  std::sort(found.begin(), found.end());
                  if (found.empty())
                    throw std::invalid_argument("run: folder '" + a + "' holds no scene (*.jsonl)");
                  o.scenes.insert(o.scenes.end(), found.begin(), found.end());
                }
              else if (fs::is_regular_file(p))
                o.scenes.push_back(p);
              else
                throw std::invalid_argument("run: no scene file or folder '" + a + "'");
            }
        }
      if (o.scenes.empty())
        throw std::invalid_argument("run: name at least one scene file or folder");
      return o;
    }

    std::string format(const double x)
    {
      char b[32];
      std::snprintf(b, sizeof b, "%.10g", x);
      return b;
    }

    SceneResult run_analytic_check(const fs::path &scene)
    {
      SceneResult result;
      result.name = scene.stem().string();
      std::ifstream in(scene);
      if (!in)
        throw std::runtime_error("cannot open scene '" + scene.string() + "'");
      std::string line;
      int number = 0;
      const auto start = std::chrono::steady_clock::now();
      while (std::getline(in, line))
        {
          ++number;
          if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
            continue;
          json j;
          try
            {
              j = json::parse(line);
            }
          catch (const json::exception &e)
            {
              throw std::runtime_error(scene.string() + ":" + std::to_string(number) + ": not valid JSON (" +
                                       e.what() + ")");
            }
          Row row;
          row.name = j.value("name", scene.stem().string() + ":" + std::to_string(number));
          row.case_name = j.value("case", "");
          row.quantity = j.value("quantity", "");
          row.tolerance = j.value("tolerance", 1e-9);
          const double floor = j.value("abs_floor", 0.);
          for (const char *key : {"name", "tolerance", "abs_floor", "method"})
            j.erase(key);
          const auto t0 = std::chrono::steady_clock::now();
          j["method"] = "closed_form";
          const batch::Answer closed = batch::evaluate(j.dump());
          j["method"] = "numerical_mdr";
          const batch::Answer numeric = batch::evaluate(j.dump());
          row.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
          if (!closed.ok || !numeric.ok)
            row.error = !closed.ok ? "closed form: " + closed.error : "numerical MDR: " + numeric.error;
          else
            {
              row.reference = numeric.value;
              row.value = closed.value;
              row.abs_error = std::abs(closed.value - numeric.value);
              row.rel_error = row.abs_error / std::max(std::abs(numeric.value), 1e-300);
              row.pass = row.rel_error <= row.tolerance || row.abs_error <= floor;
            }
          result.rows.push_back(row);
        }
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }

    void write_report(const SceneResult &s, const fs::path &folder)
    {
      std::ofstream csv(folder / "errors.csv");
      csv << "name,case,quantity,reference_numerical_mdr,value_closed_form,abs_error,rel_error,tolerance,pass,"
             "milliseconds,error\n";
      std::ofstream md(folder / "errors.md");
      md << "# " << s.name << ": closed form against the numerical MDR\n\n"
         << "| name | case | quantity | numerical MDR | closed form | rel. error | tolerance | pass | ms |\n"
         << "|---|---|---|---|---|---|---|---|---|\n";
      for (const Row &r : s.rows)
        {
          csv << r.name << ',' << r.case_name << ',' << r.quantity << ',' << std::setprecision(17) << r.reference
              << ',' << r.value << ',' << r.abs_error << ',' << r.rel_error << ',' << r.tolerance << ','
              << (r.pass ? "pass" : "FAIL") << ',' << r.milliseconds << ",\"" << r.error << "\"\n";
          md << "| " << r.name << " | " << r.case_name << " | " << r.quantity << " | "
             << (r.error.empty() ? format(r.reference) : "error") << " | "
             << (r.error.empty() ? format(r.value) : r.error) << " | " << format(r.rel_error) << " | "
             << format(r.tolerance) << " | " << (r.pass ? "pass" : "**FAIL**") << " | " << format(r.milliseconds)
             << " |\n";
        }
    }

    // Writes `folder` through a temporary sibling, replacing the old report only when complete.
    template <class Writer>
    void atomic_folder(const fs::path &folder, const Writer &writer)
    {
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
  } // namespace

  int run(const std::vector<std::string> &args)
  {
    const Options o = parse(args);
    const bool progress = !o.quiet && isatty(STDERR_FILENO);
    fs::create_directories(o.reports);
    std::vector<SceneResult> results;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < o.scenes.size(); ++i)
      {
        if (progress)
          std::cerr << "[" << i + 1 << "/" << o.scenes.size() << "] " << o.scenes[i].string() << " ("
                    << std::fixed << std::setprecision(1)
                    << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
                    << " s)\n";
        SceneResult s = run_analytic_check(o.scenes[i]);
        atomic_folder(o.reports / s.name, [&](const fs::path &tmp) { write_report(s, tmp); });
        if (!o.quiet)
          {
            double worst = 0.;
            for (const Row &r : s.rows)
              worst = std::max(worst, r.error.empty() ? r.rel_error : INFINITY);
            std::cout << (s.pass() ? "pass " : "FAIL ") << s.name << ": " << s.rows.size()
                      << " comparisons, worst relative error " << format(worst) << ", " << format(s.seconds)
                      << " s\n";
            if (o.verbose)
              for (const Row &r : s.rows)
                std::cout << "  " << (r.pass ? "pass " : "FAIL ") << r.name << " " << r.case_name << "/"
                          << r.quantity << " rel " << format(r.rel_error) << (r.error.empty() ? "" : " " + r.error)
                          << "\n";
          }
        results.push_back(std::move(s));
      }
    const fs::path summary = o.reports / "summary.md";
    const fs::path tmp = o.reports / ".summary.md.tmp";
    {
      std::ofstream md(tmp);
      md << "# gradcontact summary\n\n| scene | comparisons | worst rel. error | failed | seconds | report |\n"
            "|---|---|---|---|---|---|\n";
      for (const SceneResult &s : results)
        {
          double worst = 0.;
          int failed = 0;
          for (const Row &r : s.rows)
            {
              worst = std::max(worst, r.error.empty() ? r.rel_error : INFINITY);
              failed += r.pass ? 0 : 1;
            }
          md << "| " << s.name << " | " << s.rows.size() << " | " << format(worst) << " | " << failed << " | "
             << format(s.seconds) << " | [" << s.name << "/errors.md](" << s.name << "/errors.md) |\n";
        }
    }
    fs::rename(tmp, summary);
    const bool all_pass =
      std::all_of(results.begin(), results.end(), [](const SceneResult &s) { return s.pass(); });
    if (!o.quiet)
      std::cout << "summary: " << summary.string() << (all_pass ? " (all pass)" : " (FAILURES)") << "\n";
    return all_pass ? 0 : 1;
  }
} // namespace gradcontact::cases
