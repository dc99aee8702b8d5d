// gradcontact/analytic/detail: the quadratures of the numerical MDR.
//
// 1. Gauss-Jacobi rules (gauss_jacobi.h) for int u^alpha (1-u)^beta h(u) du with h analytic: the end-point
//    powers of the MDR integrals are in the weight, so the mass near an end with alpha or beta -> -1 is
//    counted exactly however small its scale, and an analytic h needs a few dozen nodes. Whether h is
//    resolved is read off the rule's own samples: the last discrete coefficients of h in the orthonormal
//    polynomials of the weight (Trefethen, Approximation Theory and Approximation Practice, 2013, ch. 8 and
//    19: for h analytic in a Bernstein ellipse of parameter rho they decay like rho^-j, and the quadrature
//    error like rho^-2n). Rules of 24, 48 and 96 nodes are tried in turn. Where h has a singularity just
//    outside [0, 1] (at the distance delta of an end), panels graded geometrically toward that end (ratio
//    1/2, down to delta) keep every panel's integrand analytic in a fixed ellipse (hp quadrature: Schwab,
//    p- and hp-Finite Element Methods, 1998, 4.4).
// 2. tanh-sinh with end-point substitutions, the fallback where a Gauss-Jacobi rule does not resolve h
//    (an unknown end-point power of a user's profile, a kink).
//
// tanh-sinh hands the integrand the exact distances to both end points:
// Boost 1.74's tanh_sinh passes the complement (distance to the end point) only on the canonical
// interval (-1, 1): f(u, uc) with uc = 1 - u for u > 0 and uc = -1 - u for u < 0. Mapping that to
// (lo, hi) here lets an integrand with an end-point singularity form (x - lo) or (hi - x) without
// the cancellation of subtracting nearly equal numbers (STYLE: ERRATA 9.2 quadrature item).
#ifndef GRADCONTACT_ANALYTIC_DETAIL_QUADRATURE_H
#define GRADCONTACT_ANALYTIC_DETAIL_QUADRATURE_H

