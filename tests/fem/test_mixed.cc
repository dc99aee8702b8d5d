// Tests of the mixed (Taylor-Hood displacement-pressure) formulation of the axisymmetric solver and of
// the Gibson medium (fem/doc/model.md "Mixed formulation (nu -> 0.5) and the Gibson medium").
// References: classical closed forms written out here (Boussinesq's flat punch, Hertz's pressure, the
// Winkler law of the Gibson medium 9.44) and the closed forms of analytic/normal.h for k = 0.5, an
// independent code path. Every tolerance is a measured error times a stated margin.
#include <fem/adhesion/adhesion.h>
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/tangential/fourier_mode1_solver.h>
#include <fem/modulus/modulus.h>

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/normal.h>

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
  constexpr double E0 = 2.0e9;
  constexpr double c0 = 3.0e-4;
  constexpr double a  = 1.0e-4;
  constexpr double pi = 3.14159265358979323846;

  DiscretizationParameters mixed(const unsigned int degree = 3)
  {
    DiscretizationParameters d;
    d.degree      = degree;
    d.formulation = Formulation::mixed;
    return d;
  }

  /// Relative L2 error of p(r) over the samples (weight r), against `exact`.
  template <typename F>
  double pressure_l2_error(const Result &r, const F &exact)
  {
    double e = 0, n = 0;
    for (const Sample &s : r.pressure)
      {
        const double p = exact(s.r);
        e += (s.value - p) * (s.value - p) * s.r;
        n += p * p * s.r;
      }
    return std::sqrt(e / n);
  }

  /// p(r) at 400 points of r < 0.99 a (the edge itself is excluded: p -> 0 like a square root there).
  OutputRequest pressure_samples()
  {
    OutputRequest out;
    for (unsigned int i = 0; i < 400; ++i)
      out.pressure_radii.push_back(0.99 * a * (i + 0.5) / 400);
    return out;
  }
} // namespace



// The default mesh for k = 0, degree 3, nu = 0.5: the flat punch and the paraboloid's p(r) are limited by the
// edge singularity as with the displacement formulation at nu < 1/2, while the displacement formulation at
// nu = 0.4999 on the same mesh misses p(r) by orders of magnitude more (volumetric locking). Tolerances: 4x the
// errors of this mesh (`fem_study formulation=mixed nu=0.5` prints them).
constexpr double mixed_punch_tolerance    = 2.5e-6;
constexpr double mixed_pressure_tolerance = 1.6e-5;

TEST_CASE("The mixed formulation shall give Boussinesq's punch force and Hertz's pressure at nu = 0.5 (k = 0)",
          "[fem][quick]")
{
  const double nu = 0.5;
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, 0.0), nu};
  AxisymmetricSolver solver(material, recommended_mesh_parameters(a, 0.0), mixed());
  REQUIRE(solver.formulation() == Formulation::mixed);
  const double E_star = E0 / (1 - nu * nu);

  // Boussinesq: F = 2 E* a d (9.16 with k = 0).
  LoadCase punch;
  punch.type         = LoadType::flat_punch;
  punch.depth        = 1e-3 * a;
  const Result    rp = solver.run(punch);
  const double    Fb = 2 * E_star * a * punch.depth;
  CAPTURE(rp.force, Fb, rp.force / Fb - 1, rp.energy_mismatch, rp.n_dofs, rp.message);
  REQUIRE(rp.reliable);
  CHECK_THAT(rp.force, WithinRel(Fb, mixed_punch_tolerance));

  // Hertz: p(r) = (2 E* a / (pi R)) sqrt(1 - r^2/a^2), d = a^2 / R.
  const double R = 50 * a;
  LoadCase     sphere;
  sphere.type        = LoadType::indenter;
  sphere.profile     = Profile::paraboloid(R);
  const Result rs    = solver.run(sphere, pressure_samples());
  const double p_err = pressure_l2_error(rs, [&](const double r) {
    return 2 * E_star * a / (pi * R) * std::sqrt(1 - r * r / (a * a));
  });
  const double d_hertz = a * a / R;
  std::cout << "[fem] mixed, nu = 0.5, k = 0: punch F " << rp.force / Fb - 1 << ", Hertz p L2 " << p_err
            << ", d " << rs.depth / d_hertz - 1 << ", " << rs.n_dofs << " DoFs\n";
  CAPTURE(p_err, rs.depth / d_hertz - 1, rs.energy_mismatch, rs.message);
  REQUIRE(rs.reliable);
  REQUIRE(rs.consistent_contact);
  CHECK(p_err <= mixed_pressure_tolerance);
  CHECK_THAT(rs.depth, WithinRel(d_hertz, mixed_punch_tolerance));
}



