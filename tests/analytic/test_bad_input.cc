// Requirement: bad input shall be a clear error naming the parameter, its value and the valid range,
// never a NaN, a silent zero or a crash: k outside (-1, 1), nu outside [0, 1/2], non-positive E0, c0,
// radii and depths, r < 0, NaN anywhere, complete contact violated for the concave punch (9.35),
// gross slip for tangential cases, no critical state, a Holl ratio for k <= 0.
#include <analytic/adhesion.h>
#include <analytic/errors.h>
#include <analytic/mdr.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace gradcontact;
using Catch::Contains;

namespace
{
  const double not_a_number = std::numeric_limits<double>::quiet_NaN();
  const GradedHalfSpace good{1e9, 1e-3, 0.5, 0.3};
}

TEST_CASE("materials outside their range are rejected with the parameter named", "[analytic]")
{
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, 1e-3, 1., 0.3}), Contains("k = 1") && Contains("(-1, 1)"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, 1e-3, -1., 0.3}), Contains("k = -1"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, 1e-3, 0.5, 0.6}), Contains("nu = 0.6") && Contains("[0, 0.5]"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, 1e-3, 0.5, -0.1}), Contains("nu = -0.1"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{0., 1e-3, 0.5, 0.3}), Contains("E0 = 0") && Contains("> 0"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, -1., 0.5, 0.3}), Contains("c0 = -1"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{not_a_number, 1e-3, 0.5, 0.3}), Contains("E0") && Contains("not a number"));
  CHECK_THROWS_WITH(medium(GradedHalfSpace{1e9, 1e-3, not_a_number, 0.3}), Contains("k = nan"));
  CHECK_THROWS_AS(h_N(0.5, not_a_number), DomainError);
}

TEST_CASE("geometry and loads outside their range are rejected", "[analytic]")
{
  const Medium m = medium(good);
  CHECK_THROWS_WITH(force(m, Paraboloid{-1.}, 1e-4), Contains("R = -1"));
  CHECK_THROWS_WITH(force(m, Paraboloid{1e-2}, 0.), Contains("a = 0"));
  CHECK_THROWS_WITH(pressure(m, Paraboloid{1e-2}, 1e-4, -1e-5), Contains("r = -1e-05") && Contains(">= 0"));
  CHECK_THROWS_WITH(pressure(m, Cone{0.1}, 1e-4, not_a_number), Contains("r = nan"));
  CHECK_THROWS_WITH(force(m, PowerLaw{0., 1.}, 1e-4), Contains("n = 0"));
  CHECK_THROWS_WITH(contact_radius_from_depth(m, PowerLaw{2., 1.}, -1e-6), Contains("d = -1e-06"));
  CHECK_THROWS_WITH(pressure(m, FlatPunch{1e-4}, 1e-6, 1e-4), Contains("unbounded"));
  // a sharp tip has an unbounded pressure at r = 0
  CHECK_THROWS_WITH(pressure(medium(GradedHalfSpace{1e9, 1e-3, -0.5, 0.3}), Cone{0.1}, 1e-4, 0.),
                    Contains("n + k"));
}

TEST_CASE("the concave punch requires complete contact (9.35)", "[analytic]")
{
  const Medium m = medium(good);
  const ConcavePunch punch{1e-4, 1e-7};
  const double d_min = minimum_centre_displacement(m, punch);
  CHECK(d_min > 0.);
  CHECK_NOTHROW(force(m, punch, 1.01 * d_min));
  CHECK_THROWS_WITH(force(m, punch, 0.99 * d_min), Contains("d0") && Contains("complete contact"));
  CHECK_THROWS_WITH(pressure(m, punch, 0.5 * d_min, 0.), Contains("9.35"));
}

TEST_CASE("adhesion: dgamma, sigma_th and the existence of a critical state are checked", "[analytic]")
{
  const Medium m = medium(good);
  CHECK_THROWS_WITH(jkr::critical_state(m, Paraboloid{1e-2}, 0., jkr::Control::force), Contains("dgamma"));
  CHECK_THROWS_WITH(jkr::critical_state(m, Paraboloid{1e-2}, -0.1, jkr::Control::force), Contains("dgamma (work of adhesion) = -0.1"));
  // 2n + k - 1 <= 0: F(a) and d(a) have no minimum
  CHECK_THROWS_WITH(jkr::critical_state(medium(GradedHalfSpace{1e9, 1e-3, -0.5, 0.3}), PowerLaw{0.7, 1.}, 0.05,
                                        jkr::Control::force),
                    Contains("no critical state"));
  CHECK_THROWS_WITH(jkr::critical_state(m, ConcavePunch{1e-4, 1e-7}, 0.05, 0., jkr::Mechanism::centre),
                    Contains("sigma_th = 0"));
  CHECK_THROWS_WITH(jkr::transition_h0(m, 1e-4, 0.05, 1.), Contains("too small"));
  // the numerical engine reports a minimum on the end of the bracket instead of a wrong answer
  CHECK_THROWS_WITH(mdr::critical_state(mdr::power_law(2., 50.), m, 0.05, mdr::Control::force, 1e-3, 1e-2),
                    Contains("no critical state"));
}

TEST_CASE("tangential: friction, gross slip, stick radius and the Holl ratio are checked", "[analytic]")
{
  const Medium m = medium(good);
  const double a = 1e-4, R = 1e-2;
  const double FN = force(m, Paraboloid{R}, a);
  CHECK_THROWS_WITH(tangential::tangential_force(m, {R, 0.}, a, 0.5 * a), Contains("mu"));
  CHECK_THROWS_WITH(tangential::stick_radius(m, {R, 0.3}, a, 0.3 * FN), Contains("gross slip"));
  CHECK_THROWS_WITH(tangential::tangential_force(m, {R, 0.3}, a, 1.5 * a), Contains("c (stick radius)"));
  CHECK_THROWS_WITH(tangential::dissipated_energy(m, {R, 0.3}, a, 0.31 * FN), Contains("gross slip"));
  CHECK_THROWS_WITH(tangential::holl_ratio(-0.2), Contains("k = -0.2"));
  CHECK(tangential::holl_ratio(0.5) == Approx(0.4).epsilon(1e-15));
}
