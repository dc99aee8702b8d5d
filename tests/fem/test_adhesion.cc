// Tests of the FE adhesive (JKR) contact, fem/adhesion/adhesion.h. References: the JKR closed forms of
// analytic/adhesion.h (9.50-9.68, the MDR path, independent of the FE model) and, at k = 0, the
// classical JKR pull-off forces -3/2 pi dgamma R and -5/6 pi dgamma R (Johnson-Kendall-Roberts 1971,
// Maugis 2000), which involve neither code.
#include <fem/adhesion/adhesion.h>
#include <fem/accuracy/convergence.h>
#include <fem/modulus/modulus.h>

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/normal.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

using namespace gradcontact::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  constexpr double nu     = 0.3;
  constexpr double E0     = 2.0e9;
  constexpr double c0     = 3.0e-4;
  constexpr double R      = 5e-3;
  constexpr double dgamma = 0.05; // J/m^2
  constexpr double pi     = 3.14159265358979323846;

  Material power_law_material(const double k)
  {
    return Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  }
  gradcontact::Medium medium(const double k)
  {
    return gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  }
  /// The fast test meshes: degree 2 on the recommended geometry (measured pull-off errors in
  /// fem/doc/loads-and-contact.md, "Adhesion (JKR)").
  AdhesiveContact::SettingsFunction test_settings(const double k)
  {
    return [k](const double a) {
      Settings s = recommended_settings(a, k, 1e-5);
      s.discretization.degree = 2;
      return s;
    };
  }
  void print(const char *what, const double k, const AdhesiveCriticalState &c, const double ref_F,
             const double ref_a, const double ref_d)
  {
    std::cout << what << " k=" << k << " F_err=" << (c.state.force - ref_F) / ref_F
              << " a_err=" << (c.state.radius - ref_a) / ref_a << " d_err=" << (c.state.depth - ref_d) / ref_d
              << " radii=" << c.radii_solved << " iterations=" << c.iterations << " dofs=" << c.max_dofs
              << " fe_seconds=" << c.fe_seconds << " shift=" << c.search_shift
              << " aK'/K=" << c.state.scaling_exponent << "\n";
  }
} // namespace

TEST_CASE("The fitting code: the energy release rate and the stiffness slope of the FE flat punch are "
          "consistent, and a K'(a)/K(a) = 1 + k on scaled meshes",
          "[fem]")
{
  // A check of the fitting code, not of the physics: G(a) is compared with the expression of the stiffness
  // slope that `energy_release_rate` itself evaluates, and the scaling identity
  // K ~ a^(1+k) holds by construction on meshes that are scaled copies. The physics of the pull-off is
  // checked against 9.51-9.57 by the tests below.
  const double    k = GENERATE(-0.5, 0.0, 0.5);
  AdhesiveContact punch(power_law_material(k), std::nullopt, test_settings(k));
  const double    a   = 1e-4;
  const double    G   = punch.energy_release_rate(a, 1e-7);
  const auto      st  = punch.adhesive_state(a, 0.05);
  CAPTURE(k, st.scaling_exponent, G);
  // The meshes of the three radii are scaled copies, so the identity holds to the solver's round-off;
  // 1e-6 leaves room for gmsh placing nodes differently on the scaled geometries.
  CHECK_THAT(st.scaling_exponent, WithinRel(1 + k, 1e-6));
  CHECK_THAT(G, WithinRel(1e-14 * st.stiffness_slope / (4 * pi * a), 1e-12));
}

TEST_CASE("The FE flat-punch pull-off force and depth agree with 9.51-9.52", "[fem][quick]")
{
  const double    k = GENERATE(-0.5, 0.0, 0.5);
  const double    a = 1e-4;
  AdhesiveContact punch(power_law_material(k), std::nullopt, test_settings(k));
  const auto      c   = punch.periphery_state(a, dgamma);
  const auto      ref = gradcontact::jkr::critical_state(medium(k), gradcontact::FlatPunch{a}, dgamma);
  print("flat punch", k, c, ref.force, ref.radius, ref.depth);
  CHECK_THAT(c.state.force, WithinRel(ref.force, 1e-4));
  CHECK_THAT(c.state.depth, WithinRel(ref.depth, 1e-4));
}

