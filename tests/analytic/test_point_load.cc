// Requirement: the graded Boussinesq field (analytic/point_load.h) shall meet every exact limit written here from an
// independent path: Froehlich's radial distribution at Holl's ratio, Boussinesq's field at k = 0 (textbook formulas,
// Johnson, Contact Mechanics, 1985, eqs. 3.19-3.20), the force P through any plane z = const, pointwise equilibrium
// by finite differences, a traction-free surface, and the surface displacement of the MDR's uniformly loaded circle
// (9.40) as its radius vanishes.
#include <analytic/errors.h>
#include <analytic/normal.h>
#include <analytic/point_load.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <catch2/catch.hpp>

#include <cmath>

using namespace gradcontact;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double pi = boost::math::constants::pi<double>();
  /// Two series of a few dozen terms, summed in double: the field is exact to a few hundred ulp.
  constexpr double series_tol = 1e-13;
  /// A k of 1e-8 moves the field by O(1e-8) from Boussinesq's.
  constexpr double near_zero_tol = 5e-8;
  /// Central differences with h = 1e-4 R: truncation O(h^2) times the third derivative, rounding eps / h.
  constexpr double difference_tol = 1e-6;
}

TEST_CASE("At Holl's ratio the point-load field shall be Froehlich's radial distribution", "[analytic][stress]")
{
  const double k = GENERATE(0.1, 0.5, 0.9);
  const PointLoadField field(k, 1 / (2 + k));
  for (double theta = 0; theta < 1.57; theta += 0.0625)
    {
      const SphericalStress S = field.angular(theta);
      const double          radial = -(3 + k) / (2 * pi) * std::pow(std::cos(theta), 1 + k);
      CAPTURE(k, theta, S.RR, radial, S.thth, S.phph, S.Rth);
      CHECK_THAT(S.RR, WithinRel(radial, series_tol) || WithinAbs(radial, series_tol));
      CHECK_THAT(S.thth, WithinAbs(0, series_tol));
      CHECK_THAT(S.phph, WithinAbs(0, series_tol));
      CHECK_THAT(S.Rth, WithinAbs(0, series_tol));
    }
}

namespace
{
  /// Boussinesq's stresses of a unit force (Johnson 3.20), tension positive, z depth.
  AxisymmetricStress boussinesq(const double nu, const double r, const double z)
  {
    const double R = std::hypot(r, z), R5 = std::pow(R, 5);
    AxisymmetricStress s;
    s.zz = -3 * z * z * z / (2 * pi * R5);
    s.rz = -3 * r * z * z / (2 * pi * R5);
    // (1 - z/R) / r^2 = 1 / (R (R + z)), which stays finite on the axis
    const double g = 1 / (R * (R + z));
    s.rr = ((1 - 2 * nu) * g - 3 * r * r * z / R5) / (2 * pi);
    s.tt = -(1 - 2 * nu) * (g - z / (R * R * R)) / (2 * pi);
    return s;
  }

  void check_against_boussinesq(const PointLoadField &field, const double nu, const double tol)
  {
    for (const double r : {0., 0.1, 0.5, 1., 2., 10.})
      for (const double z : {1e-3, 0.1, 1., 3.})
        {
          const AxisymmetricStress s = field.stress(1., r, z), b = boussinesq(nu, r, z);
          const double             scale = 1 / (r * r + z * z); // |sigma| ~ P / R^2
          CAPTURE(field.k(), nu, r, z);
          CHECK_THAT(s.rr, WithinAbs(b.rr, tol * scale));
          CHECK_THAT(s.zz, WithinAbs(b.zz, tol * scale));
          CHECK_THAT(s.tt, WithinAbs(b.tt, tol * scale));
          CHECK_THAT(s.rz, WithinAbs(b.rz, tol * scale));
        }
  }
}

TEST_CASE("At k = 0 the point-load field shall be Boussinesq's, and near k = 0 differ from it by O(k)",
          "[analytic][stress]")
{
  const double nu = GENERATE(0., 0.3, 0.49);
  check_against_boussinesq(PointLoadField(0., nu), nu, series_tol);
  check_against_boussinesq(PointLoadField(1e-8, nu), nu, near_zero_tol);
  check_against_boussinesq(PointLoadField(-1e-8, nu), nu, near_zero_tol);

  // Displacements (Johnson 3.19), u_z positive into the half-space.
  const GradedHalfSpace body{2e9, 1e-3, 0., nu};
  const PointLoadField  field(0., nu);
  for (const double r : {0., 0.5, 2.})
    for (const double z : {0., 0.3, 1.})
      if (r > 0 || z > 0)
        {
          const double R = std::hypot(r, z), f = (1 + nu) / (2 * pi * body.E0);
          const double ur = f * (r * z / (R * R * R) - (1 - 2 * nu) * r / (R * (R + z)));
          const double uz = f * (2 * (1 - nu) / R + z * z / (R * R * R));
          const auto   u  = field.displacement(body, 1., r, z);
          CAPTURE(nu, r, z, u[0], ur, u[1], uz);
          CHECK_THAT(u[0], WithinAbs(ur, series_tol * f / R));
          CHECK_THAT(u[1], WithinRel(uz, series_tol));
        }
}

