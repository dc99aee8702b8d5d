// Tests of the Lennard-Jones adhesion FE, fem/adhesion/smooth_cohesion.h. References: the law's own integrals (computed
// here by quadrature), the rigid sphere's force-separation curve (Derjaguin: F(d) = -2 pi R Phi(-d), Phi the
// law's work beyond a gap, written out below; its minimum -2 pi dgamma R is the DMT pull-off for every k), the
// chapter's JKR critical states (analytic/adhesion.h, 9.55-9.56) at large Tabor parameter, and the FE on a finer
// mesh.
#include <fem/modulus/modulus.h>
#include <fem/adhesion/smooth_cohesion.h>

#include <analytic/adhesion.h>
#include <analytic/material.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <utility>
#include <vector>

using namespace gradcontact::fem;

namespace
{
  constexpr double nu = 0.3, c0 = 1.0, R = 1.0, dgamma = 1e-3;
  constexpr double pi = 3.14159265358979323846;

  Material power_law_material(const double E0, const double k)
  {
    return Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  }

  /// The law's work beyond the gap h >= eps / 2, \int_h^inf sigma: 8 dgamma / (3 eps) (eps^3 / (2 h^2) - eps^9 / (8 h^8)).
  double work_beyond(const double h, const double eps)
  {
    const double q = eps / h;
    return dgamma * (4.0 / 3.0 * q * q - std::pow(q, 8) / 3.0);
  }

  /// Tabor's parameter mu = (R dgamma^2 / (E*^2 eps^3))^{1/3} (k = 0, E* = E0 / (1 - nu^2)) -> eps.
  double separation_of_tabor(const double mu, const double E0)
  {
    const double E_star = E0 / (1 - nu * nu);
    return std::cbrt(R * dgamma * dgamma / (E_star * E_star)) / mu;
  }
} // namespace

TEST_CASE("Lennard-Jones law: zero at eps, largest at 3^(1/6) eps, work dgamma, slope", "[fem][quick]")
{
  const LennardJonesLaw law{dgamma, 2e-3};
  REQUIRE(std::abs(law.stress(law.separation)) <= 1e-15 * law.max_stress());
  const double h_max = std::pow(3.0, 1.0 / 6.0) * law.separation;
  CHECK_THAT(law.stress(h_max), Catch::Matchers::WithinRel(law.max_stress(), 1e-14));
  CHECK(law.stress(1.01 * h_max) < law.stress(h_max));
  CHECK(law.stress(0.99 * h_max) < law.stress(h_max));
  // The work beyond a gap h0, \int_h0^inf sigma: composite Gauss-Legendre on h = h0 / t, t in (0, 1]
  // (dh = h0 / t^2 dt), 400 panels of 8 points.
  const auto work_from = [&law](const double h0) {
    double             work   = 0;
    const unsigned int panels = 400;
    const double       x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    const double       w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    for (unsigned int p = 0; p < panels; ++p)
      for (unsigned int i = 0; i < 4; ++i)
        for (const double sign : {-1.0, 1.0})
          {
            const double t = (p + 0.5 + sign * 0.5 * x[i]) / panels;
            work += 0.5 * w[i] / panels * law.stress(h0 / t) * h0 / (t * t);
          }
    return work;
  };
  CHECK_THAT(work_from(law.separation), Catch::Matchers::WithinRel(dgamma, 1e-12));
  // The written-out work of the rigid-limit test below against the law's own stress.
  for (const double h : {1.0, 1.5, 3.0})
    CHECK_THAT(work_beyond(h * law.separation, law.separation),
               Catch::Matchers::WithinRel(work_from(h * law.separation), 1e-12));
  for (const double h : {0.6, 0.9, 1.0, 1.3, 2.0, 5.0})
    {
      const double step  = 1e-6 * law.separation, at = h * law.separation;
      const double slope = (law.stress(at + step) - law.stress(at - step)) / (2 * step);
      CHECK_THAT(law.slope(at), Catch::Matchers::WithinRel(slope, 1e-7));
    }
  // Below eps / 2 it continues linearly, finite.
  CHECK(std::isfinite(law.stress(0)));
  CHECK(law.stress(0) < law.stress(0.5 * law.separation));
  const LennardJonesLaw same = LennardJonesLaw::with_max_stress(law.max_stress(), dgamma);
  CHECK_THAT(same.separation, Catch::Matchers::WithinRel(law.separation, 1e-14));
}

