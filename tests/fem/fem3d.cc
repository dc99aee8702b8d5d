// fem3d: flat-punch runs of the 3D half-space model (fem/half_space_3d.h, p4est + Trilinos), checked
// against the meridian models on the same truncated body and against itself on one process.
//
//   mpirun -np 2 fem3d load=all k=0 nu=0.3 p=2 L=8 g3=1.6 R0=0.5 h_edge=1e-3 q=2 edge=0 grading=1 contact_ref=0 global3=0
//                      solver=direct|amg write=F against=F serial_tol=1e-10 compare=1 expect=1e-2
// load = normal (u_z = d, u_x, u_y free), tangential (u_x = delta, u_y = 0, u_z free), bonded (u = (delta, 0, d)),
// all (the three), or sphere: Coulomb frictional contact of a rigid sphere (fem/coulomb_contact_3d.h; keys mu,
// mu_normal, depth, delta, normal_steps, tangential_steps, cycle, candidates; compare=1: F_z at the end of the
// normal loading against the frictionless axisymmetric model, expect=X; theory=1: F_z and the loading F_x(delta)
// against the chapter's closed forms for the half-space (9.24, 9.80; a decoupled pairing at a large L),
// expect_theory=X). serial=1 (with np > 1): process 0 also runs the 3D model on MPI_COMM_SELF, and the
// program fails unless every force agrees within serial_tol relative. compare=1: process 0 runs the
// axisymmetric model (normal punch: F_z) and the Fourier mode-1 model (tangential punch: F_x) on the
// meridian mesh of the same body (the cylinder r <= L, z <= L; fem/mesh.h at L, otherwise the recommended
// mesh) and prints the relative differences; with expect=X it fails when one exceeds X. Prints key=value
// lines (process 0).
#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>
#include <fem/axisymmetric_solver.h>
#include <fem/coulomb_contact_3d.h>
#include <fem/fourier_mode1_solver.h>
#include <fem/half_space_3d.h>
#include <fem/modulus.h>

#include "study_arguments.h"

#include <deal.II/base/mpi.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace gradcontact::fem;

