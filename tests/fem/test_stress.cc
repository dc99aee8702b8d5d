// Tests of the FE stresses (fem/elasticity/stress_recovery.h) below a contact.
// References, each from a path independent of the FE:
// - k = 0: Huber's closed-form Hertz field (Ann. Phys. 14 (1904) 153), written out here: the axis stresses
//     sigma_zz = -p0 / (1 + z^2/a^2),
//     sigma_rr = sigma_tt = -p0 [ (1 + nu) (1 - (z/a) atan(a/z)) - 1 / (2 (1 + z^2/a^2)) ],
//   the largest shear 0.31002 p0 at z = 0.48087 a (nu = 0.3; the root of d(sigma_rr - sigma_zz)/dz = 0 of these
//   formulas), and the surface radial stress (1 - 2 nu) p0 / 3 at the contact edge.
// - Holl's ratio nu = 1/(2 + k): the superposition of Froehlich's radial point-load field over the contact pressure
//   (analytic/subsurface.h, itself checked against a one-dimensional integral of Froehlich's field in
//   tests/analytic/test_subsurface.cc).
// - Other k: the same superposition of the graded Boussinesq field (analytic/point_load.h).
#include <fem/accuracy/accuracy.h>
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/modulus/modulus.h>

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/subsurface.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <iostream>
#include <memory>
#include <stdexcept>

using namespace gradcontact::fem;

namespace
{
  constexpr double E0 = 2.0e9;
  constexpr double c0 = 3.0e-4;
  constexpr double a  = 1.0e-4;
  constexpr double pi = 3.14159265358979323846;

  /// The largest relative difference of the four components, relative to `scale`.
  double difference(const StressValue &fe, const gradcontact::AxisymmetricStress &ref, const double scale)
  {
    return std::max({std::abs(fe.rr - ref.rr), std::abs(fe.zz - ref.zz), std::abs(fe.tt - ref.tt),
                     std::abs(fe.rz - ref.rz)}) /
           scale;
  }

  gradcontact::AxisymmetricStress huber_axis(const double p0, const double nu, const double z)
  {
    const double t = z / a, s = -p0 * ((1 + nu) * (1 - t * std::atan(1 / t)) - 0.5 / (1 + t * t));
    return {s, -p0 / (1 + t * t), s, 0.0};
  }

  /// The paraboloid of radius R pressed to contact radius a on E0 (z/c0)^k, nu, with the stresses at `points`.
  Result paraboloid(const double k, const double nu, const std::vector<StressPoint> &points,
                    const DiscretizationParameters &discretization, const MeshParameters &mesh)
  {
    Material           material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
    AxisymmetricSolver solver(material, mesh, discretization);
    LoadCase           sphere;
    sphere.type    = LoadType::indenter;
    sphere.profile = Profile::paraboloid(50 * a);
    OutputRequest out;
    out.stress_points = points;
    return solver.run(sphere, out);
  }
} // namespace



TEST_CASE("The FE stresses of the Hertz contact (k = 0) shall equal Huber's field", "[fem][quick]")
{
  const double nu = 0.3, R = 50 * a;
  const double p0 = 2 * E0 / (1 - nu * nu) * a / (pi * R); // Hertz: p0 = 2 E* a / (pi R)
  std::vector<StressPoint> points;
  for (const double z : {0.1, 0.25, 0.48087, 1.0, 2.0})
    points.push_back({0.0, z * a});
  points.push_back({a, 0.0});
  DiscretizationParameters d;
  d.degree = 3;
  const Result r = paraboloid(0.0, nu, points, d, recommended_mesh_parameters(a, 0.0));
  REQUIRE(r.reliable);
  REQUIRE(r.stress.size() == points.size());
  double worst = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    {
      const double e = difference(r.stress[i], huber_axis(p0, nu, points[i].z), p0);
      std::cout << "[fem] Hertz axis z/a = " << points[i].z / a << ": " << e << "\n";
      worst = std::max(worst, e);
    }
  const StressValue &m          = r.stress[2];
  const double       max_shear  = 0.5 * (m.rr - m.zz) / p0;
  const double       edge_rr    = r.stress.back().rr / p0;
  std::cout << "[fem] Hertz: largest shear " << max_shear << " (0.31002), edge sigma_rr " << edge_rr << " ("
            << (1 - 2 * nu) / 3 << "), " << r.n_dofs << " DoFs\n";
  CHECK(worst < 1e-3);
  CHECK(std::abs(max_shear - 0.31002) < 2e-4);
  CHECK(std::abs(edge_rr - (1 - 2 * nu) / 3) < 1e-2);
}



