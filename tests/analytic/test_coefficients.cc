// Requirement: the MDR coefficients beta, C, h_N, h_T and alpha (9.5-9.7, 9.78-9.79) shall take their
// classical values at k = 0, be continuous through k = 0 without loss of digits (no 0/0), and behave
// as their asymptotics say as k -> -1 and k -> 1.
#include <analytic/material.h>

#include <boost/math/constants/constants.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace gradcontact;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double pi = boost::math::constants::pi<double>();
  constexpr double tol_exact = 4e-16; // a few ulp: closed expressions of a few Gamma functions
}

TEST_CASE("coefficients take their classical values at k = 0", "[analytic]")
{
  const double nu = GENERATE(0., 0.25, 0.3, 0.49999, 0.5);
  CAPTURE(nu);
  CHECK_THAT(beta(0., nu), WithinRel(1., tol_exact));
  CHECK_THAT(C(0., nu), WithinRel(2. / pi, tol_exact));
  CHECK_THAT(h_N(0., nu), WithinRel(1., tol_exact));
  // c_T = 4 G / (2 - nu) = 2 E / ((1 + nu)(2 - nu)) for k = 0 (Mindlin)
  CHECK_THAT(h_T(0., nu), WithinRel(2. / ((1. + nu) * (2. - nu)), tol_exact));
}

TEST_CASE("coefficients are continuous through k = 0", "[analytic]")
{
  // Derivatives in k are O(1): at |k| = 1e-8 the change must be O(1e-8) and smooth on both sides.
  const double nu = GENERATE(0., 0.3, 0.49999);
  for (const auto coefficient : {&h_N, &h_T, &C, &beta})
    {
      const double at = coefficient(0., nu), below = coefficient(-1e-8, nu), above = coefficient(1e-8, nu);
      CAPTURE(nu, at, below, above);
      CHECK(std::abs(above - at) < 1e-7);
      CHECK(std::abs(below - at) < 1e-7);
      // central symmetry of the first-order change: (above - at) ~ -(below - at)
      CHECK(std::abs((above - at) + (below - at)) < 1e-14);
    }
}

TEST_CASE("h_N vanishes like pi (1 - nu) (1 + k)^2 as k -> -1", "[analytic]")
{
  // From 9.5: cos(k pi/2) ~ pi (1+k)/2, beta sin(beta pi/2) ~ pi beta^2/2, Gamma((1+k)/2) ~ 2/(1+k),
  // C -> 1/pi, beta^2 ~ (1+k)/(1-nu).
  const double nu = GENERATE(0., 0.3);
  for (const double target : {1e-4, 1e-6, 1e-9})
    {
      const double k = -1. + target;
      const double e = 1. + k; // the distance to -1 that k actually has as a double
      CAPTURE(nu, k, h_N(k, nu));
      CHECK_THAT(h_N(k, nu) / (pi * (1. - nu) * e * e), WithinRel(1., 10 * e));
    }
}

TEST_CASE("the Gibson medium: h_N(k, 1/2) -> pi/2 as k -> 1", "[analytic]")
{
  // 9.44: h(1, 0.5) = pi/2; at k < 1 the approach is O(1 - k) (ERRATA.md)
  double previous_gap = 1.;
  for (const double e : {1e-2, 1e-4, 1e-6})
    {
      const double gap = std::abs(h_N(1. - e, 0.5) - pi / 2.);
      CAPTURE(e, gap);
      CHECK(gap < 5. * e);
      CHECK(gap < previous_gap);
      previous_gap = gap;
    }
  // for compressible media h_N -> 0 as k -> 1 (no contact stiffness, 9.1.8)
  CHECK(h_N(1. - 1e-6, 0.3) < 1e-2);
}

TEST_CASE("the pairing of two bodies adds the compliances (9.4, 9.78)", "[analytic]")
{
  const GradedHalfSpace one{2e9, 1e-3, 0.4, 0.3};
  const Medium single = medium(one), pair = medium(one, one);
  CHECK_THAT(pair.cN0, WithinRel(single.cN0 / 2., tol_exact));
  CHECK_THAT(pair.cT0, WithinRel(single.cT0 / 2., tol_exact));
  CHECK_THAT(pair.alpha(), WithinRel(h_N(0.4, 0.3) / ((1. - 0.09) * h_T(0.4, 0.3)), 2 * tol_exact));
  // different k or c0 is not a pairing of the theory
  CHECK_THROWS_WITH(medium(one, GradedHalfSpace{2e9, 1e-3, 0.5, 0.3}), Catch::Contains("k of body 2"));
  CHECK_THROWS_WITH(medium(one, GradedHalfSpace{2e9, 2e-3, 0.4, 0.3}), Catch::Contains("c0 of body 2"));
}
