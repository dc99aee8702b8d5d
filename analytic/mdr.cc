#include <analytic/detail/quadrature.h>
#include <analytic/errors.h>
#include <analytic/mdr.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/cos_pi.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace gradcontact::mdr
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    // int_0^1 u^alpha (1-u)^beta h(u, 1-u) du for alpha, beta > -1. Split at 1/2; on the left
    // u = v^(1/(alpha+1)) / 2 turns u^alpha du into a constant times dv, on the right the same with
    // 1 - u. h gets both u and 1 - u without cancellation.
    template <class H>
    double beta_weight_integral(const H &h, const double alpha, const double beta)
    {
      const double p = 1. / (alpha + 1.), q = 1. / (beta + 1.);
      // u and 1 - u are kept above the smallest normal double: with p = 2/(1+k) -> 200 as k -> -1,
      // v^p underflows on a visible part of (0, 1), where h(u) ~ h(0) must still be counted.
      constexpr double tiny = std::numeric_limits<double>::min();
      const auto left = [&](const double v, const double, const double) {
        const double u = std::max(0.5 * std::pow(v, p), tiny);
        const double one_minus_u = 1. - u;
        return std::pow(one_minus_u, beta) * h(u, one_minus_u);
      };
      const auto right = [&](const double v, const double, const double) {
        const double one_minus_u = std::max(0.5 * std::pow(v, q), tiny);
        const double u = 1. - one_minus_u;
        return std::pow(u, alpha) * h(u, one_minus_u);
      };
      return std::pow(0.5, alpha + 1.) / (alpha + 1.) * detail::integrate_with_distances(left, 0., 1.) +
             std::pow(0.5, beta + 1.) / (beta + 1.) * detail::integrate_with_distances(right, 0., 1.);
    }

    // f'(s) (+ s f''(s)) at an abscissa s = x sqrt(u). The substitution of beta_weight_integral puts
    // nodes at u down to the smallest double; there s may underflow to 0, or f' and f'' of a sharp tip
    // (A r^n, n < 1) may overflow. Such nodes carry weights below 1e-150 of the integral (the inner
    // weight is u^(-1/2), substituted with u = v^2/2), so they are dropped rather than allowed to
    // turn the sum into inf or NaN.
    double profile_term(const double value) { return std::isfinite(value) ? value : 0.; }

    void check_k(const char *fn, const double k) { check::open_interval(fn, "k", k, -1., 1.); }

    double delta_ell(const Medium &m, const double dgamma, const double a)
    {
      return std::sqrt(2. * pi * dgamma * std::pow(m.c0, m.k) * std::pow(a, 1. - m.k) / m.cN0); // 9.45
    }
  } // namespace

  Profile power_law(const double n, const double A)
  {
    check::positive("mdr::power_law", "n", n);
    check::finite("mdr::power_law", "A", A);
    return {[=](const double r) { return A * std::pow(r, n); },
            [=](const double r) { return n * A * std::pow(r, n - 1.); },
            // n = 1: exactly 0 (not 0 * r^-1, which is NaN at r = 0)
            [=](const double r) { return n == 1. ? 0. : n * (n - 1.) * A * std::pow(r, n - 2.); }};
  }

  double equivalent_profile(const Profile &profile, const double k, const double x)
  {
    const char *fn = "mdr equivalent_profile";
    check_k(fn, k);
    check::non_negative(fn, "x", x);
    if (!profile.df)
      throw DomainError(std::string(fn) + ": the profile has no derivative f'");
    if (x == 0.)
      return 0.;
    // g(x) = x/2 int_0^1 f'(x sqrt(u)) u^(-1/2) (1-u)^((k-1)/2) du   (9.2 with r = x sqrt(u))
    const auto h = [&](const double u, const double) {
      const double s = x * std::sqrt(u);
      return s > 0. ? profile_term(profile.df(s)) : 0.;
    };
    return x / 2. * beta_weight_integral(h, -0.5, (k - 1.) / 2.);
  }

  double equivalent_profile_slope(const Profile &profile, const double k, const double x)
  {
    const char *fn = "mdr equivalent_profile_slope";
    check_k(fn, k);
    check::non_negative(fn, "x", x);
    if (!profile.df || !profile.d2f)
      throw DomainError(std::string(fn) + ": the profile needs f' and f'' for the pressure");
    // g'(x) = 1/2 int_0^1 [f'(s) + s f''(s)]_(s = x sqrt(u)) u^(-1/2) (1-u)^((k-1)/2) du
    const auto h = [&](const double u, const double) {
      const double s = x * std::sqrt(u);
      return s > 0. ? profile_term(profile.df(s) + s * profile.d2f(s)) : 0.;
    };
    return 0.5 * beta_weight_integral(h, -0.5, (k - 1.) / 2.);
  }

  Foundation indentation(const Profile &profile, const Medium &m, const double a, const double dgamma)
  {
    const char *fn = "mdr indentation";
    validate(fn, m);
    check::positive(fn, "a", a);
    check::non_negative(fn, "dgamma", dgamma);
    const double jump = dgamma > 0. ? delta_ell(m, dgamma, a) : 0.;
    Foundation w1d = indentation_to_depth(profile, m.k, a, equivalent_profile(profile, m.k, a) - jump);
    w1d.edge_value = -jump; // w1D(a) = -Delta_l(a) (9.46), exactly 0 without adhesion
    return w1d;
  }

  Foundation indentation_to_depth(const Profile &profile, const double k, const double a, const double d)
  {
    const char *fn = "mdr indentation_to_depth";
    check_k(fn, k);
    check::positive(fn, "a", a);
    check::finite(fn, "d", d);
    Foundation w1d;
    w1d.a = a;
    w1d.d = d;
    w1d.profile_slope = profile.df;
    w1d.w = [profile, k, d](const double x) { return d - equivalent_profile(profile, k, x); };
    if (profile.d2f)
      w1d.dw = [profile, k](const double x) { return -equivalent_profile_slope(profile, k, x); };
    return w1d;
  }

  Foundation flat(const double a, const double d)
  {
    check::positive("mdr flat", "a", a);
    check::finite("mdr flat", "d", d);
    Foundation w1d;
    w1d.w = [d](double) { return d; };
    w1d.dw = [](double) { return 0.; };
    w1d.a = a;
    return w1d;
  }

  Foundation from_pressure(const std::function<double(double)> &p, const Medium &m, const double a)
  {
    const char *fn = "mdr from_pressure";
    validate(fn, m);
    check::positive(fn, "a", a);
    const double k = m.k;
    const double factor = std::pow(m.c0, k) * boost::math::cos_pi(k / 2.) / m.cN0;
    Foundation w1d;
    w1d.a = a;
    // 9.13 with r^2 = x^2 + (a^2 - x^2) u:
    // w1D(x) = c0^k cos(k pi/2)/cN0 (a^2 - x^2)^((1-k)/2) int_0^1 u^(-(1+k)/2) p(r(u)) du
    w1d.edge_exponent = (1. - k) / 2.;
    w1d.edge_free = [p, k, a, factor](const double x) {
      const double D = (a - x) * (a + x);
      const auto h = [&](const double u, const double) { return p(std::sqrt(x * x + std::max(D, 0.) * u)); };
      return factor * beta_weight_integral(h, -(1. + k) / 2., 0.);
    };
    const auto phi = w1d.edge_free;
    const double e = w1d.edge_exponent;
    w1d.w = [phi, a, e](const double x) {
      const double D = (a - x) * (a + x);
      return D > 0. ? std::pow(D, e) * phi(x) : 0.;
    };
    return w1d;
  }

  double depth(const Foundation &w1d) { return w1d.w(0.); }

  double force(const Foundation &w1d, const Medium &m)
  {
    if (!w1d.profile_slope)
      return force_nested(w1d, m);
    validate("mdr force", m);
    const double k = m.k, a = w1d.a;
    // F = 2 cN0/c0^k [d a^(k+1)/(k+1) - int_0^a x^k g(x) dx] with
    // int_0^a x^k g(x) dx = 1/(k+1) int_0^a f'(r) (a^2-r^2)^((k+1)/2) dr
    //                     = a^(k+2)/(2(k+1)) int_0^1 u^(-1/2) (1-u)^((k+1)/2) f'(a sqrt(u)) du
    const auto h = [&](const double u, const double) { return w1d.profile_slope(a * std::sqrt(u)); };
    const double shape = std::pow(a, k + 2.) / (2. * (k + 1.)) * beta_weight_integral(h, -0.5, (k + 1.) / 2.);
    return 2. * m.cN0 / std::pow(m.c0, k) * (w1d.d * std::pow(a, k + 1.) / (k + 1.) - shape);
  }

  double force_nested(const Foundation &w1d, const Medium &m)
  {
    validate("mdr force", m);
    const double k = m.k, a = w1d.a;
    // 9.11 with x = a sqrt(u): F = cN0 a^(k+1)/c0^k int_0^1 u^((k-1)/2) w1D(a sqrt(u)) du
    const double prefactor = m.cN0 * std::pow(a, k + 1.) / std::pow(m.c0, k);
    if (w1d.edge_exponent != 0.)
      {
        // w1D = (a^2 (1-u))^e phi: the factor (1-u)^e joins the weight
        const double e = w1d.edge_exponent;
        const auto h = [&](const double u, const double) { return w1d.edge_free(a * std::sqrt(u)); };
        return prefactor * std::pow(a, 2. * e) * beta_weight_integral(h, (k - 1.) / 2., e);
      }
    const auto h = [&](const double u, const double) { return w1d.w(a * std::sqrt(u)); };
    return prefactor * beta_weight_integral(h, (k - 1.) / 2., 0.);
  }

  double pressure(const Foundation &w1d, const Medium &m, const double r)
  {
    const char *fn = "mdr pressure";
    validate(fn, m);
    check::non_negative(fn, "r", r);
    const double k = m.k, a = w1d.a;
    if (r > a)
      return 0.;
    const double w_edge = std::isnan(w1d.edge_value) ? w1d.w(a) : w1d.edge_value;
    if (r == a)
      {
        if (w_edge != 0.)
          check::fail(fn, "r", r, "equals a where w1D(a) != 0: the pressure is unbounded there");
        return 0.;
      }
    if (!w1d.dw)
      throw DomainError(std::string(fn) + ": the foundation has no slope w1D' (the profile needs f'')");
    const double D = (a - r) * (a + r);
    // -int_r^a w1D'(x) (x^2-r^2)^((k-1)/2) dx with x^2 = r^2 + D u:
    //   = -D^((k+1)/2)/2 int_0^1 u^((k-1)/2) w1D'(x)/x du
    // x is kept above sqrt(D) 1e-150: at r = 0 with u near the smallest double, D u underflows and
    // w1D'(x)/x would be 0/0 (w1D' is odd, the ratio tends to w1D''(0)).
    const double x_min = std::sqrt(D) * 1e-150;
    const auto h = [&](const double u, const double) {
      const double x = std::max(std::sqrt(r * r + D * u), x_min);
      return w1d.dw(x) / x;
    };
    const double smooth = -std::pow(D, (k + 1.) / 2.) / 2. * beta_weight_integral(h, (k - 1.) / 2., 0.);
    const double edge = w_edge * std::pow(D, (k - 1.) / 2.); // the jump of w1D at x = a
    return m.cN0 / (pi * std::pow(m.c0, k)) * (smooth + edge);
  }

  double displacement(const Foundation &w1d, const Medium &m, const double r)
  {
    const char *fn = "mdr displacement";
    validate(fn, m);
    check::non_negative(fn, "r", r);
    const double k = m.k, a = w1d.a;
    const double c = boost::math::cos_pi(k / 2.) / pi;
    if (r == 0.)
      return w1d.w(0.);
    const double e = w1d.edge_exponent;
    if (r == a && e != 0.)
      {
        // w1D(a sqrt(u)) = (a^2 (1-u))^e phi: the factor joins the weight (1-u)^(-(1+k)/2)
        const auto h = [&](const double u, const double) { return w1d.edge_free(a * std::sqrt(u)); };
        return c * std::pow(a, 2. * e) * beta_weight_integral(h, (k - 1.) / 2., e - (1. + k) / 2.);
      }
    if (r <= a)
      {
        // x = r sqrt(u): w = cos(k pi/2)/pi int_0^1 u^((k-1)/2) (1-u)^(-(1+k)/2) w1D(r sqrt(u)) du
        const auto h = [&](const double u, const double) { return w1d.w(r * std::sqrt(u)); };
        return c * beta_weight_integral(h, (k - 1.) / 2., -(1. + k) / 2.);
      }
    // x = a sqrt(u), r^2 - x^2 = (r^2 - a^2) + a^2 (1 - u)
    const double D = (r - a) * (r + a);
    if (e != 0.)
      {
        const auto h = [&](const double u, const double one_minus_u) {
          return w1d.edge_free(a * std::sqrt(u)) * std::pow(D + a * a * one_minus_u, -(1. + k) / 2.);
        };
        return c * std::pow(a, k + 1. + 2. * e) * beta_weight_integral(h, (k - 1.) / 2., e);
      }
    const auto h = [&](const double u, const double one_minus_u) {
      return w1d.w(a * std::sqrt(u)) * std::pow(D + a * a * one_minus_u, -(1. + k) / 2.);
    };
    return c * std::pow(a, k + 1.) * beta_weight_integral(h, (k - 1.) / 2., 0.);
  }

  CriticalState critical_state(const Profile &profile, const Medium &m, const double dgamma,
                               const Control control, double a_lo, double a_hi, const unsigned int bracket_shifts)
  {
    const char *fn = "mdr critical_state";
    validate(fn, m);
    check::positive(fn, "dgamma (work of adhesion)", dgamma);
    check::positive(fn, "a_lo", a_lo);
    check::positive(fn, "a_hi", a_hi);
    if (!(a_hi > a_lo))
      check::fail(fn, "a_hi", a_hi, "must exceed a_lo = " + check::format(a_lo));
    const auto depth_of = [&](const double a) {
      return equivalent_profile(profile, m.k, a) - delta_ell(m, dgamma, a);
    };
    const auto force_of = [&](const double a) { return force(indentation(profile, m, a, dgamma), m); };
    const auto objective = [&](const double a) {
      return control == Control::force ? force_of(a) : depth_of(a);
    };

    // 1. A log-spaced scan brackets the global minimum; a minimum on an end moves the bracket toward it
    //    (bracket_shifts times at most).
    constexpr int n_scan = 49;
    double ratio = 0;
    int best = 0;
    for (unsigned int shift = 0;; ++shift)
      {
        ratio = std::log(a_hi / a_lo) / (n_scan - 1);
        std::vector<double> values(n_scan);
        best = 0;
        for (int i = 0; i < n_scan; ++i)
          {
            values[i] = objective(a_lo * std::exp(ratio * i));
            if (values[i] < values[best])
              best = i;
          }
        if ((best != 0 && best != n_scan - 1) || shift == bracket_shifts)
          break;
        if (best == 0)
          {
            a_hi = a_lo * 10.;
            a_lo *= 1e-9;
          }
        else
          {
            a_lo = a_hi / 10.;
            a_hi *= 1e9;
          }
      }
    if (best == 0 || best == n_scan - 1)
      throw DomainError(std::string(fn) + ": no critical state in a in [" + check::format(a_lo) + ", " +
                        check::format(a_hi) + "]: the minimum of " +
                        (control == Control::force ? "F_N(a)" : "d(a)") + " lies on the " +
                        (best == 0 ? "lower" : "upper") + " end of the bracket");

    // 2. Brent's method in log a.
    const auto in_log = [&](const double s) { return objective(a_lo * std::exp(s)); };
    std::uintmax_t iterations = 200;
    const auto brent = boost::math::tools::brent_find_minima(in_log, ratio * (best - 1), ratio * (best + 1),
                                                             40, iterations);
    double ac = a_lo * std::exp(brent.first);

    // 3. A minimum is located only to sqrt(eps) by its value; the root of the derivative (fourth-order
    //    central differences of the quadrature values) is located to about 1e-11.
    const auto slope = [&](const double a) {
      const double h = 1e-3 * a;
      return (8. * (objective(a + h) - objective(a - h)) - (objective(a + 2. * h) - objective(a - 2. * h))) /
             (12. * h);
    };
    const double lo = ac * (1. - 1e-5), hi = ac * (1. + 1e-5);
    const double s_lo = slope(lo), s_hi = slope(hi);
    if (s_lo < 0. && s_hi > 0.)
      {
        std::uintmax_t max_iter = 60;
        const auto root = boost::math::tools::toms748_solve(
          slope, lo, hi, s_lo, s_hi, boost::math::tools::eps_tolerance<double>(45), max_iter);
        ac = 0.5 * (root.first + root.second);
      }
    return {ac, depth_of(ac), force_of(ac)};
  }

  CriticalState critical_state(const Profile &profile, const Medium &m, const double dgamma, const Control control)
  {
    return critical_state(profile, m, dgamma, control, m.c0 * 1e-9, m.c0 * 1e9, 4);
  }
} // namespace gradcontact::mdr