TEST_CASE("The FE paraboloid pull-off reproduces 9.55-9.56 and, at k = 0, JKR", "[fem]")
{
  // Requirement: pull-off force, critical radius and critical depth within 1e-4 of the closed
  // forms under both controls. Degree 2 meets it with a margin (fem/doc/loads-and-contact.md, "Adhesion (JKR)").
  const double    k = GENERATE(-0.5, 0.0, 0.5);
  AdhesiveContact sphere(power_law_material(k), Profile::paraboloid(R), test_settings(k));
  for (const auto control : {AdhesionControl::force, AdhesionControl::displacement})
    {
      const auto jkr_control = control == AdhesionControl::force ? gradcontact::jkr::Control::force
                                                                 : gradcontact::jkr::Control::displacement;
      const auto ref =
        gradcontact::jkr::critical_state(medium(k), gradcontact::Paraboloid{R}, dgamma, jkr_control);
      // A deliberately poor start (a factor 1.7 off the force-control critical radius) exercises the
      // search; the displacement-control search starts from the same radius and reuses the solved radii.
      const auto force_ref =
        gradcontact::jkr::critical_state(medium(k), gradcontact::Paraboloid{R}, dgamma, gradcontact::jkr::Control::force);
      const auto c = sphere.critical_state(dgamma, control, 1.7 * force_ref.radius);
      print(control == AdhesionControl::force ? "paraboloid force" : "paraboloid displacement", k, c, ref.force,
            ref.radius, ref.depth);
      CAPTURE(k, control == AdhesionControl::force);
      CHECK_THAT(c.state.force, WithinRel(ref.force, 1e-4));
      CHECK_THAT(c.state.radius, WithinRel(ref.radius, 1e-4));
      CHECK_THAT(c.state.depth, WithinRel(ref.depth, 1e-4));
      CHECK_THAT(c.state.scaling_exponent, WithinRel(1 + k, 1e-6));
      if (k == 0)
        {
          // JKR (1971): -3/2 pi dgamma R under force control, -5/6 pi dgamma R under displacement control.
          const double jkr = (control == AdhesionControl::force ? -1.5 : -5. / 6.) * pi * dgamma * R;
          CHECK_THAT(c.state.force, WithinRel(jkr, 1e-4));
        }
    }
}

TEST_CASE("The FE adhesion model rejects bad input with the parameter named", "[fem][quick]")
{
  AdhesiveContact sphere(power_law_material(0.), Profile::paraboloid(R), test_settings(0.));
  CHECK_THROWS_WITH(sphere.critical_state(0., AdhesionControl::force, 1e-4),
                    Catch::Contains("work of adhesion dgamma") && Catch::Contains("(0, inf)"));
  CHECK_THROWS_WITH(sphere.critical_state(-1., AdhesionControl::force, 1e-4), Catch::Contains("dgamma"));
  CHECK_THROWS_WITH(sphere.critical_state(dgamma, AdhesionControl::force, -1.), Catch::Contains("a0"));
  AdhesionParameters bad;
  bad.fit_points = 7;
  CHECK_THROWS_WITH(AdhesiveContact(power_law_material(0.), std::nullopt, test_settings(0.), bad),
                    Catch::Contains("fit_points"));
  AdhesiveContact punch(power_law_material(0.), std::nullopt, test_settings(0.));
  CHECK_THROWS_WITH(punch.critical_state(dgamma, AdhesionControl::force, 1e-4), Catch::Contains("curved profile"));
  CHECK_THROWS_WITH(punch.centre_state(1e-4, dgamma, 1e6), Catch::Contains("concave"));
}

