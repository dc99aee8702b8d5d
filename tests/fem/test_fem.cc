// Tests of the axisymmetric FE model of the graded half-space (fem/).
//
// References are the chapter's closed forms, written out here (the FE library never sees them):
//   h_N(k, nu)                                                         (9.5)-(9.7)
//   flat punch    F = 2 h_N E0 d a^{1+k} / ((1 - nu^2)(1 + k) c0^k)    (9.16)
//   paraboloid    d = a^2 / ((1 + k) R),
//                 F = 4 h_N E0 a^{k+3} / ((1 - nu^2) c0^k (1 + k)^2 (k + 3) R),
//                 p = 2 h_N E0 a^{k+1} / (pi (1 - nu^2) c0^k (1 + k)^2 R) (1 - r^2/a^2)^{(1+k)/2}  (9.26)
//   constant p0   w_c = 2 c0^k (1 - nu^2) cos(k pi / 2) F / (h_N (1 - k) E0 pi a^{1+k})       (9.39)
//   concave       F = 2 h_N E0 a^{1+k} / ((1 - nu^2)(1 + k) c0^k) (d0 + 2 h0 / (k + 3)),
//                 complete contact iff d0 > 2 (1 - k) h0 / (1 + k)^2                           (9.34), (9.35)
// The surface displacement outside the contact is taken from the analytic library (analytic/normal.h,
// checked against 34-digit references of the MDR integrals), not written out here.
// Tolerances are the measured errors of the default discretisation (fem_study; fem/doc/accuracy-and-cost.md)
// with a margin of about 2.5x, each with its reason; they are not loosened to pass.
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/base/gauss_jacobi.h>
#include <fem/modulus/modulus.h>

#include <analytic/material.h>
#include <analytic/normal.h>

#include "written_out.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>

using namespace gradcontact::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double pi = 3.14159265358979323846;
  constexpr double nu = 0.3;
  constexpr double E0 = 2.0e9;  // deliberately not 1: catches a missing E0 factor
  constexpr double c0 = 3.0e-4; // != a: catches a missing c0^k
  constexpr double a  = 1.0e-4;

  using gradcontact::fem::testing::h_N;

  double flat_punch_force(const double k, const double d)
  {
    return 2 * h_N(k, nu) * E0 * d * std::pow(a, 1 + k) / ((1 - nu * nu) * (1 + k) * std::pow(c0, k));
  }

  Material power_law(const double k)
  {
    return Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  }

  DiscretizationParameters default_discretization()
  {
    return DiscretizationParameters{}; // degree 3
  }

  // Bounds on the relative errors of the default discretisation (degree 3, h_edge = 1e-5 a, rings g = 1.15,
  // recommended_mesh_parameters with truncation 1e-8), with a margin over its discretisation error, which the
  // edge singularity (k <= 0) and the surface layer (k > 0) limit; `test_fem -s` prints each error (CAPTURE).
  constexpr double flat_punch_tolerance = 5e-6;
  // Paraboloid under contact-radius control: the depth from the edge-node criterion has an O(h_edge)
  // error (for k = -0.5 several times the bound without the surface layer, which the stiff surface needs).
  // The force at the FE depth is held to the required bound, 1e-5.
  // The contact radius at the FE depth, a(d) = sqrt((1 + k) R d), is off by half the depth error, so the
  // depth bound is also the radius check (a separate 1e-4 radius bound could not fail).
  constexpr double paraboloid_depth_tolerance = 5e-6;
  constexpr double paraboloid_force_tolerance = 1e-5;
  // Recovered pressure at 0.05 a .. 0.9 a, relative to p(0): largest at k = -0.5, within the bound.
  constexpr double paraboloid_pressure_tolerance = 1e-5;
  // Surface displacement of the paraboloid outside the contact: near the contact (1.5 a, 10 a) within a few
  // times the force's bound; at 1000 a a looser bound, since at k = 0.5 the far rings, h ~ 0.15 r, resolve the
  // slower decay worst.
  constexpr double outside_displacement_tolerance = 2.5e-5; // r = 1.5 a and 10 a
  constexpr double far_displacement_tolerance     = 1.5e-3; // r = 1000 a
  // Constant pressure: w_c, held to the same bound as the recovered pressure.
  constexpr double pressure_centre_tolerance = 1e-5;
} // namespace