// k = 0.5, nu = 0.5 against the closed forms of chapter 9.1 (analytic/normal.h), on a mesh cheaper
// than the recommended one (degree 3, h_edge = 1e-3 a, rings g = 1.6, surface layer 1e-6 a).
// The coarse edge and the 1e-6 a layer limit the punch force and the paraboloid's p(r); 2.5x margin over
// them. (The recommended mesh is far more accurate but too slow for [fem].)
constexpr double mixed_k05_punch_tolerance    = 4e-5;
constexpr double mixed_k05_pressure_tolerance = 3.5e-5;

// Depth and force control with the mixed formulation, the answer at a / (1 + 1e-4) on the recommended
// mesh with rings g = 1.6 and the surface layer 1e-6 a (the layer limits it, as the punch above): the force at
// the given depth, the depth at the given force and the contact radius of the paraboloid and the cone, with a
// 2.5x margin over the largest; the radius bound stays well below the 1e-4 between the answer and the mesh's
// own radius, so a solver that skipped the search fails.
constexpr double mixed_control_force_tolerance  = 4e-5;
constexpr double mixed_control_radius_tolerance = 1.5e-5;
// JKR pull-off with the mixed formulation, degree 2, force control (7 radii): F, a_c and d_c well inside the
// bound, which is the one required of the displacement formulation.
constexpr double mixed_pull_off_tolerance = 1e-4;

TEST_CASE("The mixed formulation shall match the power-law closed forms at k = 0.5, nu = 0.5", "[fem]")
{
  const double k = 0.5, nu = 0.5;
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  MeshParameters mesh          = recommended_mesh_parameters(a, k);
  mesh.h_edge                  = 1e-3;
  mesh.ring_growth             = 1.6;
  mesh.surface_layer_thickness = 1e-6;
  AxisymmetricSolver        solver(material, mesh, mixed());
  const gradcontact::Medium m = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});

  LoadCase punch;
  punch.type         = LoadType::flat_punch;
  punch.depth        = 1e-3 * a;
  const Result rp    = solver.run(punch);
  const double F_ref = gradcontact::force(m, gradcontact::FlatPunch{a}, punch.depth);

  const gradcontact::PowerLaw f = gradcontact::as_power_law(gradcontact::Paraboloid{50 * a});
  LoadCase                    sphere;
  sphere.type          = LoadType::indenter;
  sphere.profile       = Profile::paraboloid(50 * a);
  const Result rs      = solver.run(sphere, pressure_samples());
  const double a_fe    = gradcontact::contact_radius_from_depth(m, f, rs.depth); // compare at the FE depth
  const double p_err   = pressure_l2_error(rs, [&](const double r) { return gradcontact::pressure(m, f, a_fe, r); });
  std::cout << "[fem] mixed, nu = 0.5, k = 0.5: punch F " << rp.force / F_ref - 1 << ", paraboloid p L2 "
            << p_err << ", a(d) " << a_fe / a - 1 << ", " << rp.n_dofs << " DoFs\n";
  CAPTURE(rp.force / F_ref - 1, p_err, a_fe / a - 1, rp.energy_mismatch, rs.energy_mismatch, rs.message);
  REQUIRE(rp.reliable);
  REQUIRE(rs.reliable);
  REQUIRE(rs.consistent_contact);
  CHECK_THAT(rp.force, WithinRel(F_ref, mixed_k05_punch_tolerance));
  CHECK(p_err <= mixed_k05_pressure_tolerance);
}



