// Tests of the surface map (fem/modulus/surface_map.h): its derivatives against central differences of Phi, its
// refusals, and the FE with it against the flat punch (9.16) and the paraboloid (9.26), written out here,
// where the model without it is far off (k = 0.9) or needs three times the DoFs (k = 0.5).
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/modulus/modulus.h>
#include <fem/modulus/surface_map.h>

#include "written_out.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>

using namespace gradcontact::fem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double nu = 0.3;
  constexpr double E0 = 2.0e9;
  constexpr double c0 = 3.0e-4;
  constexpr double a  = 1.0e-4;

  double flat_punch_force(const double k, const double d)
  {
    return gradcontact::fem::testing::flat_punch_force(k, nu, E0, c0, a, d); // (9.16)
  }

  SurfaceMapParameters map_on(const double scale = 0)
  {
    SurfaceMapParameters p;
    p.enabled = true;
    p.scale   = scale;
    return p;
  }

  /// Phi at x (mesh coordinates) by the map.
  template <int dim>
  double phi(const SurfaceMap<dim> &map, const dealii::Point<dim> &x)
  {
    return map.at(x).z;
  }
} // namespace

TEST_CASE("The surface map's dPhi/dzeta and tangential shift equal central differences of Phi", "[fem][quick]")
{
  const double s = GENERATE(0.2, 0.5, 0.9);
  const PowerLawModulus modulus(E0, c0, s);
  const SurfaceMap<2>   map2(map_on(), modulus, a, 1e-5);
  const SurfaceMap<3>   map3(map_on(), modulus, a, 1e-5);
  REQUIRE(map2.active());
  REQUIRE(map2.exponent() == Approx(1 / (1 - s)).epsilon(1e-15));
  for (const double r : {0.0, 0.3 * a, 0.999 * a, a, 1.02 * a, 5 * a, 1e3 * a})
    for (const double zeta : {1e-9 * a, 1e-6 * a, 1e-3 * a, 0.1 * a, 2 * a, 1e4 * a})
      {
        CAPTURE(s, r / a, zeta / a);
        const dealii::Point<2> x(r, zeta);
        const auto             m = map2.at(x);
        const double           h = 1e-5 * zeta;
        const double dz_fd = (phi(map2, dealii::Point<2>(r, zeta + h)) - phi(map2, dealii::Point<2>(r, zeta - h))) / (2 * h);
        REQUIRE(m.dz > 0);
        REQUIRE(m.z > 0);
        REQUIRE_THAT(m.dz, WithinRel(dz_fd, 1e-6));
        // dPhi/dr = shift * dPhi/dzeta (Phi is even in r: no shift on the axis).
        if (r == 0.0)
          REQUIRE(m.shift[0] == 0.0);
        else
          {
            // Steps on the scale of the variation (T depends on sqrt(u^2 + zeta^2)), above Phi's round-off.
            const double hr    = 1e-6 * std::max(r, zeta);
            const double dr_fd = (phi(map2, dealii::Point<2>(r + hr, zeta)) - phi(map2, dealii::Point<2>(r - hr, zeta))) /
                                 (2 * hr);
            REQUIRE(std::abs(m.shift[0] * m.dz - dr_fd) <= 1e-6 * std::abs(m.dz) + 1e-6 * std::abs(dr_fd));
          }
        REQUIRE(m.shift[1] == 0.0);
        // 3D: the same map of r = |(x, y)|, its shift along (x, y) / r. x^2 + y^2 differs from r^2 by round-off,
        // which r^2 - a^2 amplifies near the edge (1e-16 / 2e-3 at r = 0.999 a) and T^{1-beta} by beta - 1 = 9.
        const double           c = std::cos(0.7), sn = std::sin(0.7);
        const auto             m3 = map3.at(dealii::Point<3>(r * c, r * sn, zeta));
        REQUIRE_THAT(m3.z, WithinRel(m.z, 1e-11));
        REQUIRE_THAT(m3.dz, WithinRel(m.dz, 1e-11));
        REQUIRE(std::abs(m3.shift[0] - m.shift[0] * c) <= 1e-11 * std::abs(m.shift[0]));
        REQUIRE(std::abs(m3.shift[1] - m.shift[0] * sn) <= 1e-11 * std::abs(m.shift[0]));
      }
  // Near the surface z^{1 - s} is linear in zeta: z^{1-s} / zeta -> T^{-s} as zeta -> 0.
  const dealii::Point<2> x0(0.5 * a, 1e-12 * a), x1(0.5 * a, 2e-12 * a);
  const double           T = map2.length(x0);
  REQUIRE_THAT(std::pow(phi(map2, x0), 1 - s) / x0[1], WithinRel(std::pow(T, -s), 1e-9));
  REQUIRE_THAT(std::pow(phi(map2, x1), 1 - s) / std::pow(phi(map2, x0), 1 - s), WithinRel(2.0, 1e-9));
}

TEST_CASE("The surface map's inverse returns the mesh point of every physical point", "[fem][quick]")
{
  // Points on the axis, at the contact edge and far out, from the surface layer to deep below; the inverse's Newton
  // steps must not stop on a bracket's midpoint once they have converged.
  for (const double k : {0.2, 0.5, 0.9})
    {
      const PowerLawModulus modulus(E0, c0, k);
      const SurfaceMap<2>   map(map_on(), modulus, a, 1e-5);
      for (const double r : {0.0, 0.02 * a, a, 1.5 * a, 100 * a})
        for (const double z : {1e-9 * a, 1e-3 * a, 0.1 * a, 0.25 * a, 2 * a, 1e3 * a})
          {
            const dealii::Point<2> x = map.mesh_point(dealii::Point<2>(r, z));
            CAPTURE(k, r / a, z / a, x[1] / a);
            CHECK(x[0] == r);
            CHECK(std::abs(map.physical(x)[1] - z) <= 1e-14 * z);
          }
    }
}



