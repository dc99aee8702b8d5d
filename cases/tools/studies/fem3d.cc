// fem3d: flat-punch runs of the 3D half-space model (fem/bodies/half_space_3d.h, p4est + Trilinos), checked
// against the meridian models on the same truncated body and against itself on one process.
//
//   mpirun -np 2 fem3d load=all k=0 nu=0.3 p=2 L=8 g3=1.6 R0=0.5 h_edge=1e-3 q=2 inner=0 edge=0 grading=1 contact_ref=0 global3=0
//                      solver=direct|amg write=F against=F serial_tol=1e-10 compare=1 expect=1e-2
// load = normal (u_z = d, u_x, u_y free), tangential (u_x = delta, u_y = 0, u_z free), bonded (u = (delta, 0, d)),
// all (the three), or sphere: Coulomb frictional contact of a rigid sphere (fem/tangential/coulomb_contact_3d.h; keys mu,
// mu_normal, depth, delta, normal_steps, tangential_steps, cycle, candidates; compare=1: F_z at the end of the
// normal loading against the frictionless axisymmetric model, expect=X; theory_depth=1: the chapter's depth of
// contact radius a; theory=1: the path against the chapter's closed forms for the half-space (cases/model/coulomb_sphere.h:
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

#include "study.h"

#include <cases/model/coulomb_sphere.h>

#include <deal.II/base/mpi.h>