namespace
{
  /// FE against the superposed point-load field (analytic/subsurface.h) at `points`, relative to the mean pressure;
  /// the worst difference, printed per point.
  double against_superposition(const double k, const double nu, const std::vector<StressPoint> &points,
                               const Settings &settings, const char *label)
  {
    const Result r = paraboloid(k, nu, points, settings.discretization, settings.mesh);
    REQUIRE(r.reliable);
    const double p_mean = r.force / (pi * a * a);
    const gradcontact::PointLoadField       field(k, nu);
    const gradcontact::AxisymmetricPressure load = gradcontact::contact_pressure(
      gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu}), gradcontact::Paraboloid{50 * a}, a);
    double worst = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        const double e = difference(r.stress[i],
                                    gradcontact::subsurface_stress(field, load, points[i].r, points[i].z), p_mean);
        std::cout << "[fem] " << label << " (r, z)/a = (" << points[i].r / a << ", " << points[i].z / a
                  << "): " << e << " p_m\n";
        worst = std::max(worst, e);
      }
    std::cout << "[fem] " << label << ": " << r.n_dofs << " DoFs\n";
    return worst;
  }

  std::vector<StressPoint> bulk_points()
  {
    return {{0.0, 0.5 * a}, {0.5 * a, 0.3 * a}, {0.9 * a, 0.1 * a}, {1.2 * a, 0.2 * a}, {0.3 * a, 1.0 * a},
            {2.0 * a, 1.0 * a}};
  }
} // namespace



TEST_CASE("The mixed formulation's FE stresses of the Hertz contact (k = 0, nu = 0.5) shall equal Huber's field",
          "[fem][quick]")
{
  // Huber's axis stresses hold at nu = 1/2 too; the volumetric part is the mixed formulation's pressure unknown there
  // (lambda tr eps is infinity times zero).
  const double nu = 0.5, R = 50 * a;
  const double p0 = 2 * E0 / (1 - nu * nu) * a / (pi * R);
  std::vector<StressPoint> points;
  for (const double z : {0.1, 0.48, 1.0, 2.0})
    points.push_back({0.0, z * a});
  DiscretizationParameters d;
  d.degree      = 3;
  d.formulation = Formulation::mixed;
  const Result r = paraboloid(0.0, nu, points, d, recommended_mesh_parameters(a, 0.0));
  REQUIRE(r.reliable);
  double worst = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    {
      const double e = difference(r.stress[i], huber_axis(p0, nu, points[i].z), p0);
      std::cout << "[fem] Hertz nu = 0.5, axis z/a = " << points[i].z / a << ": " << e << "\n";
      worst = std::max(worst, e);
    }
  CHECK(worst < 3e-4);
}



TEST_CASE("At Holl's ratio the FE stresses shall equal the superposed radial field (k = 0.5)", "[fem][quick]")
{
  const double k = 0.5, nu = 1 / (2 + k);
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  Settings     settings = recommended_settings(a, *material.modulus, 1e-6);
  use_surface_map(settings, *material.modulus);
  CHECK(against_superposition(k, nu, bulk_points(), settings, "Holl k = 0.5") < 4e-4);
}



TEST_CASE("On a stiff surface (k = -0.5) the FE stresses shall equal the superposed graded Boussinesq field",
          "[fem][quick]")
{
  const double k = -0.5, nu = 0.3;
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  const Settings settings = recommended_settings(a, *material.modulus, 1e-6);
  CHECK(against_superposition(k, nu, bulk_points(), settings, "k = -0.5") < 4e-4);
}