TEST_CASE("The surface map refuses what it cannot map, naming the parameter", "[fem][quick]")
{
  // Off, or a modulus finite at the surface: the identity.
  const PowerLawModulus half(E0, c0, 0.5), homogeneous(E0, c0, 0.0), negative(E0, c0, -0.5), gibson(E0, c0, 1.0);
  REQUIRE_FALSE(SurfaceMap<2>(SurfaceMapParameters{}, half, a, 1e-5).active());
  REQUIRE_FALSE(SurfaceMap<2>(map_on(), homogeneous, a, 1e-5).active());
  REQUIRE(SurfaceMap<2>(SurfaceMapParameters{}, homogeneous, a, 1e-5).at(dealii::Point<2>(a, 0.25 * a)).z == 0.25 * a);
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(), negative, a, 1e-5), Contains("surface exponent = -0.5"));
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(), gibson, a, 1e-5), Contains("surface exponent = 1"));
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(0.01), half, a, 1e-5), Contains("scale = 0.01"));
  SurfaceMapParameters bad_floor = map_on();
  bad_floor.floor                = 2;
  REQUIRE_THROWS_WITH(SurfaceMap<2>(bad_floor, half, a, 1e-5), Contains("floor = 2"));
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(), half, -a, 1e-5), Contains("contact_radius"));
  // A coating (a jump of E at H) on the power law.
  const CoatingModulus coating(E0, c0, 0.5, 0.1 * a);
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(), coating, a, 1e-5), Contains("first jump depth"));
  const PowerLawModulus steep(E0, c0, 0.96875);
  REQUIRE_THROWS_WITH(SurfaceMap<2>(map_on(), steep, a, 1e-5), Contains("surface exponent = 0.96875"));
  // The discretisation refuses a bad scale too, before any solve.
  DiscretizationParameters d;
  d.surface_map = map_on(50);
  REQUIRE_THROWS_WITH(d.validate(), Contains("scale = 50"));
}

TEST_CASE("With the surface map the flat punch reaches (9.16) at k = 0.9 and k = 0.5 without thin cells", "[fem]")
{
  const double k     = GENERATE(0.5, 0.9);
  Material     mat{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  MeshParameters mesh                 = recommended_mesh_parameters(a, k);
  mesh.surface_layer_thickness        = 1.0; // no z-halvings
  mesh.h_edge                         = 1e-7;
  mesh.h_far                          = 4.0;
  mesh.ring_growth                    = 1.3;
  DiscretizationParameters with_map;
  with_map.degree      = 4;
  with_map.surface_map = map_on();
  LoadCase punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = 1e-3 * a;
  const double F_ref = flat_punch_force(k, punch.depth);

  AxisymmetricSolver mapped(mat, mesh, with_map);
  const Result       r = mapped.run(punch);
  // The same mesh without the map: u_z ~ d - c z^{1-k} in cells of 1e-7 a .. 0.25 a thickness.
  DiscretizationParameters without = with_map;
  without.surface_map.enabled      = false;
  AxisymmetricSolver plain(mat, mesh, without);
  const Result       r0 = plain.run(punch);
  CAPTURE(k, r.n_dofs, r.force / F_ref - 1, r0.force / F_ref - 1, r.energy_mismatch);
  std::cout << "[fem] surface map, flat punch k = " << k << ": " << r.force / F_ref - 1 << " (without the map "
            << r0.force / F_ref - 1 << "), " << r.n_dofs << " DoFs\n";
  REQUIRE(r.reliable);
  REQUIRE(r.mesh.n_halvings == 0);
  // With the map the force meets the bound of each k (looser at k = 0.9, nearer the Gibson limit); without it the
  // error is more than a hundred times larger (the check below), near k = 1 of order one.
  REQUIRE_THAT(r.force, WithinRel(F_ref, k < 0.7 ? 2e-7 : 2e-5));
  REQUIRE(std::abs(r0.force / F_ref - 1) > 100 * std::abs(r.force / F_ref - 1));
}

TEST_CASE("With the surface map the mixed formulation gives the paraboloid (9.26) at k = 0.5, nu = 1/2", "[fem]")
{
  const double k  = 0.5;
  const double v  = 0.5;
  Material     mat{std::make_shared<PowerLawModulus>(E0, c0, k), v};
  MeshParameters mesh          = recommended_mesh_parameters(a, k);
  mesh.surface_layer_thickness = 1.0;
  DiscretizationParameters d;
  d.formulation = Formulation::mixed;
  d.surface_map = map_on();
  AxisymmetricSolver solver(mat, mesh, d);
  const double       R = 50 * a;
  LoadCase           sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(R);
  const Result h = solver.run(sphere);
  // (9.26) at the FE depth: a(d) = sqrt((1 + k) R d), F(a).
  const double a_fe  = std::sqrt((1 + k) * R * h.depth);
  const double F_ref = gradcontact::fem::testing::paraboloid_force(k, v, E0, c0, a_fe, R);
  CAPTURE(h.n_dofs, h.force / F_ref - 1, a_fe / a - 1);
  REQUIRE(h.reliable);
  // F and d within 1e-6; the mixed model with z-halvings to 1e-10 a gets closer, with far more DoFs.
  REQUIRE_THAT(h.force, WithinRel(F_ref, 1e-6));
  REQUIRE_THAT(a_fe, WithinRel(a, 1e-6));
}
