// fem3d: flat-punch runs of the 3D half-space model (fem/bodies/half_space_3d.h, p4est + Trilinos), checked
// against the meridian models on the same truncated body and against itself on one process.
//
//   mpirun -np 2 fem3d load=all k=0 nu=0.3 p=2 L=8 g3=1.6 R0=0.5 h_edge=1e-3 q=2 inner=0 edge=0 grading=1 contact_ref=0 global3=0
//                      solver=direct|amg write=F against=F serial_tol=1e-10 compare=1 expect=1e-2
// load = normal (u_z = d, u_x, u_y free), tangential (u_x = delta, u_y = 0, u_z free), bonded (u = (delta, 0, d)),
// all (the three), or sphere: Coulomb frictional contact of a rigid sphere (fem/tangential/coulomb_contact_3d.h; keys mu,
// mu_normal, depth, delta, normal_steps, tangential_steps, cycle, candidates; compare=1: F_z at the end of the
// normal loading against the frictionless axisymmetric model, expect=X; theory_depth=1: the chapter's depth of
// contact radius a; theory=1: the path against the chapter's closed forms for the half-space (cases/runners/fe_coulomb_3d.h:
// 9.24, 9.80, 9.81, 9.84, 9.86; a decoupled pairing at a large L), expect_theory=X (F_z and loading F_x),
// expect_branch=X (/ F_A), expect_energy=X (loop area and friction work), expect_stick_zone=X (/ a, beyond the node
// bracket), expect_round=X (the rays' spread beyond their brackets); decoupled=1: the same path without the
// normal-tangential coupling, expect_coupling=X (coupling_ring=1: the stick radius may move by one ring); idealised=1 (with decoupled=1): also decoupled with every tangential
// force along x (Cattaneo-Mindlin's assumption), expect_idealised=X; cycle=1 with expect_closure=X; vtu=PREFIX: the surface state of every
// step for ParaView, PREFIX-<i>.vtu and PREFIX.pvd; compare_friction=1: the normal loading with friction against the
// axisymmetric frictional model, expect_friction=X). Punches: mossakovskii=1 (k = 0, load=all): the bonded punch's F_z
// over the frictionless one against Mossakovskii's ratio, expect_bonded=X; closed_form=1 (k = 0): the normal and
// tangential punches against Boussinesq's and Mindlin's forces, expect_closed=X; coulomb_punch=1 (load=all): the same
// punches through the Coulomb solver (mu = inf and 0), expect_coulomb_punch=X. serial=1 (with np > 1): process 0 also runs the 3D model on MPI_COMM_SELF, and the
// program fails unless every force agrees within serial_tol relative. compare=1: process 0 runs the
// axisymmetric model (normal punch: F_z) and the Fourier mode-1 model (tangential punch: F_x) on the
// meridian mesh of the same body (the cylinder r <= L, z <= L; fem/grid/mesh.h at L, otherwise the recommended
// mesh) and prints the relative differences; with expect=X it fails when one exceeds X. Prints key=value
// lines (process 0).
#include <analytic/material.h>
#include <analytic/normal.h>
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/tangential/coulomb_contact_3d.h>
#include <fem/tangential/fourier_mode1_solver.h>
#include <fem/bodies/half_space_3d.h>
#include <fem/modulus/modulus.h>
#include <fem/contact/unilateral_contact.h>

#include "study_arguments.h"

