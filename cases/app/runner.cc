#include "app/runner.h"
#include "runners/run_scene.h"

#include "scene/expression.h"

#include "report/report.h"
#include "report/table.h"
#include "scene/scene.h"

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <chrono>
#include <cmath>
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
      std::vector<Override> overrides;
      fs::path reports = "reports";
      bool quiet = false;
      bool verbose = false;
      // --shard i/N: this process runs the items (scenes of `run`, values of `sweep`) whose 0-based
      // position j has j % N == i, so N independent jobs (an array job, one per node or rank group)
      // share a sweep without any communication; each writes summary.shard-i-of-N.md.
      unsigned int shard = 0;
      unsigned int shards = 1;
      // --map-shard i/N: the (k, lambda) points of a Tabor-parameter map at positions j % N == i go to the map's
      // point cache, no report is written; a run without it assembles the report from the cache.
      unsigned int map_shard = 0;
      unsigned int map_shards = 1;

      bool mine(const std::size_t j) const { return j % shards == shard; }
    };

    void parse_shard(unsigned int &index, unsigned int &count, const std::string &option, const std::string &text)
    {
      const auto slash = text.find('/');
      std::size_t used_i = 0, used_n = 0;
      long i = -1, n = 0;
      try
        {
          if (slash != std::string::npos)
            {
              i = std::stol(text.substr(0, slash), &used_i);
              n = std::stol(text.substr(slash + 1), &used_n);
            }
        }
      catch (const std::exception &)
        {
          i = -1;
        }
      if (slash == std::string::npos || used_i != slash || used_n != text.size() - slash - 1 || n < 1 ||
          n > 100000 || i < 0 || i >= n)
        throw std::invalid_argument("run: " + option + " '" + text +
                                    "' is not i/N with N in [1, 100000] and i in [0, N - 1] (0-based shard index)");
      index = static_cast<unsigned int>(i);
      count = static_cast<unsigned int>(n);
    }

    void add_scenes(Options &o, const std::string &a)
    {
      const fs::path p(a);
      if (fs::is_directory(p))
        {
          std::vector<fs::path> found;
          for (const auto &entry : fs::directory_iterator(p))
            if (entry.path().extension() == ".jsonl" || entry.path().extension() == ".prm" ||
                entry.path().extension() == ".json")
              found.push_back(entry.path());
          std::sort(found.begin(), found.end());
          if (found.empty())
            throw std::invalid_argument("run: folder '" + a + "' holds no scene (*.prm, *.json, *.jsonl)");
          o.scenes.insert(o.scenes.end(), found.begin(), found.end());
        }
      else if (fs::is_regular_file(p))
        {
          if (p.extension() != ".prm" && p.extension() != ".json" && p.extension() != ".jsonl")
            throw std::invalid_argument("run: '" + a + "' is not a scene (*.prm, *.json or *.jsonl)");
          o.scenes.push_back(p);
        }
      else
        throw std::invalid_argument("run: no scene file or folder '" + a + "'");
    }

    Options parse(const std::vector<std::string> &args, std::vector<std::string> *rest = nullptr)
    {
      Options o;
      for (std::size_t i = 0; i < args.size(); ++i)
        {
          const std::string &a = args[i];
          const auto value = [&]() {
            if (i + 1 == args.size())
              throw std::invalid_argument("run: " + a + " needs a value");
            return args[++i];
          };
          if (a == "--reports")
            o.reports = value();
          else if (a == "--set")
            o.overrides.push_back(parse_override(value()));
          else if (a == "--quiet")
            o.quiet = true;
          else if (a == "--force")
            o.overrides.push_back(parse_override("Discretization/memory guard=off"));
          else if (a == "--verbose")
            o.verbose = true;
          else if (a == "--shard")
            parse_shard(o.shard, o.shards, a, value());
          else if (a == "--map-shard")
            parse_shard(o.map_shard, o.map_shards, a, value());
          else if (a == "--help-scene")
            {
              std::cout << scene_documentation();
              std::exit(0);
            }
          else if (a == "--help-functions")
            {
              std::cout << "The functions of candidate expressions (Candidate/*, cases/scene/expression.h):\n"
                        << Expression::function_list();
              std::exit(0);
            }
          else if (rest && a == "--over")
            {
              rest->push_back(a);
              rest->push_back(value());
            }
          else if (!a.empty() && a[0] == '-')
            throw std::invalid_argument("run: unknown option '" + a + "'");
          else
            add_scenes(o, a);
        }
      if (o.scenes.empty())
        throw std::invalid_argument("run: name at least one scene file or folder");
      return o;
    }

    SceneResult run_analytic_check(const fs::path &scene)
    {
      SceneResult result;
      result.name = scene.stem().string();
      result.kind = "jsonl";
      result.description = "Closed forms against the numerical MDR (" + scene.filename().string() + ").";
      std::ifstream in(scene);
      if (!in)
        throw std::runtime_error("cannot open scene '" + scene.string() + "'");
      const auto start = std::chrono::steady_clock::now();
      int number = 0;
      for (std::string line; std::getline(in, line);)
        {
          ++number;
          const auto first = line.find_first_not_of(" \t\r");
          if (first == std::string::npos || line[first] == '#')
            continue;
          json j;
          try
            {
              j = json::parse(line);
            }
          catch (const json::exception &e)
            {
              throw std::runtime_error(scene.string() + ":" + std::to_string(number) + ": not valid JSON (" + e.what() + ")");
            }
          Row row;
          row.quantity = j.value("case", "") + "/" + j.value("quantity", "");
          row.metric = j.value("name", scene.stem().string() + ":" + std::to_string(number));
          row.method = "closed form";
          row.reference = "numerical MDR";
          row.tolerance = j.value("tolerance", 1e-9);
          const double floor = j.value("abs_floor", 0.);
          for (const char *key : {"name", "tolerance", "abs_floor", "method"})
            j.erase(key);
          // The value by one method, or the error that stopped it.
          const auto value_of = [&j](const batch::Method method, double &value) -> std::string {
            try
              {
                batch::Request q = batch::parse(j);
                q.method = method;
                value = batch::evaluate(q);
                return "";
              }
            catch (const std::exception &e)
              {
                return e.what();
              }
          };
          double closed = 0., numeric = 0.;
          const auto t0 = std::chrono::steady_clock::now();
          const std::string closed_error = value_of(batch::Method::closed_form, closed);
          row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          const std::string numeric_error = value_of(batch::Method::numerical_mdr, numeric);
          if (!closed_error.empty() || !numeric_error.empty())
            {
              row.error = !closed_error.empty() ? "closed form: " + closed_error : "numerical MDR: " + numeric_error;
              row.rel_error = INFINITY;
            }
          else
            {
              row.reference_value = numeric;
              row.value = closed;
              row.abs_error = std::abs(closed - numeric);
              row.rel_error = row.abs_error / std::max(std::abs(numeric), 1e-300);
              row.pass = row.rel_error <= row.tolerance || row.abs_error <= floor;
            }
          result.rows.push_back(row);
        }
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }

    /// Runs one scene (with overrides) and writes its report atomically; `suffix` names sweep variants.
    SceneResult run_one(const fs::path &file, const std::vector<Override> &overrides, const Options &o,
                        const std::string &suffix = "")
    {
      if (file.extension() == ".jsonl")
        {
          if (!overrides.empty())
            throw std::invalid_argument("run: --set applies to .prm scenes, not to " + file.string());
          SceneResult s = run_analytic_check(file);
          atomic_folder(o.reports / s.name, [&](const fs::path &tmp) { write_errors(s, tmp); });
          return s;
        }
      Scene scene = read_scene(file.string(), overrides);
      for (const std::string &note : scene.notes)
        std::cerr << "gradcontact: scene " << file.string() << ": " << note << "\n";
      scene.info.name += suffix;
      // a variant says so in its report: the description was written for the file's own values
      if (!overrides.empty())
        {
          std::string set;
          for (const Override &ov : overrides)
            {
              std::string path;
              for (const std::string &part : ov.path)
                path += (path.empty() ? "" : "/") + part;
              set += (set.empty() ? "" : ", ") + path + " = " + ov.value;
            }
          scene.info.description += (scene.info.description.empty() ? "" : " ") + std::string("[run with --set ") +
                                    set + "]";
        }
      if (o.verbose)
        std::cout << "# " << file.string() << " resolved:\n" << scene.resolved;
      try
        {
          return run_report(scene, o.reports, o.verbose);
        }
      catch (const std::invalid_argument &e)
        {
          // an entry found bad only when the scene runs (a candidate's expression): name the file as the
          // validation of read_scene does
          if (std::string(e.what()).find(file.string()) != std::string::npos)
            throw;
          throw std::invalid_argument("scene " + file.string() + ": " + e.what());
        }
    }

    void print(const SceneResult &s, const Options &o)
    {
      if (o.quiet)
        return;
      std::cout << (s.pass() ? "pass " : "FAIL ") << s.name << ": " << s.rows.size() << " comparisons, worst error "
                << format(s.worst_error()) << ", " << format(s.seconds) << " s\n";
      if (o.verbose || !s.pass())
        for (const Row &r : s.rows)
          if (o.verbose || !r.pass)
            std::cout << "  " << (r.pass ? "pass " : "FAIL ") << r.quantity << " [" << r.metric << "] " << r.method
                      << " vs " << r.reference << ": " << (r.error.empty() ? format(r.rel_error) : r.error)
                      << (r.asked > 0 ? " (asked " + format(r.asked) + ", estimate " + format(r.estimate) + ", contract " +
                                          r.contract + ")"
                                      : "")
                      << "\n";
    }

    int finish(const std::vector<SceneResult> &results, const Options &o)
    {
      const std::string stem = o.shards == 1 ? "summary"
                                              : "summary.shard-" + std::to_string(o.shard) + "-of-" +
                                                  std::to_string(o.shards);
      const fs::path summary = o.reports / (stem + ".md");
      Table table({Column::md_only("scene"), Column::md_only("comparisons"), Column::md_only("worst error"),
                   Column::md_only("failed"), Column::md_only("seconds"), Column::md_only("report")});
      for (const SceneResult &s : results)
        table.add({s.name, s.rows.size(), s.worst_error(),
                   std::count_if(s.rows.begin(), s.rows.end(), [](const Row &r) { return !r.pass; }), s.seconds,
                   "[" + s.name + "/errors.md](" + s.name + "/errors.md)"});
      // A link only to a file that exists: the figures are drawn by their own command.
      const std::string figures =
        fs::exists(o.reports / "figures" / "index.md")
          ? "\nThe chapter's figures, each FE point checked against the closed form: "
            "[figures/index.md](figures/index.md) (written by `gradcontact figures`).\n"
          : "\nThe chapter's figures, each FE point checked against the closed form, are drawn by `gradcontact "
            "figures cases/figures` (not drawn into this folder yet).\n";
      write_document(o.reports, stem, "# gradcontact summary\n\n" + table.md() + figures);
      const bool all_pass = std::all_of(results.begin(), results.end(), [](const SceneResult &s) { return s.pass(); });
      if (!o.quiet)
        std::cout << "summary: " << summary.string() << (all_pass ? " (all pass)" : " (FAILURES)") << "\n";
      return all_pass ? 0 : 1;
    }
  } // namespace

  int run(const std::vector<std::string> &args)
  {
    const Options o = parse(args);
    if (o.map_shards > 1)
      {
        // Fill the point caches of the maps; their reports are written by a run without --map-shard.
        fs::create_directories(o.reports);
        remove_stale_temporaries(o.reports);
        for (const fs::path &file : o.scenes)
          {
            const Scene scene = read_scene(file.string(), o.overrides);
            if (scene.kind != SceneKind::map || scene.map.parameter != MapParameters::Parameter::tabor_parameter)
              throw std::invalid_argument("run: --map-shard splits a Tabor-parameter map (Map/parameter = Tabor "
                                          "parameter); " + file.string() + " is not one");
            MapShard shard{o.map_shard, o.map_shards};
            const fs::path tmp = temporary_sibling(o.reports / (scene.info.name + ".map-shard"));
            fs::create_directories(tmp);
            try
              {
                run_map_scene(scene, tmp, o.verbose, shard);
              }
            catch (...)
              {
                fs::remove_all(tmp);
                throw;
              }
            fs::remove_all(tmp);
            if (!o.quiet)
              std::cout << "map shard " << o.map_shard << "/" << o.map_shards << " of " << scene.info.name << ": "
                        << shard.computed << " points solved, " << shard.cached << " already cached, " << shard.skipped
                        << " left to the other shards (" << (o.reports / ".map-points").string()
                        << "); run without --map-shard to write the report\n";
          }
        return 0;
      }
    const bool progress = !o.quiet && isatty(STDERR_FILENO);
    fs::create_directories(o.reports);
    remove_stale_temporaries(o.reports); // what a killed run left
    std::vector<SceneResult> results;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < o.scenes.size(); ++i)
      {
        if (!o.mine(i))
          continue;
        if (progress)
          std::cerr << "[" << i + 1 << "/" << o.scenes.size() << "] " << o.scenes[i].string() << " (" << std::fixed
                    << std::setprecision(1)
                    << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s)\n"
                    << std::defaultfloat;
        results.push_back(run_one(o.scenes[i], o.overrides, o));
        print(results.back(), o);
      }
    return finish(results, o);
  }

  int sweep(const std::vector<std::string> &args)
  {
    std::vector<std::string> over;
    const Options o = parse(args, &over);
    if (o.scenes.size() != 1 || o.scenes.front().extension() == ".jsonl")
      throw std::invalid_argument("sweep: name exactly one .prm or .json scene");
    if (over.size() != 2)
      throw std::invalid_argument("sweep: give one --over Section/key=v1,v2,...");
    const Override base = parse_override(over[1]);
    std::vector<std::string> values;
    std::stringstream list(base.value);
    for (std::string v; std::getline(list, v, ',');)
      values.push_back(v);
    if (values.empty())
      throw std::invalid_argument("sweep: --over " + over[1] + " lists no value");
    fs::create_directories(o.reports);
    remove_stale_temporaries(o.reports); // what a killed run left
    std::vector<SceneResult> results;
    for (std::size_t j = 0; j < values.size(); ++j)
      {
        if (!o.mine(j))
          continue;
        const std::string &v = values[j];
        std::vector<Override> overrides = o.overrides;
        overrides.push_back({base.path, v});
        results.push_back(run_one(o.scenes.front(), overrides, o, "-" + base.path.back() + "=" + v));
        print(results.back(), o);
      }
    return finish(results, o);
  }
} // namespace gradcontact::cases
