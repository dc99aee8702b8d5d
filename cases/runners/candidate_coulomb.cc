#include "runners/candidate_coulomb.h"

#include "runners/candidate.h"
#include "model/coulomb_body.h"
#include "model/coulomb_sphere.h"
#include "model/fe_model.h"
#include "model/mpi_session.h"

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
  } // namespace

  void coulomb_3d_candidate_rows(const Scene &s, const mdr::Profile &profile, const mdr::PartialSlip &slip,
                                 const std::map<std::string, double> &constants, std::vector<Row> &rows)
  {
    const CandidateParameters       &c      = s.candidate;
    const double                     a      = s.load.a, mu = s.friction.coefficient;
    const std::string                method = "FE (3D Coulomb)";
    const auto                       start  = std::chrono::steady_clock::now();
    std::vector<CoulombIndenterStep> path;
    unsigned int                     dofs = 0;
    CoulombSphereCase                body = coulomb_case(s, s.material.k, s.material.nu);
    try
      {
        body.mu = body.mu_normal = mu;
        body.depth = slip.depth(a);
        body.delta = slip.tangential_displacement(
          slip.stick_radius(s.tangential.amplitude * mu * slip.normal_force(a)));
        path = run_coulomb_indenter(mpi_world(), body, candidate_indenter(profile), s.tangential.load_steps, dofs);
      }
    catch (const std::exception &e)
      {
        rows.push_back(failed("3D Coulomb path", "candidate", method, concise(e)));
        return;
      }
    const double       seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const unsigned int m  = s.tangential.load_steps;
    const double       FA = path[m - 1].force_x; // the FE's force at delta_A
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
        const CoulombIndenterStep &st    = path[j];
        const double               delta = st.delta, Fx = st.force_x;
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
            const auto [radius, half] = fe_stick_radius(st);
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
            if (path[j].branch == branch && std::abs(path[j].delta) < body.delta * (1 - 1e-12))
              row(quantity, "delta / delta_A = " + format(path[j].delta / body.delta) + ", rel. to delta_A",
                  path[j].delta, [&] { return g->value(dealii::Point<3>(path[j].force_x, FA, a)); },
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
