#include "tools/bench.h"
#include "tools/accuracy_bench.h"
#include "tools/ring_stress.h"
#include "tools/stress_bench.h"
#include "tools/fe_bench.h"
#include "tools/fe_oracle.h"
#include "report/report.h"
#include "report/table.h"

#include <analytic/batch.h>
#include <analytic/reference_rows.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <type_traits>
#include <stdexcept>
#include <sys/utsname.h>
#include <thread>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    struct Options
    {
      fs::path reports = "reports";
      fs::path references = fs::path(GRADCONTACT_SOURCE_DIR) / "tests/data/references.jsonl";
      int repeat = 5;
      std::size_t numerical_stride = 5; // numerical MDR on every 5th row of a family (ms per row)
      std::string part = "all";         // analytic | fe | peer | oracle | accuracy | all
      bool quick = false;
      int fe_repeat = 3;
      fs::path peer_scripts = fs::path(GRADCONTACT_SOURCE_DIR) / "cases/peers/freefem";
      std::vector<std::string> scenes; // --scene a,b: FE scenes to run (empty: all)
      std::vector<double> ks;          // --k a,b: the accuracy grid's k (empty: all)
    };

    /// One family: case/quantity, with its rows (requests without method) and references.
    struct Family
    {
      std::vector<std::string> requests;
      std::vector<double> references;
    };

    struct Timing
    {
      double min = 0., median = 0.; // seconds per evaluation
      double worst_error = 0.;
      std::size_t rows = 0;
      std::size_t refused = 0; // rows the method refuses with an explicit message
      std::string first_refusal; // the message of the first row the method refused to parse
    };

    /// `text` read whole as a T (int or double); false when it is not a number or has anything after it.
    template <typename T>
    bool read_whole(const std::string &text, T &x)
    {
      std::size_t used = 0;
      try
        {
          if constexpr (std::is_same_v<T, int>)
            x = std::stoi(text, &used);
          else
            x = std::stod(text, &used);
        }
      catch (const std::logic_error &)
        {
          return false;
        }
      return used > 0 && used == text.size();
    }

    Options parse(const std::vector<std::string> &args)
    {
      Options o;
      for (std::size_t i = 0; i < args.size(); ++i)
        {
          const auto value = [&](const char *name) {
            if (i + 1 == args.size())
              throw std::invalid_argument(std::string("bench: ") + name + " needs a value");
            return args[++i];
          };
          if (args[i] == "--reports")
            o.reports = value("--reports");
          else if (args[i] == "--references")
            o.references = value("--references");
          else if (args[i] == "--repeat" || args[i] == "--fe-repeat")
            {
              const std::string name = args[i], text = value(name.c_str());
              int n = 0;
              if (!read_whole(text, n))
                throw std::invalid_argument("bench: " + name + " = '" + text + "' is not an integer in [1, 1000]");
              if (n < 1 || n > 1000)
                throw std::invalid_argument("bench: " + name + " = " + std::to_string(n) + " is outside [1, 1000]");
              (name == "--repeat" ? o.repeat : o.fe_repeat) = n;
            }
          else if (args[i] == "--part")
            {
              o.part = value("--part");
              if (o.part != "analytic" && o.part != "fe" && o.part != "peer" && o.part != "oracle" &&
                  o.part != "accuracy" && o.part != "stresses" && o.part != "all")
                throw std::invalid_argument("bench: --part = '" + o.part +
                                            "' is not one of analytic, fe, peer, oracle, accuracy, stresses, all");
            }
          else if (args[i] == "--quick")
            o.quick = true;
          else if (args[i] == "--scene")
            {
              // comma-separated; the names are checked by run_fe_bench
              std::istringstream list(value("--scene"));
              for (std::string name; std::getline(list, name, ',');)
                o.scenes.push_back(name);
            }
          else if (args[i] == "--k")
            {
              // comma-separated numbers; the range is checked by run_accuracy_bench
              std::istringstream list(value("--k"));
              for (std::string text; std::getline(list, text, ',');)
                {
                  double k = 0;
                  if (!read_whole(text, k))
                    throw std::invalid_argument("bench: --k = '" + text + "' is not a number in (-1, 1)");
                  o.ks.push_back(k);
                }
            }
          else if (args[i] == "--peer-scripts")
            o.peer_scripts = value("--peer-scripts");
          else
            throw std::invalid_argument("bench: unknown argument '" + args[i] + "'");
        }
      return o;
    }

    std::map<std::string, Family> load(const fs::path &file)
    {
      std::map<std::string, Family> families;
      for (const batch::ReferenceRow &row : batch::read_reference_rows(file.string()))
        {
          const std::string key =
            row.request.at("case").get<std::string>() + "/" + row.request.at("quantity").get<std::string>();
          families[key].requests.push_back(row.request.dump());
          families[key].references.push_back(row.reference);
        }
      return families;
    }

    // Times the evaluation of the rows of a family: each request is parsed once (batch::prepare), then
    // evaluated `repeat` times; the clock covers the evaluations only (the material coefficients of a
    // request are computed on its first evaluation, so the minimum over repetitions excludes them).
    Timing measure(const Family &f, const std::string &method, const std::size_t stride, const int repeat)
    {
      std::vector<batch::Prepared> requests;
      std::vector<double> references;
      Timing t;
      std::size_t not_available = 0;
      for (std::size_t i = 0; i < f.requests.size(); i += stride)
        {
          json q = json::parse(f.requests[i]);
          q["method"] = method;
          try
            {
              requests.push_back(batch::prepare(batch::parse(q)));
              references.push_back(f.references[i]);
            }
          catch (const std::exception &e)
            {
              ++not_available; // the method has no path for this quantity
              if (t.first_refusal.empty())
                t.first_refusal = e.what();
            }
        }
      if (requests.empty())
        {
          t.refused = not_available;
          return t;
        }
      std::vector<double> samples;
      for (int rep = 0; rep < repeat; ++rep)
        {
          double worst = 0.;
          std::size_t refused = 0, rows = 0;
          double seconds = 0.;
          for (std::size_t i = 0; i < requests.size(); ++i)
            {
              double value = 0.;
              const auto start = std::chrono::steady_clock::now();
              try
                {
                  value = requests[i]();
                }
              catch (const std::exception &)
                {
                  ++refused;
                  continue;
                }
              seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
              ++rows;
              const double r = references[i];
              worst = std::max(worst, r == 0. ? std::abs(value) : std::abs(value - r) / std::abs(r));
            }
          samples.push_back(seconds / std::max<std::size_t>(rows, 1));
          t.worst_error = worst;
          t.rows = rows;
          t.refused = refused + not_available;
        }
      std::sort(samples.begin(), samples.end());
      t.min = samples.front();
      t.median = samples[samples.size() / 2];
      return t;
    }

    std::string machine()
    {
      std::string cpu = "unknown";
      std::ifstream info("/proc/cpuinfo");
      for (std::string line; std::getline(info, line);)
        if (line.rfind("model name", 0) == 0)
          {
            cpu = line.substr(line.find(':') + 2);
            break;
          }
      // The BLAS actually loaded (CHOLMOD's and UMFPACK's speed depend on it, fem/doc/accuracy-and-cost.md,
      // "Profile and BLAS kernels").
      std::string blas = "unknown";
      std::ifstream maps("/proc/self/maps");
      for (std::string line; std::getline(maps, line);)
        if ((line.find("/libblas.so") != std::string::npos || line.find("/libopenblas") != std::string::npos) &&
            line.find('/') != std::string::npos)
          {
            blas = line.substr(line.find('/'));
            break;
          }
      utsname u{};
      uname(&u);
      std::ostringstream s;
      s << cpu << " (" << std::thread::hardware_concurrency() << " logical cores)" << "; " << u.sysname << " " << u.release << "; BLAS " << blas << "; compiler " << __VERSION__ << "; "
#ifdef NDEBUG
        << "optimised build (NDEBUG)";
#else
        << "debug build (assertions on)";
#endif
      return s.str();
    }

    std::string fmt(const double x, const char *f = "%.3g")
    {
      char b[32];
      std::snprintf(b, sizeof b, f, x);
      return b;
    }
  } // namespace

  namespace
  {
    /// analytic.{csv,md} into `tmp`.
    void analytic_part(const Options &o, const fs::path &tmp)
    {
      const auto families = load(o.references);
      if (families.empty())
        throw std::runtime_error("bench: the reference table is empty");
      Table csv({Column::csv_only("family"), Column::csv_only("method"), Column::csv_only("rows"),
                 Column::csv_only("refused"), Column::csv_only("min_seconds"), Column::csv_only("median_seconds"),
                 Column::csv_only("worst_relative_error")});
      Table table({Column::md_only("family"), Column::md_only("rows"),
                   Column::md_only("closed form min [ns]").md_as(Number{'f', 0}),
                   Column::md_only("median [ns]").md_as(Number{'f', 0}), Column::md_only("worst error").md_as(Number{'e', 1}),
                   Column::md_only("numerical MDR min [ms]").md_as(Number{'f', 3}),
                   Column::md_only("median [ms]").md_as(Number{'f', 3}), Column::md_only("worst error").md_as(Number{'e', 1})});
      std::ostringstream md;
      md << "# Analytic benchmarks: time per evaluation against error\n\n"
         << "Machine: " << machine() << ".  \n"
         << "Each family is every row of `tests/data/references.jsonl` with that case and quantity (the numerical "
            "MDR every "
         << o.numerical_stride << "th row), evaluated " << o.repeat
         << " times (the numerical MDR once); times are per evaluation of a parsed request (batch::prepare), including "
            "the look-up of its inputs, minimum and median over the repetitions. Errors are the worst relative error "
            "against the 34-digit references.\n\n";
      for (const auto &entry : families)
        {
          const Timing closed = measure(entry.second, "closed_form", 1, o.repeat);
          // Every row of the table has a closed form: a family that parses to nothing times nothing.
          if (closed.rows == 0)
            throw std::runtime_error("bench: no row of " + entry.first + " (" + std::to_string(entry.second.requests.size()) +
                                     " in the table) was evaluated by its closed form: " + closed.first_refusal);
          Timing numeric = measure(entry.second, "numerical_mdr", o.numerical_stride, 1);
          const bool has_numeric = numeric.rows > 0;
          std::cerr << entry.first << ": closed " << fmt(closed.min * 1e9) << " ns, error " << fmt(closed.worst_error)
                    << (has_numeric ? "; numerical " + fmt(numeric.min * 1e3) + " ms, error " + fmt(numeric.worst_error) : "")
                    << "\n";
          csv.add({entry.first, "closed_form", closed.rows, closed.refused, closed.min, closed.median, closed.worst_error});
          if (has_numeric)
            csv.add({entry.first, "numerical_mdr", numeric.rows, numeric.refused, numeric.min, numeric.median,
                     numeric.worst_error});
          const std::string refused = numeric.refused ? " (" + std::to_string(numeric.refused) + " refused)" : "";
          table.add({entry.first, closed.rows, closed.min * 1e9, closed.median * 1e9, closed.worst_error,
                     has_numeric ? Cell(numeric.min * 1e3) : Cell(), has_numeric ? Cell(numeric.median * 1e3) : Cell(),
                     has_numeric ? Cell(fmt(numeric.worst_error, "%.1e") + refused) : Cell()});
        }
      write_table_files(tmp, "analytic", csv, md.str() + table.md());
    }

    /// oracle.{csv,md} into `tmp`: batches of random paraboloid requests answered by the FE oracle
    /// (cases/tools/fe_oracle.h), one batch per (k, nu), against the closed forms.
    void oracle_part(const Options &o, const fs::path &tmp)
    {
      const std::size_t n = o.quick ? 100 : 1000;
      const double tolerance = 1e-5;
      std::mt19937_64 random(20261125);
      const auto uniform = [&random](const double lo, const double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
      };
      const auto log_uniform = [&](const double lo, const double hi) {
        return std::exp(uniform(std::log(lo), std::log(hi)));
      };
      Table table({Column::both("k", "k"), Column::both("nu", "nu"), Column::both("requests", "requests"),
                   Column::both("states", "FE states"), Column::both("seconds", "s").md_as(Number{'f', 1}),
                   Column::both("requests_per_second", "requests/s").md_as(Number{'f', 0}),
                   Column::both("worst_error_force_depth", "worst error F, d").md_as(Number{'e', 1}),
                   Column::both("worst_error_pressure_displacement", "worst error p, w").md_as(Number{'e', 1}),
                   Column::both("median_error_over_estimate", "error / estimate: median").md_as(Number{'f', 2}),
                   Column::both("p90_error_over_estimate", "90 %").md_as(Number{'f', 2}),
                   Column::both("worst_error_over_estimate", "worst").md_as(Number{'f', 0}),
                   Column::both("refused", "refused")});
      std::ostringstream md;
      md << "# The FE as an eval oracle: requests per second and error\n\nMachine: " << machine() << ".  \n"
         << "Per (k, nu), " << n << " paraboloid requests with \"method\": \"fe\", \"tolerance\": " << fmt(tolerance)
         << " in one `gradcontact eval` batch (cases/tools/fe_oracle.h): E0 in [1e6, 1e10] Pa, c0 in [1e-4, 0.1] m, a in "
            "[1e-6, 1e-2] m, R/a in [10, 1000] (log-uniform), the quantity force, depth, pressure at r/a in [0, 0.95) "
            "or displacement at r/a in [0, 5) (uniform). Time of the whole batch, one core (one FE state per (k, nu), "
            "the rest by scaling). Errors relative to the closed form (|value| of the request; pressures and "
            "displacements near 0 excluded below 1e-3 of the batch's scale) and against the oracle's own "
            "error estimate (the Richardson estimate of the accuracy contract's ladder, fem/accuracy/accuracy.h).\n\n";
      std::ostringstream refusals; // the first refusal of each (k, nu), below the table
      for (const auto &[k, nu] : {std::pair{-0.5, 0.3}, std::pair{0., 0.3}, std::pair{0.5, 0.3}, std::pair{0., 0.49}})
        {
          std::ostringstream batch_in;
          std::vector<json> requests;
          for (std::size_t i = 0; i < n; ++i)
            {
              const double a = log_uniform(1e-6, 1e-2);
              const int which = static_cast<int>(uniform(0, 4));
              const std::string quantity = which == 0 ? "force" : which == 1 ? "depth" : which == 2 ? "pressure"
                                                                                                   : "displacement";
              json q = {{"id", i},
                        {"case", "paraboloid"},
                        {"quantity", quantity},
                        {"material", {{"E0", log_uniform(1e6, 1e10)}, {"c0", log_uniform(1e-4, 0.1)}, {"k", k}, {"nu", nu}}},
                        {"geometry", {{"R", a * log_uniform(10, 1000)}}},
                        {"a", a}};
              if (which == 2)
                q["r"] = a * uniform(0, 0.95);
              if (which == 3)
                q["r"] = a * uniform(0, 5);
              requests.push_back(q);
              json fe = q;
              fe["method"] = "fe";
              fe["tolerance"] = tolerance;
              batch_in << fe.dump() << '\n';
            }
          FeOracle oracle;
          std::istringstream in(batch_in.str());
          std::ostringstream out;
          const auto start = std::chrono::steady_clock::now();
          const int errors = evaluate_stream(in, out, oracle);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          // A refusal of the accuracy contract (fem/accuracy/accuracy.h) names its limit: counted and reported, not an error.
          std::string first_refusal;
          std::istringstream lines(out.str());
          std::string line;
          double worst_scalar = 0, worst_profile = 0;
          std::vector<double> ratios;
          for (std::size_t i = 0; std::getline(lines, line); ++i)
            {
              const json answer = json::parse(line);
              if (answer.contains("error"))
                {
                  if (first_refusal.empty())
                    first_refusal = answer.at("error").get<std::string>();
                  continue;
                }
              const double exact = batch::evaluate(batch::parse(requests.at(i)));
              // the scale of the quantity: the pressure at the centre, the displacement at the edge
              json centre = requests[i];
              if (centre.contains("r"))
                centre["r"] = centre["quantity"] == "pressure" ? 0. : centre["a"].get<double>();
              const double scale = std::abs(batch::evaluate(batch::parse(centre)));
              if (std::abs(exact) < 1e-3 * scale)
                continue;
              const double error = std::abs(answer.at("value").get<double>() - exact) / std::abs(exact);
              (centre.contains("r") ? worst_profile : worst_scalar) =
                std::max(centre.contains("r") ? worst_profile : worst_scalar, error);
              const double ratio = std::abs(answer.at("value").get<double>() - exact) /
                                   std::max(answer.at("error_estimate").get<double>(), 1e-300);
              ratios.push_back(ratio);
            }
          std::sort(ratios.begin(), ratios.end());
          const auto quantile = [&ratios](const double f) {
            return ratios.empty() ? 0. : ratios[static_cast<std::size_t>(f * (ratios.size() - 1))];
          };
          const double worst = std::max(worst_scalar, worst_profile);
          std::cerr << "oracle k = " << k << ", nu = " << nu << ": " << n << " requests in " << fmt(seconds) << " s, "
                    << oracle.states_solved() << " states, worst error " << fmt(worst) << "\n";
          table.add({k, nu, n, oracle.states_solved(), seconds, n / seconds, worst_scalar, worst_profile, quantile(0.5),
                     quantile(0.9), quantile(1), errors});
          if (!first_refusal.empty())
            refusals << "- k = " << k << ", nu = " << nu << ": " << first_refusal << "\n";
        }
      md << table.md();
      if (!refusals.str().empty())
        md << "\nThe first refusal of each batch that had one (the limit the accuracy contract names):\n\n" << refusals.str();
      write_table_files(tmp, "oracle", table, md.str());
    }
  } // namespace

  int bench(const std::vector<std::string> &args)
  {
    const Options o = parse(args);
    // Every part writes into a temporary folder; the files of an earlier run that this run does not
    // rewrite (another part) are carried over, then the folder replaces reports/benchmarks in one rename,
    // so a failed run leaves the old report as it was.
    const fs::path folder = o.reports / "benchmarks";
    const fs::path tmp = temporary_sibling(folder);
    remove_stale_temporaries(o.reports); // what a killed run left
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    int broken = 0;
    try
      {
        if (o.part == "accuracy" || o.part == "all")
          {
            AccuracyBenchOptions accuracy;
            accuracy.quick = o.quick;
            accuracy.ks    = o.ks;
            broken = run_accuracy_bench(accuracy, tmp, machine());
          }
        if (o.part == "stresses" || o.part == "all")
          {
            StressBenchOptions stresses;
            stresses.quick = o.quick;
            broken += run_stress_bench(stresses, tmp, machine());
            RingStressOptions ring;
            ring.quick = o.quick;
            broken += run_ring_stress(ring, tmp, machine());
          }
        if (o.part == "analytic" || o.part == "all")
          analytic_part(o, tmp);
        if (o.part == "oracle" || o.part == "all")
          oracle_part(o, tmp);
        if (o.part == "fe" || o.part == "peer" || o.part == "all")
          {
            FeBenchOptions fe;
            fe.quick = o.quick;
            fe.repeat = o.quick ? 1 : o.fe_repeat;
            fe.with_fe = true;
            fe.with_peer = (o.part == "peer" || o.part == "all");
            fe.peer_scripts = o.peer_scripts;
            fe.scenes = o.scenes;
            run_fe_bench(fe, tmp, machine());
          }
        if (fs::is_directory(folder))
          for (const auto &entry : fs::directory_iterator(folder))
            if (!fs::exists(tmp / entry.path().filename()))
              fs::copy(entry.path(), tmp / entry.path().filename(), fs::copy_options::recursive);
      }
    catch (...)
      {
        fs::remove_all(tmp);
        throw;
      }
    replace_folder(tmp, folder);
    std::cout << "wrote " << folder.string() << "/ (part " << o.part << (o.quick ? ", quick" : "") << ")\n";
    if (broken > 0)
      std::cerr << "bench: the accuracy contract is broken in " << broken << " answers (" << (folder / "accuracy.md").string()
                << ", " << (folder / "stresses.md").string() << ", "
                << (folder / "ring_stress.md").string() << ")\n";
    return broken > 0 ? 1 : 0;
  }
} // namespace gradcontact::cases