TEST_CASE("Lennard-Jones FE: a rigid sphere's path is the Derjaguin integral, pull-off -2 pi dgamma R for every k",
          "[fem][quick]")
{
  // E0 = 1e10 against adhesive stresses of 0.1 (repulsion up to ~10 at the path's end): the surface moves by
  // ~1e-11 of eps, so the FE path must be the rigid one: F(d) = -2 pi R Phi(-d) exactly for the paraboloid, its
  // minimum -2 pi dgamma R at d = -eps (DMT). (On a softer body the states are off the rigid path by the elastic
  // part, which falls like 1 / E0.)
  const double          eps = 1e-2;
  const LennardJonesLaw law{dgamma, eps};
  for (const double k : {-0.5, 0.0, 0.5})
    {
      const Material            material = power_law_material(1e10, k);
      const Settings            settings = smooth_cohesion_settings(material, std::sqrt(2 * R * eps), 0.5);
      SmoothCohesiveContact     contact(material, Profile::paraboloid(R), settings);
      const SmoothCohesionPath  path = contact.trace(law);
      INFO("k = " << k << ": " << path.message);
      REQUIRE(path.converged);
      REQUIRE(path.has_force_minimum);
      CHECK_FALSE(path.has_snap_in);
      CHECK_FALSE(path.has_depth_jump);
      double worst = 0, worst_gap = 0;
      for (const SmoothCohesionState &s : path.states)
        {
          const double error = std::abs(s.force + 2 * pi * R * work_beyond(-s.depth, eps)) / (2 * pi * R * dgamma);
          if (error > worst)
            worst = error, worst_gap = s.central_gap / eps;
        }
      std::cout << "rigid limit k = " << k << ": " << path.states.size() << " states, worst |F - F_rigid| / (2 pi R dgamma) "
                << worst << " (at h_c = " << worst_gap << " eps), F_c / (-2 pi R dgamma) - 1 = " << path.force_pull_off.force / (-2 * pi * R * dgamma) - 1
                << ", d_c / eps = " << path.force_pull_off.depth / eps << ", " << path.surface_dofs
                << " surface DoFs, " << path.seconds << " s\n";
      CHECK(worst <= 1e-6);
      CHECK_THAT(path.force_pull_off.force, Catch::Matchers::WithinRel(-2 * pi * R * dgamma, 1e-6));
      CHECK_THAT(path.force_pull_off.depth, Catch::Matchers::WithinRel(-eps, 1e-5));
      // One state followed to a given central gap is the path's state there.
      const SmoothCohesionState &on_path = path.states[path.states.size() / 2];
      const SmoothCohesionState  alone   = contact.state(law, on_path.central_gap);
      CHECK_THAT(alone.central_gap, Catch::Matchers::WithinRel(on_path.central_gap, 1e-10));
      CHECK_THAT(alone.force, Catch::Matchers::WithinRel(on_path.force, 1e-8));
      CHECK_THROWS_WITH(contact.state(law, 0.1 * eps), Catch::Matchers::Contains("central gap"));
    }
}

