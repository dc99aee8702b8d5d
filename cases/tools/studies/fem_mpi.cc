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

#include "study_arguments.h"
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

int main(int argc, char **argv)
{
  // One thread per process: the machine's cores go to the MPI processes.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm     world = MPI_COMM_WORLD;
  const bool         root  = dealii::Utilities::MPI::this_mpi_process(world) == 0;
  try
    {
      const gradcontact::studies::StudyArguments args(argc, argv, "fem_mpi");
      auto num = [&](const std::string &key, const double fallback) { return args.num(key, fallback); };
      // The material and loads of fem_study: E0 = 2 GPa, c0 = 0.3 mm, a = 0.1 mm.
      const double E0 = 2e9, c0 = 3e-4, a = 1e-4, nu = num("nu", 0.3);
      const double k  = num("k", 0.0);
      const std::string load_name = args.text("load", "punch");
      MeshParameters mesh = recommended_mesh_parameters(a, k, num("truncation", 1e-8));
      // The surface layer defaults to a (p4est cannot make the z-only surface halvings).
      mesh.surface_layer_thickness = 1.0;
      args.apply(mesh);
      DiscretizationParameters disc;
      args.apply(disc);
      DistributedSolverParameters parameters;
      args.apply(parameters);

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
      const Material material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};

      // control=depth|force (paraboloid): the target of the contact radius a_true = 1.1 a by (9.26), the radius
      // found by solve_controlled (meshes graded at each trial radius).
      const std::string control = args.text("control", "radius");
      const double      R = 50 * a, a_true = 1.1 * a;
      const double F_true = testing::paraboloid_force(k, nu, E0, c0, a_true, R); // (9.26)
      if (control != "radius")
        {
          if (load_name != "paraboloid" || (control != "depth" && control != "force"))
            throw std::invalid_argument("fem_mpi: control = " + control + " needs load=paraboloid and depth|force");
          if (args.has("compare"))
            throw std::invalid_argument("fem_mpi: compare is for radius control (the serial solver's search has its own "
                                        "mesh), not with control = " + control);
          load.type  = control == "depth" ? LoadType::indenter_depth : LoadType::indenter_force;
          load.depth = a_true * a_true / ((1 + k) * R); // (9.26)
          load.force = F_true;
        }

      const auto        start = std::chrono::steady_clock::now();
      const DistributedResult r =
        control == "radius" ?
          DistributedSolver(world, material, mesh, disc, parameters).run(load) :
          solve_controlled(world, material, load,
                           [&](const double radius) {
                             Settings st{mesh, disc};
                             st.mesh.contact_radius = radius;
                             return st;
                           },
                           num("start", 1.0) * a, num("control_tol", 1e-10), 20, parameters);
      const double total = dealii::Utilities::MPI::max(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), world);
      // Peak resident memory (VmHWM) of the largest process and of all processes together [MB].
      dealii::Utilities::System::MemoryStats memory;
      dealii::Utilities::System::get_memory_stats(memory);
      const double peak_mb = static_cast<double>(memory.VmHWM) / 1024;
      const double peak_max = dealii::Utilities::MPI::max(peak_mb, world);
      const double peak_sum = dealii::Utilities::MPI::sum(peak_mb, world);
      // The flat punch against (9.16), h_N written out (tests/fem/written_out.h); NaN for the other loads.
      const double F_punch = testing::flat_punch_force(k, nu, E0, c0, a, load.depth);
      const double F_error = load_name == "punch" ? r.force / F_punch - 1 :
                             control != "radius"  ? r.force / F_true - 1 :
                                                    std::nan("");
      const double a_error = control != "radius" ? r.contact_radius / a_true - 1 : std::nan("");
      if (root && control != "radius")
        std::printf("control=%s trials=%u a_error=%.3e ", control.c_str(), r.control_trials, a_error);
      if (root)
        std::printf("load=%s k=%g p=%u np=%u solver=%s dofs=%llu cells=%u force=%.16e F_error=%.3e depth=%.16e "
                    "iterations=%u residual=%.1e mismatch=%.1e mesh=%.2f setup=%.2f assemble=%.2f "
                    "factorize=%.2f solve=%.2f total=%.2f peak_mb_max=%.0f peak_mb_sum=%.0f %s\n",
                    load_name.c_str(), k, disc.degree, r.n_processes, r.solver.c_str(),
                    static_cast<unsigned long long>(r.n_dofs), r.n_cells, r.force, F_error, r.depth, r.iterations,
                    r.residual, r.energy_mismatch, r.time.mesh, r.time.setup, r.time.assemble,
                    r.time.factorize, r.time.solve, total, peak_max, peak_sum, r.message.c_str());

      int failed = r.reliable && r.consistent_contact ? 0 : 1;
      if (args.has("expect_tol"))
        {
          if (load_name != "punch" && control == "radius")
            throw std::invalid_argument("fem_mpi: expect_tol needs load=punch or control=depth|force (load = " +
                                        load_name + ")");
          // The written-out closed form within expect_tol (the punch's F, or a and F under depth/force control).
          const double tol = num("expect_tol", 0);
          if (!(std::abs(F_error) <= tol) || (control != "radius" && !(std::abs(a_error) <= tol)))
            {
              if (root)
                std::printf("FAILED: F_error %.3e or a_error %.3e above expect_tol %.1e\n", F_error, a_error, tol);
              failed = 1;
            }
        }
      if (args.has("compare") && num("compare", 0) != 0)
        {
          // The serial reference on process 0 (the others wait): same mesh, same operator, sparse direct.
          const double tolerance = num("compare_tol", 1e-10);
          if (root)
            {
              const auto         serial_start = std::chrono::steady_clock::now();
              AxisymmetricSolver serial(material, mesh, disc);
              const Result       s = serial.run(load);
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
                  failed = 1;
                }
            }
          failed = dealii::Utilities::MPI::max(failed, world);
        }
      return failed;
    }
  catch (const std::exception &e)
    {
      std::cerr << "fem_mpi (process " << dealii::Utilities::MPI::this_mpi_process(world) << "): " << e.what()
                << '\n';
      return 1;
    }
}