TEST_CASE("The point-load field shall carry the force through every plane z = const and be in equilibrium",
          "[analytic][stress]")
{
  const double k  = GENERATE(-0.9, -0.5, 0.3, 0.9);
  const double nu = GENERATE(0., 0.3, 0.45);
  const PointLoadField field(k, nu);
  CAPTURE(k, nu);

  // 2 pi int_0^inf sigma_zz(r, z) r dr = -P on z = 1, with r = tan(theta): a surface the hemisphere scaling of the
  // field never sees.
  boost::math::quadrature::tanh_sinh<double> rule;
  const double force = 2 * pi * rule.integrate([&](const double theta) {
    const double r = std::tan(theta);
    return field.stress(1., r, 1.).zz * r * (1 + r * r);
  }, 0., pi / 2, 1e-14);
  CHECK_THAT(force, WithinRel(-1., 1e-11));

  // div sigma = 0 at inner points, by central differences.
  for (const auto &[r, z] : {std::pair{0.7, 0.4}, std::pair{0.2, 1.5}, std::pair{3., 0.5}})
    {
      const double h = 1e-4 * std::hypot(r, z);
      const auto   s = [&](const double dr, const double dz) { return field.stress(1., r + dr, z + dz); };
      const AxisymmetricStress c = s(0, 0), rp = s(h, 0), rm = s(-h, 0), zp = s(0, h), zm = s(0, -h);
      const double radial = (rp.rr - rm.rr) / (2 * h) + (zp.rz - zm.rz) / (2 * h) + (c.rr - c.tt) / r;
      const double axial  = (rp.rz - rm.rz) / (2 * h) + (zp.zz - zm.zz) / (2 * h) + c.rz / r;
      const double scale  = 1 / std::pow(r * r + z * z, 1.5); // |grad sigma| ~ P / R^3
      CAPTURE(r, z, radial, axial, scale);
      CHECK_THAT(radial, WithinAbs(0, difference_tol * scale));
      CHECK_THAT(axial, WithinAbs(0, difference_tol * scale));
    }
}

TEST_CASE("The surface of the point-load field shall be free of traction", "[analytic][stress]")
{
  // The traction-free Frobenius solutions give sigma_rz ~ (z/r)^(1+k) and sigma_zz ~ (z/r)^(2+k) at the surface; the
  // two that carry a traction would leave them finite. The ratio over three decades of depth shows the exponent.
  const double k  = GENERATE(-0.9, -0.5, 0.5, 0.9);
  const double nu = GENERATE(0., 0.3, 0.45);
  const PointLoadField     field(k, nu);
  const AxisymmetricStress near = field.stress(1., 1., 1e-6), nearer = field.stress(1., 1., 1e-9);
  CAPTURE(k, nu, near.rz, nearer.rz, near.zz, nearer.zz);
  CHECK_THAT(near.rz / nearer.rz, WithinRel(std::pow(1e3, 1 + k), 1e-4));
  CHECK_THAT(near.zz / nearer.zz, WithinRel(std::pow(1e3, 2 + k), 1e-4));
}

TEST_CASE("The surface displacement of the point-load field shall be the MDR's uniformly loaded circle as its radius "
          "vanishes (9.40)",
          "[analytic][stress]")
{
  const double k  = GENERATE(-0.9, -0.5, 0.3, 0.9);
  const double nu = GENERATE(0., 0.3, 0.45, 0.499, 0.4999);
  const GradedHalfSpace body{2e9, 1e-3, k, nu};
  const PointLoadField  field(k, nu);
  const double          P = 2., r = 1e-2, a = 1e-4 * r;
  // Outside the circle 9.40 carries 2F1((1+k)/2, (1+k)/2; 2; a^2/r^2) = 1 + ((1+k)/2)^2 (a/r)^2 / 2 + O((a/r)^4).
  const double circle = displacement(medium(body), UniformPressure{a, P / (pi * a * a)}, r) /
                        (1 + 0.125 * (1 + k) * (1 + k) * (a / r) * (a / r));
  const double point = field.displacement(body, P, r, 0.)[1];
  CAPTURE(k, nu, point, circle);
  // Near nu = 1/2 lambda' tr eps is a product of a large and a small factor: the field loses digits like
  // (1 - 2 nu)^-2.
  CHECK_THAT(point, WithinRel(circle, 1e-10 + 1e-14 / ((1 - 2 * nu) * (1 - 2 * nu))));
}

TEST_CASE("The point-load field shall refuse a grading, Poisson ratio or point outside its domain, naming it",
          "[analytic][stress]")
{
  using Catch::Matchers::Contains;
  CHECK_THROWS_WITH(PointLoadField(1., 0.3), Contains("k = 1") && Contains("(-1, 1)"));
  CHECK_THROWS_WITH(PointLoadField(std::nan(""), 0.3), Contains("k = nan"));
  CHECK_THROWS_WITH(PointLoadField(0.5, 0.5), Contains("nu = 0.5") && Contains("[0, 0.5)"));
  CHECK_THROWS_WITH(PointLoadField(0.5, -0.1), Contains("nu = -0.1"));
  const PointLoadField field(0.5, 0.3);
  CHECK_THROWS_WITH(field.stress(1., 1., 0.), Contains("z = 0"));
  CHECK_THROWS_WITH(field.angular(pi / 2), Contains("theta"));
  CHECK_THROWS_WITH(field.displacement(GradedHalfSpace{2e9, 1e-3, 0.5, 0.3}, 1., 0., 0.), Contains("load point"));
  CHECK_THROWS_WITH(field.displacement(GradedHalfSpace{2e9, 1e-3, 0.4, 0.3}, 1., 1., 0.), Contains("built for k = 0.5"));
  CHECK_THROWS_AS(field.stress(1., -1., 1.), DomainError);
}
