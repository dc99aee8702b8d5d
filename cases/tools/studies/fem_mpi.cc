// fem_mpi: one run of the distributed solver (p4est + Trilinos, fem/bodies/distributed_solver.h), optionally checked
// against the serial solver on the same mesh.
//
//   mpirun -np 2 fem_mpi load=punch k=0 p=3 h_edge=1e-5 h_far=3 g=1.15 L=1e8 layer=1 R1=4 global=0
//                        solver=direct|amg tol=1e-12 compare=1 compare_tol=1e-10
// load = punch | pressure | paraboloid | cone (the indenters under contact-radius control); the punch prints
// F_error against (9.16). control=depth|force with load=paraboloid: depth or force control (solve_controlled) to
// the state of contact radius 1.1 a of (9.26), from a first trial radius start a (start=1), printing trials,
// a_error and F_error. expect_tol=t fails the run when the punch's F_error (or a_error and F_error under control)
// exceeds t. Mesh keys default to recommended_mesh_parameters(a, k) except layer (the z-only surface halvings,
// which p4est cannot do: default 1, none). compare=1 (radius control): process 0 also runs the serial
// AxisymmetricSolver (sparse direct, fem/linear_algebra/direct_system.h) and the program fails (exit 1) unless force and depth agree within compare_tol
// relative. Prints one line of key=value pairs (process 0).
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/bodies/distributed_solver.h>
#include <fem/modulus/modulus.h>

#include "study.h"
#include "written_out.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <string>

using namespace gradcontact::fem;
using gradcontact::studies::AxisymmetricRun;
using gradcontact::studies::StudyArguments;

namespace
{
  /// The material and loads of fem_study (AxisymmetricRun), the linear solver of the run, and its load.
  struct Run : AxisymmetricRun
  {
    DistributedSolverParameters parameters;
    LoadCase                    load;
    std::string                 control; ///< radius, depth or force
    double                      R = 0, a_true = 0, F_true = 0;
  };

  /// load = punch | pressure | paraboloid | cone; the indenters under contact-radius control at the mesh's a.
  LoadCase plan_load(const std::string &load_name, const double a)
  {
    LoadCase load;
    if (load_name == "punch")
      {
        load.type  = LoadType::flat_punch;
        load.depth = 1e-3 * a;
      }
    else if (load_name == "pressure")
      {
        load.type     = LoadType::constant_pressure;
        load.pressure = 1e6;
      }
    else if (load_name == "paraboloid" || load_name == "cone")
      {
        // Contact-radius control at the mesh's a (the shapes of tests/fem/test_contact.cc).
        load.type    = LoadType::indenter;
        load.profile = load_name == "paraboloid" ? Profile::paraboloid(50 * a) : Profile::cone(0.1);
      }
    else
      throw std::invalid_argument("fem_mpi: load = " + load_name + " outside {punch, pressure, paraboloid, cone}");
    return load;
  }

  Run parse_run(const StudyArguments &args)
  {
    Run run;
    // The surface layer defaults to a (p4est cannot make the z-only surface halvings).
    static_cast<AxisymmetricRun &>(run) =
      gradcontact::studies::axisymmetric_run(args, [](MeshParameters &mesh) { mesh.surface_layer_thickness = 1.0; });
    args.apply(run.parameters);
    run.load = plan_load(run.load_name, run.a);
    return run;
  }

  /// control=depth|force (paraboloid): the target of the contact radius a_true = 1.1 a by (9.26), the radius found by
  /// solve_controlled (meshes graded at each trial radius).
  void plan_control(const StudyArguments &args, Run &run)
  {
    const double k = run.k;
    run.control    = args.text("control", "radius");
    run.R          = 50 * run.a;
    run.a_true     = 1.1 * run.a;
    run.F_true     = testing::paraboloid_force(k, run.nu, run.E0, run.c0, run.a_true, run.R); // (9.26)
    if (run.control == "radius")
      return;
    if (run.load_name != "paraboloid" || (run.control != "depth" && run.control != "force"))
      throw std::invalid_argument("fem_mpi: control = " + run.control + " needs load=paraboloid and depth|force");
    if (args.has("compare"))
      throw std::invalid_argument("fem_mpi: compare is for radius control (the serial solver's search has its own "
                                  "mesh), not with control = " + run.control);
    run.load.type  = run.control == "depth" ? LoadType::indenter_depth : LoadType::indenter_force;
    run.load.depth = run.a_true * run.a_true / ((1 + k) * run.R); // (9.26)
    run.load.force = run.F_true;
  }

  DistributedResult solve(const StudyArguments &args, const MPI_Comm world, const Material &material, const Run &run)
  {
    if (run.control == "radius")
      return DistributedSolver(world, material, run.mesh, run.disc, run.parameters).run(run.load);
    return solve_controlled(world, material, run.load,
                            [&](const double radius) {
                              Settings st{run.mesh, run.disc};
                              st.mesh.contact_radius = radius;
                              return st;
                            },
                            args.num("start", 1.0) * run.a, args.num("control_tol", 1e-10), 20, run.parameters);
  }

  /// The run's errors: F against the written-out closed form (the punch's (9.16), or (9.26) under depth or force
  /// control; NaN for the other loads) and a against a_true under control (NaN otherwise).
  struct Errors
  {
    double force = 0, radius = 0;
  };

