// cohesive_study: the Dugdale cohesive-zone FE (fem/adhesion/cohesive_zone.h) on E0 (z/c0)^k for the Tabor map's
// scene (cases/validation/map_cohesive_paraboloid.prm: E0 = 1 GPa, c0 = 1 mm, nu = 0.3, R = 5 mm,
// dgamma = 0.05 J/m^2), one state or one pull-off, for the measurements fem/doc/loads-and-contact.md names. Not a test.
//
//   cohesive_study k=0.5 lambda=10 mode=state x=1 p=2 h_edge=1e-5 zone_refinements=8
//   cohesive_study k=0.5 lambda=10 mode=critical control=force
//   cohesive_study k=0.5 mode=jkr control=force      (the FE JKR pull-off of fem/adhesion/adhesion.h on the same mesh)
//   cohesive_study k=0.5 lambda=1 mode=smooth         (the Lennard-Jones path of fem/adhesion/smooth_cohesion.h, its largest
//                                                      stress the Dugdale sigma_0 of lambda; path=1 prints the states)
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

int main(int argc, char **argv)
{
  try
    {
      const gradcontact::studies::StudyArguments args(argc, argv, "cohesive_study");
      constexpr double E0 = 1e9, c0 = 1e-3, nu = 0.3, R = 5e-3, dgamma = 0.05;
      const double     k      = args.num("k", 0.5);
      const double     lambda = args.num("lambda", 10);
      const std::string mode  = args.text("mode", "state");
      const bool force_control = args.text("control", "force") == "force";
      const auto control      = force_control ? gradcontact::Control::force : gradcontact::Control::displacement;
      const gradcontact::Medium medium = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
      const auto jkr   = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma, control);
      const auto jkr_f = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma,
                                                          gradcontact::Control::force);
      // The map's Tabor parameter (analytic/maugis_dugdale.h: C Delta_l(a_c) / h_0).
      constexpr double pi = 3.14159265358979323846;
      const DugdaleLaw law{gradcontact::maugis_dugdale::strength(medium, gradcontact::Paraboloid{R}, dgamma, lambda), dgamma};
      const double     h0 = law.range();

      const Material material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
      const auto settings = [&](const double a) {
        Settings s = recommended_settings(a, k, args.num("tol", 1e-5));
        s.discretization.degree = args.count("p", 2);
        args.apply(s.mesh);
        args.apply(s.discretization);
        return s;
      };
      CohesiveParameters parameters;
      parameters.zone_refinements = args.count("zone_refinements", parameters.zone_refinements);
      parameters.zone_tolerance   = args.num("zone_tolerance", parameters.zone_tolerance);
      parameters.zone_cells       = args.count("zone_cells", parameters.zone_cells);
      parameters.gap_window       = args.num("gap_window", parameters.gap_window);
      parameters.radius_tolerance = args.num("radius_tolerance", parameters.radius_tolerance);
      std::cout.precision(10);
      std::cout << "k=" << k << " lambda=" << lambda << " h0=" << h0 << " sigma0=" << law.strength
                << " a_jkr=" << jkr.radius << " F_jkr=" << jkr.force << " d_jkr=" << jkr.depth << '\n';

      if (mode == "jkr")
        {
          AdhesiveContact contact(material, Profile::paraboloid(R), settings);
          const auto c = contact.critical_state(dgamma, force_control ? AdhesionControl::force
                                                                       : AdhesionControl::displacement, jkr.radius);
          std::cout << "fe_jkr a/a_jkr=" << c.state.radius / jkr.radius << " F/F_jkr-1=" << c.state.force / jkr.force - 1
                    << " d/d_jkr-1=" << c.state.depth / jkr.depth - 1 << '\n';
          return 0;
        }
      if (mode == "smooth")
        {
          // One mesh for the whole path, graded toward the force-controlled JKR radius (smooth_cohesion_settings).
          Settings s = smooth_cohesion_settings(material, jkr_f.radius, args.num("refinement", 1));
          args.apply(s.mesh);
          args.apply(s.discretization);
          const LennardJonesLaw    smooth = LennardJonesLaw::with_max_stress(law.strength, dgamma);
          SmoothCohesionParameters sp;
          sp.max_change = args.num("max_change", sp.max_change);
          sp.start_gap  = args.num("start_gap", sp.start_gap);
          sp.quadrature_points = args.count("qp", sp.quadrature_points);
          sp.follow_edge       = args.count("follow_edge", 0) != 0;
          sp.max_step          = args.num("max_step", sp.max_step);
          sp.max_steps         = args.count("max_steps", sp.max_steps);
          sp.edge_band         = args.num("edge_band", sp.edge_band);
          sp.smallest_frame    = args.num("smallest_frame", sp.smallest_frame);
          SmoothCohesiveContact contact(material, Profile::paraboloid(R), s, sp);
          const SmoothCohesionPath path = contact.trace(smooth);
          const double F_dmt = -2 * pi * dgamma * R;
          const auto print = [&](const std::string &what, const SmoothCohesionState &st) {
            std::cout << what << " hc/eps=" << st.central_gap / smooth.separation << " d/eps=" << st.depth / smooth.separation
                      << " F/F_jkr=" << st.force / jkr_f.force << " F/F_dmt=" << st.force / F_dmt
                      << " a/a_jkr=" << st.contact_radius / jkr_f.radius << " ap/a_jkr=" << st.peak_radius / jkr_f.radius << " dF=" << st.force_slope
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
          std::cout << "eps=" << smooth.separation << " dofs=" << path.n_dofs << " surface=" << path.surface_dofs
                    << " steps=" << path.steps << " rejected=" << path.rejected_steps << " frames=" << path.frames << " newton=" << path.newton_iterations << " lu=" << path.factorisations
                    << " critical=" << path.critical_evaluations << " flex_s=" << path.flexibility_seconds
                    << " s=" << path.seconds << " converged=" << path.converged << " " << path.message << '\n';
          if (path.has_force_minimum)
            std::cout << "force: F_c/F_jkr-1=" << path.force_pull_off.force / jkr_f.force - 1
                      << " F_c/F_dmt-1=" << path.force_pull_off.force / F_dmt - 1 << '\n';
          if (path.has_depth_jump)
            {
              const auto jkr_d = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma,
                                                                  gradcontact::Control::displacement);
              std::cout << "displacement: F/F_jkr-1=" << path.depth_pull_off.force / jkr_d.force - 1
                        << " d/d_jkr-1=" << path.depth_pull_off.depth / jkr_d.depth - 1 << '\n';
            }
          return 0;
        }
      if (mode == "fixed")
        {
          // One mesh, the zone (a, c) given: a = x a_c,JKR, c = a (1 + zone), refined by `levels` toward a (ra=1) and c
          // (rc=1).
          const double a = args.num("x", 1) * jkr.radius;
          double c = a * (1 + args.num("zone", 2.14e-5));
          Settings s = settings(a);
          s.mesh.contact_radius = a;
          SurfaceRefinement refinement;
          refinement.levels = args.count("levels", 8);
          if (args.num("ra", 0) != 0)
            refinement.radii.push_back(a);
          if (args.num("rc", 1) != 0)
            refinement.radii.push_back(c);
          if (args.count("cells", 0) > 0)
            refinement.intervals.push_back({a, c, args.count("cells", 0)});
          const double window = args.num("window", 0) * (c - a);
          if (window > 0)
            refinement.intervals.push_back({c - window, c + window, args.count("window_cells", 16)});
          AxisymmetricSolver solver(material, s.mesh, s.discretization, refinement);
          if (args.num("node_levels", -1) >= 0)
            {
              // c moved to the surface vertex nearest to it on the mesh refined node_levels times toward c.
              SurfaceRefinement coarse = refinement;
              coarse.levels = args.count("node_levels", 0);
              AxisymmetricSolver probe(material, s.mesh, s.discretization, coarse);
              double best = c;
              double dist = 1e300;
              for (const auto &v : probe.get_triangulation().get_vertices())
                if (std::abs(v[1]) < 1e-14 * a && std::abs(v[0] - c) < dist)
                  dist = std::abs(v[0] - c), best = v[0];
              c = best;
            }
          LoadCase load;
          load.type            = LoadType::indenter;
          load.profile         = Profile::paraboloid(R);
          load.cohesion.stress = law.strength * args.num("scale", 1);
          load.cohesion.radius = c;
          OutputRequest out;
          out.displacement_radii = {c};
          const Result r = solver.run(load, out);
          const double h = load.profile(c, a) - r.depth + r.displacement.front().value;
          const double delta = args.num("avg", 0) * (c - a);
          if (delta > 0)
            {
              // The gap averaged over [c - delta, c + delta] (the antisymmetric cusp |r - c|^{1-k} sign(r - c) cancels).
              const unsigned int M = args.count("navg", 64);
              OutputRequest o;
              for (unsigned int i = 0; i <= M; ++i)
                {
                  o.displacement_radii.push_back(c - delta * i / M);
                  o.displacement_radii.push_back(c + delta * i / M);
                }
              load.cohesion.radius = c;
              const Result ra = solver.run(load, o);
              double sum = 0, weight = 0;
              for (std::size_t j = 0; j < ra.displacement.size(); ++j)
                {
                  const double wt = (j < 2 || j + 2 >= ra.displacement.size()) ? 0.5 : 1.0; // trapezoid
                  sum += wt * (load.profile(ra.displacement[j].r, a) - ra.depth + ra.displacement[j].value);
                  weight += wt;
                }
              std::cout << "avg h/h0-1=" << sum / weight / h0 - 1 << ' ';
            }
          for (int j = -4; j <= 4 && window > 0; ++j)
            {
              const double cj = c + j * window / 5;
              load.cohesion.radius = cj;
              out.displacement_radii = {cj};
              const Result rj = solver.run(load, out);
              std::cout << " h(c + " << j << " W/5)/h0-1=" << (load.profile(cj, a) - rj.depth + rj.displacement.front().value) / h0 - 1
                        << " F/F_jkr-1=" << rj.force / jkr.force - 1;
            }
          std::cout << "time mesh=" << r.time.mesh << " setup=" << r.time.setup << " assemble=" << r.time.assemble
                    << " factorize=" << r.time.factorize << " solve=" << r.time.solve << " post=" << r.time.postprocess
                    << '\n';
          std::cout << "fixed (c-a)/a=" << (c - a) / a << " levels=" << refinement.levels << " dofs=" << solver.n_dofs() << " d=" << r.depth
                    << " F=" << r.force << " h(c)/h0-1=" << h / h0 - 1 << " F/F_jkr-1=" << r.force / jkr.force - 1
                    << '\n';
          return 0;
        }
      CohesiveContact contact(material, Profile::paraboloid(R), law, settings, parameters);
      const auto print = [&](const std::string &what, const CohesiveState &s) {
        std::cout << what << " a/a_jkr=" << s.radius / jkr.radius << " (c-a)/a=" << (s.zone_radius - s.radius) / s.radius
                  << " F/F_jkr-1=" << s.force / jkr.force - 1 << " d/d_jkr-1=" << s.depth / jkr.depth - 1
                  << " F=" << s.force << " d=" << s.depth << " meshes=" << s.meshes << " solves=" << s.zone_solves
                  << " dofs=" << s.n_dofs << " s=" << s.seconds << " consistent=" << s.consistent << " " << s.message
                  << '\n';
      };
      // The same state by the MDR (analytic/maugis_dugdale.h), the independent reference.
      const auto compare = [&](const std::string &prefix, const CohesiveState &st) {
        try
          {
            const auto m = gradcontact::maugis_dugdale::state(
              medium, gradcontact::Paraboloid{R}, gradcontact::maugis_dugdale::Dugdale{law.strength, dgamma}, st.radius);
            std::cout << prefix << "mdr: F/F_mdr-1=" << st.force / m.force - 1 << " d/d_mdr-1=" << st.depth / m.depth - 1
                      << " c/c_mdr-1=" << st.zone_radius / m.zone_radius - 1
                      << " (c_mdr-a)/a=" << (m.zone_radius - st.radius) / st.radius << '\n';
          }
        catch (const std::exception &e)
          {
            std::cout << prefix << "mdr: " << e.what() << '\n'; // e.g. no closing zone next to the vanishing contact
          }
      };
      if (mode == "state")
        {
          const CohesiveState &st = contact.state(args.num("x", 1) * jkr.radius);
          print("state", st);
          compare("", st);
          return 0;
        }
      const auto c = contact.critical_state(force_control ? AdhesionControl::force : AdhesionControl::displacement,
                                            jkr.radius);
      for (const auto &[a, s] : contact.states())
        {
          print("path", s);
          compare("  ", s);
        }
      print("critical", c.state);
      std::cout << "states=" << c.states_solved << " seconds=" << c.seconds << " vanishing=" << c.at_vanishing_contact
                << '\n';
      // The same pull-off by the MDR (analytic/maugis_dugdale.h), the independent reference.
      const auto mdr = gradcontact::maugis_dugdale::pull_off(medium, gradcontact::Paraboloid{R},
                                                             gradcontact::maugis_dugdale::Dugdale{law.strength, dgamma},
                                                             control);
      std::cout << "mdr: F/F_mdr-1=" << c.state.force / mdr.state.force - 1
                << " d/d_mdr-1=" << c.state.depth / mdr.state.depth - 1
                << " a/a_mdr-1=" << c.state.radius / mdr.state.radius - 1 << " exists=" << mdr.exists << '\n';
      return 0;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 1;
    }
}