TEST_CASE("The FE power-law pull-off agrees with 9.60-9.61 and a profile without one is reported", "[fem]")
{
  // Requirement: power-law profiles f = A r^n; a critical state exists only for 2n + k - 1 > 0
  // (9.60), otherwise "no critical state", never a number.
  const double    k = 0.;
  const double    n = 1.75, A = 0.02 * std::pow(1e-4, 1 - n);
  AdhesiveContact tip(power_law_material(k), Profile::power_law(n, A), test_settings(k));
  const auto      ref = gradcontact::jkr::critical_state(medium(k), gradcontact::PowerLaw{n, A}, dgamma,
                                                    gradcontact::jkr::Control::force);
  const auto      c   = tip.critical_state(dgamma, AdhesionControl::force, 1.3 * ref.radius);
  print("power law n=1.75 force", k, c, ref.force, ref.radius, ref.depth);
  CHECK_THAT(c.state.force, WithinRel(ref.force, 1e-4));
  CHECK_THAT(c.state.radius, WithinRel(ref.radius, 1e-4));
  CHECK_THAT(c.state.depth, WithinRel(ref.depth, 1e-4));

  // n = 0.4, k = 0: 2n + k - 1 = -0.2, F(a) falls without bound as a -> 0; the search must say so.
  AdhesionParameters quick;
  quick.max_iterations = 12;
  AdhesiveContact sharp(power_law_material(k), Profile::power_law(0.4, 1e-3), test_settings(k), quick);
  CHECK_THROWS_WITH(sharp.critical_state(dgamma, AdhesionControl::force, 1e-4),
                    Catch::Contains("no critical state"));
}

TEST_CASE("The FE concave punch separates at the periphery or the centre as 9.65-9.68 predict", "[fem]")
{
  // Requirement: both mechanisms and the h0 where one takes over from the other.
  const double k        = GENERATE(-0.5, 0.0, 0.5);
  const double a        = 1e-4;
  const double sigma_th = 3e6 * std::pow(a / c0, k); // comparable to the edge mechanism for every k
  const gradcontact::Medium m = medium(k);
  for (const double h0 : {2e-8, 2e-7})
    {
      // Degree 3: the centre mechanism needs p(0), whose recovery is 3e-3 off at degree 2 (k = -0.5).
      AdhesiveContact punch(power_law_material(k), Profile::concave_paraboloid(h0), [k](const double radius) {
        return recommended_settings(radius, k, 1e-5);
      });
      const auto      periphery = punch.periphery_state(a, dgamma);
      const auto      centre    = punch.centre_state(a, dgamma, sigma_th);
      using gradcontact::jkr::Mechanism;
      const gradcontact::ConcavePunch cp{a, h0};
      const auto ref_p = gradcontact::jkr::critical_state(m, cp, dgamma, sigma_th, Mechanism::periphery);
      const auto ref_c = gradcontact::jkr::critical_state(m, cp, dgamma, sigma_th, Mechanism::centre);
      print("concave periphery", k, periphery, ref_p.force, ref_p.radius, ref_p.depth);
      print("concave centre", k, centre, ref_c.force, ref_c.radius, ref_c.depth);
      CAPTURE(k, h0);
      CHECK_THAT(periphery.state.force, WithinRel(ref_p.force, 1e-4));
      CHECK_THAT(periphery.state.depth, WithinRel(ref_p.depth, 1e-4));
      CHECK_THAT(centre.state.force, WithinRel(ref_c.force, 1e-4));
      CHECK_THAT(centre.state.depth, WithinRel(ref_c.depth, 1e-4));
      // The governing mechanism is the one with the larger critical (rim) depth.
      const bool fe_periphery = periphery.state.depth >= centre.state.depth;
      CHECK(fe_periphery == (gradcontact::jkr::governing_mechanism(m, cp, dgamma, sigma_th) == Mechanism::periphery));
      if (h0 == 2e-7)
        {
          const double h_star = punch.transition_h0(a, dgamma, sigma_th);
          const double ref    = gradcontact::jkr::transition_h0(m, a, dgamma, sigma_th);
          std::cout << "concave transition k=" << k << " h0*_err=" << (h_star - ref) / ref << "\n";
          CHECK_THAT(h_star, WithinRel(ref, 1e-4));
        }
    }
}