  Errors errors_of(const Run &run, const DistributedResult &r)
  {
    // The flat punch against (9.16), h_N written out (tests/fem/written_out.h); NaN for the other loads.
    const double F_punch = testing::flat_punch_force(run.k, run.nu, run.E0, run.c0, run.a, run.load.depth);
    Errors       e;
    e.force  = run.load_name == "punch" ? r.force / F_punch - 1 :
               run.control != "radius"  ? r.force / run.F_true - 1 :
                                          std::nan("");
    e.radius = run.control != "radius" ? r.contact_radius / run.a_true - 1 : std::nan("");
    return e;
  }

  /// The run's line (process 0): the setting, F and depth, the solver's counts, the times of the phases and the
  /// peak resident memory (VmHWM) of the largest process and of all processes together [MB].
  void print_run(const MPI_Comm world, const bool root, const Run &run, const DistributedResult &r, const Errors &e,
                 const double total)
  {
    dealii::Utilities::System::MemoryStats memory;
    dealii::Utilities::System::get_memory_stats(memory);
    const double peak_mb  = static_cast<double>(memory.VmHWM) / 1024;
    const double peak_max = dealii::Utilities::MPI::max(peak_mb, world);
    const double peak_sum = dealii::Utilities::MPI::sum(peak_mb, world);
    if (root && run.control != "radius")
      std::printf("control=%s trials=%u a_error=%.3e ", run.control.c_str(), r.control_trials, e.radius);
    if (root)
      std::printf("load=%s k=%g p=%u np=%u solver=%s dofs=%llu cells=%u force=%.16e F_error=%.3e depth=%.16e "
                  "iterations=%u residual=%.1e mismatch=%.1e mesh=%.2f setup=%.2f assemble=%.2f "
                  "factorize=%.2f solve=%.2f total=%.2f peak_mb_max=%.0f peak_mb_sum=%.0f %s\n",
                  run.load_name.c_str(), run.k, run.disc.degree, r.n_processes, r.solver.c_str(),
                  static_cast<unsigned long long>(r.n_dofs), r.n_cells, r.force, e.force, r.depth, r.iterations,
                  r.residual, r.energy_mismatch, r.time.mesh, r.time.setup, r.time.assemble,
                  r.time.factorize, r.time.solve, total, peak_max, peak_sum, r.message.c_str());
  }

  /// expect_tol=t: the written-out closed form within t (the punch's F, or a and F under depth/force control).
  bool meets_expected(const StudyArguments &args, const bool root, const Run &run, const Errors &e)
  {
    if (run.load_name != "punch" && run.control == "radius")
      throw std::invalid_argument("fem_mpi: expect_tol needs load=punch or control=depth|force (load = " +
                                  run.load_name + ")");
    const double tol = args.num("expect_tol", 0);
    if (!(std::abs(e.force) <= tol) || (run.control != "radius" && !(std::abs(e.radius) <= tol)))
      {
        if (root)
          std::printf("FAILED: F_error %.3e or a_error %.3e above expect_tol %.1e\n", e.force, e.radius, tol);
        return false;
      }
    return true;
  }

  /// compare=1: the serial reference on process 0 (the others wait): the same mesh, the same operator, sparse direct;
  /// force and depth within compare_tol relative. Returns whether it holds (on process 0).
  bool equals_serial(const StudyArguments &args, const bool root, const Material &material, const Run &run,
                     const DistributedResult &r)
  {
    const double tolerance = args.num("compare_tol", 1e-10);
    if (!root)
      return true;
    const auto         serial_start = std::chrono::steady_clock::now();
    AxisymmetricSolver serial(material, run.mesh, run.disc);
    const Result       s = serial.run(run.load);
    const double       t = std::chrono::duration<double>(std::chrono::steady_clock::now() - serial_start).count();
    const double       df = std::abs(r.force / s.force - 1), dd = std::abs(r.depth / s.depth - 1);
    const bool         same_mesh = s.n_dofs == r.n_dofs;
    std::printf("serial: dofs=%u force=%.16e depth=%.16e total=%.2f | relative difference: "
                "force=%.2e depth=%.2e (tolerance %.1e)\n",
                s.n_dofs, s.force, s.depth, t, df, dd, tolerance);
    if (!same_mesh || !(df <= tolerance) || !(dd <= tolerance))
      {
        std::printf("FAILED: %s\n", same_mesh ? "the distributed answer differs from the serial one" :
                                                "different DoF counts (different meshes)");
        return false;
      }
    return true;
  }

  /// The run of the arguments, checked as they ask; its exit code.
  int study(const StudyArguments &args, const MPI_Comm world, const bool root)
  {
    Run            run = parse_run(args);
    const Material material{std::make_shared<PowerLawModulus>(run.E0, run.c0, run.k), run.nu};
    plan_control(args, run);
    const auto              start = std::chrono::steady_clock::now();
    const DistributedResult r     = solve(args, world, material, run);
    const double total = dealii::Utilities::MPI::max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), world);
    const Errors e = errors_of(run, r);
    print_run(world, root, run, r, e, total);

    int failed = r.reliable && r.consistent_contact ? 0 : 1;
    if (args.has("expect_tol") && !meets_expected(args, root, run, e))
      failed = 1;
    if (args.has("compare") && args.num("compare", 0) != 0)
      {
        if (!equals_serial(args, root, material, run, r))
          failed = 1;
        failed = dealii::Utilities::MPI::max(failed, world);
      }
    return failed;
  }
} // namespace

int main(int argc, char **argv) { return gradcontact::studies::distributed_main(argc, argv, "fem_mpi", study); }
