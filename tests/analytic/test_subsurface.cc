// Requirement: the stresses below a contact (analytic/subsurface.h) shall meet the exact fields written here from an
// independent path: Huber's Hertz field at k = 0 on the axis and on the surface, with its largest shear of 0.31 p0 at
// 0.48 a (Johnson, Contact Mechanics, 1985, eqs. 3.44-3.45, 3.41), Love's uniformly loaded circle on the axis
// (Johnson 3.39), the radial field at Holl's ratio on the axis (a one-dimensional integral of Froehlich's
// distribution), and the normal traction of the load at the surface for every k.
#include <analytic/batch.h>
#include <analytic/request.h>
#include <analytic/subsurface.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace gradcontact;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double pi = boost::math::constants::pi<double>();
  /// Composite Gauss rules of 16 points per panel on analytic panels: rounding-limited away from the surface.
  constexpr double superposition_tol = 1e-11;
  /// At depth z the field differs from its surface value by O(z / a) (O(sqrt(z / a)) at the contact edge).
  constexpr double surface_depth = 1e-9;
  constexpr double surface_tol   = 1e-8;

  const double E = 2e9, c0 = 1e-3, a = 1e-3;
}

TEST_CASE("At k = 0 the stresses below a paraboloid shall be Huber's Hertz field", "[analytic][stress]")
{
  const double nu = GENERATE(0.0, 0.3, 0.45);
  const PointLoadField       field(0., nu);
  const AxisymmetricPressure load = contact_pressure(medium(GradedHalfSpace{E, c0, 0., nu}), Paraboloid{0.05}, a);
  const double               p0   = load.smooth(0);
  for (const double zeta : {0.01, 0.1, 0.48, 1., 3.})
    {
      const AxisymmetricStress s  = subsurface_stress(field, load, 0., zeta * a);
      const double             zz = -p0 / (1 + zeta * zeta);
      const double rr = -p0 * ((1 + nu) * (1 - zeta * std::atan(1 / zeta)) - 0.5 / (1 + zeta * zeta));
      CAPTURE(nu, zeta, s.zz, zz, s.rr, rr);
      CHECK_THAT(s.zz, WithinAbs(zz, superposition_tol * p0));
      CHECK_THAT(s.rr, WithinAbs(rr, superposition_tol * p0));
      CHECK_THAT(s.tt, WithinAbs(rr, superposition_tol * p0));
      CHECK_THAT(s.rz, WithinAbs(0, superposition_tol * p0));
    }
  for (const double rho : {0.3, 0.95, 1.5})
    {
      const AxisymmetricStress s = subsurface_stress(field, load, rho * a, surface_depth * a);
      const double             q = std::max(0., 1 - rho * rho);
      const double rr = rho < 1 ? p0 * ((1 - 2 * nu) / (3 * rho * rho) * (1 - std::pow(q, 1.5)) - std::sqrt(q)) :
                                  p0 * (1 - 2 * nu) / (3 * rho * rho);
      CAPTURE(nu, rho, s.rr, rr, s.zz);
      CHECK_THAT(s.rr, WithinAbs(rr, surface_tol * p0));
      CHECK_THAT(s.zz, WithinAbs(-p0 * std::sqrt(q), surface_tol * p0));
      if (rho > 1)
        CHECK_THAT(s.tt, WithinAbs(-rr, surface_tol * p0));
    }
  if (nu == 0.3)
    {
      // The largest shear on the axis, (sigma_zz - sigma_rr) / 2, by golden-section search.
      const auto shear = [&](const double zeta) {
        const AxisymmetricStress s = subsurface_stress(field, load, 0., zeta * a);
        return -(s.zz - s.rr) / 2;
      };
      double lo = 0.3, hi = 0.7;
      for (int i = 0; i < 60; ++i)
        {
          const double m1 = hi - 0.618 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
          (shear(m1) > shear(m2) ? hi : lo) = shear(m1) > shear(m2) ? m2 : m1;
        }
      CHECK_THAT(shear((lo + hi) / 2) / p0, WithinAbs(0.31, 0.005));
      CHECK_THAT((lo + hi) / 2, WithinAbs(0.48, 0.005));
    }
}