TEST_CASE("The FE stress shall refuse points outside the body and write its fields to the VTU file", "[fem][quick]")
{
  DiscretizationParameters d;
  d.degree = 2;
  MeshParameters mesh = recommended_mesh_parameters(a, 0.0);
  Material       material{std::make_shared<PowerLawModulus>(E0, c0, 0.0), 0.3};
  AxisymmetricSolver solver(material, mesh, d);
  LoadCase           punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = 1e-3 * a;
  OutputRequest out;
  out.stress_points = {{0.0, -0.1 * a}};
  CHECK_THROWS_WITH(solver.run(punch, out), Catch::Matchers::Contains("z >= 0"));
  out.stress_points = {{0.0, 1e9 * a}};
  CHECK_THROWS_WITH(solver.run(punch, out), Catch::Matchers::Contains("outside the meshed body"));
  out.stress_points = {};
  out.vtu_file      = "test_stress_fields.vtu";
  solver.run(punch, out);
  std::ifstream      in(out.vtu_file);
  std::stringstream  text;
  text << in.rdbuf();
  for (const char *name : {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz", "u_z"})
    CHECK(text.str().find(name) != std::string::npos);
}



// The accuracy contract of the stresses: on Hertz's field the estimate of every component bounds its true error, at
// the tolerances asked, and the ladder meets them.
TEST_CASE("The contract's stress estimates shall bound the true error of the Hertz field (k = 0)", "[fem]")
{
  const double nu = 0.3, R = 50 * a;
  const double p0 = 2 * E0 / (1 - nu * nu) * a / (pi * R);
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, 0.0), nu};
  LoadCase     sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(R);
  OutputRequest out;
  for (const double z : {0.2, 0.48087, 1.0})
    out.stress_points.push_back({0.0, z * a});
  for (const double tolerance : {1e-3, 1e-5})
    {
      ContractSolver       solver(material, contract_settings(a, material, tolerance), tolerance);
      const ContractResult r = solver.run(sphere, out);
      CAPTURE(tolerance, r.limit, r.level_dofs.size());
      REQUIRE(r.met);
      REQUIRE(r.stress.size() == out.stress_points.size());
      for (std::size_t i = 0; i < r.stress.size(); ++i)
        {
          const gradcontact::AxisymmetricStress exact = huber_axis(p0, nu, out.stress_points[i].z);
          const double components[4] = {exact.rr, exact.zz, exact.tt, exact.rz};
          for (unsigned int c = 0; c < 4; ++c)
            {
              const Estimated &e     = r.stress[i][c];
              const double     error = std::abs(e.value - components[c]);
              std::cout << "[fem] contract " << tolerance << ", z/a = " << out.stress_points[i].z / a << ", component "
                        << c << ": true " << error / e.scale << ", estimated " << e.relative() << "\n";
              CHECK(e.relative() <= tolerance);
              CHECK(error <= 3 * e.error + 1e-12 * p0);
            }
        }
    }
}



// Equilibrium of the recovered field with its load: the axial stress through a plane z = c carries the contact force,
// 2 pi \int_0^inf sigma_zz(r, c) r dr = -F, whatever the grading; the FE force comes from the reactions, a path
// independent of the recovery. Composite Gauss on geometric panels up to 100 a; beyond, the point-load field's
// sigma_zz ~ F cos^(3 + k) / R^2 leaves a tail of order (c / 100 a)^(3 + k) of F. The body's truncation at L must not
// carry load of its own through its side between the surface and the plane, as a clamped boundary would (a share
// that falls only like (c / L)^(1 + k)): the far field is condensed (exact) where the surface map does not widen L.
TEST_CASE("The recovered axial stress through a plane below the contact shall carry the contact force", "[fem][quick]")
{
  for (const double k : {-0.5, 0.0, 0.5})
    {
      const double nu = 0.3, c = 0.5 * a;
      Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
      Settings     settings = recommended_settings(a, *material.modulus, 1e-6);
      if (!use_surface_map(settings, *material.modulus))
        use_condensed_far_field(settings, material, 200);
      std::vector<StressPoint> points;
      std::vector<double>      weights;
      const double             gauss_x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                             0.8611363115940526};
      const double             gauss_w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                             0.3478548451374538};
      std::vector<double> ends{0.0};
      for (double x = 0.05 * a; x < 100 * a; x *= 1.25)
        ends.push_back(x);
      ends.push_back(100 * a);
      for (std::size_t i = 0; i + 1 < ends.size(); ++i)
        for (unsigned int q = 0; q < 4; ++q)
          {
            const double h = ends[i + 1] - ends[i], r = ends[i] + h * (1 + gauss_x[q]) / 2;
            points.push_back({r, c});
            weights.push_back(gauss_w[q] * h / 2 * r);
          }
      const Result r = paraboloid(k, nu, points, settings.discretization, settings.mesh);
      REQUIRE(r.reliable);
      double through = 0;
      for (std::size_t i = 0; i < points.size(); ++i)
        through += 2 * pi * weights[i] * r.stress[i].zz;
      const double e = std::abs(through + r.force) / r.force;
      std::cout << "[fem] equilibrium through z = 0.5 a, k = " << k << ": " << e << " of F\n";
      CHECK(e < 5e-4);
    }
}
