#include "runners/candidate_coulomb.h"

#include "runners/candidate.h"
#include "model/coulomb_body.h"
#include "model/fe_model.h"
#include "model/mpi_session.h"

#include <fem/tangential/coulomb_contact_3d.h>
#include <fem/bodies/loads.h>

#include <deal.II/base/point.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace
  {
    /// One step of the path: the FE's state and its stick zone.
    struct Step
    {
      Branch              branch;
      fem::CoulombState3D state;
      fem::ZoneShape3D    shape;
      double              friction_work = 0; ///< mu P |s| of the step's slipping nodes, whole body
    };

    /// The c in [0, a] with u(c) = u0, u falling from u(0) to u(a) = 0 (a candidate's u0(c)), by bisection; a
    /// domain_error beyond u(0), the candidate's gross slip.
    double stick_radius_of(const std::function<double(double)> &u, const double u0, const double a)
    {
      if (!(u0 <= u(0.)))
        throw std::domain_error("u0 = " + format(u0) + " is beyond the candidate's gross slip (u0(c = 0) = " +
                                format(u(0.)) + ")");
      double lo = 0, hi = a;
      for (int i = 0; i < 200 && hi - lo > 1e-15 * a; ++i)
        {
          const double mid = 0.5 * (lo + hi);
          (u(mid) > u0 ? lo : hi) = mid;
        }
      return 0.5 * (lo + hi);
    }

    /// The FE's stick radius: the mean of the brackets of the rays that have nodes, and the largest half-width.
    std::pair<double, double> fe_stick_radius(const fem::ZoneShape3D &shape)
    {
      double sum = 0, half = 0;
      int    n   = 0;
      for (const fem::RayBracket &ray : shape.stick)
        if (ray.nodes > 0)
          sum += ray.radius(), half = std::max(half, ray.half_width()), ++n;
      if (n == 0)
        throw std::runtime_error("the 3D mesh has no surface nodes on the rays of the stick zone");
      return {sum / n, half};
    }

    /// The path (`dofs`: of the 3D body): normal loading to `depth` in Tangential/load steps, then delta_A in as many, and the cycle
    /// (twice as many each way); the first step that does not converge ends it with a runtime_error.
    std::vector<Step> run_path(const Scene &s, const CoulombSphereCase &body, const mdr::Profile &profile,
                               unsigned int &dofs)
    {
      const CoulombSphereSurface surface = prepare_coulomb_sphere(mpi_world(), body);
      dofs                               = static_cast<unsigned int>(surface.dofs);
      fem::CoulombParameters     friction;
      friction.mu = body.mu;
      fem::CoulombContact3D contact(surface.compliance, candidate_indenter(profile), friction);
      const unsigned int    m = s.tangential.load_steps;
      std::vector<Step>     path;
      const auto step = [&](const std::string &phase, const Branch branch, const double d, const double delta) {
        Step st{branch, contact.step_depth(d, delta), {}, 0.};
        if (!st.state.converged)
          throw std::runtime_error(phase + " step to d = " + format(d) + ", delta = " + format(delta) +
                                   " did not converge: " + st.state.message);
        st.shape = fem::zone_shape(surface.compliance, st.state);
        add_friction_work(st.state, st.friction_work);
        path.push_back(std::move(st));
      };
      for (unsigned int i = 1; i <= m; ++i)
        step("normal", Branch::loading, body.depth * i / m, 0.);
      path.clear(); // the rows are of the tangential steps
      for (unsigned int j = 1; j <= m; ++j)
        step("loading", Branch::loading, body.depth, body.delta * j / m);
      for (unsigned int j = 1; j <= 2 * m; ++j)
        step("unloading", Branch::unloading, body.depth, body.delta * (1. - 1. * j / m));
      for (unsigned int j = 1; j <= 2 * m; ++j)
        step("reloading", Branch::reloading, body.depth, body.delta * (-1. + 1. * j / m));
      return path;
    }
  } // namespace

  void coulomb_3d_candidate_rows(const Scene &s, const mdr::Profile &profile, const mdr::PartialSlip &slip,
                                 const std::map<std::string, double> &constants, std::vector<Row> &rows)
  {
    const CandidateParameters &c      = s.candidate;
    const double               a      = s.load.a, mu = s.friction.coefficient;
    const std::string          method = "FE (3D Coulomb)";
    const auto                 start  = std::chrono::steady_clock::now();
    std::vector<Step>          path;
    unsigned int               dofs = 0;
    CoulombSphereCase          body = coulomb_case(s, s.material.k, s.material.nu);
    try
      {
        body.mu = body.mu_normal = mu;
        body.depth = slip.depth(a);
        body.delta = slip.tangential_displacement(
          slip.stick_radius(s.tangential.amplitude * mu * slip.normal_force(a)));
        path = run_path(s, body, profile, dofs);
      }
    catch (const std::exception &e)
      {
        rows.push_back(failed("3D Coulomb path", "candidate", method, concise(e)));
        return;
      }
    const double       seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const unsigned int m  = s.tangential.load_steps;
    const double       FA = path[m - 1].state.force_x; // the FE's force at delta_A
    const auto of = [&](const std::string &quantity, const std::string &expression, const std::string &variables) {
      return expression.empty() ? nullptr : parse_candidate_expression<2>(quantity, variables, expression, constants);
    };
    const auto u_of_c = of("tangential displacement", c.tangential_displacement, "c,a");
    const auto F_of_c = of("tangential force", c.tangential_force, "c,a");
    const auto c_of_F = of("stick radius", c.stick_radius, "Fx,a");
    const auto at     = [a](const auto &g, const double x) { return g->value(dealii::Point<2>(x, a)); };
    const auto row    = [&](const std::string &quantity, const std::string &metric, const double fe_value,
                         const std::function<double()> &candidate, const double scale, const double tolerance) {
      try
        {
          rows.push_back(compare(quantity, metric, "candidate", method, fe_value, candidate(), scale, tolerance,
                                 dofs, seconds));
        }
      catch (const std::exception &e)
        {
          rows.push_back(failed(quantity, "candidate", method, metric + ": " + concise(e)));
        }
    };
    for (unsigned int j = 0; j < m; ++j)
      {
        const Step  &st     = path[j];
        const double delta  = st.state.delta, Fx = st.state.force_x;
        const std::string x = "delta / delta_A = " + format(delta / body.delta);
        if (u_of_c && F_of_c)
          row("tangential force", x + ", relative", Fx, [&] {
            return at(F_of_c, stick_radius_of([&](const double cc) { return at(u_of_c, cc); }, delta, a));
          }, Fx, s.tolerances.force);
        if (u_of_c && c_of_F)
          row("tangential displacement", x + ", relative", delta, [&] { return at(u_of_c, at(c_of_F, Fx)); }, delta,
              s.tolerances.displacement);
        if (c_of_F)
          {
            const auto [radius, half] = fe_stick_radius(st.shape);
            // the FE knows its stick radius to the half-width of the nodes' bracket: the tolerance adds it
            row("stick radius", x + ", rel. to a (tolerance + the FE's bracket " + format(half / a) + " a)", radius,
                [&] { return at(c_of_F, Fx); }, a, s.tolerances.contact_radius + half / a);
          }
      }
    for (const auto &[quantity, expression, branch] :
         {std::tuple<std::string, std::string, Branch>{"unloading displacement", c.unloading_displacement,
                                                       Branch::unloading},
          {"reloading displacement", c.reloading_displacement, Branch::reloading}})
      if (!expression.empty())
        {
          const auto g = parse_candidate_expression<3>(quantity, "Fx,FA,a", expression, constants);
          for (std::size_t j = m; j < path.size(); ++j)
            if (path[j].branch == branch && std::abs(path[j].state.delta) < body.delta * (1 - 1e-12))
              row(quantity, "delta / delta_A = " + format(path[j].state.delta / body.delta) + ", rel. to delta_A",
                  path[j].state.delta, [&] { return g->value(dealii::Point<3>(path[j].state.force_x, FA, a)); },
                  body.delta, s.tolerances.displacement);
        }
    if (!c.dissipated_energy.empty())
      {
        double work = 0;
        for (std::size_t j = m; j < path.size(); ++j)
          work += path[j].friction_work;
        const auto g = parse_candidate_expression<2>("dissipated energy", "FA,a", c.dissipated_energy, constants);
        row("dissipated energy", "FA / (mu F_N) = " + format(FA / (mu * slip.normal_force(a))) +
                                   ", relative (the FE's friction work over the cycle)",
            work, [&] { return at(g, FA); }, work, s.tolerances.force);
      }
  }
} // namespace gradcontact::cases