TEST_CASE("The mixed formulation shall find the contact radius under depth and force control (k = 0.5, nu = 0.5)",
          "[fem]")
{
  // The paraboloid and the cone at a / (1 + 1e-4) on the mesh graded at a, as the displacement formulation
  // does (test_contact.cc); the closed forms of analytic/normal.h at nu = 0.5. The bounds: see the constants.
  const double k = 0.5, nu = 0.5;
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  MeshParameters mesh          = recommended_mesh_parameters(a, k);
  mesh.ring_growth             = 1.6;
  mesh.surface_layer_thickness = 1e-6;
  AxisymmetricSolver        solver(material, mesh, mixed());
  const gradcontact::Medium m      = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  const double              a_true = a / (1 + 1e-4);
  for (const bool by_depth : {true, false})
    for (const bool cone : {false, true})
      {
        const gradcontact::PowerLaw f = cone ? gradcontact::as_power_law(gradcontact::Cone{0.1})
                                             : gradcontact::as_power_law(gradcontact::Paraboloid{50 * a});
        LoadCase load;
        load.type    = by_depth ? LoadType::indenter_depth : LoadType::indenter_force;
        load.profile = cone ? Profile::cone(0.1) : Profile::paraboloid(50 * a);
        load.depth   = gradcontact::depth(m, f, a_true);
        load.force   = gradcontact::force(m, f, a_true);
        const Result r = solver.run(load);
        std::cout << "[fem] mixed, nu = 0.5, k = 0.5, " << (cone ? "cone" : "paraboloid")
                  << (by_depth ? " depth" : " force") << " control: F " << r.force / load.force - 1 << ", d "
                  << r.depth / load.depth - 1 << ", a " << r.contact_radius / a_true - 1 << ", " << r.iterations
                  << " trial sets\n";
        CAPTURE(cone, by_depth, r.force / load.force - 1, r.depth / load.depth - 1, r.contact_radius / a_true - 1,
                r.iterations, r.message);
        REQUIRE(r.reliable);
        REQUIRE(r.consistent_contact);
        if (by_depth)
          CHECK_THAT(r.force, WithinRel(load.force, mixed_control_force_tolerance));
        else
          CHECK_THAT(r.depth, WithinRel(load.depth, mixed_control_force_tolerance));
        CHECK_THAT(r.contact_radius, WithinRel(a_true, mixed_control_radius_tolerance));
      }
}

// Label slow (./vv test --all): the default tier keeps the mixed formulation's JKR critical state in Fig. 9.24's test.
TEST_CASE("The mixed formulation shall give the JKR pull-off of the paraboloid (9.55-9.56) at nu = 0.5", "[slow]")
{
  // The adhesive search on meshes of the mixed formulation (degree 2, the recommended geometry for each
  // radius), k = 0.5, nu = 0.5, against the closed forms at nu = 0.5, under both controls.
  const double k = 0.5, nu = 0.5, R = 5e-3, dgamma = 0.05;
  Material     material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  const gradcontact::Medium m = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  AdhesiveContact sphere(material, Profile::paraboloid(R), [k](const double radius) {
    Settings s = recommended_settings(radius, k, 1e-5);
    s.discretization.degree      = 2;
    s.discretization.formulation = Formulation::mixed;
    return s;
  });
  // Force control only: the displacement-control search differs in the search, not in the FE (tested with
  // the displacement formulation in test_adhesion.cc).
  for (const auto control : {AdhesionControl::force})
    {
      const auto ref = gradcontact::jkr::critical_state(m, gradcontact::Paraboloid{R}, dgamma,
                                                        gradcontact::jkr::Control::force);
      const auto c   = sphere.critical_state(dgamma, control, 1.2 * ref.radius);
      std::cout << "[fem] mixed, nu = 0.5, k = 0.5, pull-off "
                << (control == AdhesionControl::force ? "force" : "displacement") << " control: F "
                << c.state.force / ref.force - 1 << ", a " << c.state.radius / ref.radius - 1 << ", d "
                << c.state.depth / ref.depth - 1 << ", " << c.radii_solved << " radii\n";
      CAPTURE(control == AdhesionControl::force, c.state.force / ref.force - 1, c.state.radius / ref.radius - 1,
              c.state.depth / ref.depth - 1);
      CHECK_THAT(c.state.force, WithinRel(ref.force, mixed_pull_off_tolerance));
      CHECK_THAT(c.state.radius, WithinRel(ref.radius, mixed_pull_off_tolerance));
      CHECK_THAT(c.state.depth, WithinRel(ref.depth, mixed_pull_off_tolerance));
    }
  // The displacement formulation at nu = 0.5 is refused when a radius is solved, naming the fix.
  AdhesiveContact locked(material, Profile::paraboloid(R), [k](const double radius) {
    Settings s = recommended_settings(radius, k, 1e-5);
    s.discretization.degree = 2;
    return s;
  });
  CHECK_THROWS_WITH(locked.critical_state(dgamma, AdhesionControl::force, 1e-4), Contains("mixed formulation"));
}