TEST_CASE("At k = 0 the stresses below a uniformly loaded circle shall be Love's on the axis", "[analytic][stress]")
{
  const double               nu = 0.3, p0 = 1e6;
  const PointLoadField       field(0., nu);
  const AxisymmetricPressure load = contact_pressure(UniformPressure{a, p0});
  for (const double zeta : {0.05, 0.5, 2.})
    {
      const AxisymmetricStress s = subsurface_stress(field, load, 0., zeta * a);
      const double             g = std::pow(1 + zeta * zeta, -0.5), z3 = std::pow(zeta * g, 3);
      CAPTURE(zeta, s.zz, s.rr);
      CHECK_THAT(s.zz, WithinAbs(-p0 * (1 - z3), superposition_tol * p0));
      CHECK_THAT(s.rr, WithinAbs(-p0 / 2 * ((1 + 2 * nu) - 2 * (1 + nu) * zeta * g + z3), superposition_tol * p0));
    }
}

TEST_CASE("At Holl's ratio the axial stress on the axis shall be the 1D integral of Froehlich's radial field",
          "[analytic][stress]")
{
  // sigma_zz(0, z) = -(3 + k)/(2 pi) int_0^a p(rho) 2 pi rho z^(3+k) / (rho^2 + z^2)^((5+k)/2) drho
  const double k = GENERATE(0.3, 0.8);
  const double nu = 1 / (2 + k);
  const Medium m  = medium(GradedHalfSpace{E, c0, k, nu});
  const PointLoadField field(k, nu);
  for (const bool punch : {true, false})
    {
      const AxisymmetricPressure load = punch ? contact_pressure(m, FlatPunch{a}, 1e-6) :
                                                contact_pressure(m, Paraboloid{0.05}, a);
      const double p0 = load.smooth(0);
      boost::math::quadrature::tanh_sinh<double> rule;
      for (const double zeta : {0.1, 0.7, 2.})
        {
          const double z = zeta * a;
          const double reference = -(3 + k) * rule.integrate([&](const double rho, const double rc) {
            const double gap = rho > a / 2 ? rc * (2 * a - rc) / (a * a) : 1 - rho * rho / (a * a); // 1 - rho^2/a^2
            return load.smooth(rho) * std::pow(gap, load.edge_exponent) * rho * std::pow(z, 3 + k) /
                   std::pow(rho * rho + z * z, (5 + k) / 2);
          }, 0., a, 1e-14);
          const AxisymmetricStress s = subsurface_stress(field, load, 0., z);
          CAPTURE(k, punch, zeta, s.zz, reference);
          CHECK_THAT(s.zz, WithinRel(reference, 1e-11) || WithinAbs(reference, superposition_tol * p0));
        }
    }
}

TEST_CASE("Just below the surface the normal stress shall tend to the contact pressure and the shear to zero, for every k",
          "[analytic][stress]")
{
  // The surface layer of the graded medium: sigma_zz + p(r) ~ z^min(2, 2+k) and sigma_rz ~ z^min(1, 1+k) (the smooth
  // part of the field against the traction-free exponents of point_load.h); a limit other than the load, or a wrong
  // exponent, breaks the decade ratios.
  const double k  = GENERATE(-0.7, -0.3, 0.4, 0.8);
  const double nu = 0.3;
  const Medium m  = medium(GradedHalfSpace{E, c0, k, nu});
  const PointLoadField       field(k, nu);
  const AxisymmetricPressure load = contact_pressure(m, Paraboloid{0.05}, a);
  for (const double rho : {0.2, 0.5, 0.9})
    {
      const double p = pressure(m, Paraboloid{0.05}, a, rho * a);
      const AxisymmetricStress s1 = subsurface_stress(field, load, rho * a, 1e-4 * a);
      const AxisymmetricStress s2 = subsurface_stress(field, load, rho * a, 1e-5 * a);
      CAPTURE(k, rho, p, s1.zz, s2.zz, s1.rz, s2.rz);
      CHECK_THAT((s1.zz + p) / (s2.zz + p), WithinRel(std::pow(10., std::min(2., 2 + k)), 0.1));
      CHECK_THAT(s1.rz / s2.rz, WithinRel(std::pow(10., std::min(1., 1 + k)), 0.05));
      CHECK_THAT(s2.zz, WithinRel(-p, 1e-5));
    }
}

