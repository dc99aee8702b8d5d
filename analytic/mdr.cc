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
#include <optional>
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

    /// The tip exponent the quadratures of 9.2 assume: the profile's, or 1 (f' analytic) when unknown.
    double tip_of(const double tip_exponent) { return std::isnan(tip_exponent) ? 1. : tip_exponent; }

    /// int_0^1 v^(n-1) (1-v)^b (1+v)^b q(x v) (x v)^(1-n) dv, b = (k-1)/2, by Gauss-Jacobi: 9.2 with r = x v
    /// divided by x^n, G(x) = g(x)/x^n for q = f' and G1(x) = g'(x)/x^(n-1) for q = f' + r f''. For
    /// f'(r) = r^(n-1) phi(r) the integrand (1+v)^b phi(x v) is analytic on [0, 1].
    template <class Q>
    detail::JacobiQuadrature tip_free_integral(const Q &q, const double n, const double k, const double x)
    {
      const double b = (k - 1.) / 2.;
      const auto h = [&](const double v, double) {
        const double s = x * v;
        return std::pow(1. + v, b) * (n == 1. ? q(s) : q(s) * std::pow(s, 1. - n));
      };
      return detail::jacobi_integral(h, n, (k + 1.) / 2.);
    }

    // The tanh-sinh forms of g and g' (the fallback of equivalent_profile and its slope).
    double equivalent_profile_tanh_sinh(const Profile &profile, const double k, const double x)
    {
      // g(x) = x/2 int_0^1 f'(x sqrt(u)) u^(-1/2) (1-u)^((k-1)/2) du   (9.2 with r = x sqrt(u))
      const auto h = [&](const double u, const double) {
        const double s = x * std::sqrt(u);
        return s > 0. ? profile_term(profile.df(s)) : 0.;
      };
      return x / 2. * beta_weight_integral(h, -0.5, (k - 1.) / 2.);
    }

    double equivalent_profile_slope_tanh_sinh(const Profile &profile, const double k, const double x)
    {
      // g'(x) = 1/2 int_0^1 [f'(s) + s f''(s)]_(s = x sqrt(u)) u^(-1/2) (1-u)^((k-1)/2) du
      const auto h = [&](const double u, const double) {
        const double s = x * std::sqrt(u);
        return s > 0. ? profile_term(profile.df(s) + s * profile.d2f(s)) : 0.;
      };
      return 0.5 * beta_weight_integral(h, -0.5, (k - 1.) / 2.);
    }

    /// g(x) / x^n and g'(x) / x^(n-1) for x > 0 (Foundation::tip_free and tip_free_slope).
    double scaled_equivalent_profile(const Profile &profile, const double k, const double n, const double x)
    {
      const detail::JacobiQuadrature G = tip_free_integral(profile.df, n, k, x);
      return G.resolved ? G.value : equivalent_profile_tanh_sinh(profile, k, x) / std::pow(x, n);
    }

    double scaled_equivalent_profile_slope(const Profile &profile, const double k, const double n, const double x)
    {
      const auto q = [&](const double s) { return profile.df(s) + s * profile.d2f(s); };
      const detail::JacobiQuadrature G1 = tip_free_integral(q, n, k, x);
      return G1.resolved ? G1.value : equivalent_profile_slope_tanh_sinh(profile, k, x) / std::pow(x, n - 1.);
    }

    /// int_0^1 v^k (1-v)^beta W(v, 1-v) w1D(x0 v) dv (beta1 = beta + 1) for w1D = d - x^n G(x): on [0, 1/2]
    /// as its two terms with v^k and v^(k+n) in the weights, on [1/2, 1] as it is, where the two terms cancel
    /// toward the edge (w1D(a) = 0 without adhesion; as k -> 1, g -> f and d - f(r) << d near r = a: the two
    /// terms over all of [0, 1] lose digits as k -> 1 and r -> a). W is analytic on [0, 1] but
    /// for a singularity at the distance delta1 beyond v = 1 (the panels on [1/2, 1] are graded toward it).
    template <class W>
    detail::JacobiQuadrature split_foundation_integral(const Foundation &w1d, const double x0, const double k,
                                                       const double beta1, const double delta1, const W &weight)
    {
      const double n = w1d.tip_exponent, beta = beta1 - 1.;
      // [0, 1/2]: v = t/2
      const auto flat = [&](const double t, double) {
        const double v = t / 2.;
        return std::pow(1. - v, beta) * weight(v, 1. - v);
      };
      const auto shape = [&](const double t, double) {
        const double v = t / 2.;
        return std::pow(1. - v, beta) * weight(v, 1. - v) * w1d.tip_free(x0 * v);
      };
      const detail::JacobiQuadrature A = detail::jacobi_integral(flat, k + 1., 1.);
      const detail::JacobiQuadrature B = detail::jacobi_integral(shape, (k + 1.) + n, 1.);
      // [1/2, 1]: 1 - v = (1 - t)/2. Where the panels are graded (delta1 < 1/8), w1D on [x0/2, x0] as its
      // Chebyshev interpolant (one inner quadrature a Chebyshev point, not a node of every panel).
      std::optional<detail::ChebyshevInterpolant> interpolant;
      if (2. * delta1 < 0.25)
        {
          interpolant.emplace([&](const double x) { return w1d.w(x); }, x0 / 2., x0);
          if (!interpolant->resolved())
            interpolant.reset();
        }
      const auto whole = [&](double, const double tc) {
        const double vc = tc / 2., v = 1. - vc;
        return std::pow(v, k) * weight(v, vc) * (interpolant ? (*interpolant)(x0 * v) : w1d.w(x0 * v));
      };
      const detail::JacobiQuadrature C = detail::graded_jacobi_integral(whole, 1., beta1,
                                                                        std::numeric_limits<double>::infinity(),
                                                                        2. * delta1);
      return {w1d.d * std::pow(0.5, k + 1.) * A.value - std::pow(x0 / 2., n) * std::pow(0.5, k + 1.) * B.value +
                std::pow(0.5, beta1) * C.value,
              A.resolved && B.resolved && C.resolved};
    }

    /// w(r) pi / cos(k pi/2) (9.12) by Gauss-Jacobi, r > 0, with x = r v inside and x = a v outside:
    ///   r <= a:  int_0^1 2 v^k (1-v)^s (1+v)^s w1D(r v) dv,                                 s = -(1+k)/2
    ///   r > a:   a^(k+1) int_0^1 2 v^k w1D(a v) K(v) dv,  K = (r^2 - a^2 v^2)^s = (D + a^2 (1-v)(1+v))^s,
    /// K singular at v = r/a (panels graded toward v = 1 for r close to a). w1D = d - x^n G(x) is split on
    /// [0, 1/2] (split_foundation_integral). A foundation (a^2 - x^2)^e phi(x) gives (1-v)^e to the weight
    /// outside and at r = a, and a singularity at v = a/r inside.
    detail::JacobiQuadrature displacement_gauss_jacobi(const Foundation &w1d, const double k, const double r)
    {
      const double a = w1d.a, e = w1d.edge_exponent, s = -(1. + k) / 2., s1 = (1. - k) / 2.;
      constexpr double none = std::numeric_limits<double>::infinity();
      detail::JacobiQuadrature fast;
      if (r == a && e != 0.)
        {
          const double power = e + s;
          const auto h = [&](const double v, double) { return 2. * std::pow(1. + v, power) * w1d.edge_free(a * v); };
          fast = detail::jacobi_integral(h, k + 1., e + s1);
          fast.value *= std::pow(a, 2. * e);
          return fast;
        }
      if (r <= a)
        {
          const auto W = [&](const double v, double) { return 2. * std::pow(1. + v, s); };
          if (w1d.tip_free && e == 0.)
            return split_foundation_integral(w1d, r, k, s1, none, W);
          const auto h = [&](const double v, double) { return W(v, 1. - v) * w1d.w(r * v); };
          return detail::graded_jacobi_integral(h, k + 1., s1, none, e != 0. ? (a - r) / r : none);
        }
      const double D = (r - a) * (r + a), gap = (r - a) / a;
      const auto K = [&](const double v, const double one_minus_v) {
        return std::pow(D + a * a * one_minus_v * (1. + v), s);
      };
      if (e != 0.)
        {
          const auto h = [&](const double v, const double vc) {
            return 2. * std::pow(1. + v, e) * w1d.edge_free(a * v) * K(v, vc);
          };
          fast = detail::graded_jacobi_integral(h, k + 1., e + 1., none, gap);
          fast.value *= std::pow(a, k + 1. + 2. * e);
          return fast;
        }
      const auto W = [&](const double v, const double vc) { return 2. * K(v, vc); };
      if (w1d.tip_free)
        fast = split_foundation_integral(w1d, a, k, 1., gap, W);
      else
        {
          const auto h = [&](const double v, const double vc) { return W(v, vc) * w1d.w(a * v); };
          fast = detail::graded_jacobi_integral(h, k + 1., 1., none, gap);
        }
      fast.value *= std::pow(a, k + 1.);
      return fast;
    }
  } // namespace

  Profile power_law(const double n, const double A)
  {
    check::positive("mdr::power_law", "n", n);
    check::finite("mdr::power_law", "A", A);
    return {[=](const double r) { return A * std::pow(r, n); },
            [=](const double r) { return n * A * std::pow(r, n - 1.); },
            // n = 1: exactly 0 (not 0 * r^-1, which is NaN at r = 0)
            [=](const double r) { return n == 1. ? 0. : n * (n - 1.) * A * std::pow(r, n - 2.); }, n};
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
    // g(x) = x^n G(x), G by Gauss-Jacobi (tip_free_integral), else tanh-sinh
    const double n = tip_of(profile.tip_exponent);
    const detail::JacobiQuadrature G = tip_free_integral(profile.df, n, k, x);
    if (G.resolved)
      return std::pow(x, n) * G.value;
    return equivalent_profile_tanh_sinh(profile, k, x);
  }

  double equivalent_profile_slope(const Profile &profile, const double k, const double x)
  {
    const char *fn = "mdr equivalent_profile_slope";
    check_k(fn, k);
    check::non_negative(fn, "x", x);
    if (!profile.df || !profile.d2f)
      throw DomainError(std::string(fn) + ": the profile needs f' and f'' for the pressure");
    if (x > 0.)
      {
        // g'(x) = x^(n-1) G1(x), G1 by Gauss-Jacobi (tip_free_integral), else tanh-sinh
        const double n = tip_of(profile.tip_exponent);
        const auto q = [&](const double s) { return profile.df(s) + s * profile.d2f(s); };
        const detail::JacobiQuadrature G1 = tip_free_integral(q, n, k, x);
        if (G1.resolved)
          return (n == 1. ? 1. : std::pow(x, n - 1.)) * G1.value;
      }
    return equivalent_profile_slope_tanh_sinh(profile, k, x);
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
    // A profile of unknown tip power whose f' the Gauss-Jacobi rules do not resolve at x = a is integrated by
    // tanh-sinh throughout: the rules' attempts at every node of the outer integrals would only add to the cost.
    if (std::isnan(profile.tip_exponent) && !tip_free_integral(profile.df, 1., k, a).resolved)
      {
        w1d.gauss_jacobi = false;
        w1d.w = [profile, k, d](const double x) {
          return x == 0. ? d : d - equivalent_profile_tanh_sinh(profile, k, x);
        };
        if (profile.d2f)
          w1d.dw = [profile, k](const double x) { return -equivalent_profile_slope_tanh_sinh(profile, k, x); };
        return w1d;
      }
    w1d.w = [profile, k, d](const double x) { return d - equivalent_profile(profile, k, x); };
    if (profile.d2f)
      w1d.dw = [profile, k](const double x) { return -equivalent_profile_slope(profile, k, x); };
    if (!std::isnan(profile.tip_exponent))
      {
        const double n = profile.tip_exponent;
        w1d.tip_exponent = n;
        w1d.tip_free = [profile, k, n](const double x) { return scaled_equivalent_profile(profile, k, n, x); };
        if (profile.d2f)
          w1d.tip_free_slope = [profile, k, n](const double x) {
            return scaled_equivalent_profile_slope(profile, k, n, x);
          };
      }
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
      const detail::JacobiQuadrature fast = detail::jacobi_integral(h, (1. - k) / 2., 1.);
      return factor * (fast.resolved ? fast.value : beta_weight_integral(h, -(1. + k) / 2., 0.));
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
    //   = a^(k+n+1)/(k+1) int_0^1 v^(n-1) (1-v)^q (1+v)^q phi(a v) dv,  q = (k+1)/2   (r = a v, Gauss-Jacobi)
    //   = a^(k+2)/(2(k+1)) int_0^1 u^(-1/2) (1-u)^q f'(a sqrt(u)) du                     (tanh-sinh fallback)
    const double n = tip_of(w1d.tip_exponent), q = (k + 1.) / 2.;
    const auto hv = [&](const double v, double) {
      const double r = a * v;
      return std::pow(1. + v, q) * (n == 1. ? w1d.profile_slope(r) : w1d.profile_slope(r) * std::pow(r, 1. - n));
    };
    detail::JacobiQuadrature fast;
    if (w1d.gauss_jacobi)
      fast = detail::jacobi_integral(hv, n, q + 1.);
    double shape;
    if (fast.resolved)
      shape = std::pow(a, k + n + 1.) / (k + 1.) * fast.value;
    else
      {
        const auto h = [&](const double u, const double) { return w1d.profile_slope(a * std::sqrt(u)); };
        shape = std::pow(a, k + 2.) / (2. * (k + 1.)) * beta_weight_integral(h, -0.5, q);
      }
    return 2. * m.cN0 / std::pow(m.c0, k) * (w1d.d * std::pow(a, k + 1.) / (k + 1.) - shape);
  }

  double force_nested(const Foundation &w1d, const Medium &m)
  {
    validate("mdr force", m);
    const double k = m.k, a = w1d.a;
    // 9.11 with x = a sqrt(u): F = cN0 a^(k+1)/c0^k int_0^1 u^((k-1)/2) w1D(a sqrt(u)) du
    const double prefactor = m.cN0 * std::pow(a, k + 1.) / std::pow(m.c0, k);
    if (w1d.gauss_jacobi)
    {
      // Gauss-Jacobi with x = a v: int_0^1 2 v^k w1D(a v) dv, w1D = (a^2 (1-v)(1+v))^e phi with the
      // factor (1-v)^e in the weight, w1D = d - (a v)^n G(a v) as its two terms
      const double e = w1d.edge_exponent;
      detail::JacobiQuadrature fast;
      if (e != 0.)
        {
          const auto h = [&](const double v, double) { return 2. * std::pow(1. + v, e) * w1d.edge_free(a * v); };
          fast = detail::jacobi_integral(h, k + 1., e + 1.);
          fast.value *= std::pow(a, 2. * e);
        }
      else if (w1d.tip_free)
        {
          const double n = w1d.tip_exponent;
          const auto h = [&](const double v, double) { return 2. * w1d.tip_free(a * v); };
          fast = detail::jacobi_integral(h, (k + 1.) + n, 1.);
          fast.value = 2. * w1d.d / (k + 1.) - std::pow(a, n) * fast.value;
        }
      else
        {
          const auto h = [&](const double v, double) { return 2. * w1d.w(a * v); };
          fast = detail::jacobi_integral(h, k + 1., 1.);
        }
      if (fast.resolved)
        return prefactor * fast.value;
    }
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
    const double edge_factor = m.cN0 / (pi * std::pow(m.c0, k));
    if (w1d.gauss_jacobi || r > 0.) // for r > 0 the slope is analytic on [r, a] whatever the tip
    {
      // Gauss-Jacobi with x = r + L t, L = a - r, x^2 - r^2 = L t (2r + L t), b = (k-1)/2:
      //   -int_r^a w1D'(x) (x^2-r^2)^b dx = -L^(b+1) int_0^1 t^b (2r + L t)^b w1D'(x) dt,
      // w1D' = -x^(n-1) G1(x) for a tip of known power. Singular at x = 0 and x = -r (t = -r/L, -2r/L): the
      // panels are graded toward t = 0 for r << a. At r = 0 the powers merge: a^(k+n-1) int_0^1 t^(k+n-2)
      // G1(a t) dt (finite for n + k > 1; otherwise the tanh-sinh form below answers as before).
      const double L = a - r, b = (k - 1.) / 2.;
      const bool tip = static_cast<bool>(w1d.tip_free_slope);
      const double n = tip ? w1d.tip_exponent : 1.;
      detail::JacobiQuadrature fast;
      if (r == 0. && tip)
        {
          if ((n - 1.) + k > 0.)
            {
              const auto h = [&](const double t, double) { return w1d.tip_free_slope(a * t); };
              fast = detail::jacobi_integral(h, (n - 1.) + k, 1.);
              fast.value *= std::pow(a, (n - 1.) + k);
            }
        }
      else if (r == 0.)
        {
          // -int_0^a w1D'(x) x^(k-1) dx = -a^(k+1) int_0^1 t^k [w1D'(a t)/(a t)] dt
          const auto h = [&](const double t, double) { return -w1d.dw(a * t) / (a * t); };
          fast = detail::jacobi_integral(h, k + 1., 1.);
          fast.value *= std::pow(a, k + 1.);
        }
      else
        {
          const auto h = [&](const double t, double) {
            const double x = r + L * t;
            const double slope = tip ? (n == 1. ? 1. : std::pow(x, n - 1.)) * w1d.tip_free_slope(x) : -w1d.dw(x);
            return std::pow(2. * r + L * t, b) * slope;
          };
          fast = detail::graded_jacobi_integral(h, (k + 1.) / 2., 1., r / L);
          fast.value *= std::pow(L, b + 1.);
        }
      if (fast.resolved)
        return edge_factor * (fast.value + w_edge * std::pow((a - r) * (a + r), b));
    }
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
    return edge_factor * (smooth + edge);
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
    if (w1d.gauss_jacobi)
    {
      const detail::JacobiQuadrature fast = displacement_gauss_jacobi(w1d, k, r);
      if (fast.resolved)
        return c * fast.value;
    }
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

    // 2. With f'' the exact slope of the objective brackets the minimum's radius between the scan's neighbours
    //    of the best point, and TOMS 748 finds its root to rounding (9.10, 9.11 and 9.45 differentiated in a:
    //    d'(a) = g'(a) - (1-k)/(2a) Delta_l(a), F'(a) = 2 cN0/c0^k a^k [a d'(a)/(k+1) - Delta_l(a)], as the
    //    shape term int_0^a x^k g(x) dx has the slope a^k g(a)).
    if (profile.d2f)
      {
        const auto slope = [&](const double a) {
          const double dl = delta_ell(m, dgamma, a);
          const double dd = equivalent_profile_slope(profile, m.k, a) - (1. - m.k) / (2. * a) * dl;
          return control == Control::force ? a * dd / (m.k + 1.) - dl : dd; // F' without 2 cN0 a^k / c0^k
        };
        const double lo = a_lo * std::exp(ratio * (best - 1)), hi = a_lo * std::exp(ratio * (best + 1));
        const double s_lo = slope(lo), s_hi = slope(hi);
        if (s_lo < 0. && s_hi > 0.)
          {
            std::uintmax_t max_iter = 100;
            const auto root = boost::math::tools::toms748_solve(slope, lo, hi, s_lo, s_hi,
                                                                boost::math::tools::eps_tolerance<double>(52),
                                                                max_iter);
            const double ac = 0.5 * (root.first + root.second);
            return {ac, depth_of(ac), force_of(ac)};
          }
      }

    // 3. Otherwise Brent's method in log a.
    const auto in_log = [&](const double s) { return objective(a_lo * std::exp(s)); };
    std::uintmax_t iterations = 200;
    const auto brent = boost::math::tools::brent_find_minima(in_log, ratio * (best - 1), ratio * (best + 1),
                                                             40, iterations);
    double ac = a_lo * std::exp(brent.first);

    // 4. A minimum is located only to sqrt(eps) by its value; the root of the derivative (fourth-order
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
