// Requirement: at k = 0 every closed form shall equal its classical homogeneous limit, written here
// from the textbook formulas (independent of the MDR): Boussinesq (flat punch), Sneddon (cone), Hertz
// (paraboloid), the uniformly loaded circle, JKR, Cattaneo-Mindlin and Mindlin-Deresiewicz. At
// k = +-1e-8 the results shall differ from the k = 0 ones by O(1e-8), not by a 0/0 artefact.
#include <analytic/adhesion.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace gradcontact;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double pi = boost::math::constants::pi<double>();
  // Classical formulas and closed forms are both a handful of operations and Boost special functions.
  constexpr double tol = 2e-14;
  // |k| = 1e-8 perturbs every result by O(1e-8) times O(1) sensitivities (log(c0/a) among them).
  constexpr double tol_near_zero = 1e-7;

  const double E = 2.1e11, nu = 0.3, Es = E / (1. - nu * nu);
  const double c0 = 1e-3, a = 2e-4;

  Medium homogeneous(const double k = 0.) { return medium(GradedHalfSpace{E, c0, k, nu}); }
}

TEST_CASE("flat punch at k = 0 is Boussinesq's", "[analytic]")
{
  const Medium m = homogeneous();
  const double d = 1e-6;
  CHECK_THAT(force(m, FlatPunch{a}, d), WithinRel(2. * Es * a * d, tol));
  for (const double r : {0., 0.5 * a, 0.999 * a})
    CHECK_THAT(pressure(m, FlatPunch{a}, d, r), WithinRel(Es * d / (pi * std::sqrt((a - r) * (a + r))), tol));
  for (const double r : {1.000001 * a, 1.5 * a, 10. * a, 1e3 * a})
    CHECK_THAT(displacement(m, FlatPunch{a}, d, r), WithinRel(2. * d / pi * std::asin(a / r), tol));
}

TEST_CASE("cone at k = 0 is Sneddon's", "[analytic]")
{
  const Medium m = homogeneous();
  const double t = 0.05;
  CHECK_THAT(depth(m, Cone{t}, a), WithinRel(pi / 2. * a * t, tol));
  CHECK_THAT(force(m, Cone{t}, a), WithinRel(pi / 2. * Es * a * a * t, tol));
  for (const double r : {0.1 * a, 0.5 * a, 0.9 * a})
    CHECK_THAT(pressure(m, Cone{t}, a, r), WithinRel(Es * t / 2. * std::acosh(a / r), tol));
  for (const double r : {1.5 * a, 10. * a})
    {
      // Sneddon: w(r > a) = t (a asin(a/r) - r + sqrt(r^2 - a^2)), the last two terms written as
      // -a^2 / (r + sqrt(r^2 - a^2)) to avoid their cancellation.
      const double w = t * (a * std::asin(a / r) - a * a / (r + std::sqrt((r - a) * (r + a))));
      CAPTURE(r);
      CHECK_THAT(displacement(m, Cone{t}, a, r), WithinRel(w, tol));
    }
}

TEST_CASE("paraboloid at k = 0 is Hertz's", "[analytic]")
{
  const Medium m = homogeneous();
  const double R = 5e-3;
  CHECK_THAT(depth(m, Paraboloid{R}, a), WithinRel(a * a / R, tol));
  CHECK_THAT(force(m, Paraboloid{R}, a), WithinRel(4. * Es * a * a * a / (3. * R), tol));
  for (const double r : {0., 0.5 * a, 0.999 * a})
    CHECK_THAT(pressure(m, Paraboloid{R}, a, r),
               WithinRel(2. * Es * a / (pi * R) * std::sqrt(1. - r * r / (a * a)), tol));
  // The classical form cancels like (r/a)^2 far out, so it is used up to r = 10 a (the references of
  // test_references.cc reach 1e3 a).
  for (const double r : {1.000001 * a, 1.5 * a, 10. * a})
    {
      const double w = ((2. * a * a - r * r) * std::asin(a / r) + a * std::sqrt((r - a) * (r + a))) / (pi * R);
      CAPTURE(r);
      CHECK_THAT(displacement(m, Paraboloid{R}, a, r), WithinRel(w, 1e-12));
    }
}

TEST_CASE("uniform pressure at k = 0 is the classical loaded circle", "[analytic]")
{
  const Medium m = homogeneous();
  const double p0 = 1e7;
  const UniformPressure load{a, p0};
  CHECK_THAT(centre_displacement(m, load), WithinRel(2. * p0 * a / Es, tol));
  // w(r) = 4 p0 a / (pi E*) E(r/a) inside (complete elliptic integral of the second kind, modulus r/a)
  for (const double r : {0.25 * a, 0.75 * a, a})
    CHECK_THAT(displacement(m, load, r), WithinRel(4. * p0 * a / (pi * Es) * boost::math::ellint_2(r / a), 1e-13));
}