TEST_CASE("The Gauss-Jacobi rule shall integrate x^s times polynomials of degree 2n-1 exactly", "[fem][quick]")
{
  const double       s = GENERATE(-0.5, 0.0, 0.5, -0.9);
  const unsigned int n = GENERATE(1u, 3u, 6u);
  const auto         q = gauss_jacobi(n, s);
  for (unsigned int j = 0; j < 2 * n; ++j)
    {
      double sum = 0;
      for (unsigned int i = 0; i < q.size(); ++i)
        sum += q.weight(i) * std::pow(q.point(i)[0], j);
      const double exact = 1.0 / (j + 1 + s); // \int_0^1 x^{s+j} dx
      CAPTURE(s, n, j, sum, exact);
      REQUIRE_THAT(sum, WithinRel(exact, 1e-13));
    }
}



TEST_CASE("The corner rule shall integrate (distance from its vertex)^s over the square, at every vertex",
          "[fem][quick]")
{
  // With x, y the distances from vertex v along the axes, in closed form (integrating in x first):
  //   \int_0^1 \int_0^1 (x + y)^s dx dy   = (2^(s+2) - 2) / ((s + 1)(s + 2)),
  //   \int_0^1 \int_0^1 x (x + y)^s dx dy = (2^(s+2) - 1) / ((s + 1)(s + 2)) - (2^(s+3) - 2) / ((s + 1)(s + 2)(s + 3))
  // (both checked against mpmath's quadrature to 30 digits). The factor x, which vanishes on one edge through the
  // vertex, tells the mirrored axes apart.
  const double       s = GENERATE(-0.5, -0.9, 0.5);
  const unsigned int v = GENERATE(0u, 1u, 2u, 3u);
  const auto         q = surface_corner_quadrature(4, s, v);
  double             plain = 0, weighted = 0;
  for (unsigned int i = 0; i < q.size(); ++i)
    {
      const double x = v % 2 == 1 ? 1 - q.point(i)[0] : q.point(i)[0];
      const double y = v / 2 == 1 ? 1 - q.point(i)[1] : q.point(i)[1];
      plain += q.weight(i) * std::pow(x + y, s);
      weighted += q.weight(i) * x * std::pow(x + y, s);
    }
  const double exact_plain = (std::pow(2.0, s + 2) - 2) / ((s + 1) * (s + 2));
  const double exact_weighted =
    (std::pow(2.0, s + 2) - 1) / ((s + 1) * (s + 2)) - (std::pow(2.0, s + 3) - 2) / ((s + 1) * (s + 2) * (s + 3));
  CAPTURE(s, v, plain, exact_plain, weighted, exact_weighted);
  CHECK_THAT(plain, WithinRel(exact_plain, 1e-12));
  CHECK_THAT(weighted, WithinRel(exact_weighted, 1e-12));
  CHECK_THROWS_WITH(surface_corner_quadrature(4, s, 4), Catch::Matchers::Contains("singular_vertex = 4"));
}

TEST_CASE("The layered modulus shall hold the exact layer averages of the power law", "[fem][quick]")
{
  const double k    = GENERATE(-0.5, 0.5);
  auto         base = std::make_shared<PowerLawModulus>(E0, c0, k);
  auto         generic = std::make_shared<ExpressionModulus>(
    "E0*(z/c0)^k", std::map<std::string, double>{{"E0", E0}, {"c0", c0}, {"k", k}}, k);
  const auto layered = LayeredModulus::uniform(base, 4, 4 * a);
  for (unsigned int i = 0; i < 4; ++i)
    {
      const double z1 = i * a, z2 = (i + 1) * a;
      const double exact =
        E0 * (std::pow(z2 / c0, 1 + k) - std::pow(z1 / c0, 1 + k)) * c0 / ((1 + k) * (z2 - z1));
      CAPTURE(k, i, layered->layer_modulus[i], exact);
      REQUIRE_THAT(layered->layer_modulus[i], WithinRel(exact, 1e-13));
      // the numerical average of the generic path agrees (Gauss-Jacobi in the first layer)
      REQUIRE_THAT(generic->average(z1, z2), WithinRel(exact, 1e-12));
    }
}

