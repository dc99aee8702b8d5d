#include "runners/fe_map.h"
#include "report/table.h"
#include "report/thresholds.h"

#include "model/analytic_reference.h"
#include "model/normal_model.h"
#include "model/scene_start.h"
#include "model/map_published.h"

#include <fem/bodies/axisymmetric_solver.h>
#include <fem/contact/unilateral_contact.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Type = LoadParameters::Type;

  namespace
  {
    /// One FE solve of a map: the FE state and its deviations from the power law at the FE depth.
    struct MapPoint
    {
      double ratio = 0.;                      ///< a/z0, a/H, a/w, E1/E0 or mu (0: the idealisation itself)
      double force = 0., radius = 0., pressure = 0.; ///< FE/closed form - 1 (radius: indenters only)
      double stick = std::numeric_limits<double>::quiet_NaN(); ///< friction: the stick radius / the contact radius
      unsigned int dofs = 0;
      double seconds = 0.;
      std::string error; ///< non-empty when the solve or the reference failed
    };

    /// The radius near the axis where p is sampled (the r-weighted recovery does not constrain the axis node).
    constexpr double axis_sample = 0.02;

    bool is_indenter(const Scene &s) { return s.load.type != Type::flat_punch; }

    /// The scene at exponent k with the grading of `ratio` (0: the power law itself).
    Scene graded(const Scene &s, const double k, const double ratio)
    {
      Scene g = s;
      g.material.k = k;
      g.map.parameter = MapParameters::Parameter::none;
      if (ratio == 0.)
        g.material.modulus = MaterialParameters::Modulus::power_law;
      else if (s.map.parameter == MapParameters::Parameter::erf_width)
        {
          g.material.modulus = MaterialParameters::Modulus::error_function;
          g.material.erf_width = s.load.a / ratio;
        }
      else if (s.map.parameter == MapParameters::Parameter::surface_depth)
        {
          g.material.modulus = MaterialParameters::Modulus::shifted_power_law;
          g.material.surface_depth = s.load.a / ratio;
        }
      else
        {
          g.material.modulus = MaterialParameters::Modulus::coating;
          g.material.coating_thickness = s.load.a / ratio;
        }
      g.kind = SceneKind::normal;
      return g;
    }

    /// Solves `g` under contact-radius control and compares it with the power-law closed forms at the FE depth.
    MapPoint solve(const Scene &g, const double ratio, const unsigned int extra_refinements = 0)
    {
      MapPoint p;
      p.ratio = ratio;
      const auto start = std::chrono::steady_clock::now();
      try
        {
          const FeModel model = fe_model(g, finest_refinement(g) + extra_refinements);
          fem::OutputRequest out;
          out.pressure_radii = {axis_sample * g.load.a};
          const fem::Result r = solve_disc(model, out).result;
          p.dofs = r.n_dofs;
          if (!r.reliable)
            throw std::runtime_error("the FE solve is flagged unreliable: " + r.message);
          // The chapter's state at the FE depth: for an indenter its contact radius follows from d.
          Scene at_depth = g;
          at_depth.material.modulus = MaterialParameters::Modulus::power_law;
          if (is_indenter(g))
            {
              at_depth.load.control = LoadParameters::Control::depth;
              at_depth.load.depth = r.depth;
            }
          else
            at_depth.load.depth = r.depth;
          const AnalyticReference ref(at_depth, batch::Method::closed_form, AnalyticReference::Problem::normal);
          p.force = r.force / ref.get("force") - 1;
          p.radius = is_indenter(g) ? g.load.a / ref.radius() - 1 : 0.;
          p.pressure = r.pressure.at(0).value / ref.at("pressure", axis_sample * g.load.a) - 1;
        }
      catch (const std::exception &e)
        {
          p.error = concise(e);
        }
      p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return p;
    }

    /// The name of a map's ratio in map.md and in the header of map.csv.
    struct RatioName
    {
      std::string md, csv;
    };

    RatioName ratio_name(const Scene &s)
    {
      switch (s.map.parameter)
        {
          case MapParameters::Parameter::surface_depth:
            return {"a/z0", "a_over_z0"};
          case MapParameters::Parameter::erf_width:
            return {"a/w", "a_over_w"};
          case MapParameters::Parameter::indenter_modulus:
            return {"E1/E0", "E1_over_E0"};
          case MapParameters::Parameter::friction_coefficient:
            return {"mu", "mu"};
          default:
            return {"a/H", "a_over_H"};
        }
    }

    /// What a map compares at every point. Declared in the order in which map.md lists a panel's resolutions.
    enum class Quantity
    {
      contact_radius,
      force,
      pressure
    };

    /// The quantities of a map of `s`, in the order of its tables: the contact radius of an indenter only.
    std::vector<Quantity> map_quantities(const Scene &s)
    {
      return is_indenter(s) ? std::vector<Quantity>{Quantity::force, Quantity::contact_radius, Quantity::pressure}
                            : std::vector<Quantity>{Quantity::force, Quantity::pressure};
    }

    /// Every quantity (an elastic indenter's and a friction map's panels measure all three).
    const std::vector<Quantity> all_quantities{Quantity::force, Quantity::contact_radius, Quantity::pressure};

    /// The quantity's name in the plots' file names.
    std::string name(const Quantity q)
    {
      static const char *const names[] = {"contact radius", "force", "pressure"}; // in the order of Quantity
      return names[static_cast<int>(q)];
    }

    double deviation_of(const MapPoint &p, const Quantity q)
    {
      switch (q)
        {
          case Quantity::force:
            return p.force;
          case Quantity::contact_radius:
            return p.radius;
          case Quantity::pressure:
            break;
        }
      return p.pressure;
    }

    /// The radii (/ a) of a friction map's pressure: its deviation is the change of p(r) over them in the
    /// area-weighted L2 norm, relative to p's (a point near the axis alone would see the local, log-singular effect
    /// of the shear's jump at a small stick zone's edge). Inside the contact of every mu (friction shrinks it by a
    /// few %).
    const std::vector<double> friction_pressure_radii{0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45,
                                                      0.5,  0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9};

    /// The quantity as map.md and the plots name it: a friction map's pressure is the change of p(r) in L2.
    std::string quantity_label(const Quantity q, const bool of_friction = false)
    {
      if (q != Quantity::pressure)
        return name(q);
      return of_friction ? "p(r), L2 change" : "p(" + format(axis_sample) + " a)";
    }

    /// The points of one k, with what bounds their FE error.
    struct ExponentMap
    {
      std::vector<MapPoint> points;
      std::map<Quantity, double> resolution; ///< per quantity; missing: not measured
      std::string resolution_text;              ///< for map.md
    };

    /// The sharp-check rows of `check` (FE against closed forms where they are exact), named by `metric`.
    void add_check_rows(const Scene &s, const MapPoint &check, const std::string &metric, SceneResult &result,
                        const std::string &pressure_row = "pressure at r = " + format(axis_sample) + " a")
    {
      if (!check.error.empty())
        {
          result.rows.push_back(failed("force at the FE depth", "FE", "closed form", metric + ": " + check.error));
          return;
        }
      result.rows.push_back(compare("force at the FE depth", metric, "FE", "closed form", 1., 1. + check.force, 1.,
                                    s.tolerances.force, check.dofs, check.seconds));
      if (is_indenter(s))
        result.rows.push_back(compare("contact radius at the FE depth", metric, "FE", "closed form", 1., 1. + check.radius,
                                      1., s.tolerances.contact_radius, check.dofs, check.seconds));
      result.rows.push_back(compare(pressure_row, metric, "FE", "closed form", 1., 1. + check.pressure, 1.,
                                    s.tolerances.pressure, check.dofs, check.seconds));
    }

    /// A real grading at exponent k: the sharp check with the power law itself, the ratios, and the FE
    /// resolution from one uniform refinement more at the ratio nearest the power law.
    ExponentMap grading_map(const Scene &s, const double k, const std::vector<double> &ratios, SceneResult &result,
                            const bool verbose)
    {
      const std::string x = ratio_name(s).md;
      const bool toward_large = s.map.parameter != MapParameters::Parameter::coating_thickness;
      const std::vector<Quantity> quantities = map_quantities(s);
      ExponentMap out;
      // The sharp check: the same FE model with the power law itself, where the closed forms are exact.
      const MapPoint exact = solve(graded(s, k, 0.), 0.);
      add_check_rows(s, exact, "k = " + format(k) + ", the power law itself (" + x + (toward_large ? " -> inf)" : " -> 0)"),
                     result);
      if (verbose)
        std::cerr << "  k = " << k << ", the power law: force " << exact.force << ", radius " << exact.radius
                  << ", pressure " << exact.pressure << (exact.error.empty() ? "" : " (" + exact.error + ")") << '\n';
      for (const double ratio : ratios)
        out.points.push_back(solve(graded(s, k, ratio), ratio));
      // The FE resolution of the map: the point nearest the power law again with one uniform refinement
      // more; a deviation that changes by more than a third of a threshold cannot place that threshold.
      std::vector<MapPoint>::const_iterator at = out.points.end();
      for (auto p = out.points.begin(); p != out.points.end(); ++p)
        if (p->error.empty() && (at == out.points.end() || (toward_large ? p->ratio > at->ratio : p->ratio < at->ratio)))
          at = p;
      const double nearest = at == out.points.end() ? ratios.front() : at->ratio;
      const MapPoint finer = at == out.points.end() ? MapPoint{} : solve(graded(s, k, nearest), nearest, 1);
      if (at != out.points.end() && finer.error.empty())
        for (const Quantity q : quantities)
          out.resolution[q] = std::abs(deviation_of(finer, q) - deviation_of(*at, q));
      std::ostringstream md;
      md << "FE resolution at " << x << " = " << format(nearest) << " (the change with one uniform refinement more, "
         << finer.dofs << " DoFs):";
      if (out.resolution.empty())
        md << " not measured (" << (at == out.points.end() ? "no point was solved" : md_escape(finer.error)) << ")";
      for (const auto &[q, change] : out.resolution)
        md << " " << quantity_label(q) << " " << format(change) << ";";
      out.resolution_text = md.str();
      return out;
    }

    /// The seconds `work` takes.
    template <typename Work>
    double seconds_of(const Work &work)
    {
      const auto start = std::chrono::steady_clock::now();
      work();
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// Why a unilateral result cannot be a map point (its contact is not one disc, or the solve is flagged
    /// unreliable); empty when it can.
    std::string disc_contact_error(const fem::UnilateralResult &r)
    {
      if (r.zones.size() != 1 || r.zones.front().r_in > 0)
        return "the contact is not one disc (" + std::to_string(r.zones.size()) + " zones)";
      if (!r.reliable)
        return "the FE solve is flagged unreliable: " + r.message;
      return {};
    }

    /// A homogeneous elastic indenter (E1 = ratio E0, Indenter/nu) on the power law at exponent k, at the rigid
    /// closed form's depth of Load/a: one two-body solver (fem::UnilateralContactSolver) for every ratio (the
    /// indenter's compliance rescaled, exact in linear elasticity) and the rigid limit (factor inf). Sharp checks
    /// on the same mesh and half-space: the rigid limit, and a graded indenter E0/2 (z/c0)^k by the equivalent
    /// medium (9.4), against the closed forms; the error of the FE's ratio there is the map's FE resolution.
    ExponentMap indenter_map(const Scene &s, const double k, const std::vector<double> &ratios, SceneResult &result,
                             const bool verbose)
    {
      ExponentMap out;
      const double a = s.load.a;
      const std::string metric = "k = " + format(k) + ", ";
      try
        {
          const UnilateralPanel panel = unilateral_panel(s, k, s.material.nu);
          const Scene &g = panel.scene;
          const AnalyticReference &rigid = *panel.reference;
          fem::UnilateralLoad load = panel.load;
          // The contact grows toward the homogeneous pairing's radius at this depth as E1 / E0 falls.
          Scene homogeneous = g;
          homogeneous.material.k = 0.;
          homogeneous.load.control = LoadParameters::Control::depth;
          homogeneous.load.depth = load.depth;
          const double widest = std::max(a, AnalyticReference(homogeneous, batch::Method::closed_form,
                                                              AnalyticReference::Problem::normal).radius());
          fem::OutputRequest request;
          request.pressure_radii = {axis_sample * a};
          const auto point = [&](const fem::UnilateralResult &r, const AnalyticReference &ref, const double ratio,
                                 const double seconds, const unsigned int dofs) {
            MapPoint p;
            p.ratio = ratio;
            p.dofs = dofs;
            p.seconds = seconds;
            p.error = disc_contact_error(r);
            if (p.error.empty())
              {
                p.force = r.force / ref.get("force") - 1;
                p.radius = r.outer_edge / ref.radius() - 1;
                p.pressure = r.pressure.at(0).value / ref.at("pressure", axis_sample * a) - 1;
              }
            return p;
          };

          // The map's solver: a homogeneous indenter E0, nu_i; the rigid limit first.
          std::unique_ptr<fem::UnilateralContactSolver> solver;
          const double setup = seconds_of([&] {
            solver = elastic_indenter_solver(s, panel, 1.25 * widest);
          });
          fem::UnilateralResult r;
          solver->set_indenter_modulus_factor(std::numeric_limits<double>::infinity());
          double seconds = setup + seconds_of([&] { r = solver->run(load, request); });
          const fem::UnilateralResult rigid_fe = r;
          const MapPoint rigid_check = point(r, rigid, 0., seconds, solver->n_dofs());
          add_check_rows(s, rigid_check, metric + "rigid indenter (E1/E0 -> inf)", result);
          // A point: the FE at E1 against the rigid FE on the same mesh, which is the closed form up to the
          // rigid check's error.
          const auto relative = [&](MapPoint p) {
            if (p.error.empty() && rigid_check.error.empty())
              {
                p.force = (1 + p.force) / (1 + rigid_check.force) - 1;
                p.radius = (1 + p.radius) / (1 + rigid_check.radius) - 1;
                p.pressure = (1 + p.pressure) / (1 + rigid_check.pressure) - 1;
              }
            else if (p.error.empty())
              p.error = "the rigid limit failed: " + rigid_check.error;
            return p;
          };
          for (const double ratio : ratios)
            {
              solver->set_indenter_modulus_factor(ratio);
              seconds = seconds_of([&] { r = solver->run(load, request); });
              out.points.push_back(relative(point(r, rigid, ratio, seconds, solver->n_dofs())));
            }

          // 9.4: a graded indenter of the same law, where the equivalent medium is exact.
          Scene pair = g;
          pair.indenter.elasticity = IndenterParameters::Elasticity::graded;
          // Another E0 and nu than the half-space's: with the same ones the two bodies are one body twice and
          // the FE's ratio is exact on any mesh.
          pair.indenter.E = g.material.E0 / 2;
          pair.indenter.nu = g.material.nu < 0.4 ? 0.45 : 0.2;
          const AnalyticReference equivalent(pair, batch::Method::closed_form, AnalyticReference::Problem::normal);
          // The same solver with the graded indenter: the half-space and its compliance are kept.
          seconds = seconds_of([&] {
            solver->set_indenter_body(fe_indenter_body(pair));
            r = solver->run(load, request);
          });
          const MapPoint pair_check = point(r, equivalent, 0., seconds, solver->n_dofs());
          add_check_rows(s, pair_check,
                         metric + "graded indenter E0/2 (z/c0)^k, nu = " + format(pair.indenter.nu) + " (9.4)", result);
          if (verbose)
            std::cerr << "  k = " << k << ": rigid limit force " << rigid_check.force << ", two graded bodies (9.4) force "
                      << pair_check.force << '\n';
          // The FE resolution: the error of the FE's ratio (two bodies over the rigid indenter) where 9.4 knows it.
          const MapPoint pair_ratio = relative(pair_check);
          if (pair_ratio.error.empty())
            for (const Quantity q : all_quantities)
              out.resolution[q] = std::abs(deviation_of(pair_ratio, q)); // (FE / closed form of 9.4) / (the same, rigid) - 1
          std::ostringstream md;
          md << "FE resolution (the error of the FE's ratio two bodies / rigid indenter where 9.4 gives it, "
             << solver->n_dofs() << " DoFs):";
          if (out.resolution.empty())
            md << " not measured (" << md_escape(rigid_check.error + pair_check.error) << ")";
          for (const auto &[q, change] : out.resolution)
            md << " " << quantity_label(q) << " " << format(change) << ";";
          md << " E(a) = E0 (a/c0)^k = " << format(std::pow(a / g.material.c0, k)) << " E0, so E1/E(a) = "
             << format(std::pow(g.material.c0 / a, k)) << " E1/E0.";
          out.resolution_text = md.str();
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("indenter-modulus map", "FE", "closed form", metric + concise(e)));
          out.resolution_text = "not measured (" + md_escape(concise(e)) + ")";
        }
      return out;
    }

    /// The change of p(r) of `r` from `reference` at friction_pressure_radii in the area-weighted L2 norm
    /// (trapezoidal in r dr), relative to the reference's, with the sign of the change at r = 0.5 a; a radius beyond
    /// the contact is an error (the sampler leaves it out).
    double pressure_change(const fem::UnilateralResult &r, const std::vector<double> &reference)
    {
      if (r.pressure.size() != reference.size())
        throw std::runtime_error("p(r) sampled at " + std::to_string(r.pressure.size()) + " of " +
                                 std::to_string(reference.size()) + " radii (beyond the contact?)");
      const std::vector<double> &x = friction_pressure_radii;
      double change = 0, norm = 0, sign = 1;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          const double weight = x[i] * (x[std::min(i + 1, x.size() - 1)] - x[i == 0 ? 0 : i - 1]) / 2;
          const double dp     = r.pressure[i].value - reference[i];
          change += weight * dp * dp;
          norm += weight * reference[i] * reference[i];
          if (x[i] == 0.5)
            sign = dp < 0 ? -1 : 1;
        }
      return sign * std::sqrt(change / norm);
    }

    /// The path's error is first order in the step (a vertex that comes into contact during a step carries no
    /// shear in it): a point extrapolated from N and 2N steps, 2 X(2N) - X(N) (c/a: at 2N).
    MapPoint extrapolated(const MapPoint &coarse, const MapPoint &fine)
    {
      MapPoint p = fine;
      p.seconds += coarse.seconds;
      if (!coarse.error.empty() && p.error.empty())
        p.error = coarse.error;
      if (p.error.empty())
        {
          p.force = 2 * fine.force - coarse.force;
          p.radius = 2 * fine.radius - coarse.radius;
          p.pressure = 2 * fine.pressure - coarse.pressure;
        }
      return p;
    }

    /// A failed map point at `ratio`.
    MapPoint failed_point(const double ratio, const std::string &error)
    {
      MapPoint p;
      p.ratio = ratio;
      p.error = error;
      return p;
    }

    /// Runs `f` at friction coefficient mu: its seconds, or the error.
    std::pair<double, std::string> run_friction(FrictionSolver &f, const double mu)
    {
      f.load.friction.coefficient = mu;
      try
        {
          return std::make_pair(seconds_of([&] { f.r = f.solver->run(f.load, f.request); }), std::string());
        }
      catch (const std::exception &e)
        {
          return std::make_pair(0., concise(e));
        }
    }

    /// One point of f's last result: deviations from `force`, `radius` and `pressure` (the closed forms, or the
    /// frictionless FE on the same mesh).
    MapPoint friction_point(const FrictionSolver &f, const double mu, const double seconds, const double force,
                            const double radius, const std::vector<double> &pressure)
    {
      MapPoint p;
      p.ratio = mu;
      p.dofs = f.solver->n_dofs();
      p.seconds = seconds;
      p.error = disc_contact_error(f.r);
      if (p.error.empty())
        {
          p.force = f.r.force / force - 1;
          p.radius = f.r.outer_edge / radius - 1;
          p.pressure = pressure_change(f.r, pressure);
          if (mu > 0)
            p.stick = f.r.stick_radius / f.r.outer_edge;
        }
      return p;
    }

    /// The sharp check: the frictionless FE (f's first run, its setup included) against the closed forms.
    MapPoint frictionless_check(FrictionSolver &f, const AnalyticReference &frictionless, const double a)
    {
      auto [seconds, error] = run_friction(f, 0.);
      seconds += f.setup;
      MapPoint check;
      if (error.empty())
        try
          {
            std::vector<double> closed_pressure;
            for (const double x : friction_pressure_radii)
              closed_pressure.push_back(frictionless.at("pressure", x * a));
            check = friction_point(f, 0., seconds, frictionless.get("force"), frictionless.radius(), closed_pressure);
          }
        catch (const std::exception &e)
          {
            error = concise(e);
          }
      check.error += error;
      return check;
    }

    /// A frictional point at `steps` load steps: FE(mu) against the frictionless FE `smooth` on the same mesh.
    MapPoint friction_at_steps(FrictionSolver &f, const fem::UnilateralResult &smooth, const double mu,
                               const unsigned int steps)
    {
      f.load.friction.load_steps = steps;
      const auto [seconds, error] = run_friction(f, mu);
      if (!error.empty())
        return failed_point(mu, error);
      std::vector<double> smooth_pressure;
      for (const fem::Sample &x : smooth.pressure)
        smooth_pressure.push_back(x.value);
      try
        {
          return friction_point(f, mu, seconds, smooth.force, smooth.outer_edge, smooth_pressure);
        }
      catch (const std::exception &e)
        {
          return failed_point(mu, concise(e));
        }
    }

    /// The map's points: every mu of `ratios` (and full stick), each extrapolated from N and 2N steps. At Holl's
    /// ratio every point is a sharp check: the decoupled pairing's frictional FE against the frictionless FE.
    std::vector<MapPoint> friction_points(const Scene &s, FrictionSolver &f, const fem::UnilateralResult &smooth,
                                          const std::vector<double> &ratios, const bool holl, const std::string &metric,
                                          SceneResult &result)
    {
      const unsigned int steps = s.friction.load_steps;
      std::vector<double> mus = ratios;
      if (s.map.full_stick)
        mus.push_back(std::numeric_limits<double>::infinity());
      std::vector<MapPoint> points;
      for (const double mu : mus)
        {
          points.push_back(
            extrapolated(friction_at_steps(f, smooth, mu, steps), friction_at_steps(f, smooth, mu, 2 * steps)));
          const MapPoint &p = points.back();
          if (holl && p.error.empty())
            {
              const std::string what = metric + "mu = " + format(mu) + " against mu = 0 (decoupled: equal)";
              result.rows.push_back(compare("force at the depth (friction)", what, "FE", "FE frictionless", 1.,
                                            1. + p.force, 1., s.tolerances.force, p.dofs, p.seconds));
              result.rows.push_back(compare("contact radius (friction)", what, "FE", "FE frictionless", 1.,
                                            1. + p.radius, 1., s.tolerances.contact_radius, p.dofs, p.seconds));
            }
        }
      return points;
    }

    /// The FE resolution of a friction map into `out`: the change of the extrapolation from N/2 and N steps to N and
    /// 2N at the largest finite mu solved, where slip and stick meet (full stick only when no finite mu was solved;
    /// the mesh's error is the frictionless check's, which the text quotes).
    void friction_resolution(FrictionSolver &f, const fem::UnilateralResult &smooth, const unsigned int steps,
                             const bool holl, const MapPoint &smooth_check, ExponentMap &out)
    {
      auto largest = std::find_if(out.points.rbegin(), out.points.rend(), [](const MapPoint &p) {
        return p.error.empty() && std::isfinite(p.ratio);
      });
      if (largest == out.points.rend())
        largest = std::find_if(out.points.rbegin(), out.points.rend(), [](const MapPoint &p) { return p.error.empty(); });
      std::ostringstream md;
      if (largest != out.points.rend() && steps >= 2)
        {
          const MapPoint coarser = extrapolated(friction_at_steps(f, smooth, largest->ratio, steps / 2),
                                                friction_at_steps(f, smooth, largest->ratio, steps));
          if (coarser.error.empty())
            for (const Quantity q : all_quantities)
              out.resolution[q] = std::abs(deviation_of(*largest, q) - deviation_of(coarser, q));
          md << "Every point is extrapolated from " << steps << " and " << 2 * steps
             << " load steps (the path's error is first order). FE resolution (the change of that extrapolation from "
             << steps / 2 << " and " << steps << " steps, at mu = " << format(largest->ratio) << "; stick radius "
             << format(coarser.stick) << " at " << steps << " steps against " << format(largest->stick) << " at "
             << 2 * steps << "):";
          if (!coarser.error.empty())
            md << " not measured (" << md_escape(coarser.error) << ")";
        }
      else
        md << "FE resolution: not measured (" << (steps < 2 ? "Friction/load steps < 2" : "no frictional point was solved")
           << ")";
      for (const auto &[q, change] : out.resolution)
        md << " " << quantity_label(q, true) << " " << format(change) << ";";
      if (holl)
        md << " Holl's ratio: every deviation below is the FE's own error (exact: 0).";
      md << " " << f.solver->n_dofs() << " DoFs; the frictionless FE against the closed forms: force "
         << format(smooth_check.force) << ", contact radius " << format(smooth_check.radius) << ".";
      out.resolution_text = md.str();
    }

    /// Coulomb friction mu = ratio (and full stick, ratio inf) between a rigid indenter and the power law at
    /// exponent k and Poisson ratio nu during loading to the rigid closed form's depth of Load/a: one solver for
    /// the frictionless run and every mu (fem::UnilateralContactSolver, the shear operator built once). A point is
    /// FE(mu) / FE(frictionless) - 1 on one mesh; the stick radius is the FE's. Sharp checks: the frictionless FE
    /// against the closed forms, and at Holl's ratio nu = 1/(2 + k) (pressure causes no radial displacement of
    /// E ~ z^k) friction must change nothing. The FE resolution: the change of the largest-mu point with twice
    /// the load steps (the path's discretisation: a vertex that comes into contact during a step carries no
    /// shear in it), and, at Holl's ratio, the frictional FE's own deviation.
    ExponentMap friction_map(const Scene &s, const double k, const double nu, const std::vector<double> &ratios,
                             SceneResult &result, const bool verbose)
    {
      ExponentMap out;
      const bool holl = std::abs(nu - 1. / (2. + k)) <= 1e-12;
      const std::string metric = "k = " + format(k) + ", nu = " + (holl ? "1/(2 + k) = " : "") + format(nu) + ", ";
      try
        {
          const UnilateralPanel panel = unilateral_panel(s, k, nu);
          FrictionSolver f = friction_solver(s, panel, friction_pressure_radii);
          const MapPoint smooth_check = frictionless_check(f, *panel.reference, s.load.a);
          add_check_rows(s, smooth_check, metric + "frictionless", result,
                         "pressure, L2 change over r/a in [" + format(friction_pressure_radii.front()) + ", " +
                           format(friction_pressure_radii.back()) + "] (area-weighted, relative)");
          if (!smooth_check.error.empty())
            {
              out.resolution_text = "not measured (the frictionless FE failed: " + md_escape(smooth_check.error) + ")";
              return out;
            }
          const fem::UnilateralResult smooth = f.r;
          out.points = friction_points(s, f, smooth, ratios, holl, metric, result);
          friction_resolution(f, smooth, s.friction.load_steps, holl, smooth_check, out);
          if (verbose)
            std::cerr << "  k = " << k << ", nu = " << nu << ": frictionless force " << smooth_check.force << '\n';
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("friction map", "FE", "closed form", metric + concise(e)));
          out.resolution_text = "not measured (" + md_escape(concise(e)) + ")";
        }
      return out;
    }
  } // namespace

  namespace
  {
    /// One panel of a map: an exponent k, and for a friction map a Poisson ratio nu.
    struct Panel
    {
      double k, nu;
    };

    /// The column spec of a map kind: map.csv (every point) and each panel's table in map.md, from the kind's ratio
    /// and what its points carry: an indenter's contact radius (map.csv has the column for every kind), friction's nu
    /// and stick radius.
    struct MapColumns
    {
      RatioName ratio;
      bool radius = false, friction = false;

      std::vector<Column> columns() const
      {
        std::vector<Column> c{Column::csv_only("k")};
        if (friction)
          c.push_back(Column::csv_only("nu").csv_as(Number{'f', 6}));
        c.push_back(Column::both(ratio.csv, ratio.md));
        c.push_back(Column::both("force_deviation", "force"));
        c.push_back(radius ? Column::both("contact_radius_deviation", "contact radius")
                           : Column::csv_only("contact_radius_deviation"));
        c.push_back(Column::both("pressure_deviation", quantity_label(Quantity::pressure, friction)));
        if (friction)
          c.push_back(Column::both("stick_radius_over_a", "c/a").csv_as(Number{}));
        for (const Column &last : {Column::both("dofs", "DoFs"), Column::both("seconds", "s"),
                                   Column::csv_only("error").quoted()})
          c.push_back(last);
        return c;
      }

      /// An empty table of these columns (map.csv's numbers with 10 digits).
      Table table() const { return Table(columns(), Number{'g', 10}); }

      /// A point's row: a failed one says so in the Markdown in place of its deviations.
      std::vector<Cell> cells(const Panel &panel, const MapPoint &p) const
      {
        const bool failed = !p.error.empty();
        const auto deviation = [failed](const double value) { return failed ? Cell(value).md_text("-") : Cell(value); };
        std::vector<Cell> c{panel.k};
        if (friction)
          c.push_back(panel.nu);
        c.push_back(std::isinf(p.ratio) ? Cell(p.ratio).md_text("inf (full stick)") : Cell(p.ratio));
        c.push_back(failed ? Cell(p.force).md_text("failed: " + p.error) : Cell(p.force));
        c.push_back(deviation(radius ? p.radius : std::nan("")));
        c.push_back(deviation(p.pressure));
        if (friction)
          c.push_back(deviation(p.stick));
        for (const Cell &last : {Cell(p.dofs), Cell(p.seconds), Cell(p.error)})
          c.push_back(last);
        return c;
      }
    };

    /// What a map scene compares: its ratios (ascending), the quantities, the reference, the columns of its tables
    /// and the panels.
    struct MapPlan
    {
      std::vector<double> ratios;
      MapColumns columns;
      /// The ratio's name in map.md.
      const std::string &x() const { return columns.ratio.md; }
      bool indenter = false, of_indenter = false, of_friction = false;
      /// The chapter's idealisation is the limit a/z0 -> inf of a finite surface modulus (a/w -> inf of the error
      /// function), a/H -> 0 of a coating, E1/E0 -> inf of the indenter and mu -> 0 of friction.
      bool toward_large = true;
      std::vector<Quantity> quantities;
      std::string reference_name;
      std::vector<Panel> panels;
    };

    /// The plan of a map scene: every k, and for a friction map every nu of Map/nu values (and Holl's ratio).
    MapPlan plan_map(const Scene &s)
    {
      MapPlan plan;
      const std::vector<double> ks = s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
      plan.ratios = s.map.values;
      std::sort(plan.ratios.begin(), plan.ratios.end());
      plan.indenter = is_indenter(s);
      plan.quantities = map_quantities(s);
      plan.of_indenter = s.map.parameter == MapParameters::Parameter::indenter_modulus;
      plan.of_friction = s.map.parameter == MapParameters::Parameter::friction_coefficient;
      plan.columns = MapColumns{ratio_name(s), plan.indenter, plan.of_friction};
      plan.reference_name = plan.of_indenter   ? "closed form (rigid indenter)"
                            : plan.of_friction ? "FE frictionless"
                                               : "closed form (power-law idealisation E0, c0, k)";
      plan.toward_large = s.map.parameter != MapParameters::Parameter::coating_thickness && !plan.of_friction;
      for (const double k : ks)
        {
          std::vector<double> nus = plan.of_friction && !s.map.poisson_ratios.empty() ? s.map.poisson_ratios
                                                                                      : std::vector<double>{s.material.nu};
          if (plan.of_friction && s.map.holl_ratio && 1. / (2. + k) <= 0.5 &&
              std::none_of(nus.begin(), nus.end(), [k](const double nu) { return std::abs(nu - 1. / (2. + k)) <= 1e-12; }))
            nus.push_back(1. / (2. + k));
          for (const double nu : nus)
            plan.panels.push_back({k, nu});
        }
      return plan;
    }

    std::string panel_name(const MapPlan &plan, const Panel &p)
    {
      return "k = " + format(p.k) +
             (plan.of_friction
                ? ", nu = " + std::string(std::abs(p.nu - 1. / (2. + p.k)) <= 1e-12 ? "1/(2 + k) = " : "") + format(p.nu)
                : "");
    }

    /// The real grading of a grading map, as map.md names it.
    std::string grading_text(const Scene &s)
    {
      switch (s.map.parameter)
        {
          case MapParameters::Parameter::surface_depth:
            return "E(z) = E0 ((z + z0)/c0)^k (a finite surface modulus)";
          case MapParameters::Parameter::erf_width:
            return "E(z) = E0 [1 + (m - 1) erfc(z/w)], m = " + format(s.material.surface_modulus_ratio) +
                   " (the error-function grading of Lee, Barber & Thouless 2009)";
          default:
            return "a graded coating E0 (z/c0)^k on 0 < z <= H over the substrate E0 (H/c0)^k";
        }
    }

    /// The title of map.md and what the map compares.
    std::string map_intro(const Scene &s, const MapPlan &plan)
    {
      std::ostringstream md;
      md << "# " << s.info.name << ": applicability map\n\n" << (s.info.description.empty() ? "" : s.info.description + "\n\n");
      if (plan.of_indenter)
        md << "The FE model of a homogeneous elastic indenter (E1 = ratio E0, nu = " << format(s.indenter.nu)
           << ", a half-space carrying the profile) on E0 (z/c0)^k, at the depth where the rigid indenter's closed form "
              "has the contact radius Load/a = "
           << format(s.load.a) << " m: deviation = FE(E1) / FE(rigid indenter) - 1 on one mesh (force, contact radius, "
              "pressure at r = "
           << format(axis_sample) << " a), the deviation from the rigid indenter's closed forms up to the rigid FE's "
              "own error (the sharp-check rows of errors.csv). One mesh and solver per k (fem::UnilateralContactSolver, "
              "the contact set found); E1 enters as the scale of the indenter's compliance.\n\n";
      else if (plan.of_friction)
        md << "The FE model of a rigid indenter with Coulomb friction mu between it and E0 (z/c0)^k, loaded from zero "
              "(in "
           << s.friction.load_steps << " and " << 2 * s.friction.load_steps
           << " steps, extrapolated) to the depth where the frictionless closed form has the contact radius Load/a = "
           << format(s.load.a) << " m: deviation = FE(mu) / FE(frictionless) - 1 on one mesh (force at the depth, "
              "contact radius; for the pressure the change of p(r) sampled at r/a = "
           << format(friction_pressure_radii.front()) << ", ..., " << format(friction_pressure_radii.back())
           << " in the area-weighted L2 norm relative to p's, with the sign of the change at r = 0.5 a), the error of the "
              "chapter's frictionless closed forms up to the frictionless "
              "FE's own error (the sharp-check rows of errors.csv); c/a is the radius of the stick zone around the axis "
              "over the contact radius (slip outside it). One mesh and solver per (k, nu) (fem::UnilateralContactSolver, "
              "the contact, stick and slip sets found at every step). At Holl's ratio nu = 1/(2 + k) pressure causes no "
              "radial displacement and friction must change nothing: those rows are sharp checks.\n\n";
      else
        md << "The FE model of " << grading_text(s)
           << " against the power-law closed forms (E0, c0, k; 9.1) at the FE depth: deviation = FE / closed form - 1"
           << " (force at the depth" << (plan.indenter ? ", contact radius at the depth" : "") << ", pressure at r = "
           << format(axis_sample) << " a). Load/a = " << format(s.load.a) << " m, the FE under contact-radius control.\n\n";
      return md.str();
    }

    /// The title of map.md's threshold table.
    std::string thresholds_title(const MapPlan &plan)
    {
      return std::string("## Where ") +
             (plan.of_indenter   ? "the rigid indenter's closed forms hold"
              : plan.of_friction ? "the frictionless closed forms hold"
                                 : "the power law holds") +
             "\n\n";
    }

    /// map.md's threshold table, empty: a row per panel and quantity.
    Table thresholds_table(const Scene &s, const MapPlan &plan)
    {
      return threshold_table(plan.of_friction ? std::vector<std::string>{"k", "nu", "quantity"}
                                              : std::vector<std::string>{"k", "quantity"},
                             s.map.thresholds, "when " + plan.x());
    }

    /// The title and text of a friction map's table of the largest effects.
    std::string largest_title(const Scene &s)
    {
      return std::string("## The largest effect of friction\n\nOver the map's mu") + (s.map.full_stick ? " and full stick" : "") +
             ": the largest |FE(mu) / FE(frictionless) - 1| and the stick radius c/a at the largest finite mu.\n\n";
    }

    /// A friction map's table of the largest effects, empty: a row per panel, a column per quantity.
    Table largest_table(const MapPlan &plan)
    {
      std::vector<Column> columns{Column::md_only("k"), Column::md_only("nu")};
      for (const Quantity q : plan.quantities)
        columns.push_back(Column::md_only(quantity_label(q, true)));
      columns.push_back(Column::md_only("c/a at the largest finite mu"));
      return Table(columns);
    }

    /// The outputs of a map scene as its panels fill them: map.csv, map.md's parts, and the plots' curves.
    struct MapTables
    {
      MapTables(const Scene &s, const MapPlan &plan)
        : csv(plan.columns.table())
        , thresholds(thresholds_table(s, plan))
        , largest(largest_table(plan))
      {}
      Table csv, thresholds, largest;
      std::ostringstream md;
      std::map<Quantity, std::vector<Series>> plots; ///< |deviation| over the ratio, a curve per panel
      std::vector<Series> stick;                     ///< friction: c/a over mu, a curve per panel
    };

    /// The points of one panel: rows of map.csv and of the panel's table in map.md, and a failed row for each
    /// point that failed.
    void tabulate_points(const MapPlan &plan, const Panel &panel, const std::vector<MapPoint> &points, MapTables &t,
                         SceneResult &result, const bool verbose)
    {
      const std::string &x = plan.x();
      const bool of_friction = plan.of_friction;
      Table table = plan.columns.table();
      for (const MapPoint &p : points)
        {
          table.add(plan.columns.cells(panel, p));
          if (verbose)
            std::cerr << "  " << panel_name(plan, panel) << ", " << x << " = " << p.ratio << ": force " << p.force
                      << ", radius " << p.radius << ", pressure " << p.pressure
                      << (of_friction ? ", c/a " + format(p.stick) : "") << (p.error.empty() ? "" : " (" + p.error + ")")
                      << ", " << p.seconds << " s\n";
          if (!p.error.empty())
            result.rows.push_back(failed("map point", "FE", plan.reference_name,
                                         panel_name(plan, panel) + ", " + x + " = " + format(p.ratio) + ": " + p.error));
        }
      t.md << "## " << panel_name(plan, panel) << "\n\n" << table.md();
      t.csv.append(table);
    }

    /// A friction panel's row of the largest effects: the largest |deviation| of each quantity, and c/a at the
    /// largest finite mu.
    void tabulate_largest(const MapPlan &plan, const Panel &panel, const std::vector<MapPoint> &points, Table &largest)
    {
      std::vector<Cell> row{format(panel.k), format(panel.nu)};
      for (const Quantity q : plan.quantities)
        {
          double worst = -1;
          for (const MapPoint &p : points)
            if (p.error.empty())
              worst = std::max(worst, std::abs(deviation_of(p, q)));
          row.push_back(worst < 0 ? std::string("no point") : format(worst));
        }
      const auto last = std::find_if(points.rbegin(), points.rend(),
                                     [](const MapPoint &p) { return p.error.empty() && std::isfinite(p.ratio); });
      row.push_back(last == points.rend() ? Cell() : Cell(format(last->stick)));
      largest.add(std::move(row));
    }

    /// One threshold cell: where |deviation| stays within t toward the idealisation, unless the FE resolution
    /// cannot place it (a deviation that changes by more than t/3 with the resolution's step).
    std::string threshold_entry(const MapPlan &plan, const std::vector<double> &r, const std::vector<double> &d,
                                const std::optional<double> full_stick, const std::map<Quantity, double> &resolution,
                                const Quantity q, const double t)
    {
      if (r.empty() && !full_stick)
        return "no point";
      if (resolution.count(q) == 0)
        return "FE resolution not measured";
      if (!(resolution.at(q) <= t / 3))
        return "below the FE resolution (" + format(resolution.at(q)) + ")";
      return plan.of_friction ? friction_threshold_cell(r, d, full_stick, t) : threshold_cell(r, d, t, plan.toward_large);
    }

    /// A panel's rows of the threshold table, one per quantity, and its curves of |deviation| for the plots.
    void tabulate_thresholds(const Scene &s, const MapPlan &plan, const Panel &panel, const ExponentMap &map,
                             MapTables &t)
    {
      for (const Quantity q : plan.quantities)
        {
          std::vector<double> r, d;
          std::optional<double> full_stick;
          Series curve{panel_name(plan, panel), {}, {}, false, true};
          for (const MapPoint &p : map.points)
            if (p.error.empty() && std::isinf(p.ratio))
              full_stick = deviation_of(p, q);
            else if (p.error.empty())
              {
                r.push_back(p.ratio);
                d.push_back(deviation_of(p, q));
                curve.x.push_back(p.ratio);
                curve.y.push_back(std::max(std::abs(deviation_of(p, q)), 1e-16));
              }
          t.plots[q].push_back(curve);
          std::vector<Cell> row{format(panel.k)};
          if (plan.of_friction)
            row.push_back(format(panel.nu));
          row.push_back(quantity_label(q, plan.of_friction));
          for (const double threshold : s.map.thresholds)
            row.push_back(threshold_entry(plan, r, d, full_stick, map.resolution, q, threshold));
          t.thresholds.add(std::move(row));
        }
    }

    /// A friction panel's curve of the stick radius c/a over the finite mu.
    Series stick_curve(const MapPlan &plan, const Panel &panel, const std::vector<MapPoint> &points)
    {
      Series curve{panel_name(plan, panel), {}, {}, false, true};
      for (const MapPoint &p : points)
        if (p.error.empty() && !std::isinf(p.ratio))
          {
            curve.x.push_back(p.ratio);
            curve.y.push_back(p.stick);
          }
      return curve;
    }

    /// An erf-width panel's comparison with the published results, from its own points.
    std::string erf_published(const Scene &s, const std::vector<MapPoint> &points)
    {
      std::vector<double> r, force, radius;
      for (const MapPoint &p : points)
        if (p.error.empty())
          {
            r.push_back(p.ratio);
            force.push_back(p.force);
            radius.push_back(p.radius);
          }
      return published_comparison(s, r, force, radius);
    }

    /// Solves one panel of the map and adds it to the tables.
    void run_panel(const Scene &s, const MapPlan &plan, const Panel &panel, MapTables &t, SceneResult &result,
                   const bool verbose)
    {
      const double k = panel.k;
      if (plan.toward_large && !plan.of_indenter && k < 0)
        t.md << "k < 0 with a finite surface modulus: where z0 is thinner than the surface cells (outside r <= 1.05 a "
                "they are not halved), the plain Gauss rule under-integrates E ~ (z + z0)^k near z = 0, so the FE "
                "carries an error of about 1e-3 of the force at a/z0 >= 1e4 that one uniform refinement reduces only "
                "in part (fem/doc/limits.md); read the thresholds below 1 % with that in mind.\n\n";
      const ExponentMap map = plan.of_indenter   ? indenter_map(s, k, plan.ratios, result, verbose)
                              : plan.of_friction ? friction_map(s, k, panel.nu, plan.ratios, result, verbose)
                                                 : grading_map(s, k, plan.ratios, result, verbose);
      tabulate_points(plan, panel, map.points, t, result, verbose);
      t.md << map.resolution_text << "\n\n";
      if (plan.of_friction)
        tabulate_largest(plan, panel, map.points, t.largest);
      tabulate_thresholds(s, plan, panel, map, t);
      if (plan.of_friction)
        t.stick.push_back(stick_curve(plan, panel, map.points));
      if (s.map.parameter == MapParameters::Parameter::erf_width)
        t.md << erf_published(s, map.points);
    }

    /// map.md: the panels, the largest effects (friction), the thresholds and how they are read.
    std::string map_md(const Scene &s, const MapPlan &plan, const MapTables &t)
    {
      const bool of_friction = plan.of_friction;
      return t.md.str() + (of_friction ? largest_title(s) + t.largest.md() + "\n" : "") + thresholds_title(plan) +
             t.thresholds.md() +
             "\nThe thresholds interpolate log-log between the last ratio outside and the next one toward the "
             "chapter's idealisation; every ratio of the map beyond it is within." +
             (of_friction ? " Full stick (mu = inf) is read on its own: \"full stick included\" when it is "
                            "within too."
                          : "") +
             "\n";
    }

    /// The plots of |deviation| against the ratio with the thresholds as lines, and of friction's stick radius.
    void plot_map(const Scene &s, const fs::path &folder, const MapPlan &plan, MapTables &t)
    {
      for (auto &[q, series] : t.plots)
        {
          for (const double threshold : s.map.thresholds)
            series.push_back(Series{percent(threshold), {plan.ratios.front(), plan.ratios.back()}, {threshold, threshold},
                                    false, false});
          std::string stem = "map-" + name(q);
          std::replace(stem.begin(), stem.end(), ' ', '_');
          write_plot(folder, stem,
                     s.info.name + ": |" + quantity_label(q, plan.of_friction) +
                       (plan.of_indenter   ? " / rigid indenter - 1|"
                        : plan.of_friction ? " / frictionless - 1|"
                                           : " / power law - 1|"),
                     plan.x(), "|deviation|", series, true, true);
        }
      if (plan.of_friction)
        write_plot(folder, "map-stick_radius", s.info.name + ": stick radius c/a", plan.x(), "c/a", t.stick, true, false);
    }
  } // namespace

  SceneResult run_map_scene(const Scene &s, const fs::path &folder, const bool verbose)
  {
    require_kind(s, SceneKind::map, "run_map_scene");
    if (s.map.parameter == MapParameters::Parameter::coulomb_3d ||
        s.map.parameter == MapParameters::Parameter::tabor_parameter)
      throw std::invalid_argument("run_map_scene: scene " + s.file + " is a map of its own runner (Coulomb 3D: "
                                  "run_coulomb_map; Tabor parameter: run_cohesive_map)");
    const auto start = std::chrono::steady_clock::now();
    SceneResult result = started(s, folder);
    const MapPlan plan = plan_map(s);
    MapTables t(s, plan);
    t.md << map_intro(s, plan);
    for (const Panel &panel : plan.panels)
      run_panel(s, plan, panel, t, result, verbose);
    write_table_files(folder, "map", t.csv, map_md(s, plan, t));
    if (s.outputs.plots)
      plot_map(s, folder, plan, t);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
} // namespace gradcontact::cases
