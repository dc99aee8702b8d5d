#include <analytic/errors.h>
#include <analytic/special_functions.h>

#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace gradcontact
{
  namespace detail
  {
    constexpr double eps = std::numeric_limits<double>::epsilon();
    constexpr int max_terms = 2000;

    bool is_nonpositive_integer(const double x) { return x <= 0 && x == std::floor(x); }

    // Region predicates of hyp2f1. The Taylor series at 0 converges at least like 2^-j for z <= 1/2.
    bool taylor_region(const double z) { return z <= 0.5; }
    // The connection formula z -> 1 - z has Gamma(c-a-b) and Gamma(a+b-c) terms whose poles cancel
    // when c - a - b is an integer: within this distance of an integer the two terms lose more than
    // about log10(1/distance) digits to cancellation, so Euler's integral is used instead.
    constexpr double degenerate_width = 0.05;
    bool near_integer(const double s) { return std::abs(s - std::round(s)) < degenerate_width; }
    // Region predicate of hyp2f1_minus_one above z = 1/2: the difference F - 1 of a correctly rounded F
    // loses eps |F| / |F - 1| relative, at most one bit where |F - 1| >= |F|/2. Below that (a b -> 0, e.g.
    // k -> -1 in 9.73, where F - 1 = O(a b)) the connection formula's own rounding is amplified too: the
    // difference loses digits near k = -0.9 (the family of 9.73), the Taylor steps of the equation for F - 1
    // keep them (tests/data/special_functions.csv, rows hyp2f1_minus_one, hold both to their tolerance).
    bool difference_keeps_digits(const double F) { return std::abs(F - 1.) >= 0.5 * std::abs(F); }

    double hyp2f1_taylor(const double a, const double b, const double c, const double z)
    {
      double term = 1., sum = 1.;
      for (int j = 0; j < max_terms; ++j)
        {
          term *= (a + j) * (b + j) / ((c + j) * (j + 1.)) * z;
          sum += term;
          if (std::abs(term) <= eps * std::abs(sum) * 0.5)
            return sum;
        }
      throw std::runtime_error("hyp2f1: Taylor series did not converge (internal error)");
    }

    // Analytic continuation along (1/2, z] by Taylor steps of the hypergeometric equation
    // z (1-z) F'' + [c - (a+b+1) z] F' - a b F = 0. At z0 the local series converges for
    // |t| < 1 - z0, so each step covers half the remaining distance to the singular point 1 and the
    // terms fall like 2^-n. Used where the connection formula is degenerate (c - a - b near an
    // integer): no Gamma function of the parameters is involved, so nothing cancels.
    //
    // With minus_one, the same for u = F - 1, which solves the equation with the source a b on the right
    // (z (1-z) u'' + [c - (a+b+1) z] u' - a b u = a b): where F - 1 is small (a b -> 0) every term of u
    // keeps its relative accuracy, while F - 1 formed at the end would lose eps |F|/|F - 1| (used wherever that
    // loss exceeds one bit, not only where the connection formula is degenerate).
    double hyp2f1_taylor_minus_one(double a, double b, double c, double z);

    /// F and F' at z0 = 1 - gap.
    struct OdePoint
    {
      double F, dF;
    };

    /// One Taylor step of the hypergeometric equation from z0 = 1 - gap to z0 + t, t <= gap/2.
    OdePoint hyp2f1_ode_step(const double a, const double b, const double c, const double source, const double gap,
                             const OdePoint start, const double t)
    {
      const double s1 = a + b + 1., ab = a * b;
      const double z0 = 1. - gap;
      const double q = z0 * gap, p0 = c - s1 * z0, p1 = 2. * gap - 1.;
      // v_n = u_n t^n with u_n the Taylor coefficients of F at z0, F(z0 + t) = sum v_n. Scaling
      // by t^n keeps the terms O(2^-n) although u_n grows like (1 - z0)^-n near z = 1.
      double v0 = start.F, v1 = start.dF * t;
      double value = v0 + v1, slope_t = v1; // slope_t = t F'(z0 + t) = sum n v_n
      for (int n = 0; n < max_terms; ++n)
        {
          const double v2 = -((p1 * n + p0) * (n + 1.) * v1 * t - (n * (n - 1.) + s1 * n + ab) * v0 * t * t -
                              (n == 0 ? source * t * t : 0.)) /
                            (q * (n + 2.) * (n + 1.));
          value += v2;
          slope_t += (n + 2.) * v2;
          v0 = v1;
          v1 = v2;
          if (std::abs(v2) * (n + 2.) <= eps * 0.25 * (std::abs(value) + std::abs(slope_t)) && n > 2)
            break;
        }
      return {value, slope_t / t};
    }

    /// The states of the stepping at the gaps 1 - z0 = 2^-1, 2^-2, ... for one (a, b, c): they depend on the
    /// parameters only, not on the z asked for, so that the repeated calls of one request (a prepared
    /// request, a root search, a profile sampled along r) take only the last step. Kept per thread for the
    /// last parameters, one table for F and one for F - 1.
    struct OdePath
    {
      double a = std::nan(""), b = std::nan(""), c = std::nan("");
      std::vector<OdePoint> points; // points[i] at the gap 2^-(i+1)
    };

    double hyp2f1_ode(const double a, const double b, const double c, const double w, const bool minus_one = false)
    {
      thread_local OdePath paths[2];
      OdePath &path = paths[minus_one ? 1 : 0];
      if (!(path.a == a && path.b == b && path.c == c))
        {
          path.a = a;
          path.b = b;
          path.c = c;
          path.points.assign(
            1, {minus_one ? hyp2f1_taylor_minus_one(a, b, c, 0.5) : hyp2f1_taylor(a, b, c, 0.5),
                a * b / c * hyp2f1_taylor(a + 1., b + 1., c + 1., 0.5)});
        }
      const double source = minus_one ? a * b : 0.;
      // The state is kept as gap = 1 - z0, which halves exactly at every step but the last, so that
      // the distance to the singular point is never formed by cancellation.
      std::size_t i = 0;
      double gap = 0.5;
      while (w < 0.5 * gap)
        {
          if (i + 1 == path.points.size())
            path.points.push_back(hyp2f1_ode_step(a, b, c, source, gap, path.points[i], 0.5 * gap));
          ++i;
          gap *= 0.5;
        }
      if (!(gap > w))
        return path.points[i].F;
      return hyp2f1_ode_step(a, b, c, source, gap, path.points[i], gap - w).F;
    }

    double hyp2f1_connection(const double a, const double b, const double c, const double w)
    {
      const double s = c - a - b;
      using boost::math::tgamma;
      const double gc = tgamma(c);
      double result = 0.;
      const double A1 = gc * tgamma(s) * rgamma(c - a) * rgamma(c - b);
      if (A1 != 0.)
        result += A1 * hyp2f1_taylor(a, b, 1. - s, w);
      if (w > 0)
        {
          const double A2 = gc * tgamma(-s) * rgamma(a) * rgamma(b);
          if (A2 != 0.)
            result += A2 * std::pow(w, s) * hyp2f1_taylor(c - a, c - b, 1. + s, w);
        }
      return result;
    }

    // int_(1-w)^1 t^(x-1) (1-t)^(y-1) dt for w = 1 - z <= 1/2, any x:
    // = w^y sum_j (1-x)_j / j! w^j / (y + j), converging like 2^-j.
    double beta_upper_near_one(const double w, const double x, const double y)
    {
      double coefficient = 1., power = 1., sum = 1. / y;
      for (int j = 1; j < max_terms; ++j)
        {
          coefficient *= (j - x) / j; // (1-x)_j / j!
          power *= w;
          const double term = coefficient * power / (y + j);
          sum += term;
          if (std::abs(term) <= eps * std::abs(sum) * 0.5 && j > 1)
            return std::pow(w, y) * sum;
        }
      throw std::runtime_error("beta_upper: series did not converge (internal error)");
    }

    // 2F1(a, b; c; z) - 1: the Taylor series without its first term, for z <= 1/2.
    double hyp2f1_taylor_minus_one(const double a, const double b, const double c, const double z)
    {
      double term = 1., sum = 0.;
      for (int j = 0; j < max_terms; ++j)
        {
          term *= (a + j) * (b + j) / ((c + j) * (j + 1.)) * z;
          sum += term;
          if (std::abs(term) <= eps * std::abs(sum) * 0.5)
            return sum;
        }
      throw std::runtime_error("hyp2f1_minus_one: series did not converge (internal error)");
    }

    // int_z^h t^(m-1) dt = (h^m - z^m) / m for 0 < z < h, finite at m = 0 (= log(h/z)).
    double power_integral(const double z, const double h, const double m, const double L)
    {
      // L = log(h/z) > 0. For |m L| < 1 use z^m L expm1(m L)/(m L): no 0/0 and no cancellation.
      const double mL = m * L;
      if (std::abs(mL) < 1.)
        return std::pow(z, m) * (mL == 0. ? L : L * std::expm1(mL) / mL);
      return (std::pow(h, m) - std::pow(z, m)) / m;
    }
  } // namespace detail

  namespace detail
  {
    /// The domain of 2F1 (hyp2f1, hyp2f1_minus_one), named after `fn`.
    void check_hyp2f1(const char *fn, const double a, const double b, const double c, const double z,
                      const double one_minus_z)
    {
      check::finite(fn, "a", a);
      check::finite(fn, "b", b);
      check::finite(fn, "c", c);
      check::closed_interval(fn, "z", z, 0., 1.);
      if (is_nonpositive_integer(c))
        check::fail(fn, "c", c, "must not be 0, -1, -2, ... (2F1 is undefined)");
      const double s = c - a - b;
      const double w = one_minus_z >= 0. ? one_minus_z : 1. - z;
      if (z > 0.5 && w == 0. && !(s > 0.))
        check::fail(fn, "c - a - b", s, "must be > 0 at z = 1 (Gauss's sum diverges otherwise)");
    }
  } // namespace detail

  double rgamma(const double x)
  {
    if (detail::is_nonpositive_integer(x))
      return 0.;
    return 1. / boost::math::tgamma(x);
  }

  double hyp2f1(const double a, const double b, const double c, const double z, const double one_minus_z)
  {
    detail::check_hyp2f1("hyp2f1", a, b, c, z, one_minus_z);
    if (z == 0.)
      return 1.;
    if (detail::taylor_region(z))
      return detail::hyp2f1_taylor(a, b, c, z);
    const double s = c - a - b;
    const double w = one_minus_z >= 0. ? one_minus_z : 1. - z;
    if (!detail::near_integer(s))
      return detail::hyp2f1_connection(a, b, c, w);
    if (w == 0.)
      {
        // Gauss's sum, exact at z = 1 for c - a - b > 0.
        using boost::math::tgamma;
        return tgamma(c) * tgamma(s) * rgamma(c - a) * rgamma(c - b);
      }
    return detail::hyp2f1_ode(a, b, c, w);
  }

  double hyp2f1_minus_one(const double a, const double b, const double c, const double z, const double one_minus_z)
  {
    const char *fn = "hyp2f1_minus_one";
    detail::check_hyp2f1(fn, a, b, c, z, one_minus_z);
    if (z == 0.)
      return 0.;
    if (detail::taylor_region(z))
      return detail::hyp2f1_taylor_minus_one(a, b, c, z);
    const double s = c - a - b;
    if (!detail::near_integer(s))
      {
        const double F = hyp2f1(a, b, c, z, one_minus_z);
        if (detail::difference_keeps_digits(F))
          return F - 1.;
      }
    // F - 1 directly: the Taylor steps of its inhomogeneous equation (no difference formed)
    const double w = one_minus_z >= 0. ? one_minus_z : 1. - z;
    if (w > 0.)
      return detail::hyp2f1_ode(a, b, c, w, true);
    // Gauss's sum minus 1 as expm1 of its log-gamma sum where the arguments are positive: near a b = 0 the
    // log-gammas are near their zeros at 1 and 2, where they are accurate relative to themselves.
    if (c > 0. && s > 0. && c - a > 0. && c - b > 0.)
      {
        using boost::math::lgamma;
        return std::expm1(lgamma(c) + lgamma(s) - lgamma(c - a) - lgamma(c - b));
      }
    return hyp2f1(a, b, c, z, one_minus_z) - 1.;
  }

  double beta_upper(const double z, const double x, const double y, const double one_minus_z)
  {
    const char *fn = "beta_upper";
    check::finite(fn, "x", x);
    check::positive(fn, "y", y);
    check::closed_interval(fn, "z", z, 0., 1.);
    if (z == 0.)
      {
        if (!(x > 0.))
          check::fail(fn, "z", z, "must be > 0 when x <= 0 (the integral diverges at t = 0)");
        return boost::math::beta(x, y);
      }
    // The distance to 1 as the caller formed it: z itself may have rounded to 1 although 1 - z > 0.
    const double w = one_minus_z >= 0. ? one_minus_z : 1. - z;
    if (w == 0.)
      return 0.;
    if (z >= 0.5)
      return detail::beta_upper_near_one(w, x, y);
    // int_z^(1/2) t^(x-1) (1-t)^(y-1) dt = sum_j (1-y)_j / j! int_z^(1/2) t^(x+j-1) dt, then the
    // piece from 1/2 to 1. For 0 < y <= 1 all terms are positive (no cancellation).
    // The powers h^m and z^m of the power integrals (h^m - z^m)/m, m = x + j, are carried from term to term;
    // the form without 0/0 (power_integral) only where m is within 1 of 0 (x <= 0) and m L is small: there
    // the difference would cancel to nothing. Elsewhere it loses at most eps h^m/|m| absolutely, small
    // against the piece from 1/2 to 1.
    const double h = 0.5;
    const double L = std::log(h / z);
    double coefficient = 1.;
    double h_power = std::pow(h, x), z_power = std::pow(z, x);
    const auto power_integral = [&](const double m) {
      const double mL = m * L;
      if (std::abs(m) < 1. && std::abs(mL) < 1.)
        return z_power * (mL == 0. ? L : L * std::expm1(mL) / mL);
      return (h_power - z_power) / m;
    };
    double sum = power_integral(x);
    for (int j = 1; j < detail::max_terms; ++j)
      {
        coefficient *= (j - y) / j;
        h_power *= h;
        z_power *= z;
        const double term = coefficient * power_integral(x + j);
        sum += term;
        if (x + j > 0 && std::abs(term) <= detail::eps * std::abs(sum) * 0.5)
          return sum + detail::beta_upper_near_one(1. - h, x, y);
      }
    throw std::runtime_error("beta_upper: series did not converge (internal error)");
  }

  double incomplete_beta(const double z, const double x, const double y, const double one_minus_z)
  {
    const char *fn = "incomplete_beta";
    check::finite(fn, "x", x);
    check::positive(fn, "y", y);
    check::closed_interval(fn, "z", z, 0., 1.);
    if (detail::is_nonpositive_integer(x))
      check::fail(fn, "x", x, "must not be 0, -1, -2, ... (B(z; x, y) has a pole; use beta_upper)");
    if (z == 0.)
      {
        if (!(x > 0.))
          check::fail(fn, "z", z, "must be > 0 when x < 0 (B(z; x, y) diverges at z = 0)");
        return 0.;
      }
    // Two series, each converging like 2^-j, in double: Boost's incomplete beta in double loses up to
    // 1e-13 near z = 1 (where 1 - z is rounded) and B(x, y) - B(1 - z; y, x) cancels log10(1/y) digits as
    // y -> 0; in long double it is several times slower.
    // Below 1/2: 9.21 written as sum_j (1-y)_j / j! t^(x+j) / (x+j) at t = min(z, 1/2), positive terms for
    // y <= 1.
    const double t = std::min(z, 0.5);
    double coefficient = 1., power = std::pow(t, x);
    double lower = power / x;
    for (int j = 1;; ++j)
      {
        if (j == detail::max_terms)
          throw std::runtime_error("incomplete_beta: series did not converge (internal error)");
        coefficient *= (j - y) / j;
        power *= t;
        const double term = coefficient * power / (x + j);
        lower += term;
        if (x + j > 0 && std::abs(term) <= detail::eps * std::abs(lower) * 0.5)
          break;
      }
    if (z <= 0.5)
      return lower;
    // int_(1/2)^z t^(x-1) (1-t)^(y-1) dt = sum_j (1-x)_j / j! int_w^(1/2) s^(y+j-1) ds, w = 1 - z (as the
    // caller formed it), each power integral (h^m - w^m)/m with the powers carried from term to term; only
    // the first (m = y, which may be tiny) needs the form without 0/0 (power_integral). All terms are
    // positive for x < 1. (B(x, y) - beta_upper(z, x, y) would cancel ~log10(1/y) digits here.)
    const double w = one_minus_z >= 0. ? one_minus_z : 1. - z, h = 0.5, L = std::log(h / w);
    double upper = detail::power_integral(w, h, y, L);
    double h_power = std::pow(h, y), w_power = std::pow(w, y);
    coefficient = 1.;
    for (int j = 1; j < detail::max_terms; ++j)
      {
        coefficient *= (j - x) / j;
        h_power *= h;
        w_power *= w;
        const double term = coefficient * (h_power - w_power) / (y + j);
        upper += term;
        if (std::abs(term) <= detail::eps * (std::abs(lower) + std::abs(upper)) * 0.5)
          return lower + upper;
      }
    throw std::runtime_error("incomplete_beta: series did not converge (internal error)");
  }
} // namespace gradcontact
