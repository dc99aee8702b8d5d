#include "runners/fe_cohesive.h"
#include "report/map_pipeline.h"
#include "model/maugis_dugdale_rows.h"

#include "report/table.h"
#include "report/thresholds.h"
#include "model/fe_adhesive.h"
#include "model/scene_start.h"

#include <analytic/adhesion.h>
#include <analytic/maugis_dugdale.h>
#include <fem/base/errors.h>
#include <fem/adhesion/smooth_cohesion.h>

#include <boost/math/tools/toms748_solve.hpp>

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
  using json = nlohmann::json;

  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// One pull-off of the map.
    struct Point
    {
      double       lambda = 0, strength = 0, range = 0;
      bool         force_control = true;
      double       force = 0, radius = 0, depth = 0, zone_ratio = 0; ///< FE
      double       force_jkr = 0, radius_jkr = 0, depth_jkr = 0, force_rigid = 0;  ///< chapter JKR; rigid (DMT-like) limit
      bool         vanishing = false;                               ///< no interior minimum (cohesive_zone.h)
      unsigned int states = 0, dofs = 0;
      double       seconds = 0;
      std::string  error, note;
      double force_deviation() const { return vanishing && !force_control ? 1.0 : force / force_jkr - 1; }
      double radius_deviation() const { return vanishing ? std::nan("") : radius / radius_jkr - 1; }
      double rigid_deviation() const { return force / force_rigid - 1; }
    };

    /// A trend check: a deviation must fall toward a limit, from `before` to `after` (rel_error = after / before < 1).
    Row falling_row(const std::string &quantity, const std::string &metric, const std::string &reference,
                    const double before, const double after, const Point &at, const std::string &method)
    {
      Row row;
      row.quantity        = quantity;
      row.metric          = metric + " (must fall: < 1)";
      row.method          = method;
      row.reference       = reference;
      row.reference_value = before;
      row.value           = after;
      row.abs_error       = std::abs(after - before);
      row.rel_error       = before > 0 ? after / before : std::numeric_limits<double>::infinity();
      row.tolerance       = 1;
      row.pass            = after < before;
      row.dofs            = at.dofs;
      row.seconds         = at.seconds;
      return row;
    }

    std::string control_name(const bool force_control)
    {
      return force_control ? "force control" : "displacement control";
    }

    std::string exact(const double x)
    {
      std::ostringstream s;
      s.precision(17);
      s << x;
      return s.str();
    }

    // JSON has no NaN: a non-finite number is stored as its text.
    json number(const double x) { return std::isfinite(x) ? json(x) : json(exact(x)); }
    double number(const json &j) { return j.is_number() ? j.get<double>() : std::stod(j.get<std::string>()); }

    /// One lambda of one k: the pull-off of each control, the states of the path F(d) (every state the searches and
    /// the curve points solved, ascending in a) and the curve points that failed. What the point cache stores.
    struct LambdaSolution
    {
      std::vector<Point> points;
      struct State
      {
        double a = 0, c = 0, d = 0, F = 0;
        bool   consistent = true;
      };
      std::vector<State>                          path;
      std::vector<std::pair<double, std::string>> path_errors; ///< (a / a_c,JKR, message)

      json to_json() const
      {
        json j{{"points", json::array()}, {"path", json::array()}, {"path_errors", json::array()}};
        for (const Point &p : points)
          j["points"].push_back({{"lambda", number(p.lambda)},       {"strength", number(p.strength)},
                                 {"range", number(p.range)},         {"force_control", p.force_control},
                                 {"force", number(p.force)},         {"radius", number(p.radius)},
                                 {"depth", number(p.depth)},         {"zone_ratio", number(p.zone_ratio)},
                                 {"force_jkr", number(p.force_jkr)}, {"radius_jkr", number(p.radius_jkr)},
                                 {"depth_jkr", number(p.depth_jkr)}, {"force_rigid", number(p.force_rigid)},
                                 {"vanishing", p.vanishing},         {"states", p.states},
                                 {"dofs", p.dofs},                   {"seconds", number(p.seconds)},
                                 {"error", p.error},                 {"note", p.note}});
        for (const State &st : path)
          j["path"].push_back({number(st.a), number(st.c), number(st.d), number(st.F), st.consistent});
        for (const auto &[x, e] : path_errors)
          j["path_errors"].push_back({number(x), e});
        return j;
      }

      static LambdaSolution from_json(const json &j)
      {
        LambdaSolution s;
        for (const json &q : j.at("points"))
          {
            Point p;
            p.lambda        = number(q.at("lambda"));
            p.strength      = number(q.at("strength"));
            p.range         = number(q.at("range"));
            p.force_control = q.at("force_control");
            p.force         = number(q.at("force"));
            p.radius        = number(q.at("radius"));
            p.depth         = number(q.at("depth"));
            p.zone_ratio    = number(q.at("zone_ratio"));
            p.force_jkr     = number(q.at("force_jkr"));
            p.radius_jkr    = number(q.at("radius_jkr"));
            p.depth_jkr     = number(q.at("depth_jkr"));
            p.force_rigid   = number(q.at("force_rigid"));
            p.vanishing     = q.at("vanishing");
            p.states        = q.at("states");
            p.dofs          = q.at("dofs");
            p.seconds       = number(q.at("seconds"));
            p.error         = q.at("error");
            p.note          = q.at("note");
            s.points.push_back(p);
          }
        for (const json &q : j.at("path"))
          s.path.push_back({number(q.at(0)), number(q.at(1)), number(q.at(2)), number(q.at(3)), q.at(4).get<bool>()});
        for (const json &q : j.at("path_errors"))
          s.path_errors.emplace_back(number(q.at(0)), q.at(1).get<std::string>());
        return s;
      }
    };

    /// Solves one lambda of the map (`base`: its lambda, strength, range and rigid limit) under `controls`, then
    /// the states of the curve points `curve_points` (a / a_c,JKR).
    LambdaSolution solve_lambda(DugdaleModel contact, const gradcontact::Medium &medium, const JkrProfile &profile,
                                const double dgamma, const Point &base, const std::vector<bool> &controls,
                                const std::vector<double> &curve_points)
    {
      LambdaSolution solution;
      for (const bool force_control : controls)
        {
          Point p            = base;
          p.force_control    = force_control;
          const auto control = force_control ? gradcontact::Control::force : gradcontact::Control::displacement;
          const auto jkr     = jkr_critical(medium, profile, dgamma, control);
          p.force_jkr        = jkr.force;
          p.radius_jkr       = jkr.radius;
          p.depth_jkr        = jkr.depth;
          try
            {
              const CohesiveCriticalPoint c = contact.critical_state(control, jkr.radius);
              p.force      = c.state.force;
              p.radius     = c.state.radius;
              p.depth      = c.state.depth;
              p.zone_ratio = c.state.zone_radius / c.state.radius;
              p.vanishing  = c.at_vanishing_contact;
              p.states     = c.states_solved;
              p.dofs       = c.max_dofs;
              p.seconds    = c.seconds;
              // Under displacement control a vanishing contact has no pull-off ("none"): the state where the
              // walk stopped is not compared, so its checks are noted, not failed.
              if (!c.state.consistent && !(p.vanishing && !force_control))
                p.error = "inconsistent state: " + c.state.message;
              else if (!c.state.consistent)
                p.note = "the last state before the contact vanished: " + c.state.message;
            }
          catch (const std::exception &e)
            {
              p.error = concise(e);
            }
          solution.points.push_back(p);
        }
      // The path F(d) of this lambda: the curve points (a / a_c,JKR under force control) and every state the
      // searches solved, ascending in a.
      const auto jkr_force = jkr_critical(medium, profile, dgamma, gradcontact::Control::force);
      for (const double x : curve_points)
        try
          {
            contact.state(x * jkr_force.radius);
          }
        catch (const std::exception &e)
          {
            solution.path_errors.emplace_back(x, concise(e));
          }
      for (const auto &[a, st] : contact.states())
        solution.path.push_back({a, st.zone_radius, st.depth, st.force, st.consistent});
      return solution;
    }

    /// The Lennard-Jones map's lambda (fem/adhesion/smooth_cohesion.h: its largest stress the Dugdale sigma_0 of lambda): one
    /// path, through snap-in and both pull-offs, on the model of its k (the surface flexibility shared by every
    /// lambda). Its depths are shifted by the law's equilibrium separation eps (d + eps: the approach beyond the
    /// touching of the surfaces, JKR's depth); a displacement-controlled pull-off without a jump is "none".
    LambdaSolution solve_lambda_smooth(LennardJonesModel &model, const gradcontact::Medium &medium,
                                       const JkrProfile &profile, const double dgamma, const Point &base,
                                       const std::vector<bool> &controls)
    {
      LambdaSolution          solution;
      const LennardJonesTrace trace = model.trace(base.strength, dgamma);
      for (const bool force_control : controls)
        {
          Point p            = base;
          p.force_control    = force_control;
          const auto control = force_control ? gradcontact::Control::force : gradcontact::Control::displacement;
          const auto jkr     = jkr_critical(medium, profile, dgamma, control);
          p.force_jkr        = jkr.force;
          p.radius_jkr       = jkr.radius;
          p.depth_jkr        = jkr.depth;
          p.zone_ratio       = std::nan("");
          p.states           = trace.path.steps;
          p.dofs             = trace.path.n_dofs;
          p.seconds          = trace.path.seconds;
          const bool found   = trace.has_pull_off(control);
          if (!trace.path.converged)
            p.error = "Lennard-Jones path: " + trace.path.message + " (" + std::to_string(trace.path.steps) +
                      " steps, " + std::to_string(trace.path.rejected_steps) + " rejected, " +
                      std::to_string(trace.path.newton_iterations) + " Newton solves, " +
                      std::to_string(trace.path.factorisations) + " factorisations)";
          else if (!found && force_control)
            p.error = "Lennard-Jones path: no minimum of F before the contact";
          p.vanishing = !force_control && !found;
          if (found)
            {
              const AdhesivePoint c = trace.pull_off(control); // its radius: JKR's a as lambda grows
              p.force               = c.force;
              p.radius              = c.radius;
              p.depth               = c.depth;
            }
          solution.points.push_back(p);
        }
      for (const AdhesivePoint &st : trace.states())
        solution.path.push_back({st.radius, std::nan(""), st.depth, st.force, true});
      return solution;
    }
  } // namespace



  double lennard_jones_edge_refinement(const double lambda)
  {
    if (!(lambda > 0 && lambda <= lennard_jones_largest_lambda()))
      fem::fail("lennard_jones_edge_refinement", "Tabor parameter lambda", lambda,
           "(0, " + format(lennard_jones_largest_lambda()) + "]");
    return lambda <= 5 ? 1.0 : std::exp2(std::ceil(std::log2(lambda * lambda / 25 * (1 - 1e-12))));
  }

  double lennard_jones_largest_lambda()
  {
    static_assert(largest_lennard_jones_lambda * largest_lennard_jones_lambda == 25 * fem::max_edge_refinement,
                  "the scene's largest Lennard-Jones lambda is 5 sqrt(fem::max_edge_refinement)");
    return largest_lennard_jones_lambda;
  }



  namespace
  {
    /// What a Tabor-parameter map compares: the law, the profile (the chapter's and the FE's), the ks, the lambdas
    /// (ascending) and the controls.
    struct CohesivePlan
    {
      double dgamma = 0;
      bool paraboloid = true, smooth = false;
      JkrProfile profile;
      std::vector<double> ks, lambdas;
      std::vector<bool> controls;
      std::string profile_name, law_name;
    };

    CohesivePlan plan_cohesive_map(const Scene &s)
    {
      using Type = LoadParameters::Type;
      CohesivePlan plan;
      plan.dgamma = s.adhesion.work_of_adhesion;
      plan.paraboloid = s.load.type == Type::paraboloid;
      plan.profile = plan.paraboloid ? JkrProfile{gradcontact::Paraboloid{s.load.R}}
                                     : JkrProfile{gradcontact::PowerLaw{s.load.n, s.load.A}};
      plan.ks = s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
      plan.lambdas = s.map.values;
      std::sort(plan.lambdas.begin(), plan.lambdas.end());
      if (s.adhesion.force_control)
        plan.controls.push_back(true);
      if (s.adhesion.displacement_control)
        plan.controls.push_back(false);
      plan.profile_name =
        plan.paraboloid ? "paraboloid R = " + format(s.load.R) + " m" : "power law f = A r^n, n = " + format(s.load.n);
      plan.smooth = s.adhesion.law == AdhesionParameters::Law::lennard_jones;
      plan.law_name = plan.smooth ? "Lennard-Jones" : "Dugdale";
      return plan;
    }

    /// The outputs of a Tabor-parameter map as its points fill them: map.csv, map.md's parts, the plots' curves.
    struct CohesiveTables
    {
      CohesiveTables(Table points, const Scene &s)
        : csv(std::move(points))
        , thresholds(threshold_table({"k", "control"}, s.map.thresholds, "when lambda"))
      {}
      Table csv, thresholds; ///< map.csv; map.md's threshold table, a row per k and control
      std::ostringstream md;
      std::map<std::string, std::vector<Series>> plots;
    };

    /// The title of map.md and what the map compares.
    std::string cohesive_intro(const Scene &s, const CohesivePlan &plan)
    {
      const bool smooth = plan.smooth;
      std::ostringstream md;
      md << "# " << s.info.name << ": where the chapter's JKR pull-off holds\n\n"
         << (s.info.description.empty() ? "" : s.info.description + "\n\n")
         << "The FE model of a rigid " << plan.profile_name
         << (smooth ? " with the Lennard-Jones law (sigma(h) = 8 dgamma / (3 eps) ((eps/h)^3 - (eps/h)^9), repulsion "
                      "included, its largest attraction sigma_0, fem/adhesion/smooth_cohesion.h)"
                    : " with a Dugdale cohesive zone (tension sigma_0 where the gap is below h_0 = dgamma / sigma_0, "
                      "fem/adhesion/cohesive_zone.h)")
         << " on E0 (z/c0)^k, dgamma = " << format(plan.dgamma) << " J/m^2, nu = " << format(s.material.nu)
         << (smooth ? ": its pull-off (the last minimum of F under force control, of d under displacement control, along "
                      "the equilibrium path followed by pseudo-arclength from the surfaces apart through snap-in into "
                      "contact, on a mesh that follows the contact edge; the contact radius where the gap is 3^(1/6) eps (the "
                      "largest attraction: the adhesive zone's inner end, JKR's a as lambda grows), the depth d + eps)"
                    : ": its pull-off (the minimum of F(a) under force control, of d(a) under displacement control, along "
                      "the path parametrised by the contact radius)")
         << " against the chapter's JKR critical state (9.55-9.56 for the paraboloid, "
            "9.60-9.61 for the power law). lambda is the Tabor parameter C Delta_l(a_c) / h_0 (cases/runners/fe_cohesive.h; "
            "Maugis' at k = 0"
         << (smooth ? "; with sigma_0 the Lennard-Jones' largest stress, lambda = 1.16 mu, mu Tabor's" : "")
         << (smooth ? "). F_rigid is the law's pull-off in the rigid limit: the smallest of Derjaguin's F(d) = -2 pi "
                      "\\int sigma(f(r) - d) r dr over d (DMT: -2 pi dgamma R for the paraboloid, for every k). Where"
                    : "). F_rigid = -pi sigma_0 c^2 with f(c) = h_0 is the Dugdale law's pull-off in the rigid limit (DMT: "
                      "-2 pi dgamma R for the paraboloid, for every k and law). Where")
         << " the contact shrinks to nothing without a jump "
            "(no minimum of d, small lambda) the chapter's displacement-controlled instability does not exist: "
            "\"none\", counted as a deviation of 100 %.\n\n";
      return md.str();
    }

    /// One k of the map: the scene at k and its medium, the refinement level of its meshes, and (Lennard-Jones) one
    /// model per edge refinement (lennard_jones_edge_refinement), built when a point is solved here (its mesh graded
    /// toward the force-controlled JKR radius, refined 2^level times), its construction's seconds counted toward the
    /// first lambda it serves. A Dugdale lambda builds its own model (its law is the model's).
    struct CohesiveExponent
    {
      double k = 0;
      Scene scene;
      gradcontact::Medium medium{};
      unsigned int level = 0;
      std::map<double, std::unique_ptr<LennardJonesModel>> smooth_contact;
      std::map<double, double> flexibility_seconds;
    };

    CohesiveExponent cohesive_exponent(const Scene &s, const double k)
    {
      CohesiveExponent e;
      e.k = k;
      e.scene = s;
      e.scene.material.k = k;
      e.medium = gradcontact::medium(gradcontact::GradedHalfSpace{s.material.E0, s.material.c0, k, s.material.nu});
      e.level = finest_refinement(s);
      return e;
    }

    /// The Lennard-Jones model of `e` at `edge_refinement`, built on first use.
    LennardJonesModel &smooth_model(CohesiveExponent &e, const CohesivePlan &plan, const double edge_refinement)
    {
      auto &model = e.smooth_contact[edge_refinement];
      if (!model)
        {
          const auto   start_model = std::chrono::steady_clock::now();
          const double a_c = jkr_critical(e.medium, plan.profile, plan.dgamma, gradcontact::Control::force).radius;
          model = std::make_unique<LennardJonesModel>(e.scene, a_c, e.level, edge_refinement);
          e.flexibility_seconds[edge_refinement] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_model).count();
        }
      return *model;
    }

    /// The point of one lambda before its solve: the strength and range of the law, and its rigid limit (Dugdale's
    /// tension sigma_0 on f(c) <= h_0; the Lennard-Jones', Derjaguin's integral of the law over the tip minimised in
    /// d; both -2 pi dgamma R for the paraboloid).
    Point lambda_base(const Scene &s, const CohesivePlan &plan, const gradcontact::Medium &medium, const double lambda)
    {
      Point base;
      base.lambda   = lambda;
      base.strength = cohesive_strength(lambda, medium, plan.profile, plan.dgamma);
      base.range    = plan.dgamma / base.strength;
      const double c_rigid =
        plan.paraboloid ? std::sqrt(2 * s.load.R * base.range) : std::pow(base.range / s.load.A, 1 / s.load.n);
      base.force_rigid = -pi * base.strength * c_rigid * c_rigid;
      if (plan.smooth)
        try
          {
            base.force_rigid = rigid_lennard_jones_pull_off(s, base.strength);
          }
        catch (const std::exception &)
          {
            base.force_rigid = std::nan(""); // no rigid limit for this tip: the column prints "-"
          }
      return base;
    }

    /// The column spec of a Tabor-parameter map: map.csv (every pull-off: the FE's values and the chapter's) and each
    /// k's table in map.md (their ratios).
    Table pull_off_table()
    {
      return Table({Column::csv_only("k"), Column::both("lambda", "lambda"), Column::both("control", "control"),
                    Column::csv_only("sigma0"), Column::csv_only("h0"), Column::csv_only("force"),
                    Column::csv_only("force_jkr"), Column::csv_only("force_deviation"), Column::md_only("F_c / F_c,JKR"),
                    Column::csv_only("radius"), Column::csv_only("radius_jkr"), Column::csv_only("radius_deviation"),
                    Column::md_only("a_c / a_c,JKR"), Column::csv_only("depth"), Column::csv_only("depth_jkr"),
                    Column::md_only("d_c / d_c,JKR"), Column::both("zone_over_a", "c / a"),
                    Column::csv_only("force_rigid"), Column::csv_only("rigid_deviation"),
                    Column::md_only("F_c / F_rigid"), Column::csv_only("vanishing_contact"),
                    Column::both("states", "states"), Column::both("dofs", "DoFs"), Column::both("seconds", "s"),
                    Column::csv_only("error").quoted()},
                   Number{'g', 10});
    }

    /// A pull-off's row of pull_off_table(): in the Markdown a failed pull-off, or none (no jump under displacement
    /// control), says so in place of its ratios.
    std::vector<Cell> pull_off_cells(const CohesivePlan &plan, const double k, const Point &p)
    {
      const bool shown = p.error.empty() && !(p.vanishing && !p.force_control);
      const auto md = [shown](const Cell &c) { return shown ? c : c.md_text("-"); };
      const Cell force = shown                ? Cell(p.force / p.force_jkr)
                         : !p.error.empty()   ? Cell("failed: " + p.error)
                                              : Cell("none (no jump" + (p.note.empty() ? "" : "; " + p.note) + ")");
      return {k, p.lambda, Cell(p.force_control ? "force" : "displacement").md_text(control_name(p.force_control)),
              p.strength, p.range, p.force, p.force_jkr, p.force_deviation(), force, p.radius, p.radius_jkr,
              p.radius_deviation(), md(p.vanishing ? Cell("0 (contact vanished)") : Cell(p.radius / p.radius_jkr)),
              p.depth, p.depth_jkr, md(p.depth / p.depth_jkr),
              plan.smooth ? Cell(p.zone_ratio).md_text("-") : md(p.zone_ratio), p.force_rigid, p.rigid_deviation(),
              md(std::isfinite(p.force_rigid) ? Cell(p.force / p.force_rigid) : Cell("-")), p.vanishing ? 1 : 0,
              p.states, p.dofs, p.seconds, p.error};
    }

    /// One pull-off's row of map.csv and of the k's table in map.md.
    void tabulate_pull_off(const CohesivePlan &plan, const double k, const Point &p, Table &table, const bool verbose)
    {
      const bool force_control = p.force_control;
      const double lambda = p.lambda;
      table.add(pull_off_cells(plan, k, p));
      if (verbose)
        std::cerr << "  k = " << k << ", lambda = " << lambda << ", " << control_name(force_control)
                  << ": F/F_JKR = " << p.force / p.force_jkr << (plan.smooth ? "" : ", c/a = " + format(p.zone_ratio))
                  << ", " << p.states << " states, " << p.seconds << " s" << (p.error.empty() ? "" : " (" + p.error + ")")
                  << "\n";
    }

    /// One pull-off's row of errors.csv: its failure, or the sharp check of a Dugdale map, Maugis-Dugdale (Maugis'
    /// closed form at k = 0 for the paraboloid, the MDR solution of the graded medium otherwise).
    void check_pull_off(const Scene &s, const CohesivePlan &plan, const CohesiveExponent &e, const Point &p,
                        SceneResult &result)
    {
      const bool force_control = p.force_control;
      const double k = e.k, lambda = p.lambda;
      if (!p.error.empty())
        {
          result.rows.push_back(failed("pull-off force (" + control_name(force_control) + ")", "FE " + plan.law_name,
                                       "closed form (JKR idealisation)",
                                       "k = " + format(k) + ", lambda = " + format(lambda) + ": " + p.error));
          return;
        }
      const std::string metric =
        "k = " + format(k) + ", lambda = " + format(lambda) + ", " + control_name(force_control) + ", relative";
      if (!plan.smooth && k == 0 && plan.paraboloid && lambda >= 1e-3 && lambda <= 1e3)
        {
          const double E_star = s.material.E0 / (1 - s.material.nu * s.material.nu);
          if (const auto row = maugis_dugdale_row(lambda, force_control, !(p.vanishing && !force_control), p.force,
                                                  p.depth, plan.dgamma, s.load.R, E_star, metric, "FE cohesive",
                                                  s.tolerances.force, s.tolerances.depth, p.dofs, p.seconds))
            result.rows.push_back(*row);
        }
      else if (!plan.smooth)
        try
          {
            if (const auto row = graded_maugis_dugdale_row(
                  e.medium, plan.profile, p.strength, plan.dgamma, force_control, !(p.vanishing && !force_control),
                  p.force, p.depth, metric, "FE cohesive", s.tolerances.force, s.tolerances.depth, p.dofs, p.seconds))
              result.rows.push_back(*row);
          }
        catch (const std::exception &ex)
          {
            result.rows.push_back(failed(force_control ? "pull-off force" : "critical depth", "FE cohesive",
                                         "Maugis-Dugdale on the graded medium (MDR)", metric + ": " + ex.what()));
          }
    }

    /// The path F(d) of one lambda: its failed curve points as rows, its states into path-k<k>-lambda<lambda>.csv
    /// and its curve (scaled by the force-controlled JKR state) for the k's path plot.
    void write_path(const fs::path &folder, const CohesivePlan &plan, const CohesiveExponent &e, const double lambda,
                    const LambdaSolution &solution, CohesiveTables &t, SceneResult &result)
    {
      const double k = e.k;
      for (const auto &[x, error] : solution.path_errors)
        result.rows.push_back(failed("F(d) path", "FE " + plan.law_name, "-",
                                     "k = " + format(k) + ", lambda = " + format(lambda) + ", a = " + format(x) +
                                       " a_c,JKR: " + error));
      const auto jkr_force = jkr_critical(e.medium, plan.profile, plan.dgamma, gradcontact::Control::force);
      const std::string path_name = "path-k" + format(k) + "-lambda" + format(lambda);
      Table path({Column::csv_only("a"), Column::csv_only("c"), Column::csv_only("d"), Column::csv_only("F"),
                  Column::csv_only("consistent")},
                 Number{'g', 10});
      Series curve{"lambda = " + format(lambda), {}, {}, false, true};
      for (const LambdaSolution::State &st : solution.path)
        {
          path.add({st.a, st.c, st.d, st.F, st.consistent ? 1 : 0});
          curve.x.push_back(st.d / std::abs(jkr_force.depth));
          curve.y.push_back(st.F / std::abs(jkr_force.force));
        }
      write_table_csv(folder, path_name, path);
      t.plots["path k = " + format(k)].push_back(curve);
    }

    /// The trend checks of one k and control: the deviation from JKR must fall toward large lambda, and (force
    /// control, paraboloid or Lennard-Jones) the deviation from the rigid limit toward small lambda. `r`, `d`, `dd`:
    /// lambda, F_c / F_c,JKR - 1 and d_c / d_c,JKR - 1 of the points that did not fail.
    void trend_rows(const CohesivePlan &plan, const double k, const bool force_control, const std::vector<Point> &points,
                    const std::vector<double> &r, const std::vector<double> &d, const std::vector<double> &dd,
                    SceneResult &result)
    {
      if (r.size() >= 2)
        {
          // The Dugdale search under displacement control minimises d(a): its d_c is accurate, the force at
          // that flat minimum moves with its location (at large lambda it is an order of magnitude further
          // off the MDR solution than d_c), so the trend toward JKR is read on d_c there.
          const bool                 on_depth = !plan.smooth && !force_control;
          const std::vector<double> &trend    = on_depth ? dd : d;
          const double prev = std::abs(trend[trend.size() - 2]), last = std::abs(trend.back());
          result.rows.push_back(falling_row("JKR limit (" + control_name(force_control) + ")",
                                            "k = " + format(k) + (on_depth ? ": |d_c / d_c,JKR - 1|" : ": |F_c / F_c,JKR - 1|") +
                                              " at lambda = " + format(r.back()) + " over its value at lambda = " +
                                              format(r[r.size() - 2]),
                                            "closed form (JKR idealisation)", prev, last, points.back(),
                                            "FE " + plan.law_name));
        }
      if (force_control && (plan.paraboloid || plan.smooth) && r.size() >= 2)
        {
          const Point &p0 = points[0], &p1 = points[1];
          if (p0.error.empty() && p1.error.empty())
            {
              result.rows.push_back(falling_row("DMT limit (force control)",
                                                "k = " + format(k) + ": |F_c / " +
                                                  (plan.paraboloid ? "(-2 pi dgamma R)" : "F_rigid") +
                                                  " - 1| at lambda = " + format(p0.lambda) +
                                                  " over its value at lambda = " + format(p1.lambda),
                                                plan.paraboloid ? "rigid sphere (DMT)" : "rigid tip (Derjaguin)",
                                                std::abs(p1.rigid_deviation()), std::abs(p0.rigid_deviation()), p0,
                                                "FE " + plan.law_name));
            }
        }
    }

    /// One k and control of the map: its curves (F_c / F_c,JKR and |deviation|), its row of the threshold table,
    /// and its trend checks.
    void tabulate_control(const Scene &s, const CohesivePlan &plan, const double k, const bool force_control,
                          const std::vector<Point> &points, CohesiveTables &t, SceneResult &result)
    {
      std::vector<double> r, d, dd; // lambda, F_c / F_c,JKR - 1, d_c / d_c,JKR - 1 (1: no jump)
      Series curve{"k = " + format(k) + ", " + control_name(force_control), {}, {}, false, true};
      Series deviation = curve;
      for (const Point &p : points)
        if (p.error.empty())
          {
            r.push_back(p.lambda);
            d.push_back(p.force_deviation());
            dd.push_back(p.vanishing && !force_control ? 1.0 : p.depth / p.depth_jkr - 1);
            if (!(p.vanishing && !force_control))
              {
                curve.x.push_back(p.lambda);
                curve.y.push_back(p.force / p.force_jkr);
              }
            deviation.x.push_back(p.lambda);
            deviation.y.push_back(std::max(std::abs(p.force_deviation()), 1e-16));
          }
      t.plots["pull-off force"].push_back(curve);
      t.plots["deviation"].push_back(deviation);
      std::vector<Cell> row{format(k), control_name(force_control)};
      for (const double threshold : s.map.thresholds)
        row.push_back(r.empty() ? std::string("no point") : threshold_cell(r, d, threshold, true));
      t.thresholds.add(std::move(row));
      trend_rows(plan, k, force_control, points, r, d, dd, result);
    }

    /// Maugis-Dugdale as dense curves on the force plot: the MDR solution at every k of a Dugdale map; Maugis' at
    /// k = 0 beside a Lennard-Jones map of the paraboloid.
    void add_maugis_dugdale_curves(const Scene &s, const CohesivePlan &plan, std::vector<Series> &force_plot)
    {
      const std::vector<double> &lambdas = plan.lambdas;
      if (!plan.smooth)
        for (const double k : plan.ks)
          {
            const gradcontact::Medium medium =
              gradcontact::medium(gradcontact::GradedHalfSpace{s.material.E0, s.material.c0, k, s.material.nu});
            for (const bool force_control : plan.controls)
              {
                Series curve{"Maugis-Dugdale (MDR), k = " + format(k) + ", " + control_name(force_control), {}, {}, false,
                             false};
                const auto jkr = jkr_critical(medium, plan.profile, plan.dgamma,
                                              force_control ? gradcontact::Control::force : gradcontact::Control::displacement);
                for (int i = 0; i <= 40; ++i)
                  {
                    const double lambda = lambdas.front() * std::pow(lambdas.back() / lambdas.front(), i / 40.0);
                    try
                      {
                        const auto p = graded_pull_off(medium, plan.profile,
                                                       cohesive_strength(lambda, medium, plan.profile, plan.dgamma),
                                                       plan.dgamma, force_control);
                        if (p.exists)
                          {
                            curve.x.push_back(lambda);
                            curve.y.push_back(p.state.force / jkr.force);
                          }
                      }
                    catch (const std::exception &)
                      {
                        // a lambda the solution refuses: a gap in the drawn curve (the rows report the points)
                      }
                  }
                force_plot.push_back(curve);
              }
          }
      else if (plan.paraboloid && std::find(plan.ks.begin(), plan.ks.end(), 0.0) != plan.ks.end())
        for (const bool force_control : plan.controls)
          {
            Series curve{"Maugis-Dugdale (k = 0), " + control_name(force_control), {}, {}, false, false};
            const double jkr = force_control ? -1.5 : -5.0 / 6;
            for (int i = 0; i <= 60; ++i)
              {
                const double lambda = lambdas.front() * std::pow(lambdas.back() / lambdas.front(), i / 60.0);
                if (lambda < 1e-3 || lambda > 1e3)
                  continue;
                const auto p = gradcontact::maugis_dugdale::pull_off(
                  lambda, force_control ? gradcontact::Control::force : gradcontact::Control::displacement);
                if (p.exists)
                  {
                    curve.x.push_back(lambda);
                    curve.y.push_back(p.state.P / jkr);
                  }
              }
            force_plot.push_back(curve);
          }
    }

    /// The ks of the MDR threshold table: -0.9 to 0.9 in steps of 0.1 and the map's own, ascending.
    std::vector<double> dense_exponents(const std::vector<double> &ks)
    {
      std::vector<double> dense;
      for (int i = -9; i <= 9; ++i)
        dense.push_back(i / 10.0);
      for (const double k : ks)
        if (std::find(dense.begin(), dense.end(), k) == dense.end())
          dense.push_back(k);
      std::sort(dense.begin(), dense.end());
      return dense;
    }

    /// One (k, control) row of the MDR threshold table, its lines of mdr_thresholds.csv and its points of the
    /// threshold curves.
    void mdr_threshold_row(const Scene &s, const CohesivePlan &plan, const double k, const bool force_control,
                           Table &mdr_md, Table &mdr_csv, std::map<std::string, Series> &curves)
    {
      const gradcontact::Medium medium =
        gradcontact::medium(gradcontact::GradedHalfSpace{s.material.E0, s.material.c0, k, s.material.nu});
      std::vector<Cell> row{format(k) + (std::find(plan.ks.begin(), plan.ks.end(), k) != plan.ks.end() ? " *" : ""),
                            control_name(force_control)};
      for (const double t : s.map.thresholds)
        {
          std::optional<double> at;
          try
            {
              at = graded_maugis_dugdale_threshold(medium, plan.profile, plan.dgamma, force_control, t);
              row.push_back(!at ? "not within it up to 1000" : *at <= 1e-2 ? "at every lambda from 0.01"
                                                                           : ">= " + format(*at));
            }
          catch (const std::exception &e)
            {
              row.push_back("- (" + std::string(e.what()) + ")"); // e.g. no JKR pull-off for this tip at this k
            }
          mdr_csv.add({k, control_name(force_control), t, at ? *at : std::numeric_limits<double>::quiet_NaN()});
          const std::string name  = control_name(force_control) + ", within " + percent(t);
          Series           &curve = curves[name];
          curve.title             = name;
          curve.linespoints       = true;
          if (at)
            {
              curve.x.push_back(k);
              curve.y.push_back(*at);
            }
        }
      mdr_md.add(std::move(row));
    }

    /// The thresholds of the Maugis-Dugdale solution of the graded medium (MDR) for every k from -0.9 to 0.9: the
    /// same question answered by the theory the FE matches, at the resolution the FE map cannot afford. Writes
    /// mdr_thresholds.csv and its plot; returns the section of map.md.
    std::string mdr_thresholds(const Scene &s, const fs::path &folder, const CohesivePlan &plan)
    {
      std::ostringstream intro;
      Table mdr_md = threshold_table({"k", "control"}, s.map.thresholds, "when lambda");
      Table mdr_csv({Column::csv_only("k"), Column::csv_only("control"), Column::csv_only("threshold"),
                     Column::csv_only("lambda")},
                    Number{'g', 10});
      intro << "\n## Where the Maugis-Dugdale solution of the graded medium (MDR) holds JKR, every k\n\n"
             << "The same Dugdale law solved by the MDR (analytic/maugis_dugdale.h; Maugis' closed form at k = 0), "
                "which the FE pull-offs above are checked against (errors.csv): the smallest lambda from which its "
                "pull-off stays within the threshold of the chapter's JKR pull-off up to lambda = 1000 (4 lambdas per "
                "decade from 0.01, then the crossing by TOMS 748; no jump under displacement control counts as 100 %). "
                "k of the FE map marked *.\n\n";
      std::map<std::string, Series> curves;
      for (const double k : dense_exponents(plan.ks))
        for (const bool force_control : plan.controls)
          mdr_threshold_row(s, plan, k, force_control, mdr_md, mdr_csv, curves);
      write_table_csv(folder, "mdr_thresholds", mdr_csv);
      if (s.outputs.plots)
        {
          std::vector<Series> series;
          for (const auto &[name, curve] : curves)
            series.push_back(curve);
          write_plot(folder, "map-mdr-thresholds",
                     s.info.name + ": Maugis-Dugdale (MDR) within the threshold of JKR from lambda", "k",
                     "Tabor parameter lambda", series, false, true);
        }
      return intro.str() + mdr_md.md();
    }

    /// map.md: the panels, the thresholds of the FE map and how they are read, and the MDR's thresholds.
    std::string cohesive_md(const CohesiveTables &t, const std::string &mdr_md)
    {
      return t.md.str() + "## Where the chapter's JKR pull-off force holds\n\n" + t.thresholds.md() +
             "\nThe thresholds interpolate log-log between the last lambda outside and the next one toward large lambda "
             "(the JKR limit); every lambda of the map beyond it is within.\n" +
             mdr_md;
    }

    /// The plots of the map: F_c / F_c,JKR, the path F(d) of every k, and |deviation| with the thresholds as lines.
    void plot_cohesive_map(const Scene &s, const fs::path &folder, const CohesivePlan &plan,
                           std::map<std::string, std::vector<Series>> &plots)
    {
      auto &dev = plots["deviation"];
      for (const double t : s.map.thresholds)
        dev.push_back(Series{percent(t), {plan.lambdas.front(), plan.lambdas.back()}, {t, t}, false, false});
      write_plot(folder, "map-pull_off_force", s.info.name + ": F_c / F_c,JKR", "Tabor parameter lambda", "F_c / F_c,JKR",
                 plots["pull-off force"], true, false);
      for (const double k : plan.ks)
        write_plot(folder, "map-path-k" + format(k),
                   s.info.name + ": F(d) along the path, k = " + format(k) + " (every FE state solved)",
                   "d / |d_c,JKR|", "F / |F_c,JKR|", plots["path k = " + format(k)], false, false);
      write_plot(folder, "map-deviation", s.info.name + ": |F_c / F_c,JKR - 1|", "Tabor parameter lambda",
                 "|deviation|", dev, true, true);
    }

    /// The Tabor-parameter map as a strategy of the map pipeline: a panel per k, a point per lambda (both controls
    /// and the path's states, cached), per k its table in map.md and per control its thresholds and trend checks;
    /// after the panels the MDR's thresholds and the plots.
    class CohesiveMap final : public MapStrategy
    {
    public:
      explicit CohesiveMap(const Scene &scene)
        : s(scene)
        , plan(plan_cohesive_map(scene))
        , t(pull_off_table(), scene)
        , table(pull_off_table())
      {
        t.md << cohesive_intro(s, plan);
      }

      std::size_t panels() const override { return plan.ks.size(); }
      std::size_t points(std::size_t) const override { return plan.lambdas.size(); }

      void open_panel(const std::size_t panel, SceneResult &, bool) override
      {
        e = cohesive_exponent(s, plan.ks.at(panel));
        table = pull_off_table();
        solutions.assign(plan.lambdas.size(), std::nullopt);
      }

      std::optional<MapPointKey> point_key(const std::size_t panel, const std::size_t point) const override
      {
        return MapPointKey{"cohesive map point", "k = " + exact(plan.ks.at(panel)) + ", lambda = " +
                                                   exact(plan.lambdas.at(point)) + (plan.smooth ? ", Lennard-Jones" : "")};
      }

      /// The pull-offs of every control and the states of the path of one lambda.
      void solve(std::size_t, const std::size_t point, SceneResult &, bool) override
      {
        const double lambda = plan.lambdas.at(point);
        const Point  base   = lambda_base(s, plan, e.medium, lambda);
        if (plan.smooth)
          {
            const double edge_refinement = lennard_jones_edge_refinement(lambda);
            LambdaSolution solution = solve_lambda_smooth(smooth_model(e, plan, edge_refinement), e.medium, plan.profile,
                                                          plan.dgamma, base, plan.controls);
            for (Point &p : solution.points)
              p.seconds += e.flexibility_seconds[edge_refinement];
            e.flexibility_seconds[edge_refinement] = 0;
            solutions.at(point) = std::move(solution);
          }
        else
          solutions.at(point) = solve_lambda(DugdaleModel::on_plain_meshes(e.scene, base.strength, e.level), e.medium,
                                             plan.profile, plan.dgamma, base, plan.controls, s.adhesion.curve_points);
      }

      json stored(std::size_t, const std::size_t point) const override { return solutions.at(point)->to_json(); }

      void restore(std::size_t, const std::size_t point, const json &value) override
      {
        solutions.at(point) = LambdaSolution::from_json(value);
      }

      /// Every lambda solved or read (one left to another shard is left out): its rows, its path; then per control
      /// the thresholds and trend checks, and the k's table.
      void close_panel(std::size_t, const fs::path &folder, SceneResult &result, const bool verbose) override
      {
        std::map<bool, std::vector<Point>> by_control;
        for (std::size_t i = 0; i < plan.lambdas.size(); ++i)
          if (const std::optional<LambdaSolution> &solution = solutions[i])
            {
              for (const Point &p : solution->points)
                {
                  by_control[p.force_control].push_back(p);
                  tabulate_pull_off(plan, e.k, p, table, verbose);
                  check_pull_off(s, plan, e, p, result);
                }
              write_path(folder, plan, e, plan.lambdas[i], *solution, t, result);
            }
        for (const bool force_control : plan.controls)
          tabulate_control(s, plan, e.k, force_control, by_control[force_control], t, result);
        t.md << "## k = " << format(e.k) << "\n\n" << table.md() << '\n';
        t.csv.append(table);
      }

      MapReport report(const fs::path &folder, bool) override
      {
        const std::string mdr_md = plan.smooth ? std::string() : mdr_thresholds(s, folder, plan);
        return {t.csv, cohesive_md(t, mdr_md)};
      }

      void plot(const fs::path &folder) override
      {
        add_maugis_dugdale_curves(s, plan, t.plots["pull-off force"]);
        plot_cohesive_map(s, folder, plan, t.plots);
      }

    private:
      const Scene                                &s;
      const CohesivePlan                          plan;
      CohesiveTables                              t;
      CohesiveExponent                            e;         ///< the open panel's k
      Table                                       table;     ///< the open panel's pull-offs
      std::vector<std::optional<LambdaSolution>> solutions; ///< the open panel's, per lambda
    };
  } // namespace

  std::unique_ptr<MapStrategy> cohesive_map_strategy(const Scene &s)
  {
    require_kind(s, SceneKind::map, "cohesive_map_strategy");
    if (s.map.parameter != MapParameters::Parameter::tabor_parameter)
      throw std::invalid_argument("cohesive_map_strategy: scene " + s.file + " is not a Tabor-parameter map");
    return std::make_unique<CohesiveMap>(s);
  }
} // namespace gradcontact::cases