#include <cases/runners/fe_coulomb_3d.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <iostream>
#include <limits>
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

  /// The meridian references' discretisation (degree 3: their error well below the 3D model's), in the 3D model's
  /// formulation (the mixed one at nu = 1/2).
  DiscretizationParameters meridian_discretization(const Formulation formulation)
  {
    DiscretizationParameters d;
    d.degree      = 3;
    d.formulation = formulation;
    return d;
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm world = MPI_COMM_WORLD;
  const bool     root  = dealii::Utilities::MPI::this_mpi_process(world) == 0;
  try
    {
      const gradcontact::studies::StudyArguments args(argc, argv, "fem3d");
      auto num = [&](const std::string &key, const double fallback) { return args.num(key, fallback); };
      // The material of fem_study: E0 = 2 GPa, c0 = 3 a, a = 0.1 mm.
      const double E0 = 2e9, c0 = 3e-4, a = 1e-4, nu = num("nu", 0.3), k = num("k", 0.0);
      const Material material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};

      HalfSpaceMesh3DParameters mesh;
      mesh.contact_radius      = a;
      args.apply(mesh);
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
          // theory_depth=1: the chapter's depth at which the contact radius is the mesh's a (9.24 family)
          if (num("theory_depth", 0) != 0)
            d_max = gradcontact::depth(gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu}),
                                       gradcontact::Paraboloid{R}, a);
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
                  const DiscretizationParameters reference_disc = meridian_discretization(disc.formulation);
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
          gradcontact::cases::CoulombSphereCase study;
          study.E0 = E0;
          study.c0 = c0;
          study.k  = k;
          study.nu = nu;
          study.R  = R;
          study.mesh             = mesh;
          study.discretization   = disc;
          study.solver           = parameters;
          study.candidates       = num("candidates", study.candidates);
          study.depth            = d_max;
          study.mu               = num("mu", 0.3);
          study.mu_normal        = num("mu_normal", study.mu);
          study.normal_steps     = args.count("normal_steps", 10);
          study.tangential_steps = args.count("tangential_steps", 10);
          study.cycle            = num("cycle", 0) != 0;
          study.decoupled_reference = num("decoupled", 0) != 0;
          study.idealised_reference = num("idealised", 0) != 0;
          const double mu        = study.mu;
          // mu = 0 or tangential_steps = 0: the normal loading only (frictionless with mu = 0).
          study.delta = mu == 0 || study.tangential_steps == 0 ? 0.0 : num("delta", 1.0) * mu * d_max;
          int failed = 0;
          // vtu=PREFIX: the surface state of every step of the FE path, PREFIX-<step>.vtu, and PREFIX.pvd (process 0).
          const std::string vtu = args.text("vtu", "");
          std::vector<std::string> vtu_files;
          const auto print = [&](const gradcontact::cases::CoulombSphereStep &step, const SurfaceCompliance3D &C) {
            if (!root)
              return;
            if (!vtu.empty() && step.path == gradcontact::cases::CoulombPathKind::fe)
              {
                vtu_files.push_back(vtu + "-" + std::to_string(vtu_files.size()) + ".vtu");
                write_surface_vtu(C, step.state, vtu_files.back());
              }
            const CoulombState3D &st = step.state;
            std::printf("%s%s d/d_max=%.4f delta/(mu d)=%.4f Fz=%.10e Fx=%.10e contact=%u stick=%u slip=%u "
                        "iterations=%u%s%s",
                        step.path == gradcontact::cases::CoulombPathKind::fe ? "" : (to_string(step.path) + " ").c_str(), step.phase.c_str(), st.depth / d_max, st.delta / (std::max(mu, 1e-300) * d_max), st.force_z,
                        st.force_x, st.n_contact, st.n_stick, st.n_slip, st.iterations,
                        st.converged ? "" : " NOT CONVERGED: ", st.message.c_str());
            const auto &x = step.shape.stick;
            if (step.phase != "normal")
              std::printf(" stick_radius/a(+x,-x,+y)=%.4f,%.4f,%.4f(+-%.4f)", x[0].radius() / a, x[1].radius() / a,
                          x[2].radius() / a, std::max({x[0].half_width(), x[1].half_width(), x[2].half_width()}) / a);
            if (std::isfinite(step.theory_force_x))
              std::printf(" | chapter Fx=%.10e stick_radius/a=%.4f", step.theory_force_x, step.theory_stick / a);
            std::printf("\n");
          };
          const gradcontact::cases::CoulombSphereResult r = gradcontact::cases::run_coulomb_sphere(world, study, print);
          if (!vtu_files.empty())
            {
              std::ofstream pvd(vtu + ".pvd");
              pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
              for (std::size_t i = 0; i < vtu_files.size(); ++i)
                pvd << "<DataSet timestep=\"" << i << "\" file=\"" << std::filesystem::path(vtu_files[i]).filename().string()
                    << "\"/>\n";
              pvd << "</Collection>\n</VTKFile>\n";
              if (!pvd)
                throw std::runtime_error("fem3d: cannot write " + vtu + ".pvd");
            }
          if (root)
            std::printf("sphere k=%g nu=%g p=%u np=%u dofs=%llu surface_nodes=%u unknowns=%u compliance_time=%.2f "
                        "time=%.2f peak_mb=%.0f largest_iterations=%u\n",
                        k, nu, disc.degree, r.processes, r.dofs, r.surface_nodes, r.unknowns, r.compliance_seconds,
                        r.seconds, r.memory_mb, r.fe.max_iterations);
          if (!r.fe.converged)
            {
              if (root)
                std::printf("FAILED: %s\n", r.fe.message.c_str());
              failed = 1;
            }
          // The largest of several measures, NaN when one is NaN (not measured: a check of it must fail, not skip it).
          const auto worst_of = [](std::initializer_list<double> values) {
            double w = 0;
            for (const double v : values)
              w = std::isnan(v) || std::isnan(w) ? std::numeric_limits<double>::quiet_NaN() : std::max(w, v);
            return w;
          };
          const auto fails = [&](const char *key, const double value, const char *what) {
            const double limit = num(key, 0);
            if (limit > 0 && !(value <= limit))
              {
                if (root)
                  std::printf("FAILED: %s %.3e exceeds %s=%.1e\n", what, value, key, limit);
                failed = 1;
              }
          };
          // expect_stick=1: a decoupled pairing (k = 0 with nu = 1/2, nu = 1 / (2 + k)) loaded normally with
          // friction has no tangential traction, so no node may slip.
          if (num("expect_stick", 0) != 0 && study.mu_normal > 0 && r.fe.normal_slip > 0)
            {
              if (root)
                std::printf("FAILED: %u nodes slipped during the normal loading of a decoupled pairing\n", r.fe.normal_slip);
              failed = 1;
            }
          const double force_z = r.fe.steps.size() < study.normal_steps ? 0.0 : r.fe.steps[study.normal_steps - 1].state.force_z;
          if (compare)
            {
              const double difference = std::abs(force_z / reference_force - 1);
              if (root)
                std::printf("compare sphere F_z at d (frictionless meridian model at contact radius a): 3D %.10e "
                            "meridian %.10e relative difference %.3e\n",
                            force_z, reference_force, difference);
              fails("expect", difference, "F_z against the meridian model");
            }
          // compare_friction=1: the normal loading with friction mu_normal against the axisymmetric frictional model
          // of the same body (fem::UnilateralContactSolver with Friction, the meridian mesh of L, the same number of
          // equal depth steps, and twice as many, extrapolated): the 3D normal loading is axisymmetric, so the two differ
          // by discretisation only, and
          // the coupling of the normal loading (the Spence effect) is checked by an independent model. expect_friction=X
          // bounds the relative difference of F_z.
          if (num("compare_friction", 0) != 0 && r.fe.steps.size() >= study.normal_steps)
            {
              double reference[2] = {0, 0};
              if (root)
                {
                  const DiscretizationParameters reference_disc = meridian_discretization(disc.formulation);
                  UnilateralContactSolver axisymmetric(material, meridian_of(mesh, k), reference_disc, 1.3 * a);
                  UnilateralLoad load;
                  load.indenter             = Indenter::of(Profile::paraboloid(R), a);
                  load.friction.coefficient = study.mu_normal;
                  load.depth                = d_max;
                  // Its path error is first order in the step (a vertex that comes into contact during a step carries
                  // no shear in it): N and 2N steps, extrapolated.
                  load.friction.load_steps = study.normal_steps;
                  const UnilateralResult coarse = axisymmetric.run(load);
                  load.friction.load_steps = 2 * study.normal_steps;
                  const UnilateralResult fine = axisymmetric.run(load);
                  reference[0]                = 2 * fine.force - coarse.force;
                  reference[1]                = fine.stick_radius;
                  std::printf("compare_friction: axisymmetric F_z %.10e (%u steps), %.10e (%u steps)\n", coarse.force,
                              study.normal_steps, fine.force, 2 * study.normal_steps);
                }
              MPI_Bcast(reference, 2, MPI_DOUBLE, 0, world);
              const gradcontact::cases::CoulombSphereStep &last = r.fe.steps[study.normal_steps - 1];
              const double difference      = std::abs(last.state.force_z / reference[0] - 1);
              if (root)
                std::printf("compare_friction: F_z after the normal loading with mu = %g: 3D %.10e axisymmetric %.10e "
                            "(extrapolated) relative difference %.3e; stick radius / a: 3D (+x, -x, +y) %.4f, %.4f, %.4f "
                            "(+-%.4f), axisymmetric %.4f\n",
                            study.mu_normal, last.state.force_z, reference[0], difference,
                            last.shape.stick[0].radius() / a, last.shape.stick[1].radius() / a,
                            last.shape.stick[2].radius() / a, last.shape.stick[0].half_width() / a, reference[1] / a);
              fails("expect_friction", difference, "F_z with friction against the axisymmetric frictional model");
            }
          // theory=1: the chapter's closed forms for the half-space (cases/runners/fe_coulomb_3d.h; meaningful at a large L
          // and for a decoupled pairing).
          if (num("theory", 0) != 0 && root)
            {
              std::printf("theory: a/a_mesh=%.6f F_N(a)=%.10e F_z/F_N-1=%.3e loading F_x/F_x(9.80)-1 max %.3e\n",
                          r.a_theory / a, r.force_n_theory, r.fe.force_z_deviation, r.fe.loading_deviation);
              std::printf("theory: stick zone (rays +x, -x, +y) |c - c(9.80, 9.81)|/a max %.3e, bracket half-width %.3e, "
                          "spread over the rays %.3e; slip direction to x max %.3e rad, sum |Q_y| / sum |Q| of the slipping nodes max %.3e\n",
                          r.fe.stick_deviation, r.fe.stick_resolution, r.fe.out_of_round, r.fe.slip_angle, r.fe.slip_force_y);
              if (study.cycle)
                std::printf("theory: branches |F_x - F_x(9.84)|/F_A max %.3e; loop area %.10e, 9.86 %.10e, relative "
                            "difference %.3e (Simpson's rule on the closed-form loop: %.3e); friction work %.10e, "
                            "relative difference %.3e; closure %.3e\n",
                            r.fe.branch_deviation, r.fe.energy, r.energy_theory, r.fe.energy / r.energy_theory - 1,
                            r.energy_rule, r.fe.friction_work, r.fe.friction_work / r.energy_theory - 1, r.fe.closure);
            }
          if (num("theory", 0) != 0)
            {
              fails("expect_theory", worst_of({std::abs(r.fe.force_z_deviation), r.fe.loading_deviation}),
                    "the largest difference from 9.24 (F_z) and 9.80 (F_x)");
              fails("expect_branch", r.fe.branch_deviation, "|F_x - F_x(9.84)| / F_A on the branches");
              fails("expect_energy",
                    worst_of({std::abs(r.fe.energy / r.energy_theory - 1), std::abs(r.fe.friction_work / r.energy_theory - 1)}),
                    "the loop area and the friction work against 9.86");
              // a disc: the stick radii of the three rays agree to their brackets
              fails("expect_round", r.fe.out_of_round - 2 * r.fe.stick_resolution,
                    "the stick zone's spread over the rays beyond its brackets (/ a)");
              // the stick zone: the closed form's radius within the FE's bracket plus this
              fails("expect_stick_zone", r.fe.stick_deviation - r.fe.stick_resolution,
                    "the stick radius beyond the FE's bracket (/ a)");
            }
          // decoupled=1: the same path without the normal-tangential coupling (fem::without_coupling).
          if (study.decoupled_reference && root)
            std::printf("coupling (against the decoupled compliance, same mesh): F_z %.3e, loading F_x max %.3e, "
                        "branches max %.3e (/ F_A), loop area %.3e, stick radius max %.3e (/ a); the decoupled path "
                        "against the chapter: F_z %.3e, loading F_x %.3e, branches %.3e, loop area %.3e\n",
                        r.coupling_force_z, r.coupling_loading, r.coupling_branch, r.coupling_energy, r.coupling_stick,
                        r.decoupled.force_z_deviation, r.decoupled.loading_deviation, r.decoupled.branch_deviation,
                        r.decoupled.energy / r.energy_theory - 1);
          // expect_coupling=X (a decoupled pairing): the FE model equals its decoupled self within X, the stick radius
          // included. The stick radius moves by whole rings: with coupling_ring=1 a move of one ring (twice the bracket's
          // half-width) is allowed, the flip of a node on the stick-slip boundary under the discrete body's residual
          // coupling (the mixed element's at nu = 1/2, about 2e-5 of F_x), which is below the zone's resolution.
          const double stick_coupling = num("coupling_ring", 0) == 0 ? r.coupling_stick
                                        : std::isnan(r.coupling_stick)
                                          ? r.coupling_stick
                                          : std::max(0.0, r.coupling_stick - 2 * r.fe.stick_resolution);
          if (study.decoupled_reference)
            fails("expect_coupling",
                  worst_of({std::abs(r.coupling_force_z), r.coupling_loading, r.coupling_branch, std::abs(r.coupling_energy),
                            stick_coupling}),
                  "the coupling's largest effect");
          if (study.decoupled_reference && !r.decoupled.converged)
            {
              if (root)
                std::printf("FAILED: decoupled path: %s\n", r.decoupled.message.c_str());
              failed = 1;
            }
          // idealised=1 (with decoupled=1): the path of the chapter's idealisation on the same body (decoupled, every
          // tangential force along x: Cattaneo-Mindlin's assumption) against the chapter, expect_idealised=X (loading
          // F_x, branches / F_A, loop area): at a decoupled pairing the FE's own error; and the decoupled path against it,
          // the effect of the free slip direction.
          if (study.idealised_reference)
            {
              const gradcontact::cases::CoulombPath &p = r.idealised;
              if (root)
                std::printf("idealised (decoupled, forces along x) against the chapter: F_z %.3e, loading F_x %.3e, branches "
                            "%.3e (/ F_A), loop area %.3e, friction work %.3e; the free slip direction (decoupled against "
                            "idealised): loading F_x %.3e, branches %.3e, loop area %.3e; sum |Q_y| / sum |Q| %.3e\n",
                            p.force_z_deviation, p.loading_deviation, p.branch_deviation, p.energy / r.energy_theory - 1,
                            p.friction_work / r.energy_theory - 1, r.direction_loading, r.direction_branch,
                            r.direction_energy, r.decoupled.slip_force_y);
              fails("expect_idealised",
                    worst_of({std::abs(p.force_z_deviation), p.loading_deviation, p.branch_deviation,
                              std::abs(p.energy / r.energy_theory - 1)}),
                    "the idealised path's largest difference from the chapter");
              if (!p.converged)
                {
                  if (root)
                    std::printf("FAILED: idealised path: %s\n", p.message.c_str());
                  failed = 1;
                }
            }
          if (study.cycle && r.fe.converged)
            {
              if (root)
                std::printf("cycle: F_x at delta_max after the cycle against the loading value: relative difference %.3e\n",
                            r.fe.closure);
              fails("expect_closure", r.fe.closure, "the hysteresis loop's closure");
            }
          return dealii::Utilities::MPI::max(failed, world);
        }

      // (refused before any solve, on every process)
      if (num("closed_form", 0) != 0 && k != 0)
        throw std::invalid_argument("fem3d: closed_form=1 needs k = 0 (the homogeneous half-space)");
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

      // mossakovskii=1 (k = 0, loads normal and bonded): the bonded punch, u = (delta, 0, d) on the disc, against the
      // frictionless one. Its F_z does not depend on delta (antisymmetric in x), and for the homogeneous half-space
      // the ratio is (1 - nu) ln(3 - 4 nu) / (1 - 2 nu) (Mossakovskii, Prikl. Mat. Mekh. 18 (1954) 187-196; Spence,
      // J. Elasticity 5 (1975)): a classical solution of the coupled problem, the normal traction and the radial
      // shear of a rigid disc that does not slip. The ratio cancels the truncation to first order. expect_bonded=X.
      // (the preconditions on every process: an exception on one alone would leave the others in a collective)
      if (num("mossakovskii", 0) != 0 && (k != 0 || !results.count("normal") || !results.count("bonded")))
        throw std::invalid_argument("fem3d: mossakovskii=1 needs k = 0 and load = all (normal and bonded)");
      if (num("mossakovskii", 0) != 0 && root)
        {
          const double ratio = results["bonded"].force[2] / results["normal"].force[2];
          // (its limit at nu = 1/2 is 1: the incompressible body decouples, the bonded punch is the frictionless one)
          const double exact = nu == 0.5 ? 1.0 : (1 - nu) * std::log(3 - 4 * nu) / (1 - 2 * nu);
          std::printf("mossakovskii: F_z bonded / frictionless %.10f, (1 - nu) ln(3 - 4 nu) / (1 - 2 nu) = %.10f, "
                      "relative difference %.3e\n",
                      ratio, exact, std::abs(ratio / exact - 1));
          const double expect = num("expect_bonded", 0);
          if (expect > 0 && !(std::abs(ratio / exact - 1) <= expect))
            {
              std::printf("FAILED: the bonded punch is more than %.1e off Mossakovskii's ratio\n", expect);
              failed = 1;
            }
        }
      // closed_form=1 (k = 0): the punches against the homogeneous half-space's closed forms, the normal punch
      // F_z = 2 a E d / (1 - nu^2) (Boussinesq; the chapter's 9.16 at k = 0) and the tangential punch (u_x = delta,
      // u_y = 0, u_z free) F_x = 8 G a delta / (2 - nu) = 4 E a delta / ((1 + nu)(2 - nu)) (Mindlin, J. Appl. Mech. 16
      // (1949) 259-268: the traction F / (2 pi a sqrt(a^2 - r^2)) along x moves the disc rigidly in x and leaves no
      // normal traction, so it is exact for this load at every nu). The body is truncated at L (u = 0 there), which
      // stiffens it by O(a / L); expect_closed=X bounds the largest relative difference.
      if (num("closed_form", 0) != 0 && root)
        {
          double       worst    = 0;
          unsigned int compared = 0;
          const auto check = [&](const char *what, const double fe3d, const double exact) {
            const double difference = std::abs(fe3d / exact - 1);
            worst                   = std::max(worst, difference);
            ++compared;
            std::printf("closed form %s: 3D %.12e exact %.12e relative difference %.3e\n", what, fe3d, exact, difference);
          };
          if (results.count("normal"))
            check("normal punch F_z (Boussinesq)", results["normal"].force[2], 2 * a * E0 * d / (1 - nu * nu));
          if (results.count("tangential"))
            check("tangential punch F_x (Mindlin)", results["tangential"].force[0],
                  4 * E0 * a * d / ((1 + nu) * (2 - nu)));
          const double expect = num("expect_closed", 0);
          if (compared == 0)
            {
              std::printf("FAILED: closed_form=1 compared nothing (load = normal, tangential or all)\n");
              failed = 1;
            }
          if (expect > 0 && !(worst <= expect))
            {
              std::printf("FAILED: a punch is more than %.1e off its closed form\n", expect);
              failed = 1;
            }
        }
      // coulomb_punch=1 (load = all): the same punches through the Coulomb contact solver (fem/tangential/coulomb_contact_3d.h): a
      // flat punch as the convex profile f = 1e3 max(0, r - a), pressed to d in one step with mu = inf (full stick:
      // the bonded punch) and mu = 0 (the frictionless one). On the same discrete body the contact solver must give
      // the prescribed-displacement solves' F_z (every disc node in contact, none beyond), up to the dense solve's
      // round-off; expect_coulomb_punch=X bounds the relative difference. Collective.
      if (num("coulomb_punch", 0) != 0)
        {
          if (!results.count("normal") || !results.count("bonded"))
            throw std::invalid_argument("fem3d: coulomb_punch=1 needs load = all (normal and bonded)");
          const SurfaceCompliance3D surface = solver.surface_compliance(1.3 * a);
          const Profile punch = Profile::custom([a](const double r) { return 1e3 * std::max(0.0, r - a); }, 1.0);
          CoulombParameters stick;
          stick.mu = std::numeric_limits<double>::infinity();
          CoulombContact3D contact(surface, punch, stick);
          const CoulombState3D bonded = contact.step_depth(d, 0.0);
          contact.reset();
          contact.set_friction(0.0);
          const CoulombState3D frictionless = contact.step_depth(d, 0.0);
          const double worst = std::max(std::abs(bonded.force_z / results["bonded"].force[2] - 1),
                                        std::abs(frictionless.force_z / results["normal"].force[2] - 1));
          if (root)
            std::printf("coulomb_punch: F_z full stick %.12e (prescribed %.12e, %u of %zu nodes in contact), frictionless "
                        "%.12e (prescribed %.12e), largest relative difference %.3e\n",
                        bonded.force_z, results["bonded"].force[2], bonded.n_contact, surface.nodes.size(),
                        frictionless.force_z, results["normal"].force[2], worst);
          const double expect = num("expect_coulomb_punch", 0);
          if (!bonded.converged || !frictionless.converged || (expect > 0 && !(worst <= expect)))
            {
              if (root)
                std::printf("FAILED: the Coulomb solver's punches differ from the prescribed ones by more than %.1e%s\n",
                            expect, bonded.converged && frictionless.converged ? "" : " (not converged)");
              failed = 1;
            }
        }
      if (num("compare", 0) != 0)
        {
          if (root)
            {
              // The meridian models of the same cylinder r <= L, z <= L.
              const MeshParameters meridian = meridian_of(mesh, k);
              const DiscretizationParameters reference_disc = meridian_discretization(disc.formulation);
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
              if (results.count("tangential") && resolve_formulation(disc, nu) == Formulation::mixed)
                std::printf("compare tangential punch F_x: not compared (the Fourier mode-1 model has no mixed "
                            "formulation; closed_form=1 checks it against Mindlin at k = 0)\n");
              else if (results.count("tangential"))
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
      // An exception on some processes only would leave the others waiting in a collective: end them all.
      if (dealii::Utilities::MPI::n_mpi_processes(world) > 1)
        MPI_Abort(world, 1);
      return 1;
    }
}
