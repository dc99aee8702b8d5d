// cohesive_study: the Dugdale cohesive-zone FE (fem/adhesion/cohesive_zone.h) on E0 (z/c0)^k for the Tabor map's
// scene (cases/validation/map_cohesive_paraboloid.prm: E0 = 1 GPa, c0 = 1 mm, nu = 0.3, R = 5 mm,
// dgamma = 0.05 J/m^2), one state or one pull-off, the numbers fem/doc/loads-and-contact.md names. Not a test.
//
//   cohesive_study k=0.5 lambda=10 mode=state x=1 p=2 h_edge=1e-5 zone_refinements=8
//   cohesive_study k=0.5 lambda=10 mode=critical control=force
//   cohesive_study k=0.5 mode=jkr control=force      (the FE JKR pull-off of fem/adhesion/adhesion.h on the same mesh)
//   cohesive_study k=0.5 lambda=1 mode=smooth         (the Lennard-Jones path of fem/adhesion/smooth_cohesion.h, its largest
//                                                      stress the Dugdale sigma_0 of lambda; path=1 prints the states)
//   cohesive_study k=0.5 lambda=10 mode=fixed x=1 zone=2.14e-5   (one solve with the zone (a, c) given)
// lambda is the map's Tabor parameter (cases/runners/fe_cohesive.h); x: a / a_c,JKR of the state. Every key is optional;
// the mesh and discretisation keys of study_arguments.h override the recommended settings (force tolerance
// 1e-5). Prints key=value lines.
#include <fem/adhesion/adhesion.h>
#include <fem/adhesion/cohesive_zone.h>
#include <fem/modulus/modulus.h>
#include <fem/adhesion/smooth_cohesion.h>

#include "study_arguments.h"

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/maugis_dugdale.h>

#include <cmath>
#include <iostream>
#include <memory>

using namespace gradcontact::fem;
using gradcontact::studies::StudyArguments;

namespace
{
  constexpr double E0 = 1e9, c0 = 1e-3, nu = 0.3, R = 5e-3, dgamma = 0.05;

  /// The map's scene at k and lambda, its JKR critical states and the Dugdale law of lambda.
  struct Scene
  {
    double                       k = 0, lambda = 0;
    std::string                  mode;
    bool                         force_control = true;
    gradcontact::Control         control       = gradcontact::Control::force;
    gradcontact::Medium          medium;
    gradcontact::jkr::CriticalState jkr, jkr_f; ///< in the asked control, and in force control
    DugdaleLaw                   law;
    double                       h0 = 0; ///< the Dugdale range
    Material                     material;
  };