TEST_CASE("JKR at k = 0: pull-off -3/2 pi dgamma R (force) and -5/6 pi dgamma R (displacement)", "[analytic]")
{
  const Medium m = homogeneous();
  const double R = 5e-3, dgamma = 0.05;
  const auto force_control = jkr::critical_state(m, Paraboloid{R}, dgamma, jkr::Control::force);
  const auto depth_control = jkr::critical_state(m, Paraboloid{R}, dgamma, jkr::Control::displacement);
  CHECK_THAT(force_control.force, WithinRel(-1.5 * pi * dgamma * R, tol));
  CHECK_THAT(depth_control.force, WithinRel(-5. / 6. * pi * dgamma * R, tol));
  // classical critical radius under force control: a_c^3 = 9 pi dgamma R^2 / (8 E*)
  CHECK_THAT(force_control.radius, WithinRel(std::cbrt(9. * pi * dgamma * R * R / (8. * Es)), tol));
  // Kendall's flat punch: F_c = -sqrt(8 pi a^3 dgamma E*)
  CHECK_THAT(jkr::critical_state(m, FlatPunch{a}, dgamma).force,
             WithinRel(-std::sqrt(8. * pi * a * a * a * dgamma * Es), tol));
}

TEST_CASE("tangential sphere at k = 0 is Cattaneo-Mindlin and Mindlin-Deresiewicz", "[analytic]")
{
  const Medium m = homogeneous();
  const double R = 5e-3, mu = 0.4;
  const tangential::SphereSlip s{R, mu};
  const double FN = force(m, Paraboloid{R}, a);
  const double G = E / (2. * (1. + nu));
  const double Gs = 4. * G / (2. - nu); // the tangential modulus of a rigid sphere on one body
  const double c = 0.6 * a;
  CHECK_THAT(tangential::tangential_force(m, s, a, c), WithinRel(mu * FN * (1. - std::pow(c / a, 3)), tol));
  // Mindlin: u0 = 3 mu F_N / (8 a G*) ... with G* = 4G/(2-nu) written as u0 = mu F_N/(a Gs) 3/2 (1-c^2/a^2)
  // (equivalently mu (2 - nu)/(4 G) ... : u0 = 3 mu F_N (2-nu) / (16 G a) [1 - (c/a)^2])
  CHECK_THAT(tangential::tangential_displacement(m, s, a, c),
             WithinRel(3. * mu * FN * (2. - nu) / (16. * G * a) * (1. - c * c / (a * a)), tol));
  const double FA = 0.7 * mu * FN, phi = FA / (mu * FN);
  // 9.87 with G* of the rigid pairing (ERRATA.md): 9 mu^2 F_N^2/(10 G* a)*2 = 18/5 ...
  const double MD = 18. * mu * mu * FN * FN / (5. * Gs * a) *
                    (1. - std::pow(1. - phi, 5. / 3.) - 5. / 6. * phi * (1. + std::pow(1. - phi, 2. / 3.)));
  CHECK_THAT(tangential::dissipated_energy(m, s, a, FA), WithinRel(MD, tol));
}

TEST_CASE("closed forms are continuous through k = 0", "[analytic]")
{
  const double R = 5e-3, t = 0.05, d = 1e-6, dgamma = 0.05;
  const Medium m0 = homogeneous(0.);
  for (const double k : {-1e-8, 1e-8})
    {
      const Medium m = homogeneous(k);
      CAPTURE(k);
      CHECK_THAT(force(m, Paraboloid{R}, a), WithinRel(force(m0, Paraboloid{R}, a), tol_near_zero));
      CHECK_THAT(force(m, FlatPunch{a}, d), WithinRel(force(m0, FlatPunch{a}, d), tol_near_zero));
      for (const double r : {0.3 * a, 0.999 * a})
        CHECK_THAT(pressure(m, Cone{t}, a, r), WithinRel(pressure(m0, Cone{t}, a, r), tol_near_zero));
      for (const double r : {1.5 * a, 1e3 * a})
        CHECK_THAT(displacement(m, Cone{t}, a, r), WithinRel(displacement(m0, Cone{t}, a, r), tol_near_zero));
      // the power-law pressure at the Gamma pole n = 1, k = 0 (9.30) and next to it
      CHECK_THAT(pressure(m, PowerLaw{1., t}, a, 0.5 * a),
                 WithinRel(pressure(m0, PowerLaw{1., t}, a, 0.5 * a), tol_near_zero));
      CHECK_THAT(pressure(m, PowerLaw{3., 1e6}, a, 0.5 * a),
                 WithinRel(pressure(m0, PowerLaw{3., 1e6}, a, 0.5 * a), tol_near_zero));
      CHECK_THAT(displacement(m, UniformPressure{a, 1e7}, 0.9 * a),
                 WithinRel(displacement(m0, UniformPressure{a, 1e7}, 0.9 * a), tol_near_zero));
      CHECK_THAT(jkr::critical_state(m, Paraboloid{R}, dgamma, jkr::Control::displacement).force,
                 WithinRel(jkr::critical_state(m0, Paraboloid{R}, dgamma, jkr::Control::displacement).force,
                           tol_near_zero));
    }
}
