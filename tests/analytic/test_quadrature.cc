// Requirements on the quadratures of the numerical MDR (numerics/gauss_jacobi.h, quadrature.h):
// the Gauss-Jacobi rule shall be exact for its polynomials with the end-point exponents down to -1 + 1e-3;
// a rule shall report an integrand it does not resolve; the engine shall keep its digits at the edges of
// the parameter space (k -> +-1, r -> 0, r -> a from both sides) and through the tanh-sinh fallback (a
// profile whose tip power it is not told).
#include <numerics/gauss_jacobi.h>
#include <analytic/detail/quadrature.h>
#include <analytic/material.h>
#include <analytic/mdr.h>
#include <analytic/normal.h>

#include <boost/math/special_functions/beta.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace gradcontact;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  // Moments of the rule against Boost's beta function (an independent implementation), over exponents plus one
  // down to 1e-3 and n up to 96 (long double sums of the products): a few tens of eps, which the test CAPTUREs.
  constexpr double tol_moments = 5e-14;
  // The numerical MDR against the closed forms (normal.h) at the edges: both paths keep a few eps there except
  // just outside the contact at k -> +-1, where the closed displacement (against a 40-digit mpmath quadrature of
  // 9.12 at r = 1.00001 a) and the numerical one lose about two digits more; the bound keeps a decade over them.
  constexpr double tol_edges = 1e-12;
} // namespace

TEST_CASE("The Gauss-Jacobi rule shall integrate u^alpha (1-u)^beta times polynomials of degree 2n-1 exactly",
          "[analytic]")
{
  const double alpha1 = GENERATE(1e-3, 0.05, 0.5, 1., 2.5);
  const double beta1 = GENERATE(1e-3, 0.5, 1., 1.9);
  const unsigned int n = GENERATE(1u, 5u, 24u, 96u);
  const detail::GaussJacobiRule rule = detail::gauss_jacobi_rule(n, alpha1, beta1);
  REQUIRE(rule.size() == n);
  for (unsigned int j = 0; j < 2 * n; j += n > 8 ? 5 : 1)
    {
      // int_0^1 u^(alpha+j) (1-u)^beta and int_0^1 u^alpha (1-u)^(beta+j), the latter through the complements
      long double left = 0., right = 0.;
      for (std::size_t q = 0; q < n; ++q)
        {
          left += rule.weight[q] * std::pow(static_cast<long double>(rule.node[q]), j);
          right += rule.weight[q] * std::pow(static_cast<long double>(rule.complement[q]), j);
        }
      const double exact_left = boost::math::beta(alpha1 + j, beta1), exact_right = boost::math::beta(alpha1, beta1 + j);
      CAPTURE(alpha1, beta1, n, j, exact_left, exact_right, tol_moments);
      CHECK_THAT(static_cast<double>(left), WithinRel(exact_left, tol_moments));
      CHECK_THAT(static_cast<double>(right), WithinRel(exact_right, tol_moments));
    }
}

TEST_CASE("A Gauss-Jacobi quadrature shall resolve an analytic integrand and report one it does not", "[analytic]")
{
  // (1 + u)^(-1/2) with the weight u^-0.9 (1-u)^-0.5: analytic, resolved by the first rule
  const auto smooth = [](const double u, double) { return 1. / std::sqrt(1. + u); };
  const detail::JacobiQuadrature s = detail::jacobi_integral(smooth, 0.1, 0.5);
  CHECK(s.resolved);
  // sqrt(u) with the weight 1: the kink at u = 0 is not resolved by 24, 48 or 96 nodes (the value is still close)
  const auto kink = [](const double u, double) { return std::sqrt(u); };
  const detail::JacobiQuadrature k = detail::jacobi_integral(kink, 1., 1.);
  CAPTURE(k.value);
  CHECK_FALSE(k.resolved);
  CHECK_THAT(k.value, WithinRel(2. / 3., 1e-5));
  // a singularity 1e-8 beyond u = 1, (1 + 1e-8 - u)^(-1/2): unresolved on [0, 1], resolved on graded panels
  const double delta = 1e-8;
  const auto near = [&](double, const double uc) { return 1. / std::sqrt(delta + uc); };
  CHECK_FALSE(detail::jacobi_integral(near, 1., 1.).resolved);
  const detail::JacobiQuadrature graded =
    detail::graded_jacobi_integral(near, 1., 1., std::numeric_limits<double>::infinity(), delta);
  const double exact = 2. * (std::sqrt(1. + delta) - std::sqrt(delta));
  CAPTURE(graded.value, exact);
  CHECK(graded.resolved);
  CHECK_THAT(graded.value, WithinRel(exact, 1e-14));
}

TEST_CASE("The numerical MDR shall keep its digits at k -> +-1 and at r -> 0 and r -> a (power law n = 1.5)",
          "[analytic]")
{
  const double k = GENERATE(-0.999, -0.99, 0.99, 0.999);
  const double a = 1e-4, n = 1.5, A = 1e-6 / std::pow(a, n);
  const Medium m = medium(GradedHalfSpace{1e9, 1e-3, k, 0.3});
  const PowerLaw closed{n, A};
  const mdr::Foundation w1d = mdr::indentation(mdr::power_law(n, A), m, a);
  for (const double s : {1e-6, 1e-3, 0.5, 1. - 1e-5})
    {
      const double p = mdr::pressure(w1d, m, s * a), reference = pressure(m, closed, a, s * a);
      CAPTURE(k, s, p, reference, tol_edges);
      CHECK_THAT(p, WithinRel(reference, tol_edges));
    }
  for (const double s : {1e-6, 1. - 1e-5, 1. + 1e-10, 1. + 1e-5, 1e3})
    {
      const double w = mdr::displacement(w1d, m, s * a), reference = displacement(m, closed, a, s * a);
      CAPTURE(k, s, w, reference, tol_edges);
      CHECK_THAT(w, WithinRel(reference, tol_edges));
    }
}

TEST_CASE("The numerical MDR shall give the same values without the tip exponent (the tanh-sinh fallback)",
          "[analytic]")
{
  // f = A r^1.5 without tip_exponent: f'(x v) ~ v^0.5 is not analytic, no Gauss-Jacobi rule resolves it and
  // every integral falls back to tanh-sinh, which still meets the closed forms to a few eps.
  const double k = GENERATE(-0.9, 0., 0.9);
  const double a = 1e-4, n = 1.5, A = 1e-6 / std::pow(a, n);
  const Medium m = medium(GradedHalfSpace{1e9, 1e-3, k, 0.3});
  mdr::Profile unknown_tip = mdr::power_law(n, A);
  unknown_tip.tip_exponent = std::numeric_limits<double>::quiet_NaN();
  const mdr::Foundation w1d = mdr::indentation(unknown_tip, m, a);
  const PowerLaw closed{n, A};
  constexpr double tol_fallback = 1e-13;
  CAPTURE(k);
  CHECK_THAT(mdr::depth(w1d), WithinRel(depth(m, closed, a), tol_fallback));
  CHECK_THAT(mdr::force(w1d, m), WithinRel(force(m, closed, a), tol_fallback));
  CHECK_THAT(mdr::pressure(w1d, m, 0.5 * a), WithinRel(pressure(m, closed, a, 0.5 * a), tol_fallback));
  CHECK_THAT(mdr::displacement(w1d, m, 0.5 * a), WithinRel(displacement(m, closed, a, 0.5 * a), tol_fallback));
  CHECK_THAT(mdr::displacement(w1d, m, 2. * a), WithinRel(displacement(m, closed, a, 2. * a), tol_fallback));
}
