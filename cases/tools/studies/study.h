// What the FE studies share beyond their command line (study_arguments.h): the run of an axisymmetric study (its unit
// material and contact radius, its load's name, its mesh and discretisation from the arguments), and the start of a
// distributed study's main (MPI, the arguments, and an error reported by the process that met it).
#ifndef GRADCONTACT_CASES_TOOLS_STUDIES_STUDY_H
#define GRADCONTACT_CASES_TOOLS_STUDIES_STUDY_H

#include "study_arguments.h"

#include <fem/grid/discretization.h>
#include <fem/grid/mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <exception>
#include <functional>
#include <iostream>
#include <string>

namespace gradcontact::studies
{
  /// One axisymmetric run: the material E0 = 2 GPa, c0 = 0.3 mm at the contact radius a = 0.1 mm (c0 = 3 a), its
  /// nu and k, the load's name, and the mesh and discretisation.
  struct AxisymmetricRun
  {
    double                        E0 = 2e9, c0 = 3e-4, a = 1e-4, nu = 0.3, k = 0;
    std::string                   load_name;
    fem::MeshParameters           mesh;
    fem::DiscretizationParameters disc;
  };

  /// nu (0.3), k (0), load (punch) and the mesh recommended for a and k (truncation, 1e-8), which `study_defaults`
  /// changes before the mesh and discretisation keys of the arguments apply (a study's own defaults).
  inline AxisymmetricRun axisymmetric_run(const StudyArguments &args,
                                          const std::function<void(fem::MeshParameters &)> &study_defaults)
  {
    AxisymmetricRun run;
    run.nu        = args.num("nu", 0.3);
    run.k         = args.num("k", 0.0);
    run.load_name = args.text("load", "punch");
    run.mesh      = fem::recommended_mesh_parameters(run.a, run.k, args.num("truncation", 1e-8));
    study_defaults(run.mesh);
    args.apply(run.mesh);
    args.apply(run.disc);
    return run;
  }

  /// The main of a distributed study named `tool`: MPI with one thread per process (the machine's cores go to the
  /// processes), the arguments, and the exit code of `study(args, world, root)`, root being process 0. An error is
  /// printed with the process that met it; with several processes it ends them all, since an exception on some
  /// processes only would leave the others waiting in a collective.
  inline int distributed_main(int argc, char **argv, const std::string &tool,
                              const std::function<int(const StudyArguments &, MPI_Comm, bool)> &study)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const MPI_Comm world = MPI_COMM_WORLD;
    const bool     root  = dealii::Utilities::MPI::this_mpi_process(world) == 0;
    try
      {
        const StudyArguments args(argc, argv, tool);
        return study(args, world, root);
      }
    catch (const std::exception &e)
      {
        std::cerr << tool << " (process " << dealii::Utilities::MPI::this_mpi_process(world) << "): " << e.what() << '\n';
        if (dealii::Utilities::MPI::n_mpi_processes(world) > 1)
          MPI_Abort(world, 1);
        return 1;
      }
  }
} // namespace gradcontact::studies

#endif
