#include "model/maugis_dugdale_rows.h"

#include <analytic/maugis_dugdale.h>
#include <fem/base/errors.h>

#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gradcontact::cases
{
  gradcontact::jkr::CriticalState jkr_critical(const gradcontact::Medium &m, const JkrProfile &profile,
                                               const double dgamma, const gradcontact::Control control)
  {
    return std::visit([&](const auto &p) { return gradcontact::jkr::critical_state(m, p, dgamma, control); },
                      profile);
  }

  gradcontact::PowerLaw as_tip(const JkrProfile &profile)
  {
    if (const auto *sphere = std::get_if<gradcontact::Paraboloid>(&profile))
      return gradcontact::as_power_law(*sphere);
    return std::get<gradcontact::PowerLaw>(profile);
  }

  gradcontact::maugis_dugdale::GradedPullOff graded_pull_off(const gradcontact::Medium &medium,
                                                             const JkrProfile &profile, const double strength,
                                                             const double dgamma, const bool force_control)
  {
    return gradcontact::maugis_dugdale::pull_off(medium, as_tip(profile),
                                                 gradcontact::maugis_dugdale::Dugdale{strength, dgamma},
                                                 force_control ? gradcontact::Control::force
                                                               : gradcontact::Control::displacement);
  }

  double cohesive_strength(const double lambda, const gradcontact::Medium &medium, const JkrProfile &profile,
                           const double dgamma)
  {
    if (!(lambda > 0) || !std::isfinite(lambda))
      throw std::invalid_argument("cohesive_strength: Tabor parameter lambda = " + format(lambda) + " must be in (0, inf)");
    return gradcontact::maugis_dugdale::strength(medium, as_tip(profile), dgamma, lambda);
  }



  namespace
  {
    /// A Maugis-Dugdale row (maugis_dugdale_row) from the reference's pull-off: `exists` (an instability),
    /// its force and depth, and the depth where its contact vanishes.
    std::optional<Row> dugdale_reference_row(const std::string &reference, const bool exists, const double ref_force,
                                             const double ref_depth, const double ref_vanishing_depth,
                                             const bool force_control, const bool fe_instability, const double force,
                                             const double depth, const std::string &metric, const std::string &method,
                                             const double force_tolerance, const double depth_tolerance,
                                             const unsigned int dofs, const double seconds)
    {
      if (exists != fe_instability)
        {
          // Under displacement control only (force control always has a pull-off). Where d(a) is flat to 1e-5 as the
          // contact vanishes (small lambda), a side's discretisation or search can find a minimum of d the other
          // does not: a jump is then real only if its depth differs from the vanishing contact's. The FE's depth (its
          // minimum of d, or its last state) against the reference's (its minimum, or its vanishing contact).
          if (force_control)
            return failed("pull-off force", method, reference, metric + ": the FE and Maugis-Dugdale disagree on a pull-off");
          const double reference_depth = exists ? ref_depth : ref_vanishing_depth;
          return compare("critical depth",
                         metric + (exists ? ": Maugis-Dugdale has a jump, the FE none (its last state's depth)"
                                          : ": the FE has a jump, Maugis-Dugdale none (its depth as the contact vanishes)"),
                         method, reference, reference_depth, depth, reference_depth, depth_tolerance, dofs, seconds);
        }
      if (!exists) // neither has one: the contact shrinks to nothing without a jump, nothing to compare
        return std::nullopt;
      // Under displacement control the search minimises d(a): d_c is what it finds accurately; the force there moves
      // with the location of that flat minimum.
      if (force_control)
        return compare("pull-off force", metric, method, reference, ref_force, force, ref_force, force_tolerance, dofs,
                       seconds);
      return compare("critical depth", metric, method, reference, ref_depth, depth, ref_depth, depth_tolerance, dofs,
                     seconds);
    }


    /// |F_c / F_c,JKR - 1| of the graded Maugis-Dugdale pull-off at lambda (1 where there is no jump).
    double graded_deviation(const gradcontact::Medium &medium, const JkrProfile &profile, const double dgamma,
                            const bool force_control, const double lambda)
    {
      const auto p = graded_pull_off(medium, profile, cohesive_strength(lambda, medium, profile, dgamma), dgamma,
                                     force_control);
      if (!p.exists)
        return 1;
      const auto jkr = jkr_critical(medium, profile, dgamma,
                                    force_control ? gradcontact::Control::force : gradcontact::Control::displacement);
      return std::abs(p.state.force / jkr.force - 1);
    }
  } // namespace

  std::optional<Row> maugis_dugdale_row(const double lambda, const bool force_control, const bool fe_instability, const double force,
                         const double depth, const double dgamma, const double R, const double E_star,
                         const std::string &metric, const std::string &method, const double force_tolerance,
                         const double depth_tolerance, const unsigned int dofs, const double seconds)
  {
    const auto md     = gradcontact::maugis_dugdale::pull_off(lambda, force_control ? gradcontact::Control::force
                                                                                    : gradcontact::Control::displacement);
    const auto scales = gradcontact::maugis_dugdale::scales(dgamma, R, E_star);
    return dugdale_reference_row("Maugis-Dugdale (Maugis 1992)", md.exists, md.state.P * scales.force,
                                 md.state.Delta * scales.depth,
                                 gradcontact::maugis_dugdale::vanishing_contact(lambda).Delta * scales.depth,
                                 force_control, fe_instability, force, depth, metric, method, force_tolerance,
                                 depth_tolerance, dofs, seconds);
  }

  std::optional<Row> graded_maugis_dugdale_row(const gradcontact::Medium &medium, const JkrProfile &profile,
                                               const double strength, const double dgamma, const bool force_control,
                                               const bool fe_instability, const double force, const double depth,
                                               const std::string &metric, const std::string &method,
                                               const double force_tolerance, const double depth_tolerance,
                                               const unsigned int dofs, const double seconds)
  {
    const auto md  = graded_pull_off(medium, profile, strength, dgamma, force_control);
    const auto end =
      gradcontact::maugis_dugdale::vanishing_contact(medium, as_tip(profile), gradcontact::maugis_dugdale::Dugdale{strength, dgamma});
    return dugdale_reference_row("Maugis-Dugdale on the graded medium (MDR)", md.exists, md.state.force,
                                 md.state.depth, end.depth, force_control, fe_instability, force, depth, metric, method,
                                 force_tolerance, depth_tolerance, dofs, seconds);
  }

  std::optional<double> graded_maugis_dugdale_threshold(const gradcontact::Medium &medium, const JkrProfile &profile,
                                                        const double dgamma, const bool force_control,
                                                        const double threshold)
  {
    if (!(threshold > 0 && threshold < 1))
      fem::fail("graded_maugis_dugdale_threshold", "threshold", threshold, "(0, 1)");
    const auto excess = [&](const double ln_lambda) {
      return graded_deviation(medium, profile, dgamma, force_control, std::exp(ln_lambda)) - threshold;
    };
    const double lo = std::log(1e-2), hi = std::log(1e3);
    const int    samples = 20; // 4 per decade
    int          last_outside = -1;
    double       f_outside = 0, f_inside = 0;
    for (int i = samples; i >= 0; --i)
      {
        const double f = excess(lo + (hi - lo) * i / samples);
        if (f > 0)
          {
            last_outside = i;
            f_outside    = f;
            break;
          }
        f_inside = f;
      }
    if (last_outside == samples)
      return std::nullopt;
    if (last_outside < 0)
      return 1e-2;
    std::uintmax_t iterations = 60;
    const double   a = lo + (hi - lo) * last_outside / samples, b = lo + (hi - lo) * (last_outside + 1) / samples;
    const auto     root = boost::math::tools::toms748_solve(excess, a, b, f_outside, f_inside,
                                                            boost::math::tools::eps_tolerance<double>(30), iterations);
    return std::exp((root.first + root.second) / 2);
  }
} // namespace gradcontact::cases