namespace
{
  /// The meridian mesh of the same truncated body (the cylinder r <= L, z <= L) for the axisymmetric and
  /// mode-1 references: the recommended mesh for k with the far field at L.
  MeshParameters meridian_of(const HalfSpaceMesh3DParameters &mesh, const double k)
  {
    MeshParameters meridian  = recommended_mesh_parameters(mesh.contact_radius, k, 1e-8);
    meridian.far_field_size  = mesh.far_field_size;
    meridian.near_field_size = std::min(meridian.near_field_size, mesh.far_field_size);
    meridian.h_far           = std::min(meridian.h_far, meridian.near_field_size);
    return meridian;
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm world = MPI_COMM_WORLD;
  const bool     root  = dealii::Utilities::MPI::this_mpi_process(world) == 0;
  try
    {
      const testing::StudyArguments args(argc, argv, "fem3d");
      auto num = [&](const std::string &key, const double fallback) { return args.num(key, fallback); };
      // The material of fem_study: E0 = 2 GPa, c0 = 3 a, a = 0.1 mm.
      const double E0 = 2e9, c0 = 3e-4, a = 1e-4, nu = num("nu", 0.3), k = num("k", 0.0);
      const Material material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};

      HalfSpaceMesh3DParameters mesh;
      mesh.contact_radius      = a;
      mesh.core_radius         = num("R0", mesh.core_radius);
      mesh.sectors             = args.count("sectors", mesh.sectors);
      mesh.far_field_size      = num("L", mesh.far_field_size);
      mesh.ring_growth         = num("g3", mesh.ring_growth);
      mesh.h_edge              = num("h_edge", mesh.h_edge);
      mesh.edge_ratio          = num("q", mesh.edge_ratio);
      mesh.surface_layer_thickness = num("layer", mesh.surface_layer_thickness);
      mesh.edge_refinements    = args.count("edge", mesh.edge_refinements);
      mesh.edge_grading        = num("grading", mesh.edge_grading);
      mesh.contact_refinements = args.count("contact_ref", mesh.contact_refinements);
      mesh.global_refinements  = args.count("global3", mesh.global_refinements);
      DiscretizationParameters disc;
      disc.degree = 2;
      args.apply(disc);
      DistributedSolverParameters parameters;
      args.apply(parameters);

      if (args.text("load", "all") == "sphere")
        {
          // A rigid sphere (radius R = 50 a): normal loading to d = depth a^2 / R in `normal_steps` steps with
          // friction mu_normal (default mu), then friction mu and a tangential displacement to delta mu d in
          // `tangential_steps` steps, then back to -delta mu d and again to +delta mu d (one cycle) when cycle=1.
          const double R = 50 * a;
          double       d_max = num("depth", 1.0) * a * a / R;
          // compare=1: the depth at which the frictionless axisymmetric model of the same body has the contact
          // radius a (its mesh's), and its force there; the 3D normal loading goes to that depth.
          const bool compare         = num("compare", 0) != 0;
          double     reference_force = 0;
          if (compare)
            {
              double reference[2] = {0, 0};
              if (root)
                {
                  const MeshParameters meridian = meridian_of(mesh, k);
                  DiscretizationParameters reference_disc;
                  reference_disc.degree = 3;
                  AxisymmetricSolver axisymmetric(material, meridian, reference_disc);
                  LoadCase           load;
                  load.type    = LoadType::indenter;
                  load.profile = Profile::paraboloid(R);
                  const Result r = axisymmetric.run(load);
                  reference[0]   = r.depth;
                  reference[1]   = r.force;
                }
              MPI_Bcast(reference, 2, MPI_DOUBLE, 0, world);
              d_max           = reference[0];
              reference_force = reference[1];
            }
          const double mu = num("mu", 0.3), mu_normal = num("mu_normal", mu);
          const unsigned int normal_steps = args.count("normal_steps", 10), tangential_steps = args.count("tangential_steps", 10);
          HalfSpace3DSolver solver(world, material, mesh, disc, parameters);
          const auto        compliance_start = std::chrono::steady_clock::now();
          const SurfaceCompliance3D surface  = solver.surface_compliance(num("candidates", 1.3) * a);
          const double compliance_time = dealii::Utilities::MPI::max(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - compliance_start).count(), world);
          CoulombParameters friction;
          friction.mu = mu_normal;
          CoulombContact3D contact(surface, Profile::paraboloid(R), friction);
          if (root)
            std::printf("sphere k=%g nu=%g p=%u np=%u dofs=%llu surface_nodes=%zu unknowns=%u compliance_time=%.2f\n", k,
                        nu, disc.degree, dealii::Utilities::MPI::n_mpi_processes(world),
                        static_cast<unsigned long long>(solver.n_dofs()), surface.nodes.size(), static_cast<unsigned int>(surface.C.m()),
                        compliance_time);
          int failed = 0;
          const auto print = [&](const char *phase, const CoulombState3D &st) {
            if (root)
              std::printf("%s d/d_max=%.4f delta/(mu d)=%.4f Fz=%.10e Fx=%.10e contact=%u stick=%u slip=%u "
                          "iterations=%u%s%s\n",
                          phase, st.depth / d_max, st.delta / (std::max(mu, 1e-300) * d_max), st.force_z, st.force_x,
                          st.n_contact, st.n_stick, st.n_slip, st.iterations, st.converged ? "" : " NOT CONVERGED: ",
                          st.message.c_str());
            if (!st.converged)
              failed = 1;
          };
          CoulombState3D state;
          unsigned int   normal_slip = 0;
          for (unsigned int i = 1; i <= normal_steps; ++i)
            {
              print("normal", state = contact.step_depth(d_max * i / normal_steps, 0.0));
              normal_slip = std::max(normal_slip, state.n_slip);
            }
          // expect_stick=1: a decoupled pairing (k = 0 with nu = 1/2, nu = 1 / (2 + k)) loaded normally with
          // friction has no tangential traction, so no node may slip.
          if (num("expect_stick", 0) != 0 && mu_normal > 0 && normal_slip > 0)
            {
              if (root)
                std::printf("FAILED: %u nodes slipped during the normal loading of a decoupled pairing\n", normal_slip);
              failed = 1;
            }
          if (compare)
            {
              const double difference = std::abs(state.force_z / reference_force - 1);
              if (root)
                std::printf("compare sphere F_z at d (frictionless meridian model at contact radius a): 3D %.10e "
                            "meridian %.10e relative difference %.3e\n",
                            state.force_z, reference_force, difference);
              const double expect = num("expect", 0);
              if (expect > 0 && !(difference <= expect))
                {
                  if (root)
                    std::printf("FAILED: F_z differs from the meridian model by more than %.1e\n", expect);
                  failed = 1;
                }
            }
          contact.set_friction(mu);
          const double delta_max = num("delta", 1.0) * mu * d_max;
          if (mu > 0 && tangential_steps > 0)
            {
              // theory=1: the chapter's closed forms for the half-space (meaningful at a large L and for a
              // decoupled pairing): the contact radius at d (9.24 family), F_N(a), and on loading the Cattaneo-Mindlin
              // law of the graded sphere (9.80): delta = mu alpha d [1 - (c/a)^2], F_x = mu F_N [1 - (c/a)^(k+3)].
              const bool theory       = num("theory", 0) != 0;
              double     theory_worst = 0; // the largest relative difference from the closed forms
              gradcontact::Medium medium{};
              double              a_theory = 0;
              const gradcontact::Paraboloid sphere{R};
              if (theory)
                {
                  medium   = gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu});
                  a_theory = gradcontact::contact_radius_from_depth(medium, gradcontact::as_power_law(sphere), d_max);
                  const double F_theory = gradcontact::force(medium, sphere, a_theory);
                  theory_worst          = std::abs(state.force_z / F_theory - 1);
                  if (root)
                    std::printf("theory: a/a_mesh=%.6f F_N=%.10e 3D F_z=%.10e relative difference %.3e\n", a_theory / a,
                                F_theory, state.force_z, std::abs(state.force_z / F_theory - 1));
                }
              for (unsigned int i = 1; i <= tangential_steps; ++i)
                {
                  print("loading", state = contact.step_depth(d_max, delta_max * i / tangential_steps));
                  if (theory)
                    {
                      const double full = mu * medium.alpha() * gradcontact::depth(medium, sphere, a_theory);
                      const double u    = delta_max * i / tangential_steps;
                      if (u < full)
                        {
                          const double c  = a_theory * std::sqrt(1 - u / full);
                          const double Fx = gradcontact::tangential::tangential_force(
                            medium, gradcontact::tangential::SphereSlip{R, mu}, a_theory, c);
                          const double difference = std::abs(state.force_x / Fx - 1);
                          if (root)
                            std::printf("theory: delta=%.4e c/a=%.4f F_x(9.80)=%.10e 3D F_x=%.10e relative difference %.3e\n",
                                        u, c / a_theory, Fx, state.force_x, difference);
                          theory_worst = std::max(theory_worst, difference);
                        }
                    }
                }
              const double expect_theory = num("expect_theory", 0);
              if (theory && expect_theory > 0 && !(theory_worst <= expect_theory))
                {
                  if (root)
                    std::printf("FAILED: the 3D model is %.2e off the closed forms (9.24, 9.80), more than %.1e\n",
                                theory_worst, expect_theory);
                  failed = 1;
                }
              const double loaded = state.force_x;
              if (num("cycle", 0) != 0)
                {
                  for (unsigned int i = 1; i <= 2 * tangential_steps; ++i)
                    print("unloading", state = contact.step_depth(d_max, delta_max * (1.0 - 2.0 * i / (2 * tangential_steps))));
                  for (unsigned int i = 1; i <= 2 * tangential_steps; ++i)
                    print("reloading", state = contact.step_depth(d_max, delta_max * (-1.0 + 2.0 * i / (2 * tangential_steps))));
                  // The loop closes: back at delta_max after a full cycle, F_x is the loading curve's (Masing;
                  // exact for the decoupled pairings, where the state at +-delta_max is the same slip pattern).
                  const double closure = std::abs(state.force_x / loaded - 1);
                  if (root)
                    std::printf("cycle: F_x at delta_max on loading %.10e, after the cycle %.10e, relative difference %.3e\n",
                                loaded, state.force_x, closure);
                  const double expect_closure = num("expect_closure", 0);
                  if (expect_closure > 0 && !(closure <= expect_closure))
                    {
                      if (root)
                        std::printf("FAILED: the hysteresis loop does not close within %.1e\n", expect_closure);
                      failed = 1;
                    }
                }
            }
          return dealii::Utilities::MPI::max(failed, world);
        }

      // The loads (unit-free amplitudes: d = delta = 1e-3 a).
      const double d = 1e-3 * a;
      std::map<std::string, FlatPunch3D> loads;
      const std::string load_name = args.text("load", "all");
      if (load_name == "normal" || load_name == "all")
        loads["normal"] = FlatPunch3D{{{false, false, true}}, {{0, 0, d}}};
      if (load_name == "tangential" || load_name == "all")
        loads["tangential"] = FlatPunch3D{{{true, true, false}}, {{d, 0, 0}}};
      if (load_name == "bonded" || load_name == "all")
        loads["bonded"] = FlatPunch3D{{{true, true, true}}, {{d, 0, d}}};
      if (loads.empty())
        throw std::invalid_argument("fem3d: load = " + load_name + " outside {normal, tangential, bonded, all}");

      const auto        start = std::chrono::steady_clock::now();
      HalfSpace3DSolver solver(world, material, mesh, disc, parameters);
      std::map<std::string, HalfSpace3DResult> results;
      int failed = 0;
      for (const auto &[name, punch] : loads)
        {
          const HalfSpace3DResult r = solver.run(punch);
          results[name]             = r;
          if (root)
            std::printf("load=%s k=%g nu=%g p=%u np=%u solver=%s dofs=%llu cells=%u min_edge_cell=%.2e "
                        "Fx=%.12e Fz=%.12e mismatch=%.1e residual=%.1e mesh=%.2f setup=%.2f assemble=%.2f "
                        "factorize=%.2f solve=%.2f peak_mb=%.0f %s\n",
                        name.c_str(), k, nu, disc.degree, r.n_processes, r.linear.solver.c_str(),
                        static_cast<unsigned long long>(r.n_dofs), r.n_cells, r.mesh.min_edge_cell, r.force[0],
                        r.force[2], r.energy_mismatch, r.linear.residual, r.time.mesh, r.time.setup,
                        r.time.assemble, r.time.factorize, r.time.solve, r.memory_mb, r.message.c_str());
          if (!r.reliable)
            failed = 1;
        }
      // collective: every process takes part in the maximum
      const double total = dealii::Utilities::MPI::max(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), world);
      if (root)
        std::printf("total=%.2f\n", total);

      // The answer on another number of processes: write=FILE stores the forces, against=FILE compares with them.
      if (args.has("write") && root)
        {
          std::ofstream out(args.text("write"));
          out.precision(17);
          for (const auto &[name, r] : results)
            out << name << ' ' << r.n_dofs << ' ' << r.force[0] << ' ' << r.force[2] << '\n';
          if (!out)
            throw std::runtime_error("fem3d: cannot write " + args.text("write"));
        }
      if (args.has("against") && root)
        {
          const double  tolerance = num("serial_tol", 1e-10);
          std::ifstream in(args.text("against"));
          if (!in)
            throw std::runtime_error("fem3d: cannot read " + args.text("against") + " (run with write= first)");
          std::string                    name;
          unsigned long long             dofs = 0;
          double                         fx = 0, fz = 0;
          unsigned int                   compared = 0;
          while (in >> name >> dofs >> fx >> fz)
            if (results.count(name))
              {
                const HalfSpace3DResult &r = results[name];
                // Relative to the largest force (a free component's force is round-off).
                const double scale = std::max(std::abs(fx), std::abs(fz));
                const double worst = std::max(std::abs(r.force[0] - fx), std::abs(r.force[2] - fz)) / scale;
                std::printf("against load=%s dofs=%llu Fx=%.12e Fz=%.12e | difference / largest force %.2e "
                            "(tolerance %.1e)\n",
                            name.c_str(), dofs, fx, fz, worst, tolerance);
                ++compared;
                if (dofs != r.n_dofs || !(worst <= tolerance))
                  {
                    std::printf("FAILED: the answer on %u processes differs from the stored one\n", r.n_processes);
                    failed = 1;
                  }
              }
          if (compared != results.size())
            {
              std::printf("FAILED: %s holds %u of the %zu loads\n", args.text("against").c_str(), compared,
                          results.size());
              failed = 1;
            }
        }

      if (num("compare", 0) != 0)
        {
          if (root)
            {
              // The meridian models of the same cylinder r <= L, z <= L.
              const MeshParameters meridian = meridian_of(mesh, k);
              DiscretizationParameters reference_disc;
              reference_disc.degree = 3;
              const double expect   = num("expect", 0);
              const auto   report   = [&](const char *what, const double fe3d, const double reference) {
                const double difference = std::abs(fe3d / reference - 1);
                std::printf("compare %s: 3D %.12e meridian %.12e relative difference %.3e\n", what, fe3d, reference,
                            difference);
                if (expect > 0 && !(difference <= expect))
                  {
                    std::printf("FAILED: %s differs from the meridian model by more than %.1e\n", what, expect);
                    failed = 1;
                  }
              };
              if (results.count("normal"))
                {
                  AxisymmetricSolver axisymmetric(material, meridian, reference_disc);
                  LoadCase           load;
                  load.type  = LoadType::flat_punch;
                  load.depth = d;
                  report("normal punch F_z", results["normal"].force[2], axisymmetric.run(load).force);
                }
              if (results.count("tangential"))
                {
                  FourierMode1Solver mode1(material, meridian, reference_disc);
                  report("tangential punch F_x", results["tangential"].force[0],
                         mode1.run(TangentialLoad::flat_punch(d)).force);
                }
            }
        }
      return dealii::Utilities::MPI::max(failed, world);
    }
  catch (const std::exception &e)
    {
      std::cerr << "fem3d (process " << dealii::Utilities::MPI::this_mpi_process(world) << "): " << e.what() << '\n';
      return 1;
    }
}
