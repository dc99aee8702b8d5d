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
//    p- and hp-Finite Element Methods, 1998, 4.4); the panels are judged together, so that a panel where
//    h is small and only its rounding is left need not resolve that. An inner integral evaluated on many
//    panels is replaced by its Chebyshev interpolant where that resolves it (ChebyshevInterpolant).
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

#include <numerics/gauss_jacobi.h>

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

  /// A Gauss-Jacobi quadrature's value, whether the rule resolved the integrand, and the two sizes that
  /// decide it: error = sqrt(mass) |last coefficients| (the quadrature error is about its square for an
  /// analytic integrand) and scale = sqrt(mass) sqrt(sum_q w_q h_q^2) (at least int w |h|, Cauchy-Schwarz).
  struct JacobiQuadrature
  {
    double value = 0.;
    bool resolved = false;
    double error = 0., scale = 0.;
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
    JacobiQuadrature result{sum, false, std::numeric_limits<double>::infinity(), 0.};
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
    const double root_mass = std::sqrt(rule.mass);
    result.error = root_mass * std::sqrt(tail);
    result.scale = root_mass * std::sqrt(squares);
    result.resolved = result.error <= jacobi_tail_tolerance * result.scale;
    return result;
  }

  /// int_0^1 u^alpha (1-u)^beta h(u, 1-u) du by the Gauss-Jacobi rules of jacobi_sizes, the first that
  /// resolves h (resolved = false when none does). The exponents come as alpha1 = alpha + 1 and
  /// beta1 = beta + 1, formed where they keep their digits (gauss_jacobi.h). After two rules the next is
  /// tried only if the errors' geometric decay (doubling n squares the error) would take it below the
  /// tolerance: an h with an end-point power the weight does not hold decays algebraically and goes to the
  /// caller's fallback at once (the 96 nodes were most of the cost of a nested fallback).
  template <class H>
  JacobiQuadrature jacobi_integral(const H &h, const double alpha1, const double beta1)
  {
    constexpr std::size_t n_levels = sizeof(jacobi_sizes) / sizeof(jacobi_sizes[0]);
    JacobiQuadrature result, previous;
    for (std::size_t i = 0; i < n_levels; ++i)
      {
        if (i >= 2)
          {
            const double predicted = previous.error > 0. ? result.error * result.error / previous.error : 0.;
            if (!(predicted <= jacobi_tail_tolerance * result.scale))
              break;
          }
        previous = result;
        result = jacobi_sum(*cached_gauss_jacobi_rule(jacobi_sizes[i], alpha1, beta1), h);
        if (result.resolved)
          break;
      }
    return result;
  }

  /// int_0^1 u^alpha (1-u)^beta h(u, 1-u) du (alpha1 = alpha + 1, beta1 = beta + 1) for h analytic on [0, 1]
  /// but with singularities at the distances delta0 below 0 and delta1 above 1 (infinity: none). Where a
  /// delta is below 1/4, panels graded by halving toward that end, the last of a length below 2 delta:
  /// every panel's h is then analytic in the same ellipse. The end panels carry the end-point powers in their
  /// rule; the others evaluate them. Resolved when the panels' errors together are within the tolerance of
  /// their scales together: a panel where h is small (w1D -> 0 at the contact edge, formed as d - g with an
  /// error of eps d) need not resolve its own rounding noise. The panels with the largest errors get the
  /// larger rules first.
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
    points.push_back({0., 1.});
    if (left)
      {
        std::vector<Point> descending;
        for (double b = 0.5; b > 2. * delta0 && descending.size() < 1100; b *= 0.5)
          descending.push_back({b, 1. - b});
        points.insert(points.end(), descending.rbegin(), descending.rend());
      }
    if (right)
      {
        if (!left)
          points.push_back({0.5, 0.5});
        for (double c = 0.25; c > 2. * delta1 && points.size() < 2200; c *= 0.5)
          points.push_back({1. - c, c});
      }
    points.push_back({1., 0.});
    const std::size_t n_panels = points.size() - 1;
    const auto panel = [&](const std::size_t i, const unsigned int size) {
      const Point lo = points[i], hi = points[i + 1];
      JacobiQuadrature result;
      double factor;
      if (i == 0)
        {
          // [0, b]: u = b t, the power u^alpha in the rule
          const double b = hi.u;
          const auto g = [&](const double t, double) {
            const double u = b * t, uc = 1. - u;
            return std::pow(uc, beta) * h(u, uc);
          };
          result = jacobi_sum(*cached_gauss_jacobi_rule(size, alpha1, 1.), g);
          factor = std::pow(b, alpha1);
        }
      else if (i + 1 == n_panels)
        {
          // [1 - c, 1]: 1 - u = c (1 - t), the power (1-u)^beta in the rule
          const double c = lo.complement;
          const auto g = [&](double, const double tc) {
            const double uc = c * tc, u = 1. - uc;
            return std::pow(u, alpha) * h(u, uc);
          };
          result = jacobi_sum(*cached_gauss_jacobi_rule(size, 1., beta1), g);
          factor = std::pow(c, beta1);
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
          result = jacobi_sum(*cached_gauss_jacobi_rule(size, 1., 1.), g);
          factor = length;
        }
      result.value *= factor;
      result.error *= factor;
      result.scale *= factor;
      return result;
    };
    std::vector<JacobiQuadrature> panels(n_panels);
    std::vector<std::size_t> level(n_panels, 0);
    for (std::size_t i = 0; i < n_panels; ++i)
      panels[i] = panel(i, jacobi_sizes[0]);
    constexpr std::size_t n_levels = sizeof(jacobi_sizes) / sizeof(jacobi_sizes[0]);
    while (true)
      {
        double error = 0., scale = 0.;
        std::size_t worst = n_panels;
        for (std::size_t i = 0; i < n_panels; ++i)
          {
            error += panels[i].error;
            scale += panels[i].scale;
            if (level[i] + 1 < n_levels && (worst == n_panels || panels[i].error > panels[worst].error))
              worst = i;
          }
        const bool resolved = std::isfinite(error) && error <= jacobi_tail_tolerance * scale;
        if (resolved || worst == n_panels)
          {
            JacobiQuadrature total{0., resolved, error, scale};
            for (const JacobiQuadrature &p : panels)
              total.value += p.value;
            return total;
          }
        panels[worst] = panel(worst, jacobi_sizes[++level[worst]]);
      }
  }

  /// int_lo^hi f(x, x - lo, hi - x) dx (as integrate_with_distances) for an f analytic on [lo, hi]: by
  /// Gauss-Legendre rules (jacobi_integral with both powers 0) where one resolves f, else by tanh-sinh.
  template <class F>
  double integrate_analytic_with_distances(const F &f, const double lo, const double hi)
  {
    if (!(hi > lo))
      return 0.;
    const double length = hi - lo;
    const auto g = [&](const double t, const double tc) {
      const double to_lo = length * t, to_hi = length * tc;
      return f(t <= 0.5 ? lo + to_lo : hi - to_hi, to_lo, to_hi);
    };
    const JacobiQuadrature fast = jacobi_integral(g, 1., 1.);
    return fast.resolved ? length * fast.value : integrate_with_distances(f, lo, hi);
  }

  /// A function on [lo, hi] as its interpolant in the Chebyshev points of the first kind, for an inner
  /// integral that a quadrature on many panels would otherwise evaluate at every node (Trefethen 2013, ch. 3
  /// and 8). Resolved when the last three coefficients are within a few eps of the coefficients' sum: the
  /// interpolant then agrees with the function to rounding of its largest value.
  class ChebyshevInterpolant
  {
  public:
    static constexpr int size = 32;

    template <class F>
    ChebyshevInterpolant(const F &f, const double lo, const double hi) : lo_(lo), hi_(hi)
    {
      const Table &T = table();
      double values[size];
      for (int j = 0; j < size; ++j)
        values[j] = f(0.5 * (lo + hi) + 0.5 * (hi - lo) * T.cosine[1][j]);
      double sum = 0., tail = 0.;
      for (int m = 0; m < size; ++m)
        {
          double c = 0.;
          for (int j = 0; j < size; ++j)
            c += values[j] * T.cosine[m][j];
          c_[m] = (m == 0 ? 1. : 2.) / size * c;
          sum += std::abs(c_[m]);
          if (m >= size - 3)
            tail = std::max(tail, std::abs(c_[m]));
        }
      resolved_ = std::isfinite(sum) && tail <= 8. * std::numeric_limits<double>::epsilon() * sum;
    }

    bool resolved() const { return resolved_; }

    /// The interpolant at x in [lo, hi] (Clenshaw's recurrence).
    double operator()(const double x) const
    {
      const double t = (2. * x - lo_ - hi_) / (hi_ - lo_);
      double b1 = 0., b2 = 0.;
      for (int m = size - 1; m >= 1; --m)
        {
          const double b0 = 2. * t * b1 - b2 + c_[m];
          b2 = b1;
          b1 = b0;
        }
      return t * b1 - b2 + c_[0];
    }

  private:
    /// cos(pi m (j + 1/2) / size): T_m at the Chebyshev points (row 1: the points themselves).
    struct Table
    {
      double cosine[size][size];
      Table()
      {
        constexpr double pi = 3.141592653589793238462643383279502884;
        for (int m = 0; m < size; ++m)
          for (int j = 0; j < size; ++j)
            cosine[m][j] = std::cos(pi * m * (j + 0.5) / size);
      }
    };
    static const Table &table()
    {
      static const Table t;
      return t;
    }

    double lo_, hi_, c_[size] = {};
    bool resolved_ = false;
  };
} // namespace gradcontact::detail

#endif
