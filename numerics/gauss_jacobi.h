// gradcontact/numerics: header-only numerics that analytic/ and fem/ share and neither owns.
// The n-point Gauss-Jacobi rule on [0, 1] with weight u^alpha (1-u)^beta,
// alpha, beta > -1,
//     int_0^1 u^alpha (1-u)^beta h(u) du = sum_q w_q h(u_q)   exactly for polynomials h of degree <= 2n - 1.
// Header only and free of deal.II and Boost: the numerical MDR (analytic/) and the surface cell layer of
// the FE model (fem/base/gauss_jacobi.h) share it without a link dependency between the two libraries.
//
// Golub and Welsch (Math. Comp. 23 (1969) 221-230): the nodes are the eigenvalues of the symmetric
// tridiagonal Jacobi matrix of the three-term recurrence of the orthonormal polynomials p_j. The
// eigenvalues come from the implicit QL iteration with Wilkinson shifts (Golub and Van Loan, Matrix
// Computations, 4th ed., 8.3); each is polished by Newton's method on p_n, and the weights are the
// Christoffel numbers w_q = 1 / sum_{j<n} p_j(u_q)^2 (Gautschi, Orthogonal Polynomials, 2004, 1.4), which
// keep their relative accuracy at the small weights near the ends where eigenvector components do not.
// For beta < 0 the nodes above 1/2 come from the mirrored rule (alpha and beta exchanged) as their
// distances 1 - u to the end 1, so that a weight (1-u)^beta with beta -> -1 meets nodes whose distance to
// 1 is exact to rounding, not to eps absolute. The eigenvalues are found in double; the Newton steps, the
// weights and the polynomials at the nodes in long double, then rounded.
//
// Recurrence (monic Jacobi polynomials on [-1, 1] with weight (1-t)^a (1+t)^b, Gautschi 2004, Table 1.1;
// here t = 2u - 1, a = beta, b = alpha):
//   a_0 = (b - a)/(a + b + 2),   a_j = (b^2 - a^2)/((2j + a + b)(2j + a + b + 2))                 (j >= 1)
//   b_1 = 4 (1 + a)(1 + b)/((2 + a + b)^2 (3 + a + b))
//   b_j = 4 j (j + a)(j + b)(j + a + b)/((2j + a + b)^2 (2j + a + b + 1)(2j + a + b - 1))        (j >= 2)
// mapped to [0, 1]: diagonal (1 + a_j)/2, off-diagonal sqrt(b_j)/2; mass mu_0 = B(alpha + 1, beta + 1).
//
// The rule takes the exponents plus one, alpha + 1 and beta + 1: near -1 an exponent rounded to double
// (-(1+k)/2 at k = 0.999) has lost the relative accuracy of its distance to -1, and the mass ~ 1/(beta + 1)
// with it (1e-13 at k = 0.999), while (1-k)/2 keeps it.
#ifndef GRADCONTACT_NUMERICS_GAUSS_JACOBI_H
#define GRADCONTACT_NUMERICS_GAUSS_JACOBI_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace gradcontact::detail
{
  /// An n-point Gauss-Jacobi rule on [0, 1] for the weight u^alpha (1-u)^beta.
  struct GaussJacobiRule
  {
    double alpha_plus_one = 1., beta_plus_one = 1.;
    double mass = 0.;                ///< int_0^1 u^alpha (1-u)^beta du = B(alpha + 1, beta + 1)
    std::vector<double> node;        ///< u_q, ascending
    std::vector<double> complement;  ///< 1 - u_q, exact to rounding (not formed as 1 - u_q above 1/2)
    std::vector<double> weight;      ///< w_q (sum = mass)
    /// The orthonormal polynomials at the nodes, p_j(u_q) at [j * n + q], j < n: the discrete coefficients
    /// c_j = sum_q w_q h(u_q) p_j(u_q) of an integrand show how well the rule resolves it.
    std::vector<double> orthonormal;

    std::size_t size() const { return node.size(); }
  };

  namespace gauss_jacobi_detail
  {
    /// Diagonal d[j] (j < n) and off-diagonal e[j] = sqrt(b_(j+1))/2 (j < n, e[n-1] for p_n) of the
    /// Jacobi matrix on [0, 1] for the weight u^alpha (1-u)^beta, from alpha + 1 and beta + 1.
    template <class Real>
    void recurrence(const unsigned int n, const Real alpha1, const Real beta1, std::vector<Real> &d,
                    std::vector<Real> &e)
    {
      using std::sqrt;
      const Real a1 = beta1, b1 = alpha1, a = a1 - 1, b = b1 - 1, s = a + b;
      d.assign(n, 0.);
      e.assign(n, 0.);
      for (unsigned int j = 0; j < n; ++j)
        {
          const Real two_j = 2 * j;
          const Real aj = j == 0 ? (b - a) / (s + 2) : (b - a) * (b + a) / ((two_j + s) * (two_j + s + 2));
          d[j] = (1 + aj) / 2;
          const Real J = j + 1;
          const Real t = 2 * J + s;
          const Real bj = j == 0 ? 4 * a1 * b1 / ((2 + s) * (2 + s) * (3 + s))
                                 : 4 * J * (J + a) * (J + b) * (J + s) / (t * t * (t + 1) * (t - 1));
          e[j] = sqrt(bj) / 2;
        }
    }

    /// The eigenvalues of the symmetric tridiagonal matrix (diagonal d, off-diagonal e[0..n-2]), ascending:
    /// implicit QL with Wilkinson shifts (Golub and Van Loan 2013, 8.3.3; EISPACK tql1).
    template <class Real>
    std::vector<Real> tridiagonal_eigenvalues(std::vector<Real> d, std::vector<Real> e)
    {
      using std::abs;
      using std::copysign;
      using std::sqrt;
      const int n = static_cast<int>(d.size());
      e.resize(n);
      e[n - 1] = 0;
      for (int l = 0; l < n; ++l)
        {
          for (int iteration = 0;; ++iteration)
            {
              int m = l;
              for (; m < n - 1; ++m)
                {
                  const Real scale = abs(d[m]) + abs(d[m + 1]);
                  if (abs(e[m]) <= std::numeric_limits<Real>::epsilon() * scale)
                    break;
                }
              if (m == l)
                break;
              if (iteration == 60)
                throw std::runtime_error("gauss_jacobi: the QL iteration did not converge");
              Real g = (d[l + 1] - d[l]) / (2 * e[l]);
              Real r = sqrt(g * g + 1);
              g = d[m] - d[l] + e[l] / (g + copysign(r, g));
              Real s = 1, c = 1, p = 0;
              int i = m - 1;
              for (; i >= l; --i)
                {
                  Real f = s * e[i];
                  const Real b = c * e[i];
                  r = sqrt(f * f + g * g); // entries are O(1): no overflow to guard against
                  e[i + 1] = r;
                  if (r == 0)
                    {
                      d[i + 1] -= p;
                      e[m] = 0;
                      break;
                    }
                  s = f / r;
                  c = g / r;
                  g = d[i + 1] - p;
                  r = (d[i] - g) * s + 2 * c * b;
                  p = s * r;
                  d[i + 1] = g + p;
                  g = c * r - b;
                }
              if (r == 0 && i >= l)
                continue;
              d[l] -= p;
              e[l] = g;
              e[m] = 0;
            }
        }
      std::sort(d.begin(), d.end());
      return d;
    }

    /// p_0 ... p_(n-1) at x into P (stride 1) and p_n, p_n' by the recurrence
    /// e_j p_(j+1) = (x - d_j) p_j - e_(j-1) p_(j-1), p_0 = 1/sqrt(mass).
    template <class Real>
    void orthonormal_at(const Real x, const std::vector<Real> &d, const std::vector<Real> &e, const Real p0, Real *P,
                        Real &pn, Real &dpn)
    {
      const std::size_t n = d.size();
      Real p_prev = 0, p = p0, dp_prev = 0, dp = 0;
      for (std::size_t j = 0; j < n; ++j)
        {
          if (P)
            P[j] = p;
          const Real below = j == 0 ? Real(0) : e[j - 1];
          const Real p_next = ((x - d[j]) * p - below * p_prev) / e[j];
          const Real dp_next = (p + (x - d[j]) * dp - below * dp_prev) / e[j];
          p_prev = p;
          p = p_next;
          dp_prev = dp;
          dp = dp_next;
        }
      pn = p;
      dpn = dp;
    }

    /// Nodes (ascending) and Christoffel weights of the rule for u^alpha (1-u)^beta (alpha + 1, beta + 1 given).
    template <class Real>
    void nodes_and_weights(const unsigned int n, const Real alpha1, const Real beta1, const Real mass,
                           std::vector<Real> &x, std::vector<Real> &w)
    {
      using std::abs;
      using std::sqrt;
      std::vector<Real> d, e;
      recurrence(n, alpha1, beta1, d, e);
      // the eigenvalues in double (eps absolute), then Newton in Real
      {
        std::vector<double> dd(d.begin(), d.end()), ee(e.begin(), e.end() - 1);
        const std::vector<double> eigenvalues = tridiagonal_eigenvalues(dd, ee);
        x.assign(eigenvalues.begin(), eigenvalues.end());
      }
      w.assign(n, Real(0));
      const Real p0 = 1 / sqrt(mass);
      std::vector<Real> P(n);
      for (unsigned int q = 0; q < n; ++q)
        {
          // Newton's method on p_n from the eigenvalue (quadratic convergence: two or three steps)
          for (int it = 0; it < 5; ++it)
            {
              Real pn, dpn;
              orthonormal_at(x[q], d, e, p0, static_cast<Real *>(nullptr), pn, dpn);
              const Real step = pn / dpn;
              if (!(abs(step) < 1))
                break;
              const Real next = std::clamp<Real>(x[q] - step, 0, 1);
              const bool done = abs(next - x[q]) <= 4 * std::numeric_limits<Real>::epsilon() * x[q];
              x[q] = next;
              if (done)
                break;
            }
          Real pn, dpn, sum = 0;
          orthonormal_at(x[q], d, e, p0, P.data(), pn, dpn);
          for (unsigned int j = 0; j < n; ++j)
            sum += P[j] * P[j];
          w[q] = 1 / sum;
        }
    }
  } // namespace gauss_jacobi_detail

  /// B(x, y) for x, y > 0 from std::tgamma (relative error a few ulp for the arguments here, (0, 2]).
  inline double beta_function(const double x, const double y)
  {
    if (y == 1.)
      return 1. / x;
    if (x == 1.)
      return 1. / y;
    return std::tgamma(x) * std::tgamma(y) / std::tgamma(x + y);
  }

  /// The n-point Gauss-Jacobi rule on [0, 1] for the weight u^alpha (1-u)^beta, given alpha + 1 and
  /// beta + 1. std::invalid_argument for n = 0 or alpha + 1, beta + 1 outside (0, inf).
  inline GaussJacobiRule gauss_jacobi_rule(const unsigned int n, const double alpha_plus_one,
                                           const double beta_plus_one)
  {
    if (n == 0)
      throw std::invalid_argument("gauss_jacobi_rule: n = 0, need n >= 1");
    if (!(alpha_plus_one > 0.) || !(beta_plus_one > 0.) || !std::isfinite(alpha_plus_one) ||
        !std::isfinite(beta_plus_one))
      throw std::invalid_argument("gauss_jacobi_rule: exponents plus one alpha + 1 = " +
                                  std::to_string(alpha_plus_one) + ", beta + 1 = " + std::to_string(beta_plus_one) +
                                  " must lie in (0, inf)");
    // Built in long double: near u = 0 with alpha -> -1 the recurrence gives p_n to its epsilon absolute only,
    // which locates the first node to about eps/|p_n'| (2e-10 relative in double at alpha = -0.999, n = 96)
    // and its Christoffel number to about alpha + 1 times that; the extended precision's 11 more bits leave
    // double rounding.
    using Real = long double;
    GaussJacobiRule rule;
    rule.alpha_plus_one = alpha_plus_one;
    rule.beta_plus_one = beta_plus_one;
    rule.mass = beta_function(alpha_plus_one, beta_plus_one);
    std::vector<Real> x, w, xm, wm;
    gauss_jacobi_detail::nodes_and_weights<Real>(n, alpha_plus_one, beta_plus_one, rule.mass, x, w);
    std::size_t lower = 0;
    while (lower < n && x[lower] <= 0.5L)
      ++lower;
    // Nodes above 1/2 as their distance to 1 from the mirrored rule where the weight (1-u)^beta is singular
    // (beta < 0); otherwise 1 - u_q is exact to the extended precision's rounding.
    const bool mirrored = lower < n && beta_plus_one < 1.;
    if (mirrored)
      gauss_jacobi_detail::nodes_and_weights<Real>(n, beta_plus_one, alpha_plus_one, rule.mass, xm, wm);
    rule.node.resize(n);
    rule.complement.resize(n);
    rule.weight.resize(n);
    std::vector<Real> u(n); // the nodes in extended precision, for the polynomials below
    for (std::size_t q = 0; q < n; ++q)
      {
        Real uq, cq, wq;
        if (q < lower || !mirrored)
          {
            uq = x[q];
            cq = 1 - x[q];
            wq = w[q];
          }
        else
          {
            const std::size_t m = n - 1 - q; // the mirrored rule's node nearest to 0 is this rule's last
            cq = xm[m];
            uq = 1 - xm[m];
            wq = wm[m];
          }
        u[q] = uq;
        rule.node[q] = static_cast<double>(uq);
        rule.complement[q] = static_cast<double>(cq);
        rule.weight[q] = static_cast<double>(wq);
      }
    // The orthonormal polynomials at the nodes, in extended precision too: near an end with a weight exponent
    // -> -1 one node carries most of the mass, and p_j there in double (p_j' ~ j^2 p_j) would leave a noise
    // of the coefficients above the resolution tolerance (2e-12 of the norm at beta = -0.9995, n = 48).
    std::vector<Real> d, e;
    gauss_jacobi_detail::recurrence<Real>(n, alpha_plus_one, beta_plus_one, d, e);
    rule.orthonormal.assign(std::size_t(n) * n, 0.);
    std::vector<Real> P(n);
    const Real p0 = 1 / std::sqrt(static_cast<Real>(rule.mass));
    for (std::size_t q = 0; q < n; ++q)
      {
        Real pn, dpn;
        gauss_jacobi_detail::orthonormal_at<Real>(u[q], d, e, p0, P.data(), pn, dpn);
        for (std::size_t j = 0; j < n; ++j)
          rule.orthonormal[j * n + q] = static_cast<double>(P[j]);
      }
    return rule;
  }
} // namespace gradcontact::detail

#endif