TEST_CASE("The FE surface under a constant tension -sigma_th has the optimal shape 9.71-9.73", "[fem]")
{
  // Requirement: load the FE model with p = -sigma_th on r < a and compare w(r) (9.71) and the
  // centre displacement (9.72); the optimal profile (9.73) is w_c - w(r).
  const double k = GENERATE(-0.5, 0.0, 0.5);
  const double a = 1e-4, sigma_th = 1e6;
  Settings     s = recommended_settings(a, k, 1e-5);
  AxisymmetricSolver solver(power_law_material(k), s.mesh, s.discretization);
  LoadCase           tension;
  tension.type     = LoadType::constant_pressure;
  tension.pressure = -sigma_th;
  OutputRequest out;
  out.displacement_radii = {0., 0.25 * a, 0.5 * a, 0.75 * a, 0.9 * a, 1.5 * a};
  const Result r = solver.run(tension, out);
  const gradcontact::jkr::OptimalProfile opt{a, sigma_th};
  const gradcontact::Medium              m  = medium(k);
  const double                           wc = gradcontact::jkr::centre_displacement(m, opt);
  CHECK_THAT(r.depth, WithinRel(wc, 1e-4));
  for (const Sample &w : r.displacement)
    {
      const double ref = gradcontact::jkr::displacement(m, opt, w.r);
      CAPTURE(k, w.r / a, w.value, ref);
      // Relative to the centre displacement (the profile's scale).
      CHECK_THAT(w.value, WithinAbs(ref, 1e-4 * std::abs(wc)));
      if (w.r <= a)
        CHECK_THAT(wc - w.value, WithinAbs(gradcontact::jkr::profile(m, opt, w.r), 1e-4 * std::abs(wc)));
    }
  // An input check, not an FE result: the force is the quadrature of the prescribed tension.
  CHECK_THAT(r.force, WithinRel(gradcontact::jkr::force(opt), 1e-12));
}

TEST_CASE("The FE pull-off force converges at the energy rate 2p under uniform h-refinement", "[verification]")
{
  // Requirement: asserted convergence of the FE pull-off force. Degree 1, k = 0, both controls,
  // uniform refinements 0-2 of every radius's mesh, against 9.56 (= JKR at k = 0). The expected order is the
  // energy rate 2p = 2 of degree 1 over the last three levels.
  const double k = 0.;
  for (const auto control : {AdhesionControl::force, AdhesionControl::displacement})
    {
      const auto jkr_control = control == AdhesionControl::force ? gradcontact::jkr::Control::force
                                                                 : gradcontact::jkr::Control::displacement;
      const auto ref = gradcontact::jkr::critical_state(medium(k), gradcontact::Paraboloid{R}, dgamma, jkr_control);
      std::vector<double> h, err;
      for (unsigned int level = 0; level <= 2; ++level)
        {
          AdhesionParameters p;
          p.local_stencil = false;
          AdhesiveContact sphere(power_law_material(k), Profile::paraboloid(R), [level](const double a) {
            Settings s = recommended_settings(a, 0., 1e-5);
            s.discretization.degree = 1;
            s.mesh.global_refinements = level;
            return s;
          }, p);
          const auto c = sphere.critical_state(dgamma, control, 1.2 * ref.radius);
          h.push_back(std::log(std::ldexp(1., -static_cast<int>(level)))); // log h
          err.push_back(std::abs(c.state.force / ref.force - 1));
          std::cout << "pull-off h-study control=" << (control == AdhesionControl::force ? "force" : "displacement")
                    << " level=" << level << " dofs=" << c.max_dofs << " error=" << err.back() << "\n";
        }
      const double order = observed_order(h, err);
      CAPTURE(err[0], err[1], err[2], order);
      CHECK(err[2] < err[1]);
      CHECK(err[1] < err[0]);
      // p = 1: the force is an energy-like functional, error ~ h^(2p) = h^2.
      CHECK(order > 1.8);
      CHECK(order < 2.3);
    }
}

