// gradcontact/analytic/detail: tanh-sinh quadrature that hands the integrand the exact distances
// to both end points.
//
// Boost 1.74's tanh_sinh passes the complement (distance to the end point) only on the canonical
// interval (-1, 1): f(u, uc) with uc = 1 - u for u > 0 and uc = -1 - u for u < 0. Mapping that to
// (lo, hi) here lets an integrand with an end-point singularity form (x - lo) or (hi - x) without
// the cancellation of subtracting nearly equal numbers (STYLE: ERRATA 9.2 quadrature item).
#ifndef GRADCONTACT_ANALYTIC_DETAIL_QUADRATURE_H
#define GRADCONTACT_ANALYTIC_DETAIL_QUADRATURE_H

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>

namespace gradcontact::detail
{
  /// Default relative tolerance of the MDR quadratures: tanh-sinh roughly doubles its digits per
  /// level, so the error is far below the tolerance once the tolerance is met.
  constexpr double quadrature_tolerance = 1e-14;

  // One integrator (its abscissa tables) per thread; Boost 1.74 declares the two-argument
  // integrate() non-const, hence no const here.
  inline boost::math::quadrature::tanh_sinh<double> &tanh_sinh_integrator()
  {
    thread_local boost::math::quadrature::tanh_sinh<double> integrator(15);
    return integrator;
  }

  /// int_lo^hi f(x, x - lo, hi - x) dx, with both distances formed without cancellation.
  template <class F>
  double integrate_with_distances(const F &f, const double lo, const double hi,
                                  const double tolerance = quadrature_tolerance,
                                  double *error_estimate = nullptr)
  {
    if (!(hi > lo))
      return 0.;
    const double half = 0.5 * (hi - lo);
    const auto g = [&](const double u, const double uc) -> double {
      double to_lo, to_hi;
      if (u < 0)
        {
          to_lo = half * (-uc); // uc = -1 - u, so -uc = 1 + u exactly
          to_hi = half * (1. - u);
        }
      else
        {
          to_lo = half * (1. + u);
          to_hi = half * uc;    // uc = 1 - u
        }
      const double x = (u < 0) ? lo + to_lo : hi - to_hi;
      if (!(to_lo > 0) || !(to_hi > 0))
        return 0.;
      return f(x, to_lo, to_hi);
    };
    double err = 0., L1 = 0.;
    const double q = tanh_sinh_integrator().integrate(g, tolerance, &err, &L1);
    if (error_estimate)
      *error_estimate = half * err;
    return half * q;
  }
} // namespace gradcontact::detail

#endif