TEST_CASE("Lennard-Jones rigid limit: Derjaguin's integral for the paraboloid, the FE path of a rigid power-law tip",
          "[fem]")
{
  const double          eps = 1e-2;
  const LennardJonesLaw law{dgamma, eps};
  // The paraboloid: F(d) = -2 pi R Phi(-d) in closed form (work_beyond above), pull-off -2 pi R dgamma at d = -eps.
  for (const double d : {-2.5 * eps, -1.3 * eps, -eps, -0.7 * eps})
    CHECK_THAT(rigid_force(law, Profile::paraboloid(R), d),
               Catch::Matchers::WithinRel(-2 * pi * R * work_beyond(-d, eps), 1e-13));
  const RigidPullOff sphere = rigid_pull_off(law, Profile::paraboloid(R));
  CHECK_THAT(sphere.force, Catch::Matchers::WithinRel(-2 * pi * R * dgamma, 1e-13));
  CHECK_THAT(sphere.depth, Catch::Matchers::WithinRel(-eps, 1e-6));

  // The power-law tip f = A r^4: F(d) = -(pi / 2) A^{-1/2} \int_0^inf sigma(u - d) u^{-1/2} du (u = f(r)), here by
  // Gauss-Legendre in t = sqrt(u) on [0, 40 sqrt(eps)] and the tail sigma ~ (8 dgamma / 3) eps^2 / u^3 beyond it.
  const double  A   = 1.0 / (4 * R * R * R);
  const Profile tip = Profile::power_law(4, A);
  const auto    by_u = [&](const double d) {
    const double       t_max = 40 * std::sqrt(eps);
    const unsigned int panels = 4000;
    const double       x[2] = {-0.5773502691896257, 0.5773502691896257};
    double             integral = 0;
    for (unsigned int i = 0; i < panels; ++i)
      for (const double xi : x)
        {
          const double t = (i + 0.5 + 0.5 * xi) * t_max / panels;
          integral += 2 * law.stress(t * t - d) * 0.5 * t_max / panels;
        }
    const double u_max = t_max * t_max; // \int_umax^inf (8 dgamma / 3) eps^2 / u^3 u^{-1/2} du, beyond which h ~ u
    integral += 8 * dgamma / 3 * eps * eps / (2.5 * std::pow(u_max, 2.5));
    return -pi / 2 / std::sqrt(A) * integral;
  };
  for (const double d : {-2 * eps, -eps, -0.6 * eps})
    CHECK_THAT(rigid_force(law, tip, d), Catch::Matchers::WithinRel(by_u(d), 1e-8));
  const RigidPullOff rigid = rigid_pull_off(law, tip);
  CHECK(rigid.force < by_u(rigid.depth - 0.05 * eps));
  CHECK(rigid.force < by_u(rigid.depth + 0.05 * eps));

  // The FE path of the rigid tip (E0 = 1e10, as in the sphere's test above) is F(d) of the rigid limit at every
  // state, and its pull-off the smallest F; on a fixed mesh and on the edge-following one (fem/adhesion/smooth_cohesion.h,
  // "Following the edge"), whatever the state's frame.
  const double r_eps = std::pow(eps / A, 0.25);
  for (const auto &[k, follow_edge] : {std::pair{0.0, false}, std::pair{0.5, false}, std::pair{0.5, true}})
    {
      const Material           material = power_law_material(1e10, k);
      SmoothCohesionParameters parameters;
      parameters.follow_edge = follow_edge;
      SmoothCohesiveContact    contact(material, tip, smooth_cohesion_settings(material, r_eps, 0.5), parameters);
      const SmoothCohesionPath path = contact.trace(law);
      INFO("k = " << k << (follow_edge ? ", following the edge" : "") << ": " << path.message);
      REQUIRE(path.converged);
      REQUIRE(path.has_force_minimum);
      double worst = 0;
      for (const SmoothCohesionState &s : path.states)
        worst = std::max(worst, std::abs(s.force - rigid_force(law, tip, s.depth)) / std::abs(rigid.force));
      std::cout << "rigid power-law tip n = 4, k = " << k << (follow_edge ? ", following the edge" : "") << ": "
                << path.frames << " frames, " << path.states.size() << " states, worst |F - F_rigid(d)| / |F_c,rigid| "
                << worst
                << ", F_c / F_c,rigid - 1 = " << path.force_pull_off.force / rigid.force - 1
                << " (F_c,rigid / (2 pi dgamma r_eps) = " << rigid.force / (2 * pi * dgamma * r_eps) << ", d = "
                << rigid.depth / eps << " eps), " << path.seconds << " s\n";
      if (follow_edge)
        {
          CHECK(path.frames > 5);
          CHECK(worst <= 1e-7);
          CHECK_THAT(path.force_pull_off.force, Catch::Matchers::WithinRel(rigid.force, 1e-7));
        }
      else
        {
          CHECK(worst <= 1e-6);
          CHECK_THAT(path.force_pull_off.force, Catch::Matchers::WithinRel(rigid.force, 1e-6));
          CHECK_THAT(path.force_pull_off.depth, Catch::Matchers::WithinRel(rigid.depth, 1e-4));
        }
    }
  CHECK_THROWS_WITH(rigid_force(law, Profile::concave_paraboloid(0.1), -eps), Catch::Matchers::Contains("concave"));
  CHECK_THROWS_WITH(rigid_force(law, Profile::power_law(0.5, 1.0), -eps), Catch::Matchers::Contains("exponent"));
}