TEST_CASE("The FE pull-off error shall be the error of the two FE states it is built from (k = 0), and fall "
          "with the edge cell",
          "[verification]")
{
  // Requirement: the critical-state search and the fit of ln K, ln F_n add nothing measurable to the
  // pull-off force; its error is that of the FE states. At k = 0 the meshes of all radii are scaled copies,
  // so the FE gives K = K_1 a and F_n = A a^3 exactly; F(a) = F_n - K delta with delta = sqrt(4 pi a dgamma
  // / K') (the JKR superposition, 9.45-9.49) has its minimum at F_c = -pi dgamma K_1 / A. Against JKR's
  // -3/2 pi dgamma R (K_1 = 2 E*, A = 4 E* / (3 R): Boussinesq and Hertz, 9.16 and 9.26) the relative error
  // is therefore (1 + e_K) / (1 + e_Fn) - 1, with e_K and e_Fn the errors of the flat-punch stiffness and
  // of the non-adhesive force at one radius against the closed forms.
  // Scene: the paraboloid of `gradcontact bench` (E0 = 2 GPa, c0 = 3 a, a = 0.1 mm, R = 50 a, dgamma =
  // 0.05 J/m^2), degree 3, on its levels 2 and 3 (fe_mesh_level in cases/tools/fe_bench.cc: h_edge 1e-4 a, rings
  // 1.3, h_far 4; h_edge 1e-5 a, rings 1.15, h_far 3).
  // At level 2 both states are limited by the edge cell (the edge singularity: a degree step gains little,
  // finer rings hardly change F_c), and the error of F_n exceeds that of K there, so the pull-off error is
  // negative at level 2 while it is positive at levels 0-1; at level 3 e_K, e_Fn and F_c fall by an order of
  // magnitude and more. The test prints e_K, e_Fn and F_c per level.
  // The error of F_c minus (1 + e_K) / (1 + e_Fn) - 1 is at round-off at both levels (the fitted a K'/K is 1 to
  // round-off and enters F_c one to one; the search ends where F is flat in a).
  // Tolerances: the search and fit 1e-10; the level-2 deviation is pinned at its value level2_error within 5 %
  // (a change of the mesh or of a state's accuracy shows here); level 3 with a tenfold margin over its error.
  constexpr double search_tolerance = 1e-10;
  constexpr double level2_error     = -8.48e-6;
  constexpr double level2_tolerance = 0.05;
  constexpr double level3_bound     = 8e-7;
  const double     k                = 0.;
  const auto       m                = medium(k);
  const double     F_c_jkr          = -1.5 * pi * dgamma * R; // JKR (1971), force control
  struct Level
  {
    double h_edge, ring_growth, h_far;
  };
  std::vector<double> errors;
  for (const Level level : {Level{1e-4, 1.3, 4.}, Level{1e-5, 1.15, 3.}})
    {
      AdhesiveContact sphere(power_law_material(k), Profile::paraboloid(R), [level](const double a) {
        Settings s{recommended_mesh_parameters(a, 0.), DiscretizationParameters{}};
        s.mesh.h_edge           = level.h_edge;
        s.mesh.ring_growth      = level.ring_growth;
        s.mesh.h_far            = level.h_far;
        s.discretization.degree = 3;
        return s;
      });
      const auto ref = gradcontact::jkr::critical_state(m, gradcontact::Paraboloid{R}, dgamma,
                                                        gradcontact::jkr::Control::force);
      const auto   c           = sphere.critical_state(dgamma, AdhesionControl::force, 1.2 * ref.radius);
      const double a_c         = c.state.radius;
      const auto  &state       = sphere.state(a_c); // K and F_n at a_c (scale-free at k = 0: any radius)
      const double e_K         = state.stiffness / gradcontact::force(m, gradcontact::FlatPunch{a_c}, 1.) - 1;
      const double e_Fn        = state.force / gradcontact::force(m, gradcontact::Paraboloid{R}, a_c) - 1;
      const double error       = c.state.force / F_c_jkr - 1;
      const double from_states = (1 + e_K) / (1 + e_Fn) - 1;
      std::cout << "[verification] pull-off k = 0, degree 3, h_edge " << level.h_edge << " a: error " << error
                << " (e_K " << e_K << ", e_Fn " << e_Fn << ", error - from states " << error - from_states << ")\n";
      CAPTURE(level.h_edge, error, e_K, e_Fn, from_states, error - from_states, c.state.scaling_exponent,
              c.search_shift, c.max_dofs);
      CHECK_THAT(error, WithinAbs(from_states, search_tolerance));
      errors.push_back(error);
    }
  CAPTURE(errors[0], level2_error, level2_tolerance, errors[1], level3_bound);
  CHECK_THAT(errors[0], WithinRel(level2_error, level2_tolerance));
  CHECK(std::abs(errors[1]) < level3_bound);
}