  Scene parse_scene(const StudyArguments &args)
  {
    Scene sc;
    sc.k             = args.num("k", 0.5);
    sc.lambda        = args.num("lambda", 10);
    sc.mode          = args.text("mode", "state");
    sc.force_control = args.text("control", "force") == "force";
    sc.control       = sc.force_control ? gradcontact::Control::force : gradcontact::Control::displacement;
    sc.medium        = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, sc.k, nu});
    sc.jkr   = gradcontact::jkr::critical_state(sc.medium, gradcontact::Paraboloid{R}, dgamma, sc.control);
    sc.jkr_f = gradcontact::jkr::critical_state(sc.medium, gradcontact::Paraboloid{R}, dgamma,
                                                gradcontact::Control::force);
    // The map's Tabor parameter (analytic/maugis_dugdale.h: C Delta_l(a_c) / h_0).
    sc.law = DugdaleLaw{gradcontact::maugis_dugdale::strength(sc.medium, gradcontact::Paraboloid{R}, dgamma, sc.lambda),
                        dgamma};
    sc.h0       = sc.law.range();
    sc.material = Material{std::make_shared<PowerLawModulus>(E0, c0, sc.k), nu};
    return sc;
  }

  /// The recommended settings at contact radius a (force tolerance tol=, degree p=, default 2), with the mesh and
  /// discretisation keys applied.
  Settings settings_at(const StudyArguments &args, const double k, const double a)
  {
    Settings s = recommended_settings(a, k, args.num("tol", 1e-5));
    s.discretization.degree = args.count("p", 2);
    args.apply(s.mesh);
    args.apply(s.discretization);
    return s;
  }

  CohesiveParameters parse_cohesive_parameters(const StudyArguments &args)
  {
    CohesiveParameters parameters;
    parameters.zone_refinements = args.count("zone_refinements", parameters.zone_refinements);
    parameters.zone_tolerance   = args.num("zone_tolerance", parameters.zone_tolerance);
    parameters.zone_cells       = args.count("zone_cells", parameters.zone_cells);
    parameters.gap_window       = args.num("gap_window", parameters.gap_window);
    parameters.radius_tolerance = args.num("radius_tolerance", parameters.radius_tolerance);
    return parameters;
  }

  /// mode=jkr: the FE JKR pull-off of fem/adhesion/adhesion.h on the same mesh.
  void run_jkr(const StudyArguments &args, const Scene &sc)
  {
    AdhesiveContact contact(sc.material, Profile::paraboloid(R),
                            [&](const double a) { return settings_at(args, sc.k, a); });
    const auto c = contact.critical_state(dgamma, sc.force_control ? AdhesionControl::force
                                                                   : AdhesionControl::displacement, sc.jkr.radius);
    std::cout << "fe_jkr a/a_jkr=" << c.state.radius / sc.jkr.radius << " F/F_jkr-1=" << c.state.force / sc.jkr.force - 1
              << " d/d_jkr-1=" << c.state.depth / sc.jkr.depth - 1 << '\n';
  }

  SmoothCohesionParameters parse_smooth_parameters(const StudyArguments &args)
  {
    SmoothCohesionParameters sp;
    sp.max_change        = args.num("max_change", sp.max_change);
    sp.start_gap         = args.num("start_gap", sp.start_gap);
    sp.quadrature_points = args.count("qp", sp.quadrature_points);
    sp.follow_edge       = args.count("follow_edge", 0) != 0;
    sp.max_step          = args.num("max_step", sp.max_step);
    sp.max_steps         = args.count("max_steps", sp.max_steps);
    sp.edge_band         = args.num("edge_band", sp.edge_band);
    sp.smallest_frame    = args.num("smallest_frame", sp.smallest_frame);
    return sp;
  }

  /// The path's counts and its pull-offs against JKR (and DMT, -2 pi dgamma R).
  void print_smooth_summary(const Scene &sc, const LennardJonesLaw &smooth, const SmoothCohesionPath &path,
                            const double F_dmt)
  {
    std::cout << "eps=" << smooth.separation << " dofs=" << path.n_dofs << " surface=" << path.surface_dofs
              << " steps=" << path.steps << " rejected=" << path.rejected_steps << " frames=" << path.frames << " newton=" << path.newton_iterations << " lu=" << path.factorisations
              << " critical=" << path.critical_evaluations << " flex_s=" << path.flexibility_seconds
              << " s=" << path.seconds << " converged=" << path.converged << " " << path.message << '\n';
    if (path.has_force_minimum)
      std::cout << "force: F_c/F_jkr-1=" << path.force_pull_off.force / sc.jkr_f.force - 1
                << " F_c/F_dmt-1=" << path.force_pull_off.force / F_dmt - 1 << '\n';
    if (path.has_depth_jump)
      {
        const auto jkr_d = gradcontact::jkr::critical_state(sc.medium, gradcontact::Paraboloid{R}, dgamma,
                                                            gradcontact::Control::displacement);
        std::cout << "displacement: F/F_jkr-1=" << path.depth_pull_off.force / jkr_d.force - 1
                  << " d/d_jkr-1=" << path.depth_pull_off.depth / jkr_d.depth - 1 << '\n';
      }
  }

  /// mode=smooth: the Lennard-Jones path on one mesh, graded toward the force-controlled JKR radius
  /// (smooth_cohesion_settings); path=1 prints every state.
  void run_smooth(const StudyArguments &args, const Scene &sc)
  {
    constexpr double pi = 3.14159265358979323846;
    Settings s = smooth_cohesion_settings(sc.material, sc.jkr_f.radius, args.num("refinement", 1));
    args.apply(s.mesh);
    args.apply(s.discretization);
    const LennardJonesLaw          smooth = LennardJonesLaw::with_max_stress(sc.law.strength, dgamma);
    const SmoothCohesionParameters sp     = parse_smooth_parameters(args);
    SmoothCohesiveContact          contact(sc.material, Profile::paraboloid(R), s, sp);
    const SmoothCohesionPath       path  = contact.trace(smooth);
    const double                   F_dmt = -2 * pi * dgamma * R;
    const auto print = [&](const std::string &what, const SmoothCohesionState &st) {
      std::cout << what << " hc/eps=" << st.central_gap / smooth.separation << " d/eps=" << st.depth / smooth.separation
                << " F/F_jkr=" << st.force / sc.jkr_f.force << " F/F_dmt=" << st.force / F_dmt
                << " a/a_jkr=" << st.contact_radius / sc.jkr_f.radius << " ap/a_jkr=" << st.peak_radius / sc.jkr_f.radius << " dF=" << st.force_slope
                << " dd=" << st.depth_slope << " it=" << st.newton_iterations << " lu=" << st.factorisations << '\n';
    };
    if (args.count("path", 0))
      for (const auto &st : path.states)
        print("path", st);
    if (path.has_snap_in)
      print("snap_in", path.snap_in);
    if (path.has_depth_jump)
      print("depth_pull_off", path.depth_pull_off);
    if (path.has_force_minimum)
      print("force_pull_off", path.force_pull_off);
    print_smooth_summary(sc, smooth, path, F_dmt);
  }

  /// The surface refinement of mode=fixed: `levels` toward a (ra=1) and c (rc=1), cells= in (a, c), window_cells= in
  /// c +- window, window = window= (c - a).
  SurfaceRefinement fixed_refinement(const StudyArguments &args, const double a, const double c, double &window)
  {
    SurfaceRefinement refinement;
    refinement.levels = args.count("levels", 8);
    if (args.num("ra", 0) != 0)
      refinement.radii.push_back(a);
    if (args.num("rc", 1) != 0)
      refinement.radii.push_back(c);
    if (args.count("cells", 0) > 0)
      refinement.intervals.push_back({a, c, args.count("cells", 0)});
    window = args.num("window", 0) * (c - a);
    if (window > 0)
      refinement.intervals.push_back({c - window, c + window, args.count("window_cells", 16)});
    return refinement;
  }

  /// node_levels=n: c moved to the surface vertex nearest to it on the mesh refined n times toward c.
  double snap_to_vertex(const StudyArguments &args, const Scene &sc, const Settings &s,
                        const SurfaceRefinement &refinement, const double a, const double c)
  {
    SurfaceRefinement coarse = refinement;
    coarse.levels            = args.count("node_levels", 0);
    AxisymmetricSolver probe(sc.material, s.mesh, s.discretization, coarse);
    double             best = c;
    double             dist = 1e300;
    for (const auto &v : probe.get_triangulation().get_vertices())
      if (std::abs(v[1]) < 1e-14 * a && std::abs(v[0] - c) < dist)
        dist = std::abs(v[0] - c), best = v[0];
    return best;
  }

  /// avg=t: the gap averaged over [c - delta, c + delta], delta = t (c - a), by the trapezoid rule over navg= points
  /// a side (the antisymmetric cusp |r - c|^{1-k} sign(r - c) cancels).
  void print_averaged_gap(const StudyArguments &args, AxisymmetricSolver &solver, LoadCase &load, const double a,
                          const double c, const double h0)
  {
    const double delta = args.num("avg", 0) * (c - a);
    if (!(delta > 0))
      return;
    const unsigned int M = args.count("navg", 64);
    OutputRequest      o;
    for (unsigned int i = 0; i <= M; ++i)
      {
        o.displacement_radii.push_back(c - delta * i / M);
        o.displacement_radii.push_back(c + delta * i / M);
      }
    load.cohesion.radius = c;
    const Result ra = solver.run(load, o);
    double       sum = 0, weight = 0;
    for (std::size_t j = 0; j < ra.displacement.size(); ++j)
      {
        const double wt = (j < 2 || j + 2 >= ra.displacement.size()) ? 0.5 : 1.0; // trapezoid
        sum += wt * (load.profile(ra.displacement[j].r, a) - ra.depth + ra.displacement[j].value);
        weight += wt;
      }
    std::cout << "avg h/h0-1=" << sum / weight / h0 - 1 << ' ';
  }

  /// mode=fixed: one mesh, the zone (a, c) given: a = x a_c,JKR, c = a (1 + zone); the gap at c against h0, and with
  /// window=w the gap and force at nine zone ends across c +- w (c - a).
  void run_fixed(const StudyArguments &args, const Scene &sc)
  {
    const double a = args.num("x", 1) * sc.jkr.radius;
    double       c = a * (1 + args.num("zone", 2.14e-5));
    Settings     s = settings_at(args, sc.k, a);
    s.mesh.contact_radius = a;
    double                  window     = 0;
    const SurfaceRefinement refinement = fixed_refinement(args, a, c, window);
    AxisymmetricSolver      solver(sc.material, s.mesh, s.discretization, refinement);
    if (args.num("node_levels", -1) >= 0)
      c = snap_to_vertex(args, sc, s, refinement, a, c);
    LoadCase load;
    load.type            = LoadType::indenter;
    load.profile         = Profile::paraboloid(R);
    load.cohesion.stress = sc.law.strength * args.num("scale", 1);
    load.cohesion.radius = c;
    OutputRequest out;
    out.displacement_radii = {c};
    const Result r = solver.run(load, out);
    const double h = load.profile(c, a) - r.depth + r.displacement.front().value;
    print_averaged_gap(args, solver, load, a, c, sc.h0);
    for (int j = -4; j <= 4 && window > 0; ++j)
      {
        const double cj = c + j * window / 5;
        load.cohesion.radius   = cj;
        out.displacement_radii = {cj};
        const Result rj = solver.run(load, out);
        std::cout << " h(c + " << j << " W/5)/h0-1=" << (load.profile(cj, a) - rj.depth + rj.displacement.front().value) / sc.h0 - 1
                  << " F/F_jkr-1=" << rj.force / sc.jkr.force - 1;
      }
    std::cout << "time mesh=" << r.time.mesh << " setup=" << r.time.setup << " assemble=" << r.time.assemble
              << " factorize=" << r.time.factorize << " solve=" << r.time.solve << " post=" << r.time.postprocess
              << '\n';
    std::cout << "fixed (c-a)/a=" << (c - a) / a << " levels=" << refinement.levels << " dofs=" << solver.n_dofs() << " d=" << r.depth
              << " F=" << r.force << " h(c)/h0-1=" << h / sc.h0 - 1 << " F/F_jkr-1=" << r.force / sc.jkr.force - 1
              << '\n';
  }

  void print_state(const Scene &sc, const std::string &what, const CohesiveState &s)
  {
    std::cout << what << " a/a_jkr=" << s.radius / sc.jkr.radius << " (c-a)/a=" << (s.zone_radius - s.radius) / s.radius
              << " F/F_jkr-1=" << s.force / sc.jkr.force - 1 << " d/d_jkr-1=" << s.depth / sc.jkr.depth - 1
              << " F=" << s.force << " d=" << s.depth << " meshes=" << s.meshes << " solves=" << s.zone_solves
              << " dofs=" << s.n_dofs << " s=" << s.seconds << " consistent=" << s.consistent << " " << s.message
              << '\n';
  }

  /// The same state by the MDR (analytic/maugis_dugdale.h), the independent reference.
  void compare_state(const Scene &sc, const std::string &prefix, const CohesiveState &st)
  {
    try
      {
        const auto m = gradcontact::maugis_dugdale::state(
          sc.medium, gradcontact::Paraboloid{R}, gradcontact::maugis_dugdale::Dugdale{sc.law.strength, dgamma}, st.radius);
        std::cout << prefix << "mdr: F/F_mdr-1=" << st.force / m.force - 1 << " d/d_mdr-1=" << st.depth / m.depth - 1
                  << " c/c_mdr-1=" << st.zone_radius / m.zone_radius - 1
                  << " (c_mdr-a)/a=" << (m.zone_radius - st.radius) / st.radius << '\n';
      }
    catch (const std::exception &e)
      {
        std::cout << prefix << "mdr: " << e.what() << '\n'; // e.g. no closing zone next to the vanishing contact
      }
  }

  /// mode=state: one state at a = x a_c,JKR; otherwise (mode=critical) the pull-off in the asked control with the
  /// states of its search, each against the MDR, and the MDR's pull-off.
  void run_cohesive(const StudyArguments &args, const Scene &sc, const CohesiveParameters &parameters)
  {
    CohesiveContact contact(sc.material, Profile::paraboloid(R), sc.law,
                            [&](const double a) { return settings_at(args, sc.k, a); }, parameters);
    if (sc.mode == "state")
      {
        const CohesiveState &st = contact.state(args.num("x", 1) * sc.jkr.radius);
        print_state(sc, "state", st);
        compare_state(sc, "", st);
        return;
      }
    const auto c = contact.critical_state(sc.force_control ? AdhesionControl::force : AdhesionControl::displacement,
                                          sc.jkr.radius);
    for (const auto &[a, s] : contact.states())
      {
        print_state(sc, "path", s);
        compare_state(sc, "  ", s);
      }
    print_state(sc, "critical", c.state);
    std::cout << "states=" << c.states_solved << " seconds=" << c.seconds << " vanishing=" << c.at_vanishing_contact
              << '\n';
    // The same pull-off by the MDR (analytic/maugis_dugdale.h), the independent reference.
    const auto mdr = gradcontact::maugis_dugdale::pull_off(sc.medium, gradcontact::Paraboloid{R},
                                                           gradcontact::maugis_dugdale::Dugdale{sc.law.strength, dgamma},
                                                           sc.control);
    std::cout << "mdr: F/F_mdr-1=" << c.state.force / mdr.state.force - 1
              << " d/d_mdr-1=" << c.state.depth / mdr.state.depth - 1
              << " a/a_mdr-1=" << c.state.radius / mdr.state.radius - 1 << " exists=" << mdr.exists << '\n';
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const StudyArguments     args(argc, argv, "cohesive_study");
      const Scene              sc         = parse_scene(args);
      const CohesiveParameters parameters = parse_cohesive_parameters(args);
      std::cout.precision(10);
      std::cout << "k=" << sc.k << " lambda=" << sc.lambda << " h0=" << sc.h0 << " sigma0=" << sc.law.strength
                << " a_jkr=" << sc.jkr.radius << " F_jkr=" << sc.jkr.force << " d_jkr=" << sc.jkr.depth << '\n';
      if (sc.mode == "jkr")
        run_jkr(args, sc);
      else if (sc.mode == "smooth")
        run_smooth(args, sc);
      else if (sc.mode == "fixed")
        run_fixed(args, sc);
      else
        run_cohesive(args, sc, parameters);
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 1;
    }
}