TEST_CASE("eval shall answer the stress below a contact by component, and name a wrong component",
          "[analytic][stress]")
{
  using Catch::Matchers::Contains;
  // Hertz at k = 0 on the axis (Huber), through the JSON request of gradcontact eval.
  const double nu = 0.3, R = 0.05, zeta = 0.48;
  const nlohmann::json material = {{"E0", E}, {"c0", c0}, {"k", 0.}, {"nu", nu}};
  const auto ask = [&](const std::string &component) {
    return batch::evaluate(batch::parse(nlohmann::json{{"case", "paraboloid"}, {"quantity", "stress"},
                                                       {"material", material}, {"geometry", {{"R", R}}},
                                                       {"a", a}, {"r", 0.}, {"z", zeta * a}, {"component", component}}));
  };
  const double p0 = pressure(medium(GradedHalfSpace{E, c0, 0., nu}), Paraboloid{R}, a, 0.);
  const double zz = -p0 / (1 + zeta * zeta);
  const double rr = -p0 * ((1 + nu) * (1 - zeta * std::atan(1 / zeta)) - 0.5 / (1 + zeta * zeta));
  CHECK_THAT(ask("zz"), WithinRel(zz, 1e-11));
  CHECK_THAT(ask("rr"), WithinRel(rr, 1e-11));
  CHECK_THAT(ask("tt"), WithinRel(rr, 1e-11));
  CHECK_THAT(ask("max_shear"), WithinRel((rr - zz) / 2, 1e-11));
  CHECK_THAT(ask("von_mises"), WithinRel(rr - zz, 1e-11));
  CHECK_THAT(ask("principal_min"), WithinRel(zz, 1e-11));
  CHECK_THAT(ask("principal_max"), WithinRel(rr, 1e-11));
  CHECK_THROWS_WITH(ask("xy"), Contains("component = 'xy'") && Contains("von_mises"));
  CHECK_THROWS_WITH(batch::evaluate(batch::parse(nlohmann::json{{"case", "flat_punch"}, {"quantity", "stress"},
                                                                {"material", material}, {"a", a}, {"d", 1e-6},
                                                                {"r", 0.}, {"component", "zz"}})),
                    Contains("z: missing"));
}

TEST_CASE("At k = 0 the axial stress below a JKR contact shall be Boussinesq's axis kernel over the JKR pressure",
          "[analytic][stress]")
{
  // sigma_zz(0, z) = -int_0^a p(rho) 3 z^3 rho / (rho^2 + z^2)^(5/2) drho (the axis stress of a ring of force
  // p 2 pi rho drho, from Boussinesq's sigma_zz), with p the JKR pressure (9.53) through eval.
  const double nu = 0.3, R = 0.05, dgamma = 0.5;
  const nlohmann::json material = {{"E0", E}, {"c0", c0}, {"k", 0.}, {"nu", nu}};
  const auto request = [&](const std::string &quantity, const double r, const double z) {
    nlohmann::json j = {{"case", "jkr_paraboloid"}, {"quantity", quantity}, {"material", material},
                        {"geometry", {{"R", R}}}, {"a", a}, {"dgamma", dgamma}, {"r", r}};
    if (quantity == "stress")
      {
        j["z"]         = z;
        j["component"] = "zz";
      }
    return batch::evaluate(batch::parse(j));
  };
  boost::math::quadrature::tanh_sinh<double> rule;
  for (const double zeta : {0.05, 0.5, 2.})
    {
      const double z = zeta * a;
      // rho = a sin(t): the edge's (a^2 - rho^2)^(-1/2) times drho = a cos(t) dt stays bounded.
      const double reference = -rule.integrate([&](const double t) {
        const double rho = a * std::sin(t);
        if (rho >= a) // t within rounding of pi/2, where the bounded integrand has no weight
          return 0.;
        return request("pressure", rho, 0.) * a * std::cos(t) * 3 * z * z * z * rho / std::pow(rho * rho + z * z, 2.5);
      }, 0., pi / 2, 1e-14);
      const double value = request("stress", 0., z);
      CAPTURE(zeta, value, reference);
      // The reference's pressure, evaluated at rho = a sin(t), rounds 1 - rho^2/a^2 near the edge: the 1D integral holds
      // about 1e-9 (the superposition, with the edge exponent in its rule, agrees with itself to 1e-16 at any rule).
      CHECK_THAT(value, WithinRel(reference, 1e-9));
    }
}