// The Gibson medium (9.42-9.44): E = E0 z / c0, nu = 1/2 behaves as a Winkler foundation,
// p = k_W w with k_W = 2 E0 / (3 c0): under p0 on r <= a, w = p0 / k_W inside and 0 outside; a flat
// punch at depth d carries F = pi a^2 k_W d. Mesh: degree 3, h_edge = 1e-3 a, g = 1.6, no surface layer
// (the Gibson displacement is regular at z = 0). |w - p0/k_W| / (p0/k_W) inside (r <= 0.9 a) and outside
// (1.1 a <= r <= 4 a) and the punch force, limited by the coarse edge (the jump of w at r = a); a margin of
// more than 2x over the largest. (The recommended mesh, h_edge 1e-5 a, is far more accurate outside.)
constexpr double gibson_displacement_tolerance = 2e-4;
constexpr double gibson_punch_tolerance        = 2e-4;

TEST_CASE("The mixed formulation shall give the Winkler response of the Gibson medium (k = 1, nu = 0.5)",
          "[fem]")
{
  Material       material{std::make_shared<PowerLawModulus>(E0, c0, 1.0), 0.5};
  MeshParameters mesh          = recommended_mesh_parameters(a, 1.0);
  mesh.h_edge                  = 1e-3;
  mesh.ring_growth             = 1.6;
  mesh.surface_layer_thickness = 1.0;
  AxisymmetricSolver solver(material, mesh, mixed());
  const double       k_W = 2 * E0 / (3 * c0); // 9.44, written out (not from the analytic library)

  LoadCase pressure;
  pressure.type     = LoadType::constant_pressure;
  pressure.pressure = 1e6;
  OutputRequest out;
  // inside away from the edge (r <= 0.9 a) and outside (r >= 1.1 a)
  for (unsigned int i = 0; i <= 90; ++i)
    out.displacement_radii.push_back(a * i / 100.0);
  for (unsigned int i = 110; i <= 400; ++i)
    out.displacement_radii.push_back(a * i / 100.0);
  const Result rw        = solver.run(pressure, out);
  const double w_winkler = pressure.pressure / k_W;
  double       inside = 0, outside = 0;
  for (const Sample &s : rw.displacement)
    (s.r < a ? inside : outside) =
      std::max(s.r < a ? inside : outside, std::abs(s.value - (s.r < a ? w_winkler : 0.0)) / w_winkler);

  LoadCase punch;
  punch.type         = LoadType::flat_punch;
  punch.depth        = 1e-3 * a;
  const Result rp    = solver.run(punch);
  const double F_ref = pi * a * a * k_W * punch.depth;
  std::cout << "[fem] Gibson: w inside " << inside << ", outside " << outside << " (of p0/k_W), punch F "
            << rp.force / F_ref - 1 << ", " << rp.n_dofs << " DoFs\n";
  CAPTURE(inside, outside, rp.force / F_ref - 1, rw.energy_mismatch, rp.energy_mismatch, rw.message);
  REQUIRE(rw.reliable);
  REQUIRE(rp.reliable);
  CHECK(inside <= gibson_displacement_tolerance);
  CHECK(outside <= gibson_displacement_tolerance);
  CHECK_THAT(rp.force, WithinRel(F_ref, gibson_punch_tolerance));
}