TEST_CASE("Lennard-Jones FE at k = -0.5 and 0: from DMT toward the chapter's JKR as the Tabor parameter grows", "[fem]")
{
  for (const double k : {-0.5, 0.0})
  {
  const double              E0 = 1;
  const Material            material = power_law_material(E0, k);
  const gradcontact::Medium medium   = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  const auto jkr = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma, gradcontact::Control::force);
  SmoothCohesiveContact contact(material, Profile::paraboloid(R), smooth_cohesion_settings(material, jkr.radius));
  // The DMT pull-off -2 pi dgamma R against JKR's (9.55) of this k: the upper end of the transition.
  const double        dmt_deviation = -2 * pi * R * dgamma / jkr.force - 1;
  std::vector<double> deviation;
  for (const double mu : {0.3, 1.0, 3.0})
    {
      const SmoothCohesionPath path = contact.trace({dgamma, separation_of_tabor(mu, E0)});
      INFO("k = " << k << ", mu = " << mu << ": " << path.message);
      REQUIRE(path.converged);
      REQUIRE(path.has_force_minimum);
      deviation.push_back(path.force_pull_off.force / jkr.force - 1);
      std::cout << "Lennard-Jones k = " << k << ", mu = " << mu << ": F_c / F_JKR - 1 = " << deviation.back()
                << " (DMT " << dmt_deviation << "), depth jump " << path.has_depth_jump << ", " << path.steps
                << " steps, " << path.newton_iterations << " Newton solves, " << path.factorisations
                << " factorisations, " << path.seconds << " s\n";
      // Between DMT and JKR.
      CHECK(deviation.back() > 0);
      CHECK(deviation.back() < dmt_deviation);
      // At k = 0 displacement control jumps off only from mu ~ 1 on (Greenwood 1997); mu of other k is not theirs.
      if (k == 0)
        CHECK(path.has_depth_jump == (mu >= 1));
      if (mu == 0.3)
        CHECK_FALSE(path.has_depth_jump);
    }
  CHECK(deviation[1] < deviation[0]);
  CHECK(deviation[2] < deviation[1]);
  CHECK(deviation[2] < (k == 0 ? 0.05 : 0.25));
  }
}

// Label slow (./vv test --all): the default tier keeps the Lennard-Jones path from DMT toward JKR on the coarser mesh.
TEST_CASE("Lennard-Jones FE: pull-off on a finer mesh", "[slow]")
{
  const double              E0 = 1, k = -0.5;
  const Material            material = power_law_material(E0, k);
  const gradcontact::Medium medium   = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
  const auto jkr = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma, gradcontact::Control::force);
  const LennardJonesLaw law{dgamma, separation_of_tabor(1.0, E0)};
  std::vector<double>   force;
  for (const double refinement : {1.0, 2.0})
    {
      SmoothCohesiveContact    contact(material, Profile::paraboloid(R), smooth_cohesion_settings(material, jkr.radius, refinement));
      const SmoothCohesionPath path = contact.trace(law);
      INFO(path.message);
      REQUIRE(path.converged);
      REQUIRE(path.has_force_minimum);
      force.push_back(path.force_pull_off.force);
      std::cout << "Lennard-Jones k = -0.5, mesh x" << refinement << ": F_c / F_JKR = " << force.back() / jkr.force
                << ", " << path.surface_dofs << " surface DoFs of " << path.n_dofs << ", flexibility "
                << path.flexibility_seconds << " s, path " << path.seconds << " s\n";
    }
  CHECK_THAT(force[0], Catch::Matchers::WithinRel(force[1], 1e-5));
}

