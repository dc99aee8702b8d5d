#include "tools/fe_bench.h"

#include "report/report.h"
#include "report/table.h"

#include <fem/adhesion/adhesion.h>
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/tangential/fourier_mode1_solver.h>
#include <fem/modulus/modulus.h>

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/normal.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  namespace
  {
    // The scene (fem_study's): SI units.
    constexpr double E0 = 2e9, a = 1e-4, c0 = 3 * a, nu = 0.3;
    constexpr double punch_depth = 1e-3 * a;
    constexpr double paraboloid_radius = 50 * a;
    constexpr unsigned int fe_levels = 5, peer_levels = 5;
    // JKR pull-off of the paraboloid (test_adhesion.cc's scene): work of adhesion, J/m^2.
    constexpr double jkr_dgamma = 0.05;
    // The pull-off search starts this factor off the closed-form critical radius (as the h-convergence
    // test of test_adhesion.cc does): the FE search, not the reference, finds a_c.
    constexpr double jkr_start_factor = 1.2;
    const std::array<double, 3> all_k{{-0.5, 0.0, 0.5}};
    // Levels of the adhesive and tangential scenes in the quick set (ctest bench.fe_quick_smoke).
    constexpr unsigned int quick_levels_new_scenes = 1;
    const std::array<const char *, 4> loads{{"flat_punch", "paraboloid", "jkr_paraboloid", "tangential_punch"}};
    /// The peer models the normal scenes only.
    bool peer_models(const std::string &load) { return load == "flat_punch" || load == "paraboloid"; }
    /// Mesh levels and repetitions per scene. A pull-off costs 7 FE solves (one per contact radius) and
    /// the mode-1 system has 3/2 the DoFs of the axisymmetric one, so these two scenes run fewer levels
    /// (0-1 and 0-2) and once each (a pull-off row already times 7 solves): their full ladders would
    /// dominate the bench's time. The times per level and scene are the wall-time
    /// columns of reports/benchmarks/fe_work_precision.md (`./vv bench --part fe`).
    unsigned int levels_of(const std::string &load)
    {
      return load == "jkr_paraboloid" ? 2 : load == "tangential_punch" ? 3 : fe_levels;
    }
    int repeats_of(const std::string &load, const int repeat)
    {
      return (load == "jkr_paraboloid" || load == "tangential_punch") ? 1 : repeat;
    }
    constexpr double inf = std::numeric_limits<double>::infinity();

    double seconds_since(const std::chrono::steady_clock::time_point &start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    double process_cpu_seconds()
    {
      timespec t{};
      clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
      return t.tv_sec + 1e-9 * t.tv_nsec;
    }

    double children_cpu_seconds()
    {
      rusage u{};
      getrusage(RUSAGE_CHILDREN, &u);
      return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
    }

    double median(std::vector<double> v)
    {
      std::sort(v.begin(), v.end());
      return v.empty() ? 0. : v[v.size() / 2];
    }

    struct References
    {
      double force = 0, depth = 0; ///< depth 0 for the flat punch (prescribed)
    };

    References references(const std::string &load, const double k)
    {
      const Medium m = medium(GradedHalfSpace{E0, c0, k, nu});
      if (load == "flat_punch")
        return {force(m, FlatPunch{a}, punch_depth), 0.};
      if (load == "jkr_paraboloid") // pull-off force under force control, a_c (9.55), F_c (9.56)
        return {jkr::critical_state(m, Paraboloid{paraboloid_radius}, jkr_dgamma, jkr::Control::force).force, 0.};
      if (load == "tangential_punch") // F_x = K_T delta, K_T = 2 h_T E0 a^{1+k} / ((1+k) c0^k) (9.78)-(9.79)
        return {2 * m.cT0 * std::pow(a, 1 + k) / ((1 + k) * std::pow(c0, k)) * punch_depth, 0.};
      return {force(m, Paraboloid{paraboloid_radius}, a), depth(m, Paraboloid{paraboloid_radius}, a)};
    }

    void set_errors(WorkPrecisionRow &row, const double F, const double d)
    {
      const References ref = references(row.load, row.k);
      row.force_error = F / ref.force - 1;
      row.depth_error = ref.depth > 0 ? d / ref.depth - 1 : 0.;
      row.error = std::max(std::abs(row.force_error), std::abs(row.depth_error));
      if (!std::isfinite(row.error))
        row.error = inf;
    }

    /// Accumulates the repetitions of one run.
    struct Samples
    {
      std::vector<double> wall, cpu, mesh, setup, assemble, factorize, solve, postprocess;
      void finish(WorkPrecisionRow &row) const
      {
        const auto min = [](const std::vector<double> &v) { return *std::min_element(v.begin(), v.end()); };
        row.wall_cold = wall.front();
        row.wall_min = min(wall);
        row.wall_median = median(wall);
        row.cpu_min = min(cpu);
        row.mesh = min(mesh);
        row.setup = min(setup);
        row.assemble = min(assemble);
        row.factorize = min(factorize);
        row.solve = min(solve);
        row.postprocess = min(postprocess);
      }
    };

    /// The normal scenes on a modulus vanishing at the surface are also run with the surface map
    /// (fem/modulus/surface_map.h) instead of z-halvings, as model "deal.II map".
    bool map_models(const std::string &load, const double k)
    {
      return (load == "flat_punch" || load == "paraboloid") && fem::surface_map_applies(fem::PowerLawModulus(E0, c0, k));
    }

    /// The variants of our model: as recommended, with the surface map, with the condensed far field
    /// (fem/elasticity/far_field.h, L = 100 a) for the radius-controlled normal scenes and the tangential punch.
    enum class Variant
    {
      plain,
      map,
      condensed
    };

    bool condensed_models(const std::string &load)
    {
      return load == "flat_punch" || load == "paraboloid" || load == "tangential_punch";
    }

    WorkPrecisionRow run_ours(const std::string &load, const double k, const unsigned int degree,
                              const unsigned int level, const int repeat, const fs::path &mesh_cache,
                              const Variant variant = Variant::plain)
    {
      WorkPrecisionRow row;
      row.load = load;
      row.k = k;
      row.model = variant == Variant::map ? "deal.II map" : variant == Variant::condensed ? "deal.II condensed" : "deal.II";
      row.degree = degree;
      row.level = level;
      fem::Settings level_settings{fe_mesh_level(a, k, level), fem::DiscretizationParameters{}};
      if (variant == Variant::map)
        fem::use_surface_map(level_settings, fem::PowerLawModulus(E0, c0, k));
      if (variant == Variant::condensed &&
          !fem::use_condensed_far_field(level_settings, fem::Material{std::make_shared<fem::PowerLawModulus>(E0, c0, k), nu}))
        row.note = "far field not condensed (clamped)";
      fem::MeshParameters mesh = level_settings.mesh;
      mesh.cache_directory = mesh_cache.string();
      row.h_edge = mesh.h_edge;
      row.ring_growth = mesh.ring_growth;
      row.far_field = mesh.far_field_size;
      fem::DiscretizationParameters discretization = level_settings.discretization;
      discretization.degree = degree;
      fem::LoadCase loadcase;
      if (load == "flat_punch" || load == "tangential_punch")
        {
          loadcase.type = fem::LoadType::flat_punch;
          loadcase.depth = punch_depth;
        }
      else
        {
          loadcase.type = fem::LoadType::indenter;
          loadcase.profile = fem::Profile::paraboloid(paraboloid_radius);
        }
      Samples s;
      try
        {
          for (int rep = 0; rep < repeat; ++rep)
            {
              const auto start = std::chrono::steady_clock::now();
              const double cpu = process_cpu_seconds();
              const fem::Material material{std::make_shared<fem::PowerLawModulus>(E0, c0, k), nu};
              fem::Timings time;
              double F = 0, d = 0;
              if (load == "jkr_paraboloid")
                {
                  // One model per contact radius, each on the level's mesh graded toward that radius.
                  fem::AdhesiveContact sphere(material, fem::Profile::paraboloid(paraboloid_radius),
                                              [&](const double contact_radius) {
                                                fem::Settings settings{fe_mesh_level(contact_radius, k, level),
                                                                       discretization};
                                                settings.mesh.cache_directory = mesh_cache.string();
                                                return settings;
                                              });
                  const Medium m = medium(GradedHalfSpace{E0, c0, k, nu});
                  const double a0 = jkr_start_factor *
                    jkr::critical_state(m, Paraboloid{paraboloid_radius}, jkr_dgamma, jkr::Control::force).radius;
                  const fem::AdhesiveCriticalState c =
                    sphere.critical_state(jkr_dgamma, fem::AdhesionControl::force, a0);
                  F = c.state.force;
                  row.dofs = c.max_dofs;
                  row.note = std::to_string(c.radii_solved) + " FE radii";
                }
              else if (load == "tangential_punch")
                {
                  fem::FourierMode1Solver solver(material, mesh, discretization);
                  const fem::TangentialResult r = solver.run(fem::TangentialLoad::flat_punch(punch_depth));
                  F = r.force;
                  time = r.time;
                  row.dofs = r.n_dofs;
                  if (!r.reliable)
                    row.note = r.message;
                }
              else
                {
                  fem::AxisymmetricSolver solver(material, mesh, discretization);
                  const fem::Result r = solver.run(loadcase);
                  F = r.force;
                  d = r.depth;
                  time = r.time;
                  row.dofs = r.n_dofs;
                  if (!r.reliable || !r.consistent_contact)
                    row.note = r.message;
                }
              s.wall.push_back(seconds_since(start));
              s.cpu.push_back(process_cpu_seconds() - cpu);
              s.mesh.push_back(time.mesh);
              s.setup.push_back(time.setup);
              s.assemble.push_back(time.assemble);
              s.factorize.push_back(time.factorize);
              s.solve.push_back(time.solve);
              s.postprocess.push_back(time.postprocess);
              set_errors(row, F, d);
            }
          s.finish(row);
        }
      catch (const std::exception &e)
        {
          row.error = inf;
          row.note = concise(e);
        }
      return row;
    }

    /// key=value pairs of the peer's `gradcontact-peer` line.
    std::map<std::string, std::string> parse_peer_line(const std::string &output)
    {
      std::map<std::string, std::string> kv;
      const auto at = output.find("gradcontact-peer ");
      if (at == std::string::npos)
        return kv;
      std::istringstream line(output.substr(at, output.find('\n', at) - at));
      for (std::string word; line >> word;)
        {
          const auto eq = word.find('=');
          if (eq != std::string::npos)
            kv[word.substr(0, eq)] = word.substr(eq + 1);
        }
      return kv;
    }

    std::string shell_quote(const std::string &s)
    {
      std::string q = "'";
      for (const char c : s)
        q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      return q + "'";
    }

    WorkPrecisionRow run_peer(const FeBenchOptions &o, const std::string &load, const double k,
                              const unsigned int level, const double far_field)
    {
      WorkPrecisionRow row;
      row.load = load;
      row.k = k;
      row.model = "FreeFem++";
      row.degree = 2;
      row.level = level;
      row.far_field = far_field;
      row.h_edge = std::pow(10., -1. - level); // the script's default for -level
      std::ostringstream cmd;
      cmd << std::setprecision(17) << "cd " << shell_quote(o.peer_scripts.string()) << " && " << o.freefem
          << " -ns -nw -v 0 " << load << ".edp -k " << k << " -nu " << nu << " -level " << level << " -L "
          << far_field << " -E0 " << E0 << " -c0 " << c0 << " -a " << a
          << (load == "flat_punch" ? " -d " : " -R ") << (load == "flat_punch" ? punch_depth : paraboloid_radius)
          << " 2>&1";
      Samples s;
      for (int rep = 0; rep < o.repeat; ++rep)
        {
          const double cpu = children_cpu_seconds();
          const auto start = std::chrono::steady_clock::now();
          FILE *pipe = popen(cmd.str().c_str(), "r");
          if (!pipe)
            throw std::runtime_error("bench: cannot start '" + cmd.str() + "'");
          std::string output;
          char buffer[4096];
          while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe))
            output.append(buffer, n);
          const int status = pclose(pipe);
          const double wall = seconds_since(start);
          const auto kv = parse_peer_line(output);
          if (status != 0 || !kv.count("force") || !kv.count("dofs"))
            {
              row.error = inf;
              std::string tail = output.substr(output.size() > 300 ? output.size() - 300 : 0);
              std::replace(tail.begin(), tail.end(), '\n', ' ');
              row.note = "FreeFem++ failed (exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                         "): " + tail;
              return row;
            }
          s.wall.push_back(wall);
          s.cpu.push_back(children_cpu_seconds() - cpu);
          s.mesh.push_back(std::stod(kv.at("mesh")));
          s.setup.push_back(0.);
          s.assemble.push_back(std::stod(kv.at("assemble_factorize")));
          s.factorize.push_back(0.);
          s.solve.push_back(std::stod(kv.at("solve")));
          s.postprocess.push_back(std::stod(kv.at("reaction")));
          row.dofs = static_cast<unsigned int>(std::stoul(kv.at("dofs")));
          row.h_edge = std::stod(kv.at("hedge"));
          set_errors(row, std::stod(kv.at("force")), std::stod(kv.at("depth")));
        }
      s.finish(row);
      return row;
    }

    bool freefem_available(const std::string &executable)
    {
      return std::system(("command -v " + executable + " > /dev/null 2>&1").c_str()) == 0;
    }

    std::string fmt(const double x, const char *f = "%.3g")
    {
      char b[32];
      std::snprintf(b, sizeof b, f, x);
      return b;
    }

    std::string k_name(const double k)
    {
      return k < 0 ? "m" + fmt(-k, "%g") : fmt(k, "%g");
    }

    /// The lower envelope of (t, e): points sorted by t whose error is below every faster point's.
    std::vector<std::pair<double, double>> envelope(const std::vector<double> &t, const std::vector<double> &e)
    {
      std::vector<std::pair<double, double>> p;
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] > 0 && e[i] > 0 && std::isfinite(e[i]))
          p.emplace_back(t[i], e[i]);
      std::sort(p.begin(), p.end());
      std::vector<std::pair<double, double>> front;
      for (const auto &q : p)
        if (front.empty() || q.second < front.back().second)
          front.push_back(q);
      return front;
    }

    /// log-log linear interpolation of y(x) through points with ascending x; NaN outside.
    double loglog(const std::vector<std::pair<double, double>> &p, const double x)
    {
      for (std::size_t i = 0; i + 1 < p.size(); ++i)
        if (x >= p[i].first && x <= p[i + 1].first)
          {
            const double w = std::log(x / p[i].first) / std::log(p[i + 1].first / p[i].first);
            return std::exp((1 - w) * std::log(p[i].second) + w * std::log(p[i + 1].second));
          }
      if (p.size() == 1 && x == p[0].first)
        return p[0].second;
      return std::numeric_limits<double>::quiet_NaN();
    }

    std::string phase_split(const WorkPrecisionRow &r)
    {
      if (r.load == "jkr_paraboloid") // a search over several models: no single split
        return "-";
      if (r.model == "FreeFem++")
        return fmt(r.mesh, "%.3f") + " / - / " + fmt(r.assemble, "%.3f") + " (incl. fact.) / " + fmt(r.solve, "%.3f") +
               " / " + fmt(r.postprocess, "%.3f");
      return fmt(r.mesh, "%.3f") + " / " + fmt(r.setup, "%.3f") + " / " + fmt(r.assemble, "%.3f") + " / " +
             fmt(r.factorize, "%.3f") + " / " + fmt(r.solve, "%.3f") + " / " + fmt(r.postprocess, "%.3f");
    }

    std::string label(const WorkPrecisionRow &r)
    {
      return r.model == "FreeFem++" ? "FreeFem++ P2" : r.model + " degree " + std::to_string(r.degree);
    }
  } // namespace

  fem::MeshParameters fe_mesh_level(const double contact_radius, const double k, const unsigned int level)
  {
    if (level >= fe_levels)
      throw std::invalid_argument("fe_mesh_level: level = " + std::to_string(level) + " is outside [0, " +
                                  std::to_string(fe_levels - 1) + "]");
    // h_edge a decade per level; the far-field rings grow slower as the edge gets finer, so that the
    // rings do not limit the error before the edge does (a coarse growth caps the error of the finer levels;
    // `fem_study g=...` shows it).
    const std::array<double, fe_levels> h_edge{{1e-2, 1e-3, 1e-4, 1e-5, 1e-6}};
    const std::array<double, fe_levels> growth{{1.6, 1.4, 1.3, 1.15, 1.15}};
    const std::array<double, fe_levels> h_far{{4, 4, 4, 3, 3}};
    fem::MeshParameters p = fem::recommended_mesh_parameters(contact_radius, k);
    p.h_edge = h_edge[level];
    p.ring_growth = growth[level];
    p.h_far = h_far[level];
    return p;
  }

  std::vector<PeerRatio> error_ratio_at_equal_time(const std::vector<double> &ours_t, const std::vector<double> &ours_e,
                                                   const std::vector<double> &peer_t, const std::vector<double> &peer_e)
  {
    const auto ours = envelope(ours_t, ours_e);
    std::vector<PeerRatio> ratios;
    for (const auto &p : envelope(peer_t, peer_e))
      {
        const double e = loglog(ours, p.first);
        if (std::isfinite(e))
          ratios.push_back({p.first, p.second / e});
      }
    return ratios;
  }

  std::vector<PeerRatio> time_ratio_at_equal_error(const std::vector<double> &ours_t, const std::vector<double> &ours_e,
                                                   const std::vector<double> &peer_t, const std::vector<double> &peer_e)
  {
    // The envelope as time(error): errors descending along it, so reverse it to ascending errors.
    auto ours = envelope(ours_t, ours_e);
    std::vector<std::pair<double, double>> inverse;
    for (auto it = ours.rbegin(); it != ours.rend(); ++it)
      inverse.emplace_back(it->second, it->first);
    std::vector<PeerRatio> ratios;
    for (const auto &p : envelope(peer_t, peer_e))
      {
        const double t = loglog(inverse, p.second);
        if (std::isfinite(t))
          ratios.push_back({p.second, p.first / t});
      }
    return ratios;
  }

  namespace
  {
    /// What a bench run measures: the exponents, degrees and levels, the scenes, and whether the peer runs.
    struct BenchPlan
    {
      std::vector<double>      ks;
      unsigned int             max_degree = 0, n_peer_levels = 0;
      std::vector<std::string> run_loads;
      fs::path                 mesh_cache;
      bool                     peer = false;
      std::string              peer_note;
    };

    /// Whether `load` is among the --scene options (all when none).
    bool selected(const FeBenchOptions &o, const std::string &load)
    {
      return o.scenes.empty() || std::find(o.scenes.begin(), o.scenes.end(), load) != o.scenes.end();
    }

    /// The mesh levels of our model per scene; quick: the two coarsest levels of the normal scenes, the coarsest of
    /// the adhesive and tangential ones.
    unsigned int n_levels(const FeBenchOptions &o, const std::string &load)
    {
      return o.quick ? (peer_models(load) ? 2u : quick_levels_new_scenes) : levels_of(load);
    }

    BenchPlan plan_fe_bench(const FeBenchOptions &o, const fs::path &folder)
    {
      BenchPlan plan;
      plan.ks = o.quick ? std::vector<double>{0.0} : std::vector<double>(all_k.begin(), all_k.end());
      plan.max_degree = o.quick ? 2 : 4;
      for (const auto &scene : o.scenes)
        if (std::find(loads.begin(), loads.end(), scene) == loads.end())
          throw std::invalid_argument("bench: --scene = '" + scene +
                                      "' is not one of flat_punch, paraboloid, jkr_paraboloid, tangential_punch");
      plan.n_peer_levels = o.quick ? 2 : peer_levels;
      plan.mesh_cache = folder / "mesh-cache";
      plan.peer = o.with_peer && freefem_available(o.freefem);
      if (o.with_peer && !plan.peer)
        plan.peer_note =
          "`" + o.freefem + "` is not on PATH: the peer was skipped (`./vv deps` installs Debian's freefem++).";
      for (const std::string load : loads)
        if (selected(o, load) && (!o.quick || peer_models(load) || quick_levels_new_scenes > 0))
          plan.run_loads.push_back(load);
      return plan;
    }

    /// Our model's runs of one scene and k: every degree, level and variant that applies.
    void run_our_rows(const FeBenchOptions &o, const BenchPlan &plan, const std::string &load, const double k,
                      std::vector<WorkPrecisionRow> &rows)
    {
      for (unsigned int degree = 1; degree <= plan.max_degree; ++degree)
        for (unsigned int level = 0; level < n_levels(o, load); ++level)
          for (const Variant variant : {Variant::plain, Variant::map, Variant::condensed})
            {
              if (variant == Variant::map && (!map_models(load, k) || degree < 2))
                continue;
              if (variant == Variant::condensed && !condensed_models(load))
                continue;
              rows.push_back(run_ours(load, k, degree, level, repeats_of(load, o.repeat), plan.mesh_cache, variant));
              const auto &r = rows.back();
              std::cerr << "bench fe: " << load << " k=" << k << " " << r.model << " degree " << degree << " level "
                        << level << ": " << r.dofs << " DoFs, error " << fmt(r.error) << ", " << fmt(r.wall_min) << " s"
                        << (r.note.empty() ? "" : " (" + r.note + ")") << "\n";
            }
    }

    /// The peer's runs of one scene and k, every level, with our coarsest level's far field.
    void run_peer_rows(const FeBenchOptions &o, const BenchPlan &plan, const std::string &load, const double k,
                       std::vector<WorkPrecisionRow> &rows)
    {
      for (unsigned int level = 0; level < plan.n_peer_levels; ++level)
        {
          rows.push_back(run_peer(o, load, k, level, fe_mesh_level(a, k, 0).far_field_size));
          const auto &r = rows.back();
          std::cerr << "bench peer: " << load << " k=" << k << " level " << level << ": " << r.dofs << " DoFs, error "
                    << fmt(r.error) << ", " << fmt(r.wall_min) << " s" << (r.note.empty() ? "" : " (" + r.note + ")")
                    << "\n";
        }
    }

    /// The column spec of fe_work_precision.csv (every number of a row) and of the table of fe_work_precision.md (the
    /// errors and times to read, the phases in one cell).
    Table work_precision_table(const std::vector<WorkPrecisionRow> &rows)
    {
      const Number seconds{'f', 3};
      Table table({Column::both("load", "scene"), Column::both("k", "k"), Column::both("model", "model"),
                   Column::both("degree", "degree"), Column::both("level", "level"),
                   Column::both("h_edge", "h_edge/a").md_as(Number{'e', 0}), Column::csv_only("ring_growth"),
                   Column::csv_only("L_over_a"), Column::both("dofs", "DoFs"),
                   Column::both("force_error", "force error").md_as(Number{'e', 2}),
                   Column::both("depth_error", "depth error").md_as(Number{'e', 2}), Column::csv_only("error"),
                   Column::both("wall_min_s", "wall min [s]").md_as(seconds),
                   Column::both("wall_median_s", "median [s]").md_as(seconds),
                   Column::both("wall_cold_s", "cold [s]").md_as(seconds),
                   Column::both("cpu_min_s", "CPU [s]").md_as(seconds), Column::csv_only("mesh_s"),
                   Column::csv_only("setup_s"), Column::csv_only("assemble_s"), Column::csv_only("factorize_s"),
                   Column::csv_only("solve_s"), Column::csv_only("postprocess_s"),
                   Column::md_only("mesh / setup / assemble / factorize / solve / post [s]"),
                   Column::both("note", "note").quoted()});
      for (const auto &r : rows)
        {
          // the CSV's note keeps its format: its double quotes written as single ones
          std::string note = r.note;
          std::replace(note.begin(), note.end(), '"', '\'');
          const Cell depth_error = r.load == "paraboloid" ? Cell(r.depth_error) : Cell(r.depth_error).md_text("-");
          table.add({r.load, r.k, r.model, r.degree, r.level, r.h_edge, r.ring_growth, r.far_field, r.dofs,
                     r.force_error, depth_error, r.error, r.wall_min, r.wall_median, r.wall_cold, r.cpu_min, r.mesh,
                     r.setup, r.assemble, r.factorize, r.solve, r.postprocess, phase_split(r),
                     Cell(note).md_text(r.note)});
        }
      return table;
    }

    /// The curves of a plot, each in the order of its runs (mesh level), not of x: timing noise would zig-zag it.
    std::vector<Series> ordered_series(const std::map<std::string, Series> &m)
    {
      std::vector<Series> v;
      for (const auto &s : m)
        {
          std::vector<std::size_t> idx(s.second.x.size());
          for (std::size_t i = 0; i < idx.size(); ++i)
            idx[i] = i;
          Series c{s.second.title, {}, {}, false};
          c.linespoints = true;
          for (const auto i : idx)
            {
              c.x.push_back(s.second.x[i]);
              c.y.push_back(s.second.y[i]);
            }
          v.push_back(c);
        }
      return v;
    }

    /// Plots per scene and k: error against wall time (min) and against DoFs, one curve per degree (+ peer).
    /// Returns the stems of the plots written.
    std::vector<std::string> plot_bench(const fs::path &folder, const std::vector<double> &ks,
                                        const std::vector<WorkPrecisionRow> &rows)
    {
      std::vector<std::string> plots;
      for (const std::string load : loads)
        for (const double k : ks)
          {
            std::map<std::string, Series> by_time, by_dofs;
            for (const auto &r : rows)
              if (r.load == load && r.k == k && std::isfinite(r.error) && r.error > 0)
                {
                  for (auto *m : {&by_time, &by_dofs})
                    (*m)[label(r)].title = label(r);
                  by_time[label(r)].x.push_back(r.wall_min);
                  by_time[label(r)].y.push_back(r.error);
                  by_dofs[label(r)].x.push_back(r.dofs);
                  by_dofs[label(r)].y.push_back(r.error);
                }
            if (by_time.empty())
              continue;
            const std::string stem = "fe_" + load + "_k" + k_name(k);
            const std::string scene = load + ", k = " + fmt(k, "%g") + ", nu = 0.3";
            write_plot(folder, stem + "_error_vs_time", scene + ": relative error against wall time (min)",
                       "wall time [s]", "relative error", ordered_series(by_time), true, true);
            write_plot(folder, stem + "_error_vs_dofs", scene + ": relative error against DoFs", "DoFs",
                       "relative error", ordered_series(by_dofs), true, true);
            plots.push_back(stem);
          }
      return plots;
    }

    /// The section of fe_work_precision.md on what is measured: the scenes, the models and the times.
    std::string bench_method_text()
    {
      return "## What is measured\n\n"
             "Each row is one FE model on one mesh: the relative error of its answer against the closed forms of "
             "`analytic/normal.h` (an independent path: the MDR closed forms, themselves checked against 34-digit "
             "references), and the wall time from the construction of the solver (mesh, DoFs, assembly, "
             "factorisation) to the answer, including post-processing.\n\n"
             "- Scenes: flat punch (radius a, depth 1e-3 a, force against (9.16)); paraboloid R = 50 a under "
             "contact-radius control (force F(a) and depth d(a) against the Hertz-type closed forms; the error is the "
             "larger of the two). E0 = 2 GPa, c0 = 3 a, a = 0.1 mm, nu = 0.3.\n"
             "- jkr_paraboloid: the JKR pull-off force of the paraboloid R = 50 a, dgamma = 0.05 J/m^2, under force "
             "control, from `AdhesiveContact::critical_state` (`fem/adhesion/adhesion.h`: one FE model per contact radius, "
             "each on the level's mesh graded toward that radius; the search starts 1.2 a_c off), against F_c of "
             "(9.55)-(9.56) (`jkr::critical_state` of `analytic/adhesion.h`; at k = 0 JKR's -3/2 pi dgamma R). "
             "The time is the whole search (all radii, noted in the row); DoFs are those of the largest model; "
             "there is no phase split. Levels 0-1, one repetition (7 FE radii per row).\n"
             "- tangential_punch: the tangential flat punch (U = V = delta = 1e-3 a on r <= a, W free) of "
             "`FourierMode1Solver` (`fem/tangential/fourier_mode1_solver.h`, Fourier mode 1, 3 fields), force F_x = K_T delta "
             "against the MDR K_T = 2 h_T E0 a^(1+k) / ((1+k) c0^k) (9.78)-(9.79) (`h_T` of "
             "`analytic/material.h`; at k = 0 Mindlin's 8 G a / (2 - nu)). Levels 0-2 (the mode-1 system has "
             "3/2 the DoFs), one repetition.\n"
             "- deal.II model (`fem/`): FE_Q degree 1-4; mesh level 0-4 = h_edge 1e-2 .. 1e-6 a, ring growth "
             "1.6, 1.4, 1.3, 1.15, 1.15 (`fe_mesh_level` in `cases/tools/fe_bench.cc`); L/a and the surface layer from "
             "`recommended_mesh_parameters(a, k)` (L/a = 1e16, 1.1e8, 2.3e5 for k = -0.5, 0, 0.5).\n"
             "- `deal.II map` (k > 0, flat punch and paraboloid, degree >= 2): the same levels with the surface map "
             "(`fem::use_surface_map`, fem/doc/meshes.md \"Surface map\") instead of the z-halvings, L widened by its "
             "contraction.\n"
             "- `deal.II condensed` (flat punch, paraboloid, tangential punch): the same levels with the half-space beyond L = 100 a "
             "condensed onto max(r, z) = L (`fem::use_condensed_far_field`, fem/doc/meshes.md \"Far field\"): no truncation "
             "error and no rings beyond 100 a.\n"
             "- Times: minimum and median wall time over the repetitions; `cold` is the first repetition, in which "
             "gmsh meshes the near field (later repetitions read its cached .msh, as repeated runs of a scene do); "
             "CPU is the process CPU time (minimum; gmsh's own process not included). The phase split is the "
             "minimum over the repetitions of `Result::time`: mesh / setup / assemble / factorize / solve / "
             "postprocess.\n"
             "- Wall times depend on the machine and on its load while the bench runs; the minimum over the "
             "repetitions is the least disturbed.\n\n";
    }

    /// fe_work_precision.md: the run, what is measured, every row (`table`), and the plots.
    std::string bench_md(const FeBenchOptions &o, const std::string &machine, const BenchPlan &plan, const double total,
                         const Table &table, const std::vector<std::string> &plots)
    {
      std::ostringstream md;
      md << "# FE work-precision benchmarks (`gradcontact bench --part fe`)\n\n"
         << "Machine: " << machine << ". Repetitions per run: " << o.repeat << (o.quick ? " (quick set)" : "")
         << ". Whole run: " << fmt(total, "%.0f") << " s.\n\n"
         << bench_method_text();
      if (plan.peer || !plan.peer_note.empty())
        md << "FreeFem++ peer rows (`cases/peers/freefem/`, P2, its own mesh ladder, the same L/a): see `peer.md`. "
           << plan.peer_note << "\n\n";
      md << "## Results\n\n" << table.md() << "\n## Plots\n\n";
      for (const auto &p : plots)
        md << "- `" << p << "_error_vs_time.png` / `" << p << "_error_vs_dofs.png` (SVG, data and gnuplot script "
           << "beside)\n";
      return md.str();
    }

    /// The table of the peer's runs.
    std::string peer_runs_table(const std::vector<WorkPrecisionRow> &rows)
    {
      std::ostringstream pm;
      pm << "## Peer runs\n\n| scene | k | level | h_edge/a | DoFs | force error | depth error | wall min [s] | "
            "CPU [s] | mesh / assemble+factorize / solve / reactions [s] | note |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
      for (const auto &r : rows)
        if (r.model == "FreeFem++")
          pm << "| " << r.load << " | " << fmt(r.k, "%g") << " | " << r.level << " | " << fmt(r.h_edge, "%.0e")
             << " | " << r.dofs << " | " << fmt(r.force_error, "%.2e") << " | "
             << (r.load == "paraboloid" ? fmt(r.depth_error, "%.2e") : "-") << " | " << fmt(r.wall_min, "%.3f")
             << " | " << fmt(r.cpu_min, "%.3f") << " | " << fmt(r.mesh, "%.3f") << " / " << fmt(r.assemble, "%.3f")
             << " / " << fmt(r.solve, "%.3f") << " / " << fmt(r.postprocess, "%.3f") << " | " << r.note << " |\n";
      return pm.str();
    }

    /// `v` as "ratio (unit at), ..."; "-" when empty.
    std::string ratio_list(const std::vector<PeerRatio> &v, const char *unit)
    {
      std::string s;
      for (const auto &p : v)
        s += (s.empty() ? "" : ", ") + fmt(p.ratio, "%.3g") + " (" + unit + fmt(p.at, "%.2g") + ")";
      return s.empty() ? std::string("-") : s;
    }

    /// The headline ratios' row of one scene and k: the best errors and the ratios of the two envelopes.
    std::string headline_row(const std::string &load, const double k, const std::vector<WorkPrecisionRow> &rows)
    {
      std::vector<double> ot, oe, pt, pe;
      double best_ours = inf, best_peer = inf;
      for (const auto &r : rows)
        if (r.load == load && r.k == k && std::isfinite(r.error))
          {
            // Ours: every deal.II variant (plain, map, condensed), as a user picks the best.
            const bool peer_row = r.model == "FreeFem++";
            (peer_row ? pt : ot).push_back(r.wall_min);
            (peer_row ? pe : oe).push_back(r.error);
            double &best = peer_row ? best_peer : best_ours;
            best         = std::min(best, r.error);
          }
      return "| " + load + " | " + fmt(k, "%g") + " | " + fmt(best_peer, "%.2e") + " | " + fmt(best_ours, "%.2e") +
             " | " + ratio_list(error_ratio_at_equal_time(ot, oe, pt, pe), "t=") + " | " +
             ratio_list(time_ratio_at_equal_error(ot, oe, pt, pe), "e=") + " |\n";
    }

    /// How the peer is written and timed.
    std::string peer_method_text()
    {
      return "The peer (`cases/peers/freefem/flat_punch.edp`, `paraboloid.edp`, `common.idp`) is written the way "
             "an engineer would model the scenes in FreeFem++: axisymmetric P2 in the meridian plane (weight "
             "r, hoop strain u_r/r), E(z) evaluated at every quadrature point (qforder 5, FreeFem's default; 9 changes the force by 5e-4 at k = 0.5), a near field "
             "R1 = 4 a meshed by buildmesh with border points graded geometrically toward the contact edge "
             "(h_edge = 1e-1 .. 1e-5 a for levels 0-4), a far field to the same L/a as ours made of "
             "conformal log-polar rings (a square() grid of (ln rho, theta) entering the weak form through "
             "the map), the force from the nodal reactions, the paraboloid by superposing a unit punch and "
             "the profile solution with the edge-force-zero condition (one factorisation, two solves), "
             "UMFPACK. Its errors are measured against the same closed forms as ours, by this program.\n\n"
             "Times: wall time of the whole FreeFem++ process (including its start-up, which the rows of the smallest meshes show), "
             "minimum over the repetitions; CPU is the child's CPU time. deal.II: wall time of solver "
             "construction + run (warm mesh cache), as in `fe_work_precision.md`.\n\n";
    }

    /// Why the peer stops converging.
    std::string peer_limits_text()
    {
      return "## Where the peer stops converging, and why\n\n"
             "- k != 0: the peer evaluates E(z) = E0 (z/c0)^k at the Gauss points of qf5pT; in the cells on "
             "the surface E is singular (k < 0) or vanishes (k > 0) like z^k, which a Gauss rule does not "
             "integrate well, and u_z ~ d - c z^(1-k) under the punch needs thin surface cells, which the "
             "peer's isotropic Delaunay mesh does not have. The deal.II model integrates those cells with a "
             "Gauss-Jacobi rule exact for z^k times a polynomial and halves them in z to 1e-10 a (k > 0) or "
             "1e-4 a (k < 0) under the contact. A FreeFem++ engineer could add both (an anisotropic "
             "adaptmesh metric, a mapped quadrature); these scripts do what the usual FreeFem++ "
             "model does, as the issue asks.\n"
             "- k = 0: the peer converges (P2, edge grading); the table above gives its error against ours at "
             "equal time, and where its finest level (h_edge 1e-5 a, P2) flattens.\n";
    }

    /// Writes peer.md: the peer's runs, the headline ratios against our envelope, and the peer's limits (or why
    /// the peer was skipped).
    void write_peer_md(const FeBenchOptions &o, const fs::path &folder, const std::string &machine,
                       const BenchPlan &plan, const std::vector<WorkPrecisionRow> &rows)
    {
      std::ostringstream pm;
      pm << "# deal.II model against a FreeFem++ peer\n\n"
         << "Machine: " << machine << ". Repetitions per run: " << o.repeat << ".\n\n";
      if (!plan.peer)
        pm << plan.peer_note << "\n";
      else
        {
          pm << peer_method_text() << peer_runs_table(rows);
          pm << "\n## Headline ratios\n\n"
             << "Each model's curve is its lower envelope over all its runs (all degrees and variants for deal.II): the best "
                "error reached within a given wall time. Error ratio at equal time: at each point of the peer's "
                "envelope, peer error / deal.II error interpolated log-log at the same time. Time ratio at equal "
                "error: peer time / deal.II time interpolated at the peer's error. Only points inside the range "
                "of the deal.II envelope are used; `-` means no overlap (the peer is faster than our fastest run, "
                "or less accurate than our least accurate run).\n\n"
             << "| scene | k | peer best error | deal.II best error | error ratio at equal time (each peer point) | "
                "time ratio at equal error (each peer point) |\n|---|---|---|---|---|---|\n";
          for (const std::string load : loads)
            for (const double k : plan.ks)
              if (peer_models(load) && selected(o, load))
                pm << headline_row(load, k, rows);
          pm << "\nThe plots `fe_<scene>_k<k>_error_vs_time.png` carry both models.\n\n" << peer_limits_text();
        }
      write_document(folder, "peer", pm.str());
    }
  } // namespace

  std::vector<WorkPrecisionRow> run_fe_bench(const FeBenchOptions &o, const fs::path &folder, const std::string &machine)
  {
    const BenchPlan plan = plan_fe_bench(o, folder);
    std::vector<WorkPrecisionRow> rows;
    const auto start = std::chrono::steady_clock::now();
    for (const std::string &load : plan.run_loads)
      for (const double k : plan.ks)
        {
          if (o.with_fe)
            run_our_rows(o, plan, load, k, rows);
          if (plan.peer && peer_models(load))
            run_peer_rows(o, plan, load, k, rows);
        }
    const double total = seconds_since(start);
    fs::remove_all(plan.mesh_cache);
    const Table table = work_precision_table(rows);
    const std::vector<std::string> plots = plot_bench(folder, plan.ks, rows);
    write_table_files(folder, "fe_work_precision", table, bench_md(o, machine, plan, total, table, plots));
    if (o.with_peer)
      write_peer_md(o, folder, machine, plan, rows);
    return rows;
  }
} // namespace gradcontact::cases
