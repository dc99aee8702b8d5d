// gradcontact/cases: MPI for the command line, started only when a command needs it.
//
// Starting MPI costs a singleton process noticeable wall time (Open MPI loads its components and
// starts a helper daemon), more than a whole short FE run of the suite. The serial models (every scene but the
// Coulomb 3D ones) do not use MPI, so `gradcontact` starts it
//  - at once when an MPI launcher started the process (mpirun/mpiexec/srun: every rank calls MPI_Init at the
//    same point), and
//  - otherwise at the first call of `mpi_world()`, which the distributed scenes make before they build a model.
// The session ends (MPI_Finalize, with deal.II's p4est and PETSc) when the MpiSession of main is destroyed,
// before the program's static objects.
#ifndef GRADCONTACT_CASES_MPI_SESSION_H
#define GRADCONTACT_CASES_MPI_SESSION_H

#include <deal.II/base/mpi.h>

#include <mpi.h>

#include <memory>

namespace gradcontact::cases
{
  /// Whether the environment shows that an MPI launcher started this process (Open MPI, MPICH/Hydra, PMIx,
  /// Slurm's PMI).
  bool launched_by_mpi();

  /// The MPI session of a program (one object, in main). Not copied or moved.
  class MpiSession
  {
  public:
    /// Starts MPI now when `launched_by_mpi()`, else leaves it to the first `mpi_world()`. `argc`/`argv` are
    /// main's; deal.II's thread count is left at its default for one process per machine.
    MpiSession(int &argc, char **&argv);
    ~MpiSession();
    MpiSession(const MpiSession &)            = delete;
    MpiSession &operator=(const MpiSession &) = delete;

    /// Starts MPI if it is not yet.
    void start();

  private:
    int                                                      &argc;
    char                                                   **&argv;
    std::unique_ptr<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  };

  /// MPI_COMM_WORLD, with MPI started by the program's MpiSession if it is not yet. Throws std::runtime_error
  /// when MPI is not running and no MpiSession exists (a program that links the cases library without one).
  /// Called from the main thread (MPI is started by one thread, as MPI_Init requires).
  MPI_Comm mpi_world();
} // namespace gradcontact::cases

#endif
