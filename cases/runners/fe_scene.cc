#include "runners/fe_scene.h"
#include "model/scene_start.h"

#include "model/analytic_reference.h"
#include "report/convergence_report.h"
#include "report/table.h"
#include "model/normal_model.h"

#include <analytic/batch.h>
#include <analytic/material.h>
#include <analytic/mdr.h>
#include <fem/base/table_file.h>

#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>


#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Type = LoadParameters::Type;
  using Control = LoadParameters::Control;

  namespace
  {
    bool curved(const LoadParameters &l)
    {
      return l.type == Type::paraboloid || l.type == Type::cone || l.type == Type::power_law;
    }

    // --- the analytic side: the scene as a normal-contact request (analytic_reference.h) ----------------
    AnalyticReference normal_reference(const Scene &s, const batch::Method method)
    {
      return AnalyticReference(s, method, AnalyticReference::Problem::normal);
    }

    // --- the FE side ------------------------------------------------------------------------------------
    struct FeRun
    {
      unsigned int refinement;
      fem::Result result;
      double seconds;
      /// Discretization/accuracy = contract: the ladder's estimates (result is its finest level's run).
      std::optional<fem::ContractResult> contract;
      /// The memory of the direct solver's factorisation and matrices (bytes); 0 where not known (unilateral).
      double factor_bytes = 0;
    };

    /// Load/contact = unilateral: the contact set found on meshes graded toward the edge found (from Load/a),
    /// as an fem::Result (the contact radius is the outer edge; r/a of p(r) beyond the contact are left out
    /// and said in the message).
    /// With friction: the loading path and the stick zone of one FE run, as friction-<level>.md / .csv in the
    /// report (the stick radius, the vertices that stick and slip, d, F, a and c at every load step).
    void write_friction(const Scene &s, const fem::UnilateralResult &u, const fs::path &folder, const unsigned int level)
    {
      const std::string stem = "friction-" + std::to_string(level);
      Table table({Column::both("step", "step"), Column::both("depth", "d [m]"), Column::both("force", "F [N]"),
                   Column::both("contact_radius", "a [m]"), Column::both("stick_radius", "c [m]"),
                   Column::both("stick_over_contact", "c/a").csv_as(Number{}).missing_as("- (no contact)"),
                   Column::both("active_set_solves", "solves")},
                  Number{'g', 12});
      unsigned int step = 0, before = 0;
      for (const fem::UnilateralResult::PathPoint &p : u.path)
        {
          // no contact yet (the first steps may not reach a vertex beyond the axis), or none at the axis: no c/a
          const bool touching = p.outer_edge > 0 && !std::isnan(p.stick_radius);
          table.add({++step, p.depth, p.force, p.outer_edge, std::isnan(p.stick_radius) ? Cell() : Cell(p.stick_radius),
                     touching ? Cell(p.stick_radius / p.outer_edge) : Cell(), p.iterations - before});
          before = p.iterations;
        }
      std::ostringstream md;
      md << "# " << s.info.name << ": Coulomb friction during loading (" << level << " refinement(s))\n\n"
         << "mu = " << format(s.friction.coefficient) << " between the rigid indenter and E0 (z/c0)^k (k = "
         << format(s.material.k) << ", nu = " << format(s.material.nu) << "), the load from zero in " << u.path.size()
         << " steps (fem::UnilateralContactSolver). At the end: contact radius " << format(u.outer_edge) << " m, "
         << (std::isnan(u.stick_radius) ? std::string("no stick zone at the axis (the axis is not in contact)")
                                        : "stick radius c = " + format(u.stick_radius) +
                                            " m (c/a = " + format(u.stick_radius / u.outer_edge) + ")")
         << "; of the surface vertices in contact " << u.stick_nodes << " stick, " << u.slip_inward_nodes
         << " slip inward (q > 0) and " << u.slip_outward_nodes << " outward (q < 0); " << u.iterations
         << " active-set solves in all.\n\n"
         << table.md();
      write_table_files(folder, stem, table, md.str());
    }

    fem::Result run_unilateral(const Scene &s, const FeModel &model, const fem::OutputRequest &out,
                               const fs::path &folder, const unsigned int level)
    {
      const fem::UnilateralResult u = solve_normal_unilateral(s, model, out);
      if (frictional_loading(s))
        write_friction(s, u, folder, level);
      return as_disc_result(s, model, u);
    }

    FeRun run_fe(const Scene &s, const unsigned int refinement, const fs::path &folder)
    {
      const auto start = std::chrono::steady_clock::now();
      const FeModel model = normal_fe_model(s, refinement);
      fem::OutputRequest out = output_request(s);
      if (s.outputs.vtu)
        out.vtu_file = (folder / ("fields-" + std::to_string(refinement) + ".vtu")).string();
      if (s.load.contact == LoadParameters::Contact::unilateral)
        return {refinement, run_unilateral(s, model, out, folder, refinement),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), {}};
      const DiscSolve disc = solve_disc(model, out);
      return {refinement, disc.result, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
              {}, disc.factor_bytes};
    }

    // The scalar quantities a scene compares, with the FE value, the reference quantity name and, under the
    // accuracy contract, the FE's estimate of it.
    struct Scalar
    {
      std::string name;      ///< row quantity
      std::string reference; ///< eval quantity
      double fe;
      double tolerance;
      const fem::Estimated fem::ContractResult::*estimate;
    };

    std::vector<Scalar> scalars(const Scene &s, const fem::Result &r)
    {
      std::vector<Scalar> out;
      const OutputParameters &o = s.outputs;
      const LoadParameters &l = s.load;
      using Contract = fem::ContractResult;
      if (o.force && l.type != Type::constant_pressure)
        out.push_back({"force", "force", r.force, s.tolerances.force, &Contract::force});
      if (o.depth && (curved(l) && l.control != Control::depth))
        out.push_back({"depth", "depth", r.depth, s.tolerances.depth, &Contract::depth});
      if (o.depth && l.type == Type::constant_pressure)
        out.push_back({"centre displacement", "depth", r.depth, s.tolerances.depth, &Contract::depth});
      if (o.contact_radius && curved(l) && l.control != Control::contact_radius)
        out.push_back({"contact radius", "", r.contact_radius, s.tolerances.contact_radius, &Contract::contact_radius});
      return out;
    }
  } // namespace

  std::string to_string(const Profile p) { return p == Profile::pressure ? "pressure" : "displacement"; }

  std::optional<Profile> profile_of(const std::string &name)
  {
    for (const Profile p : {Profile::pressure, Profile::displacement})
      if (name == to_string(p))
        return p;
    return std::nullopt;
  }

  Profile profile_named(const std::string &name, const std::string &where)
  {
    if (const std::optional<Profile> p = profile_of(name))
      return *p;
    throw std::invalid_argument(where + ": quantity = '" + name + "' must be 'pressure' or 'displacement'");
  }

  FeProfile fe_profile(const Scene &scene, const Profile quantity, const std::vector<double> &radii_over_a,
                       const std::string &normaliser, const double normaliser_r_over_a, const bool per_area)
  {
    const bool pressure = quantity == Profile::pressure;
    Scene s = scene;
    (pressure ? s.outputs.pressure_radii : s.outputs.displacement_radii) = radii_over_a;
    (pressure ? s.outputs.displacement_radii : s.outputs.pressure_radii).clear();
    s.outputs.vtu = false;
    const FeRun run = run_fe(s, finest_refinement(s), fs::temp_directory_path());
    const AnalyticReference closed = normal_reference(s, batch::Method::closed_form);
    const double a = closed.radius();
    // A profile's normaliser is taken at a radius, a scalar's is not.
    const bool needs_r = profile_of(normaliser).has_value();
    const double norm = needs_r ? closed.at(normaliser, normaliser_r_over_a * a) : closed.get(normaliser);
    const double area = per_area ? 3.14159265358979323846 * a * a : 1.;
    FeProfile out;
    for (const fem::Sample &p : pressure ? run.result.pressure : run.result.displacement)
      {
        out.x.push_back(p.r / s.load.a);
        out.y.push_back(p.value * area / norm);
      }
    return out;
  }

  namespace
  {
    using References = std::vector<std::unique_ptr<AnalyticReference>>;

    /// The analytic references the scene asks for; one whose state cannot be set up is a failed row.
    References references_of(const Scene &s, SceneResult &result)
    {
      References references;
      const auto add_reference = [&](const batch::Method method, const std::string &label) {
        try
          {
            references.push_back(std::make_unique<AnalyticReference>(normal_reference(s, method)));
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed("reference state", "-", label, e.what()));
          }
      };
      if (s.references.closed_form)
        add_reference(batch::Method::closed_form, "closed form");
      if (s.references.numerical_mdr)
        add_reference(batch::Method::numerical_mdr, "numerical MDR");
      return references;
    }


    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  SceneResult run_analytic_scene(const Scene &s, const fs::path &folder)
  {
    require_kind(s, SceneKind::analytic, "run_analytic_scene");
    const auto start = std::chrono::steady_clock::now();
    SceneResult result = started(s, folder);
    references_of(s, result); // only its failed rows: the comparison below needs both methods
    // The closed form against the numerical MDR, for the scalars and profiles asked.
    const AnalyticReference closed = normal_reference(s, batch::Method::closed_form),
                            numeric = normal_reference(s, batch::Method::numerical_mdr);
    std::vector<std::pair<std::string, std::optional<double>>> items;
    if (s.outputs.force && s.load.type != Type::constant_pressure)
      items.push_back({"force", std::nullopt});
    if (s.outputs.depth && s.load.type != Type::flat_punch && s.load.type != Type::concave_punch)
      items.push_back({"depth", std::nullopt});
    for (const double x : s.outputs.pressure_radii)
      items.push_back({"pressure", x * closed.radius()});
    for (const double x : s.outputs.displacement_radii)
      items.push_back({"displacement", x * closed.radius()});
    for (const auto &[quantity, r] : items)
      {
        const std::string metric = r ? "r/a = " + format(*r / closed.radius()) + ", relative" : "relative";
        try
          {
            const auto t0 = std::chrono::steady_clock::now();
            const double c = r ? closed.at(quantity, *r) : closed.get(quantity);
            const double seconds = seconds_since(t0);
            const double n = r ? numeric.at(quantity, *r) : numeric.get(quantity);
            result.rows.push_back(compare(quantity, metric, closed.label(), numeric.label(), n, c, n, 1e-9, 0, seconds));
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed(quantity, closed.label(), numeric.label(), e.what()));
          }
      }
    result.seconds = seconds_since(start);
    return result;
  }

  namespace
  {
    /// The memory this machine has free for a solve: MemAvailable of /proc/meminfo, in bytes; infinity where it
    /// cannot be read.
    double available_memory()
    {
      std::ifstream meminfo("/proc/meminfo");
      std::string   key, unit;
      double        kib = 0;
      while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:")
          return kib * 1024;
      return std::numeric_limits<double>::infinity();
    }

    /// A level's size before it is solved, from a coarser level solved before it: uniform refinement of the 2D mesh
    /// multiplies the DoFs by 4 per level, and the fill of a sparse direct factorisation of such a mesh grows like
    /// N log N (nested dissection; George, SIAM J. Numer. Anal. 10 (1973) 345).
    struct LevelForecast
    {
      double dofs = 0, bytes = 0;
    };
    LevelForecast forecast(const FeRun &from, const unsigned int level)
    {
      const double growth = std::pow(4.0, double(level) - double(from.refinement));
      const double n0 = std::max<double>(from.result.n_dofs, 2), n = n0 * growth;
      return {n, from.factor_bytes * growth * std::log(n) / std::log(n0)};
    }

    /// One FE solve per entry of Discretization/refinements (a failed level is a failed row). Each level beyond the
    /// first is forecast from the finest solved before it (a first level of 2 or more from a solve of level 0, which
    /// is cheap): its DoFs are said before it starts when it is large, and a level whose factorisation would not fit
    /// in the memory this machine has available is refused before it starts, with the levels above it.
    std::vector<FeRun> solve_levels(const Scene &s, const fs::path &folder, const bool verbose, SceneResult &result)
    {
      std::vector<FeRun> runs;
      std::optional<FeRun> calibration;
      const double available = available_memory();
      for (const unsigned int level : s.discretization.refinements)
        {
          std::optional<FeRun> from;
          for (const FeRun &run : runs)
            if (run.refinement < level && (!from || run.refinement > from->refinement))
              from = run;
          if (!from && level >= 2 && s.load.contact != LoadParameters::Contact::unilateral)
            {
              if (!calibration)
                try
                  {
                    Scene coarse       = s;
                    coarse.outputs.vtu = false;
                    calibration        = run_fe(coarse, 0, fs::temp_directory_path());
                  }
                catch (const std::exception &)
                  {
                    calibration = FeRun{0, {}, 0, {}}; // no forecast: the level's own solve says what fails
                  }
              from = calibration;
            }
          if (from && from->factor_bytes > 0)
            {
              const LevelForecast f = forecast(*from, level);
              if (s.discretization.memory_guard && f.bytes > 0.8 * available)
                {
                  result.rows.push_back(failed(
                    "FE solve", "FE", "-",
                    "refinement " + std::to_string(level) + " refused before it started: about " + format(f.dofs) +
                      " DoFs, whose direct factorisation needs about " + format(f.bytes / 1e9) + " GB (forecast from "
                      "refinement " + std::to_string(from->refinement) + "'s " + format(from->factor_bytes / 1e9) +
                      " GB), above 80 % of the " + format(available / 1e9) + " GB this machine has available; use "
                      "fewer refinements, Discretization/accuracy = contract with a force tolerance, or run with "
                      "--force (Discretization/memory guard = off) to solve it anyway"));
                  break;
                }
              if (verbose || f.dofs > 1e6)
                std::cerr << "  " << s.info.name << ": FE solve, " << level << " refinement(s): about "
                          << format(f.dofs) << " DoFs, " << format(f.bytes / 1e9) << " GB\n";
            }
          else if (verbose)
            std::cerr << "  " << s.info.name << ": FE solve, " << level << " refinement(s)\n";
          try
            {
              runs.push_back(run_fe(s, level, folder));
            }
          catch (const std::exception &e)
            {
              result.rows.push_back(failed("FE solve", "FE", "-", "refinement " + std::to_string(level) + ": " + concise(e)));
            }
        }
      return runs;
    }

    /// Discretization/accuracy = contract: the ladder of fem/accuracy/accuracy.h at Discretization/force tolerance; a refusal
    /// is a failed row naming its limit.
    FeRun solve_contract(const Scene &s, const bool verbose, SceneResult &result)
    {
      const auto start = std::chrono::steady_clock::now();
      const FeModel model = fe_model(s, 0);
      if (verbose)
        std::cerr << "  " << s.info.name << ": FE ladder to the relative tolerance "
                  << format(s.discretization.force_tolerance) << "\n";
      fem::ContractResult contract = solve_normal_contract(s, model);
      if (!contract.met)
        result.rows.push_back(failed("FE contract", "FE (contract)", "-",
                                     "tolerance " + format(contract.tolerance) + " not reached: " + contract.limit));
      FeRun run{static_cast<unsigned>(contract.level_dofs.size()) - 1, contract.result, seconds_since(start), {}};
      run.contract = std::move(contract);
      return run;
    }

    /// The contract's columns of a row: the asked tolerance, the estimate and the verdict.
    void add_contract(Row &row, const FeRun &run, const fem::Estimated &e)
    {
      if (!run.contract)
        return;
      row.asked    = run.contract->tolerance;
      row.estimate = e.relative();
      row.contract = run.contract->met ? "held" : "refused: " + run.contract->limit;
    }

    /// The rows of one FE run against one reference: the scalars, p(r) relative to the largest |p|, w(r).
    void add_fe_rows(const Scene &s, const FeRun &run, const AnalyticReference &ref, SceneResult &result)
    {
      const fem::Result &fe = run.result;
      const std::string checked = run.contract ? "FE (contract, " + std::to_string(run.contract->level_dofs.size()) +
                                                   " levels)"
                                               : "FE (" + std::to_string(run.refinement) + " ref.)";
      for (const Scalar &q : scalars(s, fe))
        try
          {
            const double value = q.reference.empty() ? ref.radius() : ref.get(q.reference);
            Row row = compare(q.name, "relative", checked, ref.label(), value, q.fe, value, q.tolerance, fe.n_dofs,
                              run.seconds);
            if (run.contract)
              add_contract(row, run, (*run.contract).*q.estimate);
            result.rows.push_back(row);
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed(q.name, checked, ref.label(), e.what()));
          }
      // pressure: relative to the largest |p| sampled (p -> 0 or -> inf at the edge)
      try
        {
          std::vector<double> refs;
          for (const fem::Sample &p : fe.pressure)
            refs.push_back(ref.at("pressure", p.r));
          double scale = 0.;
          for (const double v : refs)
            scale = std::max(scale, std::abs(v));
          for (std::size_t i = 0; i < fe.pressure.size(); ++i)
            {
              Row row = compare("pressure", "r/a = " + format(fe.pressure[i].r / s.load.a) + ", rel. to max |p|",
                                checked, ref.label(), refs[i], fe.pressure[i].value, scale, s.tolerances.pressure,
                                fe.n_dofs, run.seconds);
              if (run.contract)
                add_contract(row, run, run.contract->pressure.at(i));
              result.rows.push_back(row);
            }
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("pressure", checked, ref.label(), e.what()));
        }
      for (std::size_t i = 0; i < fe.displacement.size(); ++i)
        try
          {
            const fem::Sample &w = fe.displacement[i];
            const double value = ref.at("displacement", w.r);
            // Under a punch whose depth is given on the disc r <= a, w there is the imposed displacement
            // (not with Load/contact = unilateral, where the contact set is found).
            const bool imposed = (s.load.type == Type::flat_punch || s.load.type == Type::concave_punch) &&
                                 s.load.contact == LoadParameters::Contact::disc && w.r < s.load.a;
            Row row = compare(imposed ? "displacement (imposed: input check)" : "displacement",
                              "r/a = " + format(w.r / s.load.a) + ", relative", checked, ref.label(), value, w.value,
                              value, s.tolerances.displacement, fe.n_dofs, run.seconds);
            if (run.contract)
              add_contract(row, run, run.contract->displacement.at(i));
            result.rows.push_back(row);
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed("displacement", checked, ref.label(), e.what()));
          }
    }

    /// Convergence study: the scalar quantities against the first reference, level by level.
    void write_normal_convergence(const Scene &s, const std::vector<FeRun> &runs, const References &references,
                                  const fs::path &folder)
    {
      std::vector<ConvergenceSeries> series;
      const std::vector<Scalar> first_level = scalars(s, runs.front().result);
      for (std::size_t q = 0; q < first_level.size(); ++q)
        {
          ConvergenceSeries c{first_level[q].name, 0., {}};
          try
            {
              c.reference = first_level[q].reference.empty() ? references.front()->radius()
                                                             : references.front()->get(first_level[q].reference);
            }
          catch (const std::exception &)
            {
              continue; // a failed row already says why
            }
          for (const FeRun &run : runs)
            {
              const double v = scalars(s, run.result)[q].fe;
              c.levels.push_back({run.refinement, run.result.n_dofs, run.seconds, v, relative_error(v, c.reference)});
            }
          series.push_back(c);
        }
      write_convergence(folder, s.info.name, references.front()->label(), series, s.outputs.plots);
    }

    /// Profiles: the analytic curve (closed form, dense) with the FE points of the finest level.
    void plot_normal_profiles(const Scene &s, const fem::Result &fe, const AnalyticReference &closed,
                              const SceneResult &result, const fs::path &folder)
    {
      const double a = closed.radius();
      const auto profile_plot = [&](const Profile profile, const std::vector<fem::Sample> &samples,
                                    const double x_max, const std::string &ylabel) {
        if (samples.empty())
          return;
        const std::string quantity = to_string(profile);
        Series curve{"closed form", {}, {}, false}, points{"FE", {}, {}, true};
        constexpr int n = 200;
        for (int i = 0; i <= n; ++i)
          {
            // for the pressure stay inside the contact; for w also skip r = a exactly
            const double x = x_max * (profile == Profile::pressure ? 0.999 * i / n : static_cast<double>(i) / n);
            try
              {
                curve.y.push_back(closed.at(quantity, x * a));
                curve.x.push_back(x);
              }
            catch (const std::exception &)
              {
              }
          }
        double worst = 0.;
        for (const fem::Sample &p : samples)
          {
            points.x.push_back(p.r / s.load.a);
            points.y.push_back(p.value);
          }
        for (const Row &r : result.rows)
          if (r.quantity == quantity && r.error.empty() && r.reference.rfind("closed form", 0) == 0)
            worst = std::max(worst, r.rel_error);
        write_plot(folder, quantity, s.info.name + ": " + quantity + " (worst FE error " + format(worst) + ")", "r / a",
                   ylabel, {curve, points});
      };
      double w_max = 1.;
      for (const double x : s.outputs.displacement_radii)
        w_max = std::max(w_max, x);
      profile_plot(Profile::pressure, fe.pressure, 1., "p [Pa]");
      profile_plot(Profile::displacement, fe.displacement, w_max, "w [m]");
    }
  } // namespace

  namespace
  {
    /// Depth or force control of a curved profile on a grading without a closed form: the FE's mesh is graded toward
    /// a contact radius (its finest cells at the edge, where the depth- and force-controlled search of
    /// fem/bodies/axisymmetric_solver.h moves the edge within a bounded number of surface DoFs), so that radius must be near
    /// the answer. It is found by the FE itself: a secant in ln a on ln d(a) or ln F(a) of radius-controlled solves
    /// on the coarsest mesh, from Load/a (d ~ a^n for a profile ~ r^n). The scene comes back with Load/a there.
    Scene with_mesh_at_the_answer(const Scene &s, const bool verbose)
    {
      const LoadParameters &l = s.load;
      if (l.control == Control::contact_radius || !curved(l) || l.contact != LoadParameters::Contact::disc ||
          s.material.modulus == MaterialParameters::Modulus::power_law || s.discretization.contract)
        return s;
      const bool by_depth = l.control == Control::depth;
      const double target = std::log(by_depth ? l.depth : l.force);
      const double n      = l.type == Type::paraboloid ? 2. : l.type == Type::cone ? 1. : l.n;
      Scene probe = s;
      probe.load.control = Control::contact_radius;
      probe.outputs.vtu  = false;
      const auto misfit  = [&](const double ln_a) {
        probe.load.a          = std::exp(ln_a);
        const fem::Result r   = run_fe(probe, 0, fs::temp_directory_path()).result;
        return std::log(by_depth ? r.depth : r.force) - target;
      };
      double x1 = std::log(l.a);
      try
        {
          double x0 = x1, f0 = misfit(x0);
          x1        = x0 - f0 / (by_depth ? n : n + 1.);
          double f1 = misfit(x1);
          for (unsigned int i = 0; i < 8 && std::abs(x1 - x0) > 1e-4 && f1 != f0; ++i)
            {
              const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
              x0 = x1, f0 = f1;
              x1 = x2, f1 = misfit(x1);
            }
          if (!std::isfinite(x1))
            throw std::runtime_error("the secant left the finite numbers");
        }
      catch (const std::exception &e)
        {
          // the solve itself then says what limits it, on the mesh of Load/a
          if (verbose)
            std::cerr << "  " << s.info.name << ": no contact radius from the FE's own "
                      << (by_depth ? "d(a)" : "F(a)") << " (" << concise(e) << "); the mesh stays at Load/a\n";
          return s;
        }
      Scene out  = s;
      out.load.a = std::exp(x1);
      if (verbose)
        std::cerr << "  " << s.info.name << ": the mesh's contact radius from the FE's own "
                  << (by_depth ? "d(a)" : "F(a)") << ": " << format(out.load.a) << " (Load/a = " << format(l.a) << ")\n";
      return out;
    }
  } // namespace

  SceneResult run_normal_scene(const Scene &scene, const fs::path &folder, const bool verbose)
  {
    require_kind(scene, SceneKind::normal, "run_normal_scene");
    const auto start = std::chrono::steady_clock::now();
    SceneResult result = started(scene, folder);
    const Scene s = with_mesh_at_the_answer(scene, verbose);
    const References references = references_of(s, result);

    // The FE solves, shared by every quantity and every reference.
    const std::vector<FeRun> runs = s.discretization.contract ? std::vector<FeRun>{solve_contract(s, verbose, result)}
                                                              : solve_levels(s, folder, verbose, result);
    for (const FeRun &run : runs)
      {
        if (!run.result.consistent_contact || !run.result.reliable)
          result.rows.push_back(failed("FE solve", run.contract ? "FE (contract)" : "FE (" + std::to_string(run.refinement) + " ref.)",
                                       "-", run.result.message));
        for (const auto &ref : references)
          add_fe_rows(s, run, *ref, result);
      }
    if (runs.size() > 1 && !references.empty())
      write_normal_convergence(s, runs, references, folder);
    if (s.outputs.plots && !runs.empty() && s.references.closed_form && !references.empty())
      plot_normal_profiles(s, runs.back().result, *references.front(), result, folder);

    result.seconds = seconds_since(start);
    return result;
  }
} // namespace gradcontact::cases