TEST_CASE("eval shall find the largest shear below a paraboloid where Huber puts it, and refuse an unbounded one",
          "[analytic][stress]")
{
  using Catch::Matchers::Contains;
  const double nu = 0.3, R = 0.05;
  const auto ask = [&](const double k, const std::string &c, const std::string &quantity, const char *shape) {
    nlohmann::json j = {{"case", shape}, {"quantity", quantity}, {"component", c}, {"a", a},
                        {"material", {{"E0", E}, {"c0", c0}, {"k", k}, {"nu", nu}}}};
    if (std::string(shape) == "paraboloid")
      j["geometry"] = {{"R", R}};
    else
      j["d"] = 1e-6;
    return batch::evaluate(batch::parse(j));
  };
  // Johnson 3.45: the largest shear 0.31 p0 on the axis at z = 0.48 a for nu = 0.3; von Mises is twice it there.
  const double p0 = pressure(medium(GradedHalfSpace{E, c0, 0., nu}), Paraboloid{R}, a, 0.);
  CHECK_THAT(ask(0., "max_shear", "max_stress", "paraboloid") / p0, WithinAbs(0.31, 0.001));
  CHECK_THAT(ask(0., "max_shear", "max_stress_depth", "paraboloid") / a, WithinAbs(0.48, 0.002));
  CHECK_THAT(ask(0., "max_shear", "max_stress_radius", "paraboloid") / a, WithinAbs(0., 1e-4));
  CHECK_THAT(ask(0., "von_mises", "max_stress", "paraboloid") / p0, WithinAbs(0.62, 0.002));
  CHECK_THROWS_WITH(ask(-0.5, "von_mises", "max_stress", "paraboloid"), Contains("k = -0.5") && Contains("unbounded"));
  CHECK_THROWS_WITH(ask(0.5, "max_shear", "max_stress", "flat_punch"), Contains("edge exponent") && Contains("unbounded"));
  CHECK_THROWS_WITH(ask(0.5, "zz", "max_stress", "paraboloid"), Contains("von_mises or max_shear"));
}

TEST_CASE("Outside the contact the surface's radial strain shall be Boussinesq's at k = 0 for any pressure, and "
          "unbounded at a flat punch's edge otherwise",
          "[analytic][stress]")
{
  // k = 0: outside an axisymmetric load F the surface's radial stress is (1 - 2 nu) F / (2 pi r^2) (Boussinesq's
  // surface field; Johnson, Contact Mechanics, 1985, ch. 3), whatever the pressure's shape. k != 0: sigma_rr / E(z)
  // tends to a strain combination at the surface, which below a flat punch grows like (r - a)^(-(1 + k)/2) at the
  // edge (the pressure's edge singularity (a - r)^((k - 1)/2) against the surface kernel ~ distance^-(2 + k)), while
  // below a paraboloid (edge exponent (1 + k)/2) it stays bounded.
  const double nu = 0.3;
  SECTION("k = 0")
  {
    const Medium m = medium(GradedHalfSpace{E, c0, 0., nu});
    const double d = 1e-6, R = 0.05;
    const PointLoadField field(0., nu);
    for (const auto &[load, F] : {std::pair{contact_pressure(m, FlatPunch{a}, d), force(m, FlatPunch{a}, d)},
                                  std::pair{contact_pressure(m, Paraboloid{R}, a), force(m, Paraboloid{R}, a)}})
      for (const double rho : {1.01, 1.1, 1.5, 3.})
        {
          const double exact = (1 - 2 * nu) * F / (2 * pi * rho * rho * a * a);
          CAPTURE(rho);
          CHECK_THAT(subsurface_stress(field, load, rho * a, 1e-10 * a).rr, WithinRel(exact, 1e-6));
        }
  }
  SECTION("k = 0.5")
  {
    const double         k = 0.5;
    const Medium         m = medium(GradedHalfSpace{E, c0, k, nu});
    const PointLoadField field(k, nu);
    const auto strain = [&](const AxisymmetricPressure &load, const double delta) {
      const double z = 1e-7 * delta * a;
      return subsurface_stress(field, load, (1 + delta) * a, z).rr / std::pow(z / c0, k);
    };
    const auto exponent = [&](const AxisymmetricPressure &load) {
      return std::log(strain(load, 1e-5) / strain(load, 1e-4)) / std::log(0.1);
    };
    CHECK_THAT(exponent(contact_pressure(m, FlatPunch{a}, 1e-6)), WithinAbs(-(1 + k) / 2, 0.01));
    CHECK_THAT(exponent(contact_pressure(m, Paraboloid{0.05}, a)), WithinAbs(0., 0.05));
  }
}