TEST_CASE("Bad input to the mixed formulation and the Gibson medium shall throw, naming the parameter", "[fem][quick]")
{
  const MeshParameters mesh = recommended_mesh_parameters(a, 0.0);
  const auto           power_law = [](const double k, const double nu) {
    return Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  };
  // nu = 0.5 needs the mixed formulation
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(0.0, 0.5), mesh, DiscretizationParameters{}),
                      Contains("nu = 0.5") && Contains("mixed"));
  // k = 1 (Gibson) needs the mixed formulation and nu = 0.5
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(1.0, 0.3), mesh, DiscretizationParameters{}),
                      Contains("surface exponent = 1"));
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(1.0, 0.49), mesh, mixed()),
                      Contains("surface exponent = 1") && Contains("nu = 0.5"));
  REQUIRE_THROWS_WITH(PowerLawModulus(E0, c0, 1.5), Contains("k = 1.5") && Contains("(-1, 1]"));
  // the pressure space FE_Q(degree - 1) needs degree >= 2; 1/lambda needs nu > 0
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(0.0, 0.5), mesh, mixed(1)),
                      Contains("degree = 1") && Contains("[2, 8]"));
  DiscretizationParameters automatic;
  automatic.degree      = 1;
  automatic.formulation = Formulation::automatic;
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(0.0, 0.499), mesh, automatic), Contains("degree = 1"));
  REQUIRE_THROWS_WITH(AxisymmetricSolver(power_law(0.0, 0.0), mesh, mixed()),
                      Contains("nu = 0") && Contains("(0, 0.5]"));
  // solvers without the mixed formulation say so
  REQUIRE_THROWS_WITH(FourierMode1Solver(power_law(0.0, 0.3), mesh, mixed()),
                      Contains("FourierMode1Solver: not supported with the mixed formulation"));
  // automatic resolves by nu
  DiscretizationParameters a3;
  a3.formulation = Formulation::automatic;
  CHECK(resolve_formulation(a3, 0.3) == Formulation::displacement);
  CHECK(resolve_formulation(a3, automatic_mixed_threshold) == Formulation::mixed);
}

// The mixed system at k != 0 is the same system at every contact radius up to the scale of E(a) against the
// pressure block; solving for q / E(a) (mixed_pressure_scale) keeps it equally conditioned. Unscaled, one radius
// of a JKR search (a = 0.187456 c0, k = -0.5, nu = 1/2, degree 2) fails the energy check by orders of magnitude.
TEST_CASE("The mixed formulation shall solve the graded flat punch alike at every contact radius", "[fem]")
{
  const double   k = -0.5;
  const Material material{std::make_shared<PowerLawModulus>(1.0, 1.0, k), 0.5};
  DiscretizationParameters d;
  d.degree      = 2;
  d.formulation = Formulation::mixed;
  double reference = 0;
  for (const double radius : {0.187456, 1e-3, 0.2, 30.0})
    {
      MeshParameters mesh = recommended_mesh_parameters(radius, k);
      AxisymmetricSolver solver(material, mesh, d);
      LoadCase           punch;
      punch.type  = LoadType::flat_punch;
      punch.depth = 1e-3 * radius;
      const Result r = solver.run(punch);
      CAPTURE(radius, r.energy_mismatch, r.message);
      REQUIRE(r.reliable);
      // F = C E0 d a^{1+k} / c0^k (9.16): F / (d a^{1+k}) is one number for every radius.
      const double scaled = r.force / (punch.depth * std::pow(radius, 1 + k));
      if (reference == 0)
        reference = scaled;
      std::cout << "[fem] mixed k = -0.5 punch at a = " << radius << ": F / (d a^{1+k}) = " << scaled
                << ", energy mismatch " << r.energy_mismatch << "\n";
      // The same system up to scaling, solved to the conditioning of k = -0.5 (mismatch <= 1e-8): a failed
      // pivoting is O(1) off.
      CHECK_THAT(scaled, WithinRel(reference, 1e-6));
    }
}