TEST_CASE("Lennard-Jones FE following the edge: the model is self-similar, the followed path is the fixed mesh's",
          "[fem]")
{
  // The premise (fem/adhesion/smooth_cohesion.h, "Following the edge"): for E0 (z / c0)^k the FE model built at the contact
  // radius s a is the one at a scaled by s, its flexibility s^{-(1+k)} times the other's at the nodes s r_i. Both
  // are built here from scratch (mesh, halvings, condensed far field, Gauss-Jacobi cells) at a and 1.37 a.
  const double a = 0.02, s = 1.37;
  for (const double k : {-0.5, 0.5})
    {
      const Material           material = power_law_material(1, k);
      const Settings           at_a = smooth_cohesion_settings(material, a, 0.5), at_sa = smooth_cohesion_settings(material, s * a, 0.5);
      AxisymmetricSolver       small(material, at_a.mesh, at_a.discretization);
      AxisymmetricSolver       large(material, at_sa.mesh, at_sa.discretization);
      const SurfaceFlexibility C = small.surface_flexibility(), Cs = large.surface_flexibility();
      REQUIRE(C.r.size() == Cs.r.size());
      double worst_node = 0, worst = 0, largest = 0;
      for (unsigned int i = 0; i < C.r.size(); ++i)
        {
          worst_node = std::max(worst_node, std::abs(Cs.r[i] - s * C.r[i]) / (s * a));
          for (unsigned int j = 0; j < C.r.size(); ++j)
            {
              worst   = std::max(worst, std::abs(Cs.matrix(i, j) - std::pow(s, -(1 + k)) * C.matrix(i, j)));
              largest = std::max(largest, std::abs(Cs.matrix(i, j)));
            }
        }
      std::cout << "self-similar flexibility k = " << k << ": " << C.r.size() << " surface DoFs, nodes " << worst_node
                << ", entries " << worst / largest << "\n";
      CHECK(worst_node <= 1e-12);
      // k = 0.5: 9e-8, the round-off of the soft surface's flexibility (its halvings to 1e-10 a).
      CHECK(worst <= (k > 0 ? 1e-6 : 1e-9) * largest);
    }

  // Elastic, k = -0.5, mu = 1 (the fixed meshes of "pull-off on a finer mesh" agree to 1e-5 there): the
  // edge-following path's critical states are the fixed mesh's.
  {
    const double              E0 = 1, k = -0.5;
    const Material            material = power_law_material(E0, k);
    const gradcontact::Medium medium   = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
    const auto jkr = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma, gradcontact::Control::force);
    const LennardJonesLaw    law{dgamma, separation_of_tabor(1.0, E0)};
    SmoothCohesionParameters follow;
    follow.follow_edge = true;
    SmoothCohesiveContact    fixed(material, Profile::paraboloid(R), smooth_cohesion_settings(material, jkr.radius));
    SmoothCohesiveContact    moving(material, Profile::paraboloid(R), smooth_cohesion_settings(material, jkr.radius), follow);
    const SmoothCohesionPath p0 = fixed.trace(law), p1 = moving.trace(law);
    INFO(p0.message << " / " << p1.message);
    REQUIRE(p0.converged);
    REQUIRE(p1.converged);
    REQUIRE(p1.has_force_minimum);
    std::cout << "k = -0.5, mu = 1 following the edge: F_c " << p1.force_pull_off.force / p0.force_pull_off.force - 1
              << " off the fixed mesh's, " << p1.frames << " frames, peak radius / a_JKR "
              << p1.force_pull_off.peak_radius / jkr.radius << ", " << p1.seconds << " s (fixed " << p0.seconds << " s)\n";
    CHECK(p1.frames > 5);
    CHECK_THAT(p1.force_pull_off.force, Catch::Matchers::WithinRel(p0.force_pull_off.force, 1e-7));
    CHECK_THAT(p1.force_pull_off.depth, Catch::Matchers::WithinRel(p0.force_pull_off.depth, 1e-7));
    CHECK(p1.has_depth_jump == p0.has_depth_jump);
    // state() follows the same frames: the pull-off's central gap gives the pull-off back.
    const SmoothCohesionState alone = moving.state(law, p1.force_pull_off.central_gap);
    CHECK_THAT(alone.force, Catch::Matchers::WithinRel(p1.force_pull_off.force, 1e-8));
  }

  // Not self-similar: refused.
  const Material shifted{std::make_shared<ShiftedPowerLawModulus>(1, c0, 0.5, 1e-3), nu};
  SmoothCohesionParameters follow;
  follow.follow_edge = true;
  CHECK_THROWS_WITH(SmoothCohesiveContact(shifted, Profile::paraboloid(R), smooth_cohesion_settings(shifted, 0.1), follow),
                    Catch::Matchers::Contains("self-similar"));
  follow.edge_band = 0;
  CHECK_THROWS_WITH(follow.validate(), Catch::Matchers::Contains("edge_band"));
  follow = {};
  follow.smallest_frame = 2;
  CHECK_THROWS_WITH(follow.validate(), Catch::Matchers::Contains("smallest_frame"));
}