#include <array>
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
using gradcontact::studies::StudyArguments;
namespace cases = gradcontact::cases;

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

  /// The material of fem_study (E0 = 2 GPa, c0 = 3 a, a = 0.1 mm) and the 3D model's mesh, discretisation (degree 2
  /// by default) and linear solver.
  struct Setup
  {
    double                      E0 = 2e9, c0 = 3e-4, a = 1e-4, nu = 0.3, k = 0;
    Material                    material;
    HalfSpaceMesh3DParameters   mesh;
    DiscretizationParameters    disc;
    DistributedSolverParameters parameters;
  };

  Setup parse_setup(const StudyArguments &args)
  {
    Setup s;
    s.nu       = args.num("nu", 0.3);
    s.k        = args.num("k", 0.0);
    s.material = Material{std::make_shared<PowerLawModulus>(s.E0, s.c0, s.k), s.nu};
    s.mesh.contact_radius = s.a;
    args.apply(s.mesh);
    s.disc.degree = 2;
    args.apply(s.disc);
    args.apply(s.parameters);
    return s;
  }

  /// The verdict of a run: every failed check sets it; `expect` checks a measure against the bound key=X.
  struct Verdict
  {
    const StudyArguments &args;
    bool                  root;
    int                   failed = 0;

    /// key=X (X > 0): `value` (NaN fails) must be at most X.
    void expect(const char *key, const double value, const char *what)
    {
      const double limit = args.num(key, 0);
      if (limit > 0 && !(value <= limit))
        {
          if (root)
            std::printf("FAILED: %s %.3e exceeds %s=%.1e\n", what, value, key, limit);
          failed = 1;
        }
    }
  };

  /// The largest of several measures, NaN when one is NaN (not measured: a check of it must fail, not skip it).
  double worst_of(std::initializer_list<double> values)
  {
    double w = 0;
    for (const double v : values)
      w = std::isnan(v) || std::isnan(w) ? std::numeric_limits<double>::quiet_NaN() : std::max(w, v);
    return w;
  }

  // ---- load=sphere: Coulomb contact of a rigid sphere ------------------------------------------------------------

  /// compare=1: the depth at which the frictionless axisymmetric model of the same body has the contact radius a
  /// (its mesh's), and its force there (process 0, sent to all).
  std::array<double, 2> meridian_sphere_state(const MPI_Comm world, const bool root, const Setup &s, const double R)
  {
    double reference[2] = {0, 0};
    if (root)
      {
        const MeshParameters           meridian       = meridian_of(s.mesh, s.k);
        const DiscretizationParameters reference_disc = meridian_discretization(s.disc.formulation);
        AxisymmetricSolver             axisymmetric(s.material, meridian, reference_disc);
        LoadCase                       load;
        load.type      = LoadType::indenter;
        load.profile   = Profile::paraboloid(R);
        const Result r = axisymmetric.run(load);
        reference[0]   = r.depth;
        reference[1]   = r.force;
      }
    MPI_Bcast(reference, 2, MPI_DOUBLE, 0, world);
    return {{reference[0], reference[1]}};
  }

  /// The sphere's path: normal loading to d_max in normal_steps steps with friction mu_normal (default mu), then
  /// friction mu and a tangential displacement to delta mu d_max in tangential_steps steps (none with mu = 0 or
  /// tangential_steps = 0), and one cycle with cycle=1; decoupled=1, idealised=1 the reference paths.
  cases::CoulombSphereCase plan_sphere(const StudyArguments &args, const Setup &s, const double R, const double d_max)
  {
    cases::CoulombSphereCase study;
    study.E0 = s.E0;
    study.c0 = s.c0;
    study.k  = s.k;
    study.nu = s.nu;
    study.R  = R;
    study.mesh             = s.mesh;
    study.discretization   = s.disc;
    study.solver           = s.parameters;
    study.candidates       = args.num("candidates", study.candidates);
    study.depth            = d_max;
    study.mu               = args.num("mu", 0.3);
    study.mu_normal        = args.num("mu_normal", study.mu);
    study.normal_steps     = args.count("normal_steps", 10);
    study.tangential_steps = args.count("tangential_steps", 10);
    study.cycle            = args.num("cycle", 0) != 0;
    study.decoupled_reference = args.num("decoupled", 0) != 0;
    study.idealised_reference = args.num("idealised", 0) != 0;
    const double mu        = study.mu;
    // mu = 0 or tangential_steps = 0: the normal loading only (frictionless with mu = 0).
    study.delta = mu == 0 || study.tangential_steps == 0 ? 0.0 : args.num("delta", 1.0) * mu * d_max;
    return study;
  }

  /// Prints every step of the paths (process 0); vtu=PREFIX writes the surface state of every step of the FE path,
  /// PREFIX-<step>.vtu, and the collection PREFIX.pvd.
  class StepPrinter
  {
  public:
    StepPrinter(const bool root, const double a, const double d_max, const double mu, std::string vtu)
      : root(root), a(a), d_max(d_max), mu(mu), vtu(std::move(vtu))
    {}

    void operator()(const cases::CoulombSphereStep &step, const SurfaceCompliance3D &C)
    {
      if (!root)
        return;
      if (!vtu.empty() && step.path == cases::CoulombPathKind::fe)
        {
          vtu_files.push_back(vtu + "-" + std::to_string(vtu_files.size()) + ".vtu");
          write_surface_vtu(C, step.state, vtu_files.back());
        }
      const CoulombState3D &st = step.state;
      std::printf("%s%s d/d_max=%.4f delta/(mu d)=%.4f Fz=%.10e Fx=%.10e contact=%u stick=%u slip=%u "
                  "iterations=%u%s%s",
                  step.path == cases::CoulombPathKind::fe ? "" : (to_string(step.path) + " ").c_str(), step.phase.c_str(), st.depth / d_max, st.delta / (std::max(mu, 1e-300) * d_max), st.force_z,
                  st.force_x, st.n_contact, st.n_stick, st.n_slip, st.iterations,
                  st.converged ? "" : " NOT CONVERGED: ", st.message.c_str());
      const auto &x = step.shape.stick;
      if (step.phase != "normal")
        std::printf(" stick_radius/a(+x,-x,+y)=%.4f,%.4f,%.4f(+-%.4f)", x[0].radius() / a, x[1].radius() / a,
                    x[2].radius() / a, std::max({x[0].half_width(), x[1].half_width(), x[2].half_width()}) / a);
      if (std::isfinite(step.theory_force_x))
        std::printf(" | chapter Fx=%.10e stick_radius/a=%.4f", step.theory_force_x, step.theory_stick / a);
      std::printf("\n");
    }

    void write_collection() const
    {
      if (vtu_files.empty())
        return;
      std::ofstream pvd(vtu + ".pvd");
      pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
      for (std::size_t i = 0; i < vtu_files.size(); ++i)
        pvd << "<DataSet timestep=\"" << i << "\" file=\"" << std::filesystem::path(vtu_files[i]).filename().string()
            << "\"/>\n";
      pvd << "</Collection>\n</VTKFile>\n";
      if (!pvd)
        throw std::runtime_error("fem3d: cannot write " + vtu + ".pvd");
    }

  private:
    bool                     root;
    double                   a, d_max, mu;
    std::string              vtu;
    std::vector<std::string> vtu_files;
  };

  /// compare_friction=1: the normal loading with friction mu_normal against the axisymmetric frictional model of the
  /// same body (fem::UnilateralContactSolver with Friction, the meridian mesh of L, the same number of equal depth
  /// steps, and twice as many, extrapolated): the 3D normal loading is axisymmetric, so the two differ by
  /// discretisation only, and the coupling of the normal loading (the Spence effect) is checked by an independent
  /// model. expect_friction=X bounds the relative difference of F_z.
  void compare_friction(const MPI_Comm world, const Setup &s, const cases::CoulombSphereCase &study, const double R,
                        const cases::CoulombSphereResult &r, Verdict &verdict)
  {
    const double a            = s.a;
    double       reference[2] = {0, 0};
    if (verdict.root)
      {
        const DiscretizationParameters reference_disc = meridian_discretization(s.disc.formulation);
        UnilateralContactSolver axisymmetric(s.material, meridian_of(s.mesh, s.k), reference_disc, 1.3 * a);
        UnilateralLoad load;
        load.indenter             = Indenter::of(Profile::paraboloid(R), a);
        load.friction.coefficient = study.mu_normal;
        load.depth                = study.depth;
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
    const cases::CoulombSphereStep &last = r.fe.steps[study.normal_steps - 1];
    const double difference      = std::abs(last.state.force_z / reference[0] - 1);
    if (verdict.root)
      std::printf("compare_friction: F_z after the normal loading with mu = %g: 3D %.10e axisymmetric %.10e "
                  "(extrapolated) relative difference %.3e; stick radius / a: 3D (+x, -x, +y) %.4f, %.4f, %.4f "
                  "(+-%.4f), axisymmetric %.4f\n",
                  study.mu_normal, last.state.force_z, reference[0], difference,
                  last.shape.stick[0].radius() / a, last.shape.stick[1].radius() / a,
                  last.shape.stick[2].radius() / a, last.shape.stick[0].half_width() / a, reference[1] / a);
    verdict.expect("expect_friction", difference, "F_z with friction against the axisymmetric frictional model");
  }

  /// theory=1: the path against the chapter's closed forms for the half-space (cases/model/coulomb_sphere.h;
  /// meaningful at a large L and for a decoupled pairing): F_z and loading F_x (expect_theory), the branches / F_A
  /// (expect_branch), the loop area and friction work (expect_energy), the stick zone beyond its brackets
  /// (expect_round, expect_stick_zone).
  void check_theory(const cases::CoulombSphereCase &study, const double a, const cases::CoulombSphereResult &r,
                    Verdict &verdict)
  {
    if (verdict.root)
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
    verdict.expect("expect_theory", worst_of({std::abs(r.fe.force_z_deviation), r.fe.loading_deviation}),
                   "the largest difference from 9.24 (F_z) and 9.80 (F_x)");
    verdict.expect("expect_branch", r.fe.branch_deviation, "|F_x - F_x(9.84)| / F_A on the branches");
    verdict.expect("expect_energy",
                   worst_of({std::abs(r.fe.energy / r.energy_theory - 1), std::abs(r.fe.friction_work / r.energy_theory - 1)}),
                   "the loop area and the friction work against 9.86");
    // a disc: the stick radii of the three rays agree to their brackets
    verdict.expect("expect_round", r.fe.out_of_round - 2 * r.fe.stick_resolution,
                   "the stick zone's spread over the rays beyond its brackets (/ a)");
    // the stick zone: the closed form's radius within the FE's bracket plus this
    verdict.expect("expect_stick_zone", r.fe.stick_deviation - r.fe.stick_resolution,
                   "the stick radius beyond the FE's bracket (/ a)");
  }

  /// decoupled=1: the same path without the normal-tangential coupling (fem::without_coupling). expect_coupling=X (a
  /// decoupled pairing): the FE model equals its decoupled self within X, the stick radius included. The stick
  /// radius moves by whole rings: with coupling_ring=1 a move of one ring (twice the bracket's half-width) is
  /// allowed, the flip of a node on the stick-slip boundary under the discrete body's residual coupling (the mixed
  /// element's at nu = 1/2), which is below the zone's resolution.
  void check_coupling(const bool coupling_ring, const cases::CoulombSphereResult &r, Verdict &verdict)
  {
    if (verdict.root)
      std::printf("coupling (against the decoupled compliance, same mesh): F_z %.3e, loading F_x max %.3e, "
                  "branches max %.3e (/ F_A), loop area %.3e, stick radius max %.3e (/ a); the decoupled path "
                  "against the chapter: F_z %.3e, loading F_x %.3e, branches %.3e, loop area %.3e\n",
                  r.coupling_force_z, r.coupling_loading, r.coupling_branch, r.coupling_energy, r.coupling_stick,
                  r.decoupled.force_z_deviation, r.decoupled.loading_deviation, r.decoupled.branch_deviation,
                  r.decoupled.energy / r.energy_theory - 1);
    const double stick_coupling = !coupling_ring ? r.coupling_stick
                                  : std::isnan(r.coupling_stick)
                                    ? r.coupling_stick
                                    : std::max(0.0, r.coupling_stick - 2 * r.fe.stick_resolution);
    verdict.expect("expect_coupling",
                   worst_of({std::abs(r.coupling_force_z), r.coupling_loading, r.coupling_branch, std::abs(r.coupling_energy),
                             stick_coupling}),
                   "the coupling's largest effect");
    if (!r.decoupled.converged)
      {
        if (verdict.root)
          std::printf("FAILED: decoupled path: %s\n", r.decoupled.message.c_str());
        verdict.failed = 1;
      }
  }

  /// idealised=1 (with decoupled=1): the path of the chapter's idealisation on the same body (decoupled, every
  /// tangential force along x: Cattaneo-Mindlin's assumption) against the chapter, expect_idealised=X (loading F_x,
  /// branches / F_A, loop area): at a decoupled pairing the FE's own error; and the decoupled path against it, the
  /// effect of the free slip direction.
  void check_idealised(const cases::CoulombSphereResult &r, Verdict &verdict)
  {
    const cases::CoulombPath &p = r.idealised;
    if (verdict.root)
      std::printf("idealised (decoupled, forces along x) against the chapter: F_z %.3e, loading F_x %.3e, branches "
                  "%.3e (/ F_A), loop area %.3e, friction work %.3e; the free slip direction (decoupled against "
                  "idealised): loading F_x %.3e, branches %.3e, loop area %.3e; sum |Q_y| / sum |Q| %.3e\n",
                  p.force_z_deviation, p.loading_deviation, p.branch_deviation, p.energy / r.energy_theory - 1,
                  p.friction_work / r.energy_theory - 1, r.direction_loading, r.direction_branch,
                  r.direction_energy, r.decoupled.slip_force_y);
    verdict.expect("expect_idealised",
                   worst_of({std::abs(p.force_z_deviation), p.loading_deviation, p.branch_deviation,
                             std::abs(p.energy / r.energy_theory - 1)}),
                   "the idealised path's largest difference from the chapter");
    if (!p.converged)
      {
        if (verdict.root)
          std::printf("FAILED: idealised path: %s\n", p.message.c_str());
        verdict.failed = 1;
      }
  }

  /// The checks of the FE path: it converged; expect_stick=1: a decoupled pairing (k = 0 with nu = 1/2,
  /// nu = 1 / (2 + k)) loaded normally with friction has no tangential traction, so no node may slip; compare=1:
  /// F_z after the normal loading against the frictionless meridian model (expect=X).
  void check_normal_loading(const StudyArguments &args, const cases::CoulombSphereCase &study,
                            const cases::CoulombSphereResult &r, const bool compare, const double reference_force,
                            Verdict &verdict)
  {
    if (!r.fe.converged)
      {
        if (verdict.root)
          std::printf("FAILED: %s\n", r.fe.message.c_str());
        verdict.failed = 1;
      }
    if (args.num("expect_stick", 0) != 0 && study.mu_normal > 0 && r.fe.normal_slip > 0)
      {
        if (verdict.root)
          std::printf("FAILED: %u nodes slipped during the normal loading of a decoupled pairing\n", r.fe.normal_slip);
        verdict.failed = 1;
      }
    const double force_z = r.fe.steps.size() < study.normal_steps ? 0.0 : r.fe.steps[study.normal_steps - 1].state.force_z;
    if (compare)
      {
        const double difference = std::abs(force_z / reference_force - 1);
        if (verdict.root)
          std::printf("compare sphere F_z at d (frictionless meridian model at contact radius a): 3D %.10e "
                      "meridian %.10e relative difference %.3e\n",
                      force_z, reference_force, difference);
        verdict.expect("expect", difference, "F_z against the meridian model");
      }
  }

  /// load=sphere: a rigid sphere (radius R = 50 a) loaded to d = depth a^2 / R (theory_depth=1: the chapter's depth
  /// of contact radius a, 9.24 family; compare=1: the depth where the frictionless meridian model has it), sheared
  /// and cycled (plan_sphere); its path printed step by step, then the checks asked for. Collective.
  int run_sphere(const StudyArguments &args, const MPI_Comm world, const bool root, const Setup &s)
  {
    const double a = s.a, R = 50 * a;
    double       d_max = args.num("depth", 1.0) * a * a / R;
    if (args.num("theory_depth", 0) != 0)
      d_max = gradcontact::depth(gradcontact::medium(gradcontact::GradedHalfSpace{s.E0, s.c0, s.k, s.nu}),
                                 gradcontact::Paraboloid{R}, a);
    const bool compare         = args.num("compare", 0) != 0;
    double     reference_force = 0;
    if (compare)
      {
        const auto reference = meridian_sphere_state(world, root, s, R);
        d_max                = reference[0];
        reference_force      = reference[1];
      }
    const cases::CoulombSphereCase study = plan_sphere(args, s, R, d_max);
    Verdict                        verdict{args, root};
    StepPrinter                    print(root, a, d_max, study.mu, args.text("vtu", ""));
    const cases::CoulombSphereResult r =
      cases::run_coulomb_sphere(world, study, [&](const cases::CoulombSphereStep &step, const SurfaceCompliance3D &C) {
        print(step, C);
      });
    print.write_collection();
    if (root)
      std::printf("sphere k=%g nu=%g p=%u np=%u dofs=%llu surface_nodes=%u unknowns=%u compliance_time=%.2f "
                  "time=%.2f peak_mb=%.0f largest_iterations=%u\n",
                  s.k, s.nu, s.disc.degree, r.processes, r.dofs, r.surface_nodes, r.unknowns, r.compliance_seconds,
                  r.seconds, r.memory_mb, r.fe.max_iterations);
    check_normal_loading(args, study, r, compare, reference_force, verdict);
    if (args.num("compare_friction", 0) != 0 && r.fe.steps.size() >= study.normal_steps)
      compare_friction(world, s, study, R, r, verdict);
    if (args.num("theory", 0) != 0)
      check_theory(study, a, r, verdict);
    const bool coupling_ring = args.num("coupling_ring", 0) != 0;
    if (study.decoupled_reference)
      check_coupling(coupling_ring, r, verdict);
    if (study.idealised_reference)
      check_idealised(r, verdict);
    if (study.cycle && r.fe.converged)
      {
        if (root)
          std::printf("cycle: F_x at delta_max after the cycle against the loading value: relative difference %.3e\n",
                      r.fe.closure);
        verdict.expect("expect_closure", r.fe.closure, "the hysteresis loop's closure");
      }
    return dealii::Utilities::MPI::max(verdict.failed, world);
  }

  // ---- load=normal|tangential|bonded|all: the prescribed punches ----------------------------------------------------

  /// The punches asked for (unit-free amplitudes: d = delta = d_punch).
  std::map<std::string, FlatPunch3D> plan_punches(const std::string &load_name, const double d)
  {
    std::map<std::string, FlatPunch3D> loads;
    if (load_name == "normal" || load_name == "all")
      loads["normal"] = FlatPunch3D{{{false, false, true}}, {{0, 0, d}}};
    if (load_name == "tangential" || load_name == "all")
      loads["tangential"] = FlatPunch3D{{{true, true, false}}, {{d, 0, 0}}};
    if (load_name == "bonded" || load_name == "all")
      loads["bonded"] = FlatPunch3D{{{true, true, true}}, {{d, 0, d}}};
    if (loads.empty())
      throw std::invalid_argument("fem3d: load = " + load_name + " outside {normal, tangential, bonded, all}");
    return loads;
  }

  /// Solves every punch (collective) and prints its line (process 0): forces, DoFs, the linear solve, the times of
  /// the phases and the peak memory; then the total time.
  std::map<std::string, HalfSpace3DResult> solve_punches(const MPI_Comm world, const Setup &s,
                                                         HalfSpace3DSolver &solver,
                                                         const std::map<std::string, FlatPunch3D> &loads,
                                                         const std::chrono::steady_clock::time_point start,
                                                         Verdict &verdict)
  {
    std::map<std::string, HalfSpace3DResult> results;
    for (const auto &[name, punch] : loads)
      {
        const HalfSpace3DResult r = solver.run(punch);
        results[name]             = r;
        if (verdict.root)
          std::printf("load=%s k=%g nu=%g p=%u np=%u solver=%s dofs=%llu cells=%u min_edge_cell=%.2e "
                      "Fx=%.12e Fz=%.12e mismatch=%.1e residual=%.1e mesh=%.2f setup=%.2f assemble=%.2f "
                      "factorize=%.2f solve=%.2f peak_mb=%.0f %s\n",
                      name.c_str(), s.k, s.nu, s.disc.degree, r.n_processes, r.linear.solver.c_str(),
                      static_cast<unsigned long long>(r.n_dofs), r.n_cells, r.mesh.min_edge_cell, r.force[0],
                      r.force[2], r.energy_mismatch, r.linear.residual, r.time.mesh, r.time.setup,
                      r.time.assemble, r.time.factorize, r.time.solve, r.memory_mb, r.message.c_str());
        if (!r.reliable)
          verdict.failed = 1;
      }
    // collective: every process takes part in the maximum
    const double total = dealii::Utilities::MPI::max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), world);
    if (verdict.root)
      std::printf("total=%.2f\n", total);
    return results;
  }

  /// write=FILE (process 0): the forces of every punch, for a run on another number of processes to compare with.
  void write_forces(const std::string &file, const std::map<std::string, HalfSpace3DResult> &results)
  {
    std::ofstream out(file);
    out.precision(17);
    for (const auto &[name, r] : results)
      out << name << ' ' << r.n_dofs << ' ' << r.force[0] << ' ' << r.force[2] << '\n';
    if (!out)
      throw std::runtime_error("fem3d: cannot write " + file);
  }

  /// against=FILE (process 0): every punch's forces against those written by write=, within serial_tol of the largest
  /// force (a free component's force is round-off) and on as many DoFs.
  void compare_against(const StudyArguments &args, std::map<std::string, HalfSpace3DResult> &results,
                       Verdict &verdict)
  {
    const double  tolerance = args.num("serial_tol", 1e-10);
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
              verdict.failed = 1;
            }
        }
    if (compared != results.size())
      {
        std::printf("FAILED: %s holds %u of the %zu loads\n", args.text("against").c_str(), compared,
                    results.size());
        verdict.failed = 1;
      }
  }

  /// mossakovskii=1 (k = 0, loads normal and bonded; process 0): the bonded punch, u = (delta, 0, d) on the disc,
  /// against the frictionless one. Its F_z does not depend on delta (antisymmetric in x), and for the homogeneous
  /// half-space the ratio is (1 - nu) ln(3 - 4 nu) / (1 - 2 nu) (Mossakovskii, Prikl. Mat. Mekh. 18 (1954) 187-196;
  /// Spence, J. Elasticity 5 (1975)): a classical solution of the coupled problem, the normal traction and the
  /// radial shear of a rigid disc that does not slip. The ratio cancels the truncation to first order.
  /// expect_bonded=X.
  void check_mossakovskii(const StudyArguments &args, const double nu,
                          std::map<std::string, HalfSpace3DResult> &results, Verdict &verdict)
  {
    const double ratio = results["bonded"].force[2] / results["normal"].force[2];
    // (its limit at nu = 1/2 is 1: the incompressible body decouples, the bonded punch is the frictionless one)
    const double exact = nu == 0.5 ? 1.0 : (1 - nu) * std::log(3 - 4 * nu) / (1 - 2 * nu);
    std::printf("mossakovskii: F_z bonded / frictionless %.10f, (1 - nu) ln(3 - 4 nu) / (1 - 2 nu) = %.10f, "
                "relative difference %.3e\n",
                ratio, exact, std::abs(ratio / exact - 1));
    const double expect = args.num("expect_bonded", 0);
    if (expect > 0 && !(std::abs(ratio / exact - 1) <= expect))
      {
        std::printf("FAILED: the bonded punch is more than %.1e off Mossakovskii's ratio\n", expect);
        verdict.failed = 1;
      }
  }

  /// closed_form=1 (k = 0; process 0): the punches against the homogeneous half-space's closed forms, the normal
  /// punch F_z = 2 a E d / (1 - nu^2) (Boussinesq; the chapter's 9.16 at k = 0) and the tangential punch (u_x = delta,
  /// u_y = 0, u_z free) F_x = 8 G a delta / (2 - nu) = 4 E a delta / ((1 + nu)(2 - nu)) (Mindlin, J. Appl. Mech. 16
  /// (1949) 259-268: the traction F / (2 pi a sqrt(a^2 - r^2)) along x moves the disc rigidly in x and leaves no
  /// normal traction, so it is exact for this load at every nu). The body is truncated at L (u = 0 there), which
  /// stiffens it by O(a / L); expect_closed=X bounds the largest relative difference.
  void check_closed_forms(const StudyArguments &args, const Setup &s, const double d,
                          std::map<std::string, HalfSpace3DResult> &results, Verdict &verdict)
  {
    const double a = s.a, E0 = s.E0, nu = s.nu;
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
    const double expect = args.num("expect_closed", 0);
    if (compared == 0)
      {
        std::printf("FAILED: closed_form=1 compared nothing (load = normal, tangential or all)\n");
        verdict.failed = 1;
      }
    if (expect > 0 && !(worst <= expect))
      {
        std::printf("FAILED: a punch is more than %.1e off its closed form\n", expect);
        verdict.failed = 1;
      }
  }

  /// coulomb_punch=1 (load = all; collective): the same punches through the Coulomb contact solver
  /// (fem/tangential/coulomb_contact_3d.h): a flat punch as the convex profile f = 1e3 max(0, r - a), pressed to d
  /// in one step with mu = inf (full stick: the bonded punch) and mu = 0 (the frictionless one). On the same discrete
  /// body the contact solver must give the prescribed-displacement solves' F_z (every disc node in contact, none
  /// beyond), up to the dense solve's round-off; expect_coulomb_punch=X bounds the relative difference.
  void check_coulomb_punches(const StudyArguments &args, const double a, const double d, HalfSpace3DSolver &solver,
                             std::map<std::string, HalfSpace3DResult> &results, Verdict &verdict)
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
    if (verdict.root)
      std::printf("coulomb_punch: F_z full stick %.12e (prescribed %.12e, %u of %zu nodes in contact), frictionless "
                  "%.12e (prescribed %.12e), largest relative difference %.3e\n",
                  bonded.force_z, results["bonded"].force[2], bonded.n_contact, surface.nodes.size(),
                  frictionless.force_z, results["normal"].force[2], worst);
    const double expect = args.num("expect_coulomb_punch", 0);
    if (!bonded.converged || !frictionless.converged || (expect > 0 && !(worst <= expect)))
      {
        if (verdict.root)
          std::printf("FAILED: the Coulomb solver's punches differ from the prescribed ones by more than %.1e%s\n",
                      expect, bonded.converged && frictionless.converged ? "" : " (not converged)");
        verdict.failed = 1;
      }
  }

  /// compare=1 (process 0): the axisymmetric model (normal punch: F_z) and the Fourier mode-1 model (tangential
  /// punch: F_x) on the meridian mesh of the same cylinder r <= L, z <= L; expect=X bounds the relative differences.
  void compare_meridian(const StudyArguments &args, const Setup &s, const double d,
                        std::map<std::string, HalfSpace3DResult> &results, Verdict &verdict)
  {
    const MeshParameters           meridian       = meridian_of(s.mesh, s.k);
    const DiscretizationParameters reference_disc = meridian_discretization(s.disc.formulation);
    const double expect   = args.num("expect", 0);
    const auto   report   = [&](const char *what, const double fe3d, const double reference) {
      const double difference = std::abs(fe3d / reference - 1);
      std::printf("compare %s: 3D %.12e meridian %.12e relative difference %.3e\n", what, fe3d, reference,
                  difference);
      if (expect > 0 && !(difference <= expect))
        {
          std::printf("FAILED: %s differs from the meridian model by more than %.1e\n", what, expect);
          verdict.failed = 1;
        }
    };
    if (results.count("normal"))
      {
        AxisymmetricSolver axisymmetric(s.material, meridian, reference_disc);
        LoadCase           load;
        load.type  = LoadType::flat_punch;
        load.depth = d;
        report("normal punch F_z", results["normal"].force[2], axisymmetric.run(load).force);
      }
    if (results.count("tangential") && resolve_formulation(s.disc, s.nu) == Formulation::mixed)
      std::printf("compare tangential punch F_x: not compared (the Fourier mode-1 model has no mixed "
                  "formulation; closed_form=1 checks it against Mindlin at k = 0)\n");
    else if (results.count("tangential"))
      {
        FourierMode1Solver mode1(s.material, meridian, reference_disc);
        report("tangential punch F_x", results["tangential"].force[0], mode1.run(TangentialLoad::flat_punch(d)).force);
      }
  }

  /// The prescribed punches (plan_punches) on the 3D model, their forces printed, stored (write=) or compared with
  /// stored ones (against=), and the checks asked for. The preconditions of a check are tested on every process
  /// before any solve or collective: an exception on one alone would leave the others in a collective.
  int run_punches(const StudyArguments &args, const MPI_Comm world, const bool root, const Setup &s)
  {
    if (args.num("closed_form", 0) != 0 && s.k != 0)
      throw std::invalid_argument("fem3d: closed_form=1 needs k = 0 (the homogeneous half-space)");
    const double d     = 1e-3 * s.a;
    const auto   loads = plan_punches(args.text("load", "all"), d);
    const auto   start = std::chrono::steady_clock::now();
    HalfSpace3DSolver solver(world, s.material, s.mesh, s.disc, s.parameters);
    Verdict           verdict{args, root};
    std::map<std::string, HalfSpace3DResult> results = solve_punches(world, s, solver, loads, start, verdict);
    if (args.has("write") && root)
      write_forces(args.text("write"), results);
    if (args.has("against") && root)
      compare_against(args, results, verdict);
    if (args.num("mossakovskii", 0) != 0 && (s.k != 0 || !results.count("normal") || !results.count("bonded")))
      throw std::invalid_argument("fem3d: mossakovskii=1 needs k = 0 and load = all (normal and bonded)");
    if (args.num("mossakovskii", 0) != 0 && root)
      check_mossakovskii(args, s.nu, results, verdict);
    if (args.num("closed_form", 0) != 0 && root)
      check_closed_forms(args, s, d, results, verdict);
    if (args.num("coulomb_punch", 0) != 0)
      check_coulomb_punches(args, s.a, d, solver, results, verdict);
    if (args.num("compare", 0) != 0 && root)
      compare_meridian(args, s, d, results, verdict);
    return dealii::Utilities::MPI::max(verdict.failed, world);
  }
} // namespace

int main(int argc, char **argv)
{
  return gradcontact::studies::distributed_main(
    argc, argv, "fem3d", [](const StudyArguments &args, const MPI_Comm world, const bool root) {
      const Setup setup = parse_setup(args);
      return args.text("load", "all") == "sphere" ? run_sphere(args, world, root, setup) :
                                                    run_punches(args, world, root, setup);
    });
}
