#include <analytic/errors.h>
#include <analytic/maugis_dugdale.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

namespace gradcontact::maugis_dugdale
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    /// The closing condition of the header, minus 1, in t = sqrt(m^2 - 1).
    double closing(const double lambda, const double A, const double t)
    {
      const double at = std::atan(t);
      const double m1 = t * t / (std::sqrt(1 + t * t) + 1); // m - 1
      return lambda * A * A / 2 * ((t * t - 1) * at + t) + 4 * lambda * lambda * A / 3 * (t * at - m1) - 1;
    }

    void check_lambda(const char *function, const double lambda)
    {
      check::positive(function, "lambda", lambda);
      if (lambda < 1e-3 || lambda > 1e3)
        check::fail(function, "lambda", lambda, "is outside [1e-3, 1e3]");
    }
  } // namespace

  double tabor_parameter(const double sigma0, const double dgamma, const double R, const double E_star)
  {
    check::positive("maugis_dugdale::tabor_parameter", "sigma0", sigma0);
    check::positive("maugis_dugdale::tabor_parameter", "dgamma", dgamma);
    check::positive("maugis_dugdale::tabor_parameter", "R", R);
    check::positive("maugis_dugdale::tabor_parameter", "E_star", E_star);
    return sigma0 * std::cbrt(9 * R / (2 * pi * dgamma * E_star * E_star));
  }

  Scales scales(const double dgamma, const double R, const double E_star)
  {
    const double K = 4 * E_star / 3;
    return {std::cbrt(pi * dgamma * R * R / K), pi * dgamma * R, std::cbrt(pi * pi * dgamma * dgamma * R / (K * K))};
  }

  State state(const double lambda, const double A)
  {
    check::positive("maugis_dugdale::state", "lambda", lambda);
    check::positive("maugis_dugdale::state", "A", A);
    // The closing function grows with t from -1 at t = 0.
    double hi = 1;
    while (closing(lambda, A, hi) < 0)
      {
        hi *= 2;
        if (hi > 1e150)
          check::fail("maugis_dugdale::state", "A", A, "gives no closing cohesive zone");
      }
    std::uintmax_t iterations = 200;
    const auto     bracket    = boost::math::tools::toms748_solve(
      [&](const double t) { return closing(lambda, A, t); }, 0.0, hi, -1.0, closing(lambda, A, hi),
      boost::math::tools::eps_tolerance<double>(52), iterations);
    const double t = (bracket.first + bracket.second) / 2;
    State        s;
    s.A     = A;
    s.m     = std::sqrt(1 + t * t);
    s.zone  = A * s.m;
    s.P     = A * A * A - lambda * A * A * (t + (1 + t * t) * std::atan(t));
    s.Delta = A * A - 4 * lambda * A * t / 3;
    return s;
  }

  State vanishing_contact(const double lambda)
  {
    check::positive("maugis_dugdale::vanishing_contact", "lambda", lambda);
    // lambda pi C^2 / 4 + 4 lambda^2 (pi/2 - 1) C / 3 = 1, the positive root.
    const double a2 = lambda * pi / 4, a1 = 4 * lambda * lambda * (pi / 2 - 1) / 3;
    const double C  = 2 / (a1 + std::sqrt(a1 * a1 + 4 * a2)); // = (-a1 + sqrt(a1^2 + 4 a2)) / (2 a2)
    State        s;
    s.A     = 0;
    s.m     = std::numeric_limits<double>::infinity();
    s.zone  = C;
    s.P     = -lambda * pi * C * C / 2;
    s.Delta = -4 * lambda * C / 3; // A^2 - 4 lambda A t / 3 with A t -> C
    return s;
  }

  PullOff pull_off(const double lambda, const Control control)
  {
    check_lambda("maugis_dugdale::pull_off", lambda);
    const auto value = [&](const double lnA) {
      const State s = state(lambda, std::exp(lnA));
      return control == Control::force ? s.P : s.Delta;
    };
    // A scan in ln A, then Brent around the smallest sample.
    const double lo = std::log(1e-6), hi = std::log(1e2);
    const int    n  = 400;
    int          best = 0;
    double       best_value = std::numeric_limits<double>::max();
    for (int i = 0; i <= n; ++i)
      {
        const double v = value(lo + (hi - lo) * i / n);
        if (v < best_value)
          best_value = v, best = i;
      }
    PullOff p;
    const State end = vanishing_contact(lambda);
    if (best == 0)
      {
        // The minimum is the A -> 0 end (force control) or there is none inside (displacement control).
        p.state                = end;
        p.at_vanishing_contact = true;
        p.exists               = control == Control::force;
        return p;
      }
    if (best == n)
      check::fail("maugis_dugdale::pull_off", "lambda", lambda, "has no pull-off with A <= 100");
    const double   step       = (hi - lo) / n;
    std::uintmax_t iterations = 200;
    const auto     minimum    = boost::math::tools::brent_find_minima(value, lo + step * (best - 1), lo + step * (best + 1),
                                                                      40, iterations);
    p.state = state(lambda, std::exp(minimum.first));
    if (control == Control::force && end.P < p.state.P)
      {
        p.state                = end;
        p.at_vanishing_contact = true;
      }
    return p;
  }
} // namespace gradcontact::maugis_dugdale