TEST_CASE("The solver shall reject bad input with a message naming the parameter", "[fem][quick]")
{
  auto message_of = [](auto &&f) -> std::string {
    try
      {
        f();
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  };
  // k = 1 is the Gibson medium (valid for the mixed formulation with nu = 0.5 only).
  CHECK_THAT(message_of([] { PowerLawModulus(E0, c0, 1.0000001); }), Catch::Contains("k = 1.0000001"));
  CHECK_THAT(message_of([] { Material{std::make_shared<PowerLawModulus>(E0, c0, 1.0), 0.3}.validate(); }),
             Catch::Contains("surface exponent = 1"));
  CHECK_THAT(message_of([] { PowerLawModulus(-1.0, c0, 0.0); }), Catch::Contains("E0"));
  CHECK_THAT(message_of([] { Material{std::make_shared<PowerLawModulus>(E0, c0, 0.0), 0.5}.validate(); }),
             Catch::Contains("nu = 0.5"));
  CHECK_THAT(message_of([] { ExpressionModulus("E0*(z/", {}); }), Catch::Contains("cannot parse"));
  CHECK_THAT(message_of([] {
               MeshParameters p;
               p.far_field_size = 1e20;
               p.validate();
             }),
             Catch::Contains("far_field_size"));
  CHECK_THAT(message_of([] {
               DiscretizationParameters d;
               d.degree = 9;
               d.validate();
             }),
             Catch::Contains("degree = 9") && Catch::Contains("[1, 8]"));
  CHECK_THAT(message_of([] { Profile::paraboloid(-1.0); }), Catch::Contains("R = -1"));
  CHECK_THAT(message_of([] {
               LoadCase l;
               l.type  = LoadType::flat_punch;
               l.depth = 0;
               l.validate();
             }),
             Catch::Contains("depth"));
}

TEST_CASE("The solver shall reproduce the flat-punch force (9.16) and the paraboloid (9.26) "
          "under contact-radius control",
          "[fem][quick]")
{
  const double k = GENERATE(0.0, 0.5, -0.5);
  AxisymmetricSolver solver(power_law(k), recommended_mesh_parameters(a, k), default_discretization());

  // Flat punch: two depths reuse one factorisation; the force is linear in d.
  const double d = 1e-3 * a;
  LoadCase     punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = d;
  const Result flat = solver.run(punch);
  punch.depth       = 2 * d;
  const Result flat2 = solver.run(punch);
  const double F_ref = flat_punch_force(k, d);
  CAPTURE(k, flat.n_dofs, flat.force, F_ref, flat.force / F_ref - 1, flat.energy_mismatch);
  std::cout << "[fem] flat punch k = " << k << ": rel. error " << flat.force / F_ref - 1 << ", "
            << flat.n_dofs << " DoFs, mesh+setup+assembly "
            << flat.time.mesh + flat.time.setup + flat.time.assemble << " s, factorisation "
            << flat.time.factorize << " s, solve " << flat.time.solve << " s\n";
  REQUIRE(flat.reliable);
  REQUIRE_THAT(flat.force, WithinRel(F_ref, flat_punch_tolerance));
  REQUIRE(flat2.time.factorize == 0.0); // reused
  REQUIRE_THAT(flat2.force, WithinRel(2 * flat.force, 1e-12));

  // Paraboloid at contact radius a.
  const double R = 50 * a;
  LoadCase     sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(R);
  OutputRequest out;
  // Not r = 0: the r-weighted recovery M p = R barely constrains the axis node (at k = -0.5 its error there
  // is orders of magnitude above the bound, at k = 0 within it).
  out.pressure_radii = {0.05 * a, 0.3 * a, 0.6 * a, 0.9 * a};
  out.displacement_radii = {1.5 * a, 10 * a, 1000 * a};
  const Result hertz  = solver.run(sphere, out);
  // The FE gives a point (a, d, F) of its force-depth-radius curve; compare the force and the contact
  // radius at the FE depth (the required bounds 1e-5 and 1e-4), and the depth at the given radius.
  const double d_ref   = a * a / ((1 + k) * R);
  auto         force_at_radius = [&](const double r) {
    return gradcontact::fem::testing::paraboloid_force(k, nu, E0, c0, r, R);
  };
  const double a_at_depth = std::sqrt((1 + k) * R * hertz.depth);
  const double F_at_depth = force_at_radius(a_at_depth);
  const double p0 = 2 * h_N(k, nu) * E0 * std::pow(a, k + 1) /
                    (pi * (1 - nu * nu) * std::pow(c0, k) * (1 + k) * (1 + k) * R);
  CAPTURE(hertz.depth, d_ref, hertz.depth / d_ref - 1, hertz.force, F_at_depth,
          hertz.force / F_at_depth - 1, a_at_depth / a - 1, hertz.message);
  std::cout << "[fem] paraboloid k = " << k << ": depth(a) error " << hertz.depth / d_ref - 1
            << ", F(d) error " << hertz.force / F_at_depth - 1 << ", a(d) error "
            << a / a_at_depth - 1 << ", F(a) error " << hertz.force / force_at_radius(a) - 1 << '\n';
  REQUIRE(hertz.consistent_contact);
  REQUIRE_THAT(hertz.depth, WithinRel(d_ref, paraboloid_depth_tolerance));
  REQUIRE_THAT(hertz.force, WithinRel(F_at_depth, paraboloid_force_tolerance));
  for (const Sample &p : hertz.pressure)
    {
      const double exact = p0 * std::pow(1 - p.r * p.r / (a * a), (1 + k) / 2);
      CAPTURE(p.r / a, p.value, exact, (p.value - exact) / p0);
      std::cout << "[fem]   p(" << p.r / a << " a) error / p0 " << (p.value - exact) / p0 << '\n';
      REQUIRE_THAT(p.value, WithinAbs(exact, paraboloid_pressure_tolerance * p0));
    }
  // The surface outside the contact against the closed form at the prescribed radius a (w(r) for r > a,
  // analytic/normal.h), relative to the depth: see far_displacement_tolerance.
  const auto medium = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  REQUIRE(hertz.displacement.size() == 3);
  for (const Sample &w : hertz.displacement)
    {
      const double exact = gradcontact::displacement(medium, gradcontact::Paraboloid{R}, a, w.r);
      CAPTURE(w.r / a, w.value, exact, w.value / exact - 1);
      std::cout << "[fem]   w(" << w.r / a << " a) error " << w.value / exact - 1 << '\n';
      REQUIRE_THAT(w.value, WithinRel(exact, w.r < 100 * a ? outside_displacement_tolerance
                                                            : far_displacement_tolerance));
    }
}

TEST_CASE("For a force tolerance of 2e-4 or more at k <= 0.5 the recommended settings shall be degree 2 and "
          "meet it on the flat punch (9.16)",
          "[fem]")
{
  // recommended_settings (fem/grid/discretization.h): degree 2 on the mesh of degree 3. Required: half the tolerance
  // asked (1e-4 for 2e-4), a smaller margin at k = 0.5 than this file's usual 2.5x because the bound is the
  // contract (the tolerance), not a margin over this mesh's error.
  constexpr double asked = 2e-4;
  const double     k     = GENERATE(-0.5, 0.0, 0.5);
  const Settings   s     = recommended_settings(a, k, asked);
  REQUIRE(s.discretization.degree == 2);
  // the same mesh as degree 3's
  const Settings tighter = recommended_settings(a, k, 1e-4);
  CHECK(s.mesh.h_edge == tighter.mesh.h_edge);
  CHECK(s.mesh.ring_growth == tighter.mesh.ring_growth);
  CHECK(s.mesh.far_field_size == tighter.mesh.far_field_size);
  CHECK(s.mesh.surface_layer_thickness == tighter.mesh.surface_layer_thickness);
  AxisymmetricSolver solver(power_law(k), s.mesh, s.discretization);
  LoadCase           punch;
  punch.type         = LoadType::flat_punch;
  punch.depth        = 1e-3 * a;
  const Result flat  = solver.run(punch);
  const double F_ref = flat_punch_force(k, punch.depth);
  CAPTURE(k, flat.n_dofs, flat.force / F_ref - 1);
  REQUIRE(flat.reliable);
  CHECK_THAT(flat.force, WithinRel(F_ref, asked / 2));

  // Tighter tolerances, the surface exponents where degree 2 falls short of it (k = 0.9, even with the surface
  // map) and the unchecked k < -0.9 keep degree 3.
  CHECK(tighter.discretization.degree == 3);
  CHECK(recommended_settings(a, 0.9, asked).discretization.degree == 3);
  CHECK(recommended_settings(a, -0.95, asked).discretization.degree == 3);
}

TEST_CASE("The solver shall give the centre displacement of a constant pressure (9.39) and "
          "report incomplete contact of a concave punch (9.35)",
          "[fem]")
{
  const double k = GENERATE(0.0, 0.5);
  AxisymmetricSolver solver(power_law(k), recommended_mesh_parameters(a, k), default_discretization());

  const double p0 = 1e6;
  LoadCase     load;
  load.type     = LoadType::constant_pressure;
  load.pressure = p0;
  const Result pressure = solver.run(load);
  const double F        = p0 * pi * a * a;
  const double w_c      = 2 * std::pow(c0, k) * (1 - nu * nu) * std::cos(k * pi / 2) * F /
                     (h_N(k, nu) * (1 - k) * E0 * pi * std::pow(a, 1 + k));
  CAPTURE(k, pressure.depth, w_c, pressure.depth / w_c - 1);
  std::cout << "[fem] constant pressure k = " << k << ": w_c error " << pressure.depth / w_c - 1 << '\n';
  // An input check, not an FE result: the reported force is the quadrature of the prescribed pressure.
  REQUIRE_THAT(pressure.force, WithinRel(F, 1e-14));
  REQUIRE_THAT(pressure.depth, WithinRel(w_c, pressure_centre_tolerance));

  // Concave punch: complete contact above the bound of (9.35), a report below it.
  const double h0 = 1e-4 * a;
  const double d0_min = 2 * (1 - k) * h0 / ((1 + k) * (1 + k));
  load.type    = LoadType::concave_punch;
  load.profile = Profile::concave_paraboloid(h0);
  load.depth   = 3 * d0_min;
  const Result complete = solver.run(load);
  const double F_ref = 2 * h_N(k, nu) * E0 * std::pow(a, 1 + k) /
                       ((1 - nu * nu) * (1 + k) * std::pow(c0, k)) * (load.depth + 2 * h0 / (k + 3));
  CAPTURE(complete.force, F_ref, complete.force / F_ref - 1, complete.message);
  REQUIRE(complete.consistent_contact);
  REQUIRE_THAT(complete.force, WithinRel(F_ref, flat_punch_tolerance));
  load.depth = 0.3 * d0_min;
  const Result incomplete = solver.run(load);
  CAPTURE(incomplete.message);
  REQUIRE_FALSE(incomplete.consistent_contact);
  REQUIRE_THAT(incomplete.message, Catch::Contains("not complete"));
}

TEST_CASE("The flat-punch force shall converge under uniform refinement with the observed order "
          "fitted over the last three levels",
          "[verification]")
{
  // k = 0, degree 2, coarse far-field rings (g = 1.6) and a moderate edge grading, so that the smooth
  // discretisation error dominates and every level of global refinement halves all cells, including the
  // edge cells. The force is an energy functional, so its error falls faster than h^p until the edge
  // singularity starts to dominate at the finest level; the order fitted over the three levels stays above
  // the asserted 2.5 (`test_fem -s` prints the errors and the order).
  constexpr double minimum_order = 2.5;
  const double     k             = 0.0;
  const double     d             = 1e-3 * a;
  DiscretizationParameters disc;
  disc.degree = 2;
  std::vector<double> h, error;
  for (unsigned int level = 0; level < 3; ++level)
    {
      MeshParameters mesh   = recommended_mesh_parameters(a, k);
      mesh.ring_growth      = 1.6;
      mesh.h_edge           = 1e-3;
      mesh.h_far            = 1.5;
      mesh.global_refinements = level;
      AxisymmetricSolver solver(power_law(k), mesh, disc);
      LoadCase           punch;
      punch.type  = LoadType::flat_punch;
      punch.depth = d;
      const Result result = solver.run(punch);
      h.push_back(std::pow(0.5, level));
      error.push_back(std::abs(result.force / flat_punch_force(k, d) - 1));
      std::cout << "[verification] level " << level << ": " << result.n_dofs << " DoFs, error "
                << error.back() << '\n';
    }
  // least-squares slope of log(error) against log(h) over the three levels
  double mx = 0, my = 0;
  for (unsigned int i = 0; i < 3; ++i)
    {
      mx += std::log(h[i]) / 3;
      my += std::log(error[i]) / 3;
    }
  double sxy = 0, sxx = 0;
  for (unsigned int i = 0; i < 3; ++i)
    {
      sxy += (std::log(h[i]) - mx) * (std::log(error[i]) - my);
      sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
    }
  const double order = sxy / sxx;
  CAPTURE(error[0], error[1], error[2], order, minimum_order);
  std::cout << "[verification] observed order " << order << '\n';
  REQUIRE(order >= minimum_order);
}
