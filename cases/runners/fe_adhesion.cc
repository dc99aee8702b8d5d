#include "runners/fe_adhesion.h"
#include "model/maugis_dugdale_rows.h"
#include "model/fe_contract.h"

#include "report/convergence_report.h"
#include "model/fe_adhesive.h"

#include "model/analytic_reference.h"
#include "model/scene_start.h"

#include <analytic/batch.h>
#include <analytic/maugis_dugdale.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Type = LoadParameters::Type;

  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// The FE G(a) check: a K'/K = 1 + k for the power law holds to the solver's round-off on scaled meshes;
    /// 1e-6 leaves room for gmsh placing nodes differently on scaled geometries.
    constexpr double scaling_tolerance = 1e-6;

    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    std::string control_name(const Control c)
    {
      return c == Control::force ? "force control" : "displacement control";
    }

    /// One refinement level of the scene.
    struct LevelResult
    {
      unsigned int refinement = 0, dofs = 0;
      double seconds = 0;
      std::map<std::string, std::pair<double, double>> values; ///< (FE value, first reference) per quantity
    };
  } // namespace



  FeAdhesiveCurve fe_adhesive_curve(const Scene &s, const std::vector<double> &a_over_ac, const bool force_control,
                                    const std::vector<double> &pressure_radii)
  {
    const LoadParameters &l = s.load;
    if (!(l.type == Type::paraboloid || l.type == Type::cone || l.type == Type::power_law) ||
        !(s.adhesion.work_of_adhesion > 0.))
      throw std::invalid_argument("scene " + s.file + ": an FE adhesive curve needs a curved profile (paraboloid, cone, "
                                  "power law) and Adhesion/work of adhesion > 0");
    // Checked before the FE: the critical search alone costs several FE solves.
    for (std::size_t j = 0; j < pressure_radii.size(); ++j)
      if (!(pressure_radii[j] >= 0. && pressure_radii[j] < 1.))
        throw std::invalid_argument("fe_adhesive_curve: pressure_radii[" + std::to_string(j) + "] = " +
                                    format(pressure_radii[j]) +
                                    " (r / a) is outside the valid range [0, 1): the adhesive pressure is singular at "
                                    "the contact edge r = a and zero beyond it");
    AdhesiveModel model(s, finest_refinement(s), false);
    const double a0 = s.adhesion.initial_radius > 0. ? s.adhesion.initial_radius : l.a;
    const AdhesiveCriticalPoint c = model.critical_state(force_control ? Control::force : Control::displacement, a0);
    FeAdhesiveCurve curve;
    for (const double x : a_over_ac)
      {
        const AdhesivePoint st = model.state(x * c.state.radius);
        curve.radius.push_back(st.radius);
        curve.depth.push_back(st.depth);
        curve.force.push_back(st.force);
        if (pressure_radii.empty())
          continue;
        // p(r) of this state (9.53 for the paraboloid), from the FE alone: its own pull-back delta(a).
        std::vector<double> r;
        for (const double x : pressure_radii)
          r.push_back(x * st.radius);
        std::vector<double> p;
        for (const fem::Sample &sample : model.surface(st.radius, r, {}).pressure)
          p.push_back(sample.value);
        curve.pressure.push_back(p);
      }
    return curve;
  }

  namespace
  {
    /// An adhesive scene, level by level: the optimal profile (9.69-9.74) or the FE model's own JKR critical
    /// states (flat punch, concave punch, curved profiles); then the force-depth plot and the convergence report.
    class AdhesionStudy
    {
    public:
      AdhesionStudy(const Scene &s, const fs::path &folder, const bool verbose, SceneResult &result)
        : s(s), l(s.load), ad(s.adhesion), folder(folder), verbose(verbose), result(result)
      {
        if (s.references.closed_form)
          references.emplace_back(s, batch::Method::closed_form, AnalyticReference::Problem::adhesive);
        if (s.references.numerical_mdr)
          references.emplace_back(s, batch::Method::numerical_mdr, AnalyticReference::Problem::adhesive);
      }

      void run()
      {
        if (s.discretization.contract)
          run_contract();
        else
          for (const unsigned int level : s.discretization.refinements)
            {
              level_start = std::chrono::steady_clock::now();
              LevelResult lr;
              lr.refinement = level;
              level_tag = s.discretization.refinements.size() > 1 ? ", refinement " + std::to_string(level) : "";
              solve_level(level, level == s.discretization.refinements.back(), lr);
              levels.push_back(lr);
            }
        plot_force_depth();
        convergence();
      }

      /// Discretization/accuracy = contract (cases/model/fe_contract.h): the study on the ladder's levels; only the last
      /// level's plot points stay.
      void run_contract()
      {
        const fem::Material material    = fe_material(s);
        std::size_t         first_curve = curve_series.size();
        run_on_ladder(
          material, adhesive_settings(s, material, 0, true)(l.a), s.discretization.force_tolerance, verbose, result,
          [&](const unsigned int level, LadderLevel &out) {
            level_start = std::chrono::steady_clock::now();
            LevelResult lr;
            lr.refinement = level;
            first_curve   = curve_series.size();
            ladder_level  = &out;
            const bool solved = solve_level(level, true, lr);
            ladder_level      = nullptr;
            out.dofs          = lr.dofs;
            levels.push_back(lr);
            return solved;
          },
          [&] { curve_series.erase(curve_series.begin() + static_cast<std::ptrdiff_t>(first_curve), curve_series.end()); });
      }

      /// One level (of Discretization/refinements, or of the contract's ladder): the optimal profile (9.69-9.74) or
      /// the FE model's own critical states. False when the FE failed (a row says why).
      bool solve_level(const unsigned int level, const bool finest, LevelResult &lr)
      {
        bool solved = true;
        if (l.type == Type::constant_pressure)
          optimal_profile(level, finest, lr);
        else
          {
            AdhesiveModel model(s, level, s.discretization.contract);
            try
              {
                if (l.type == Type::flat_punch)
                  report_state("periphery (edge)", model.periphery_state(l.a), Inputs{}, false, lr);
                else if (l.type == Type::concave_punch)
                  concave_punch(model, lr);
                else if (ad.law == AdhesionParameters::Law::dugdale)
                  cohesive_profile(level, lr);
                else
                  curved_profile(model, finest, lr);
              }
            catch (const std::runtime_error &e)
              {
                result.rows.push_back(failed("FE adhesion", "FE", "-", concise(e)));
                solved = false;
              }
            lr.seconds = seconds_since(level_start);
          }
        return solved;
      }

    private:
      /// Compares one FE value with every analytic reference: (FE value, first reference, NaN without one).
      std::pair<double, double> check(const std::string &quantity, const std::string &metric, const double fe,
                                      const std::string &ref_quantity, const Inputs &extra, const double tolerance,
                                      const unsigned int dofs, const double seconds,
                                      const std::optional<double> scale = std::nullopt)
      {
        double first = std::numeric_limits<double>::quiet_NaN();
        if (ladder_level)
          ladder_level->value(quantity + ", " + metric, fe, scale ? *scale : fe);
        for (const AnalyticReference &ref : references)
          try
            {
              const double r = ref.get(ref_quantity, extra);
              if (&ref == &references.front())
                first = r;
              result.rows.push_back(
                compare(quantity, metric, "FE", ref.label(), r, fe, scale ? *scale : r, tolerance, dofs, seconds));
              if (ladder_level)
                ladder_level->row(result.rows.size() - 1);
            }
          catch (const std::exception &e)
            {
              result.rows.push_back(failed(quantity, "FE", ref.label(), concise(e)));
            }
        return std::make_pair(fe, first);
      }

      /// 9.69-9.74: the surface under p = -sigma_th on r <= a; f_opt(r) = w_c - w(r).
      void optimal_profile(const unsigned int level, const bool finest, LevelResult &lr)
      {
        const TensionSurface r = optimal_profile_surface(s, level, s.discretization.contract);
        lr.dofs = r.dofs;
        lr.seconds = seconds_since(level_start);
        if (!r.reliable)
          result.rows.push_back(failed("FE solve", "FE", "-", r.message));
        const double wc = r.centre_displacement;
        lr.values["centre displacement w_c,opt"] = check("centre displacement w_c,opt", "relative" + level_tag, wc, "depth",
                                                          Inputs{}, s.tolerances.depth, lr.dofs, lr.seconds);
        Series fe_profile{"FE (w_c - w)", {}, {}, true};
        for (const fem::Sample &w : r.displacement)
          {
            const std::string metric = "r/a = " + format(w.r / l.a) + ", relative to |w_c|" + level_tag;
            check("displacement w_opt", metric, w.value, "displacement", input::r(w.r), s.tolerances.displacement, lr.dofs,
                  lr.seconds, std::abs(wc));
            if (w.r <= l.a)
              {
                check("optimal profile f_opt", metric, wc - w.value, "profile", input::r(w.r), s.tolerances.displacement,
                      lr.dofs, lr.seconds, std::abs(wc));
                fe_profile.x.push_back(w.r / l.a);
                fe_profile.y.push_back((wc - w.value) / std::abs(wc));
              }
          }
        if (s.outputs.plots && !references.empty() && finest)
          {
            Series curve{"f_opt (9.73) / |w_c,opt|", {}, {}, false};
            try
              {
                const double wc_ref = std::abs(references.front().get("depth"));
                for (int i = 0; i <= 200; ++i)
                  {
                    const double x = i / 200.;
                    curve.x.push_back(x);
                    curve.y.push_back(references.front().at("profile", x * l.a) / wc_ref);
                  }
              }
            catch (const std::exception &)
              {
              }
            write_plot(folder, "optimal_profile",
                       s.info.name + ": optimal profile (worst FE error " + format(worst("optimal profile f_opt")) + ")",
                       "r / a", "f_opt / |w_c,opt|", {curve, fe_profile});
          }
      }

      /// The rows of one FE critical state: pull-off force, critical radius (`with_radius`) and depth against the
      /// references, and for the power law the scaling identity a K'(a)/K(a) = 1 + k of the FE G(a).
      void report_state(const std::string &name, const AdhesiveCriticalPoint &c, const Inputs &extra,
                        const bool with_radius, LevelResult &lr)
      {
        const double k = s.material.k;
        lr.dofs = std::max(lr.dofs, c.max_dofs);
        const double t = seconds_since(level_start);
        lr.values["pull-off force, " + name] =
          check("pull-off force", name + level_tag, c.state.force, "critical_force", extra, s.tolerances.force, c.max_dofs, t);
        if (with_radius)
          check("critical radius", name + level_tag, c.state.radius, "critical_radius", extra, s.tolerances.contact_radius,
                c.max_dofs, t);
        check("critical depth", name + level_tag, c.state.depth, "critical_depth", extra, s.tolerances.depth, c.max_dofs, t);
        if (s.material.modulus == MaterialParameters::Modulus::power_law)
          result.rows.push_back(compare("energy release rate: a K'(a)/K(a)", name + ", at the critical radius" + level_tag,
                                        "FE", "scaling identity 1 + k", 1. + k, c.state.scaling_exponent, 1. + k,
                                        scaling_tolerance, c.max_dofs, t));
        if (verbose)
          std::cerr << "  " << name << ": a_c = " << c.state.radius << ", F_c = " << c.state.force << " ("
                    << c.radii_solved << " FE radii, " << format(c.fe_seconds) << " s)\n";
      }

      /// The concave punch (9.65-9.68): the periphery mechanism, with a tensile strength the centre one and the
      /// transition h0, and p(r) in each critical state.
      void concave_punch(AdhesiveModel &model, LevelResult &lr)
      {
        report_state("periphery (9.65-9.66)", model.periphery_state(l.a), input::mechanism(Mechanism::periphery), false, lr);
        {
          const AdhesiveCriticalPoint pc = model.periphery_state(l.a);
          critical_pressure(model, "periphery", pc.state.delta, Mechanism::periphery, lr);
        }
        if (ad.tensile_strength > 0.)
          {
            const AdhesiveCriticalPoint cc = model.centre_state(l.a);
            report_state("centre (9.67-9.68)", cc, input::mechanism(Mechanism::centre), false, lr);
            critical_pressure(model, "centre", cc.state.delta, Mechanism::centre, lr);
            try
              {
                const double h_star = model.transition_h0(l.a);
                lr.values["transition h0"] = check("transition h0", "periphery -> centre" + level_tag, h_star,
                                                   "transition_h0", Inputs{}, s.tolerances.depth, lr.dofs,
                                                   seconds_since(level_start));
              }
            catch (const std::runtime_error &e)
              {
                result.rows.push_back(failed("transition h0", "FE", "-", concise(e)));
              }
          }
      }

      /// p(r) in a critical state of the concave punch (9.66, 9.68) against the closed form, relative to max |p|.
      void critical_pressure(AdhesiveModel &model, const std::string &name, const double delta,
                             const Mechanism mechanism, const LevelResult &lr)
      {
        if (s.outputs.pressure_radii.empty())
          return;
        std::vector<double> pr;
        for (const double x : s.outputs.pressure_radii)
          pr.push_back(x * l.a);
        const auto prof = model.surface_at_delta(l.a, delta, pr, {});
        const double scale = largest_magnitude(prof.pressure);
        for (const fem::Sample &p : prof.pressure)
          {
            // The centre state is defined by p(0) = -sigma_th: that row would hold by construction.
            if (mechanism == Mechanism::centre && p.r == 0.)
              continue;
            const Inputs extra = input::both(input::mechanism(mechanism), input::r(p.r));
            check("critical pressure p(r)", name + ", r/a = " + format(p.r / l.a) + ", relative to max |p|" + level_tag,
                  p.value, "pressure", extra, s.tolerances.pressure, lr.dofs, seconds_since(level_start), scale);
          }
      }

      /// A curved profile: the critical states under force and displacement control (JKR 1971 too for the
      /// paraboloid at k = 0), then p(r), w(r) and the force-depth points of the force-controlled one.
      void curved_profile(AdhesiveModel &model, const bool finest, LevelResult &lr)
      {
        const double a0 = ad.initial_radius > 0. ? ad.initial_radius : l.a;
        std::optional<AdhesiveCriticalPoint> force_state;
        for (const Control control : {Control::force, Control::displacement})
          {
            if (!controlled(control))
              continue;
            const Inputs extra = input::control(control);
            // The second search starts from the first one's answer (and reuses its FE radii).
            const double start_radius = force_state ? force_state->state.radius : a0;
            try
              {
                const AdhesiveCriticalPoint c = model.critical_state(control, start_radius);
                if (control == Control::force)
                  force_state = c;
                report_state(control_name(control), c, extra, true, lr);
                if (l.type == Type::paraboloid && s.material.k == 0.)
                  {
                    // Johnson-Kendall-Roberts (1971): -3/2 pi dgamma R (force), -5/6 pi dgamma R (displacement).
                    const double jkr =
                      (control == Control::force ? -1.5 : -5. / 6.) * pi * ad.work_of_adhesion * l.R;
                    result.rows.push_back(compare("pull-off force", control_name(control) + level_tag, "FE", "JKR (1971)",
                                                  jkr, c.state.force, jkr, s.tolerances.force, c.max_dofs,
                                                  seconds_since(level_start)));
                  }
              }
            catch (const std::runtime_error &e)
              {
                no_critical_state(control, extra, concise(e));
              }
          }
        if (force_state)
          {
            critical_profiles(model, *force_state);
            if (finest)
              force_depth_points(model, *force_state);
          }
      }

      /// Adhesion/law = Dugdale: the pull-off of the cohesive-zone FE (fem/adhesion/cohesive_zone.h) against the chapter's JKR
      /// closed forms ("(JKR idealisation)": how far they are for this adhesive), and against Maugis-Dugdale, which
      /// holds for any Tabor parameter (Maugis' closed form at k = 0 for the paraboloid, the MDR's on the graded
      /// medium otherwise; a power-law modulus only).
      void cohesive_profile(const unsigned int level, LevelResult &lr)
      {
        const double dgamma     = ad.work_of_adhesion;
        const bool   paraboloid = l.type == Type::paraboloid;
        double       sigma0     = ad.cohesive_strength;
        const auto   medium_of_scene = [&] {
          return gradcontact::medium(
            gradcontact::GradedHalfSpace{s.material.E0, s.material.c0, s.material.k, s.material.nu});
        };
        const auto jkr_profile = [&] {
          return paraboloid ? JkrProfile{gradcontact::Paraboloid{l.R}} : JkrProfile{gradcontact::PowerLaw{l.n, l.A}};
        };
        if (ad.tabor_parameter > 0.)
          sigma0 = cohesive_strength(ad.tabor_parameter, medium_of_scene(), jkr_profile(), dgamma);
        DugdaleModel model(s, sigma0, level, s.discretization.contract);
        double start = ad.initial_radius > 0. ? ad.initial_radius : l.a;
        for (const Control control : {Control::force, Control::displacement})
          {
            if (!controlled(control))
              continue;
            const Inputs      extra = input::control(control);
            const std::string name  = control_name(control) + ", Dugdale sigma_0 = " + format(sigma0) + " Pa";
            try
              {
                const CohesiveCriticalPoint c = model.critical_state(control, start);
                start                         = c.state.radius;
                const double t                = seconds_since(level_start);
                lr.dofs                       = std::max(lr.dofs, c.max_dofs);
                if (verbose)
                  std::cerr << "  " << name << ": a_c = " << c.state.radius << ", c/a = " << c.state.zone_radius / c.state.radius
                            << ", F_c = " << c.state.force << " (" << c.states_solved << " FE states, " << format(c.seconds)
                            << " s)" << (c.at_vanishing_contact ? ", the contact vanishes" : "") << "\n";
                if (!c.state.consistent)
                  result.rows.push_back(failed("cohesive state", "FE", "-", name + ": " + c.state.message));
                if (c.at_vanishing_contact && control == Control::displacement)
                  {
                    for (const AnalyticReference &ref : references)
                      result.rows.push_back(failed("critical state (" + control_name(control) + ")", "FE (Dugdale)",
                                                   ref.label(), "no instability: the contact shrinks to nothing (small "
                                                                "Tabor parameter)"));
                    continue;
                  }
                lr.values["pull-off force, " + control_name(control)] = check(
                  "pull-off force", name + level_tag, c.state.force, "critical_force", extra, s.tolerances.force, c.max_dofs, t);
                check("critical radius", name + level_tag, c.state.radius, "critical_radius", extra,
                      s.tolerances.contact_radius, c.max_dofs, t);
                check("critical depth", name + level_tag, c.state.depth, "critical_depth", extra, s.tolerances.depth,
                      c.max_dofs, t);
                if (paraboloid && s.material.k == 0. && s.material.modulus == MaterialParameters::Modulus::power_law)
                  {
                    const double E_star = s.material.E0 / (1 - s.material.nu * s.material.nu);
                    const double lambda = gradcontact::maugis_dugdale::tabor_parameter(sigma0, dgamma, l.R, E_star);
                    if (lambda < 1e-3 || lambda > 1e3)
                      continue;
                    if (const auto row = maugis_dugdale_row(
                          lambda, control == Control::force, true, c.state.force, c.state.depth, dgamma, l.R,
                          E_star, name + ", lambda = " + format(lambda) + level_tag, "FE",
                          std::min(s.tolerances.force, 1e-3), std::min(s.tolerances.depth, 1e-3), c.max_dofs, t))
                      result.rows.push_back(*row);
                  }
                else if (s.material.modulus == MaterialParameters::Modulus::power_law)
                  try
                    {
                      // The graded medium: the MDR's Maugis-Dugdale solution (analytic/maugis_dugdale.h).
                      if (const auto row = graded_maugis_dugdale_row(
                            medium_of_scene(), jkr_profile(), sigma0, dgamma, control == Control::force,
                            true, c.state.force, c.state.depth, name + level_tag, "FE",
                            std::min(s.tolerances.force, 1e-3), std::min(s.tolerances.depth, 1e-3), c.max_dofs, t))
                        result.rows.push_back(*row);
                    }
                  catch (const std::exception &e)
                    {
                      result.rows.push_back(failed("critical state (" + control_name(control) + ")", "FE (Dugdale)",
                                                   "Maugis-Dugdale on the graded medium (MDR)", e.what()));
                    }
              }
            catch (const std::runtime_error &e)
              {
                result.rows.push_back(failed("critical state (" + control_name(control) + ")", "FE (Dugdale)", "-",
                                             concise(e)));
              }
          }
      }

      /// "No critical state" (e.g. 2n + k - 1 <= 0, 9.60) is a finding: it passes when every analytic reference
      /// finds none either, and fails when one of them has a state.
      void no_critical_state(const Control control, const Inputs &extra, const std::string &what)
      {
        const std::string quantity = "critical state (" + control_name(control) + ")";
        if (what.find("no critical state") == std::string::npos || references.empty())
          result.rows.push_back(failed(quantity, "FE", "-", what));
        for (const AnalyticReference &ref : references)
          try
            {
              const double F = ref.get("critical_force", extra);
              result.rows.push_back(
                failed(quantity, "FE", ref.label(), "FE: " + what + "; but the " + ref.label() + " has F_c = " + format(F)));
            }
          catch (const std::exception &none)
            {
              if (concise(none).find("no critical state") == std::string::npos)
                {
                  result.rows.push_back(failed(quantity, "FE", ref.label(), concise(none)));
                  continue;
                }
              Row row = compare(quantity, "none exists (FE and " + ref.label() + ")", "FE", ref.label(), 0., 0., 1., 0., 0,
                                seconds_since(level_start));
              if (verbose)
                std::cerr << "  " << ref.label() << ": " << concise(none) << "\n";
              result.rows.push_back(row);
            }
      }

      /// p(r) and w(r) of the FE critical state (force control) against the closed form at the same radius
      /// (9.53-9.54, 9.58-9.59): one more FE solve.
      void critical_profiles(AdhesiveModel &model, const AdhesiveCriticalPoint &c)
      {
        if (s.outputs.pressure_radii.empty() && s.outputs.displacement_radii.empty())
          return;
        std::vector<double> pr, wr;
        for (const double x : s.outputs.pressure_radii)
          pr.push_back(x * c.state.radius);
        for (const double x : s.outputs.displacement_radii)
          wr.push_back(x * c.state.radius);
        const auto prof = model.surface(c.state.radius, pr, wr);
        const double ac = c.state.radius, t = seconds_since(level_start);
        const double p_scale = largest_magnitude(prof.pressure), w_scale = std::abs(prof.state.depth);
        for (const fem::Sample &p : prof.pressure)
          check("adhesive pressure p(r)",
                "critical state (force control), r/a_c = " + format(p.r / ac) + ", relative to max |p|" + level_tag, p.value,
                "pressure", input::a_r(ac, p.r), s.tolerances.pressure, c.max_dofs, t, p_scale);
        for (const fem::Sample &w : prof.displacement)
          check("adhesive displacement w(r)",
                "critical state (force control), r/a_c = " + format(w.r / ac) + ", relative to |d_c|" + level_tag, w.value,
                "displacement", input::a_r(ac, w.r), s.tolerances.displacement, c.max_dofs, t, w_scale);
      }

      /// FE points on the adhesive force-depth curve (force control, figures 9.22-9.23) and the closed-form curve.
      void force_depth_points(AdhesiveModel &model, const AdhesiveCriticalPoint &c)
      {
        if (ad.curve_points.empty())
          return;
        Series points{"FE", {}, {}, true};
        const double Fc = std::abs(c.state.force), dc = std::abs(c.state.depth);
        for (const double x : ad.curve_points)
          {
            const AdhesivePoint st = model.state(x * c.state.radius);
            const std::string metric = "a = " + format(x) + " a_c, relative to |F_c|";
            check("adhesive force F(a)", metric, st.force, "force", input::a(st.radius), s.tolerances.force, c.max_dofs,
                  seconds_since(level_start), Fc);
            check("adhesive depth d(a)", "a = " + format(x) + " a_c, relative to |d_c|", st.depth, "depth",
                  input::a(st.radius), s.tolerances.depth, c.max_dofs, seconds_since(level_start), dc);
            points.x.push_back(st.depth / dc);
            points.y.push_back(st.force / Fc);
          }
        curve_series.push_back(points);
        if (references.empty())
          return;
        Series curve{"closed form (9.53-9.54, 9.58-9.59)", {}, {}, false};
        const double xmax = *std::max_element(ad.curve_points.begin(), ad.curve_points.end());
        for (int i = 1; i <= 300; ++i)
          try
            {
              const double a = c.state.radius * xmax * i / 300.;
              const double F = references.front().get("force", input::a(a));
              const double d = references.front().get("depth", input::a(a));
              curve.x.push_back(d / dc);
              curve.y.push_back(F / Fc);
            }
          catch (const std::exception &)
            {
            }
        curve_series.insert(curve_series.begin(), curve);
      }

      /// Whether the scene asks for the critical state under `control` (Adhesion/force control, displacement control).
      bool controlled(const Control control) const
      {
        return control == Control::force ? ad.force_control : ad.displacement_control;
      }

      /// The largest relative error of the rows of `quantity` that evaluated.
      double worst(const std::string &quantity) const
      {
        double w = 0;
        for (const Row &row : result.rows)
          if (row.quantity == quantity && row.error.empty())
            w = std::max(w, row.rel_error);
        return w;
      }

      void plot_force_depth() const
      {
        if (s.outputs.plots && curve_series.size() > 1)
          write_plot(folder, "force_depth",
                     s.info.name + ": adhesive force against depth (worst FE error " + format(worst("adhesive force F(a)")) + ")",
                     "d / |d_c|", "F / |F_c|", curve_series);
      }

      /// Refinement study: each FE value against the first reference.
      void convergence() const
      {
        if (levels.size() < 2 || references.empty())
          return;
        std::vector<ConvergenceSeries> series;
        for (const auto &[key, first_level] : levels.front().values)
          {
            const double reference = first_level.second;
            if (!std::isfinite(reference))
              continue;
            ConvergenceSeries c{key, reference, {}};
            for (const LevelResult &lr : levels)
              if (lr.values.count(key))
                {
                  const double v = lr.values.at(key).first;
                  c.levels.push_back({lr.refinement, lr.dofs, lr.seconds, v, relative_error(v, reference)});
                }
            series.push_back(c);
          }
        write_convergence(folder, s.info.name, references.front().label(), series, s.outputs.plots);
      }

      const Scene &s;
      const LoadParameters &l;
      const AdhesionParameters &ad;
      const fs::path &folder;
      const bool verbose;
      SceneResult &result;
      std::vector<AnalyticReference> references;
      std::vector<LevelResult> levels;
      std::vector<Series> curve_series; ///< the force-depth plot (closed form first, then the FE points)
      std::chrono::steady_clock::time_point level_start;
      std::string level_tag; ///< ", refinement l" in the metrics of a refinement study
      /// Under the contract, while a level is solved: where check() records its FE values and rows.
      LadderLevel *ladder_level = nullptr;
    };
  } // namespace

  SceneResult run_adhesion_scene(const Scene &s, const fs::path &folder, const bool verbose)
  {
    require_kind(s, SceneKind::adhesion, "run_adhesion_scene");
    const auto start = std::chrono::steady_clock::now();
    SceneResult result = started(s, folder);
    AdhesionStudy(s, folder, verbose, result).run();
    result.seconds = seconds_since(start);
    return result;
  }
} // namespace gradcontact::cases
