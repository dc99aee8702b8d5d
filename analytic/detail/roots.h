// gradcontact/analytic: the root searches that the contact-radius and tangential problems share.
// solve_increasing and stable_branch_root (the numerical MDR) use TOMS 748 (Alefeld, Potra and Shi, ACM
// TOMS 21 (1995) 327-344) to 50 bits on a bracket they build first; the closed forms' adhesive radii, whose
// depth and force are two power laws (9.49), take safeguarded Newton steps (stable_branch_root with
// PowerLawParts), as does solve_from_zero.
#ifndef GRADCONTACT_ANALYTIC_DETAIL_ROOTS_H
#define GRADCONTACT_ANALYTIC_DETAIL_ROOTS_H

#include <analytic/errors.h>

#include <boost/math/tools/toms748_solve.hpp>

#include <cstdint>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace gradcontact::detail
{
  /// The x > 0 with increasing(x) = target, for a function that increases from 0 (depth or force of a
  /// non-adhesive indentation against its contact radius): the bracket [start/2, 2 start] is widened by
  /// factors 4 until it holds the root. DomainError naming `what` when no bracket is found.
  inline double solve_increasing(const std::function<double(double)> &increasing, const double target,
                                 const double start, const char *what)
  {
    double lo = start / 2., hi = start * 2.;
    for (int i = 0; i < 200 && increasing(lo) > target; ++i)
      lo /= 4.;
    for (int i = 0; i < 200 && increasing(hi) < target; ++i)
      hi *= 4.;
    const double f_lo = increasing(lo) - target, f_hi = increasing(hi) - target;
    if (f_lo == 0.)
      return lo;
    if (f_hi == 0.)
      return hi;
    if (!(f_lo <= 0. && f_hi >= 0.))
      throw DomainError(std::string(what) + ": no solution found for the target " + check::format(target));
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve([&](const double x) { return increasing(x) - target; }, lo,
                                                        hi, f_lo, f_hi,
                                                        boost::math::tools::eps_tolerance<double>(50), iterations);
    return 0.5 * (root.first + root.second);
  }

  /// The root a >= a_c of value(a) = target on the stable branch of an adhesive contact, where value
  /// (d(a) or F_N(a)) rises from its minimum value_c at the critical radius a_c. A target below
  /// value_c has no adhesive equilibrium: DomainError naming `name` (the given d or F).
  inline double stable_branch_root(const std::function<double(double)> &value, const double target, const double ac,
                                   const double value_c, const char *name)
  {
    if (target < value_c)
      check::fail("contact_radius", name, target,
                  "is below its critical value " + check::format(value_c) + ": no adhesive equilibrium");
    if (target == value_c)
      return ac;
    double hi = 2. * ac;
    for (int i = 0; i < 200 && value(hi) < target; ++i)
      hi *= 2.;
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve([&](const double a) { return value(a) - target; }, ac, hi,
                                                        value_c - target, value(hi) - target,
                                                        boost::math::tools::eps_tolerance<double>(50), iterations);
    return 0.5 * (root.first + root.second);
  }

  /// The two power laws of an adhesive depth or force (9.49): value(a) = P(a) - N(a), the non-adhesive part
  /// P ~ a^p minus the flat-punch part N ~ a^q (p = n, q = (1-k)/2 for the depth; p = n + k + 1,
  /// q = (3+k)/2 for the force), p > q > 0 where a critical state exists (2n + k - 1 > 0).
  struct PowerLawParts
  {
    double P, N;
  };

  /// stable_branch_root for value = P - N of two power laws (parts(a) returns both): Newton's method on
  /// the slope (p P - q N)/a (on log value against log a where the value is above half the target), kept inside a
  /// bracket that bisection narrows whenever a step leaves it, to a step of 4 eps relative to a. It starts from a bound the power laws give: with the minimum at a_c,
  /// value = 0 at a_0 = a_c (p/q)^(1/(p-q)), and for a target > 0 the root lies above the a where P alone
  /// reaches it (N > 0). Some 5-8 evaluations where the bracketing search of stable_branch_root takes 15-25.
  inline double stable_branch_root(const std::function<PowerLawParts(double)> &parts, const double p,
                                   const double q, const double target, const double ac, const double value_c,
                                   const char *name)
  {
    if (target < value_c)
      check::fail("contact_radius", name, target,
                  "is below its critical value " + check::format(value_c) + ": no adhesive equilibrium");
    if (target == value_c)
      return ac;
    constexpr double eps = std::numeric_limits<double>::epsilon();
    double lo = ac, hi = std::numeric_limits<double>::infinity();
    const double a0 = ac * std::pow(p / q, 1. / (p - q));
    double a = a0;
    if (target > 0.)
      {
        // P(a) = target + N(a) > target + N(a_0) = target + P(a_0) at the root
        const PowerLawParts at_zero = parts(a0);
        lo = a0;
        a = a0 * std::pow(1. + target / at_zero.P, 1. / p);
      }
    for (int i = 0; i < 200; ++i)
      {
        const PowerLawParts v = parts(a);
        const double residual = (v.P - v.N) - target;
        if (residual == 0.)
          return a;
        (residual < 0. ? lo : hi) = a;
        // Newton's step on log(value) against log(a) where both are positive (exact for P alone, so
        // that far above a_c one or two steps do), else on value against a; a dvalue/da = p P - q N.
        const double value = v.P - v.N, slope = p * v.P - q * v.N;
        double next = target > 0. && value > 0.5 * target ? a * std::exp(-std::log(value / target) * value / slope)
                                                          : a - residual * a / slope;
        // converged: tested before the bracket, which a step of a rounding error may leave
        if (std::abs(next - a) <= 4. * eps * a)
          return next;
        if (!(next > lo && next < hi))
          next = std::isinf(hi) ? 2. * a : 0.5 * (lo + hi);
        if (!std::isinf(hi) && hi - lo <= 4. * eps * hi)
          return next;
        a = next;
      }
    return a;
  }

  /// The h in [0, upper] with increasing(h) = target, for a function that rises from increasing(0) = 0 with
  /// the slope slope(h) and reaches the target by h = upper: Newton's method from the linear estimate
  /// target / slope(0), kept inside a bracket that bisection narrows whenever a step leaves it, to a step of
  /// 4 eps relative to h. The root is accurate relative to itself however small it is (the gap a - b of a
  /// slip radius b close to a, mdr_contact.cc), which a root search for b itself (to eps relative to b)
  /// is not.
  inline double solve_from_zero(const std::function<double(double)> &increasing,
                                const std::function<double(double)> &slope, const double target, const double upper)
  {
    if (!(target > 0.))
      return 0.;
    constexpr double eps = std::numeric_limits<double>::epsilon();
    double lo = 0., hi = upper;
    double h = std::min(target / slope(0.), upper);
    if (!(h > 0.))
      h = 0.5 * upper;
    for (int i = 0; i < 200; ++i)
      {
        const double value = increasing(h) - target;
        if (value == 0.)
          return h;
        (value < 0. ? lo : hi) = h;
        double next = h - value / slope(h);
        if (!(next > lo && next < hi))
          next = 0.5 * (lo + hi);
        if (std::abs(next - h) <= 4. * eps * h || hi - lo <= 4. * eps * hi)
          return next;
        h = next;
      }
    return h;
  }
} // namespace gradcontact::detail

#endif