TEST_CASE("Surface flexibility (CHOLMOD, and UMFPACK for the mixed formulation) applied to a pressure equals the solve",
          "[fem]")
{
  // The flexibility's columns against the solver's own constant-pressure solve (fem/bodies/axisymmetric_solver.h): w = C b with
  // b_i = \int_{r <= a} p0 phi_i r dr on the surface faces. The displacement formulation's matrix is positive
  // definite (CHOLMOD); the mixed one's is not (the UMFPACK fallback of DirectSystem::inverse_block).
  const double   a = 0.1, p0 = 1e-3;
  const Material material = power_law_material(1, 0.0);
  for (const Formulation formulation : {Formulation::displacement, Formulation::mixed})
    {
      Settings s                     = recommended_settings(a, 0.0, 1e-4);
      s.mesh.h_edge                  = 1e-2; // a small model: the fallback solves once per surface DoF
      s.discretization.degree        = 2;
      s.discretization.formulation   = formulation;
      AxisymmetricSolver       solver(material, s.mesh, s.discretization);
      const SurfaceFlexibility flexibility = solver.surface_flexibility();
      const unsigned int       n           = flexibility.dofs.size();
      // b_i = \int_{r <= a} p0 phi_i r dr (fem/elasticity/surface_trace.h; the solver loads its cells instead).
      const auto integrals = traction_integrals(flexibility.faces, [p0](double) { return p0; }, a, {}, GradedRule{},
                                                "test pressure");
      std::vector<double> b(n, 0.0);
      for (unsigned int f = 0; f < flexibility.faces.size(); ++f)
        for (unsigned int i = 0; i < flexibility.faces[f].r.size(); ++i)
          if (integrals[f][i] != 0)
            {
              const auto it = std::find(flexibility.dofs.begin(), flexibility.dofs.end(), flexibility.faces[f].dofs[1][i]);
              REQUIRE(it != flexibility.dofs.end());
              b[it - flexibility.dofs.begin()] += integrals[f][i];
            }
      LoadCase load;
      load.type     = LoadType::constant_pressure;
      load.pressure = p0;
      OutputRequest out;
      for (unsigned int i = 0; i < n; i += 7)
        out.displacement_radii.push_back(flexibility.r[i]);
      const Result result = solver.run(load, out);
      double       worst = 0, largest = 0;
      for (unsigned int i = 0, j = 0; i < n; i += 7, ++j)
        {
          double w = 0;
          for (unsigned int l = 0; l < n; ++l)
            w += flexibility.matrix(i, l) * b[l];
          worst   = std::max(worst, std::abs(w - result.displacement[j].value));
          largest = std::max(largest, std::abs(result.displacement[j].value));
        }
      std::cout << "surface flexibility, " << (formulation == Formulation::mixed ? "mixed" : "displacement") << ": " << n
                << " surface DoFs of " << solver.n_dofs() << " in " << flexibility.seconds << " s, against the solve "
                << worst / largest << "\n";
      CHECK(worst <= 1e-8 * largest);
      // Symmetric (Maxwell-Betti).
      double asymmetry = 0, entry = 0;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < i; ++j)
          {
            asymmetry = std::max(asymmetry, std::abs(flexibility.matrix(i, j) - flexibility.matrix(j, i)));
            entry     = std::max(entry, std::abs(flexibility.matrix(i, j)));
          }
      CHECK(asymmetry <= 1e-8 * entry);
    }
}

TEST_CASE("Lennard-Jones FE: bad input names the parameter", "[fem][quick]")
{
  CHECK_THROWS_WITH((LennardJonesLaw{0, 1}.validate()), Catch::Matchers::Contains("work of adhesion"));
  CHECK_THROWS_WITH((LennardJonesLaw{1, -1}.validate()), Catch::Matchers::Contains("separation"));
  CHECK_THROWS_WITH(LennardJonesLaw::with_max_stress(std::nan(""), 1), Catch::Matchers::Contains("max_stress"));
  SmoothCohesionParameters p;
  p.min_gap = 0.2;
  CHECK_THROWS_WITH(p.validate(), Catch::Matchers::Contains("min_gap"));
  p         = {};
  p.start_gap = 1;
  CHECK_THROWS_WITH(p.validate(), Catch::Matchers::Contains("start_gap"));
  const Material material = power_law_material(1, 0);
  CHECK_THROWS_WITH(smooth_cohesion_settings(material, 0.1, 100), Catch::Matchers::Contains("refinement"));
  CHECK_THROWS_WITH(SmoothCohesiveContact(material, Profile::concave_paraboloid(0.01), smooth_cohesion_settings(material, 0.1)),
                    Catch::Matchers::Contains("concave"));
}