#include <analytic/detail/gauss_jacobi.h>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

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

  /// A Gauss-Jacobi rule of the calling thread's cache (the rules of the last 64 (n, alpha, beta) asked for).
  /// Shared ownership: an outer quadrature keeps its rule while inner ones evict others.
  inline std::shared_ptr<const GaussJacobiRule> cached_gauss_jacobi_rule(const unsigned int n, const double alpha1,
                                                                         const double beta1)
  {
    thread_local std::vector<std::shared_ptr<const GaussJacobiRule>> cache;
    thread_local std::size_t next = 0;
    constexpr std::size_t capacity = 64;
    for (const auto &rule : cache)
      if (rule->size() == n && rule->alpha_plus_one == alpha1 && rule->beta_plus_one == beta1)
        return rule;
    auto rule = std::make_shared<const GaussJacobiRule>(gauss_jacobi_rule(n, alpha1, beta1));
    if (cache.size() < capacity)
      cache.push_back(rule);
    else
      {
        cache[next] = rule;
        next = (next + 1) % capacity;
      }
    return rule;
  }

  /// A Gauss-Jacobi quadrature's value and whether the rule resolved the integrand.
  struct JacobiQuadrature
  {
    double value = 0.;
    bool resolved = false;
  };

  /// The relative size of the last coefficients (of the integrand's L2 norm in the weight) below which a
  /// rule counts as resolving it. Geometric decay rho^-j then bounds the quadrature error by about its
  /// square; an algebraic decay j^-p (a singular derivative of order p) by 2^-p times it, hence the margin.
  constexpr double jacobi_tail_tolerance = 1e-12;
  /// The rule sizes tried in turn.
  constexpr unsigned int jacobi_sizes[] = {24, 48, 96};
  constexpr std::size_t max_jacobi_size = 96;

  /// sum_q w_q h(u_q, 1 - u_q) with the resolution check: the last four discrete coefficients
  /// c_j = sum_q w_q h_q p_j(u_q) against sqrt(sum_q w_q h_q^2) (their total, by discrete orthogonality).
  template <class H>
  JacobiQuadrature jacobi_sum(const GaussJacobiRule &rule, const H &h)
  {
    const std::size_t n = rule.size();
    double v[max_jacobi_size]; // on the stack: h may run quadratures of its own
    double sum = 0., squares = 0.;
    for (std::size_t q = 0; q < n; ++q)
      {
        v[q] = rule.weight[q] * h(rule.node[q], rule.complement[q]);
        sum += v[q];
      }
    for (std::size_t q = 0; q < n; ++q)
      squares += v[q] * v[q] / rule.weight[q];
    JacobiQuadrature result{sum, false};
    if (!std::isfinite(sum) || !std::isfinite(squares))
      return result;
    double tail = 0.;
    const std::size_t last = std::min<std::size_t>(4, n);
    for (std::size_t j = n - last; j < n; ++j)
      {
        double c = 0.;
        const double *p = &rule.orthonormal[j * n];
        for (std::size_t q = 0; q < n; ++q)
          c += v[q] * p[q];
        tail += c * c;
      }
    result.resolved = tail <= jacobi_tail_tolerance * jacobi_tail_tolerance * squares;
    return result;
  }

  /// int_0^1 u^alpha (1-u)^beta h(u, 1-u) du by the Gauss-Jacobi rules of jacobi_sizes, the first that
  /// resolves h (resolved = false when none does). The exponents come as alpha1 = alpha + 1 and
  /// beta1 = beta + 1, formed where they keep their digits (gauss_jacobi.h).
  template <class H>
  JacobiQuadrature jacobi_integral(const H &h, const double alpha1, const double beta1)
  {
    JacobiQuadrature result;
    for (const unsigned int n : jacobi_sizes)
      {
        result = jacobi_sum(*cached_gauss_jacobi_rule(n, alpha1, beta1), h);
        if (result.resolved)
          break;
      }
    return result;
  }

  /// int_0^1 u^alpha (1-u)^beta h(u, 1-u) du (alpha1 = alpha + 1, beta1 = beta + 1) for h analytic on [0, 1]
  /// but with singularities at the
  /// distances delta0 below 0 and delta1 above 1 (infinity: none). Where a delta is below 1/4, panels
  /// graded by halving toward that end, the last of a length below 2 delta: every panel's h is then analytic
  /// in the same ellipse. The end panels carry the end-point powers in their rule; the others
  /// evaluate them. Resolved when every panel is.
  template <class H>
  JacobiQuadrature graded_jacobi_integral(const H &h, const double alpha1, const double beta1,
                                          const double delta0 = std::numeric_limits<double>::infinity(),
                                          const double delta1 = std::numeric_limits<double>::infinity())
  {
    constexpr double grade_below = 0.25;
    const bool left = delta0 < grade_below, right = delta1 < grade_below;
    if (!left && !right)
      return jacobi_integral(h, alpha1, beta1);
    const double alpha = alpha1 - 1., beta = beta1 - 1.; // evaluated away from their ends only
    // Break points as (u, 1 - u), each formed where it is small. Left: 1/2, 1/4, ... while above 2 delta0.
    struct Point
    {
      double u, complement;
    };
    std::vector<Point> points;
    if (left)
      {
        double b = 0.5;
        std::vector<Point> descending;
        for (; b > 2. * delta0 && descending.size() < 1100; b *= 0.5)
          descending.push_back({b, 1. - b});
        points.push_back({0., 1.});
        points.insert(points.end(), descending.rbegin(), descending.rend());
      }
    else
      points.push_back({0., 1.});
    if (right)
      {
        if (!left)
          points.push_back({0.5, 0.5});
        for (double c = 0.25; c > 2. * delta1 && points.size() < 2200; c *= 0.5)
          points.push_back({1. - c, c});
        points.push_back({1., 0.});
      }
    else
      points.push_back({1., 0.});
    JacobiQuadrature total{0., true};
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
      {
        const Point lo = points[i], hi = points[i + 1];
        const bool first = i == 0, last = i + 2 == points.size();
        JacobiQuadrature panel;
        if (first)
          {
            // [0, b]: u = b t, the power u^alpha in the rule
            const double b = hi.u;
            const auto g = [&](const double t, double) {
              const double u = b * t, uc = 1. - u;
              return std::pow(uc, beta) * h(u, uc);
            };
            panel = jacobi_integral(g, alpha1, 1.);
            panel.value *= std::pow(b, alpha1);
          }
        else if (last)
          {
            // [1 - c, 1]: 1 - u = c (1 - t), the power (1-u)^beta in the rule
            const double c = lo.complement;
            const auto g = [&](double, const double tc) {
              const double uc = c * tc, u = 1. - uc;
              return std::pow(u, alpha) * h(u, uc);
            };
            panel = jacobi_integral(g, 1., beta1);
            panel.value *= std::pow(c, beta1);
          }
        else
          {
            const bool in_right_half = lo.u >= 0.5;
            const double length = in_right_half ? lo.complement - hi.complement : hi.u - lo.u;
            const auto g = [&](const double t, const double tc) {
              double u, uc;
              if (in_right_half)
                {
                  uc = hi.complement + length * tc;
                  u = 1. - uc;
                }
              else
                {
                  u = lo.u + length * t;
                  uc = 1. - u;
                }
              return std::pow(u, alpha) * std::pow(uc, beta) * h(u, uc);
            };
            panel = jacobi_integral(g, 1., 1.);
            panel.value *= length;
          }
        total.value += panel.value;
        total.resolved = total.resolved && panel.resolved;
        if (!total.resolved)
          break;
      }
    return total;
  }
} // namespace gradcontact::detail

#endif
