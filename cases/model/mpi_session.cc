#include "model/mpi_session.h"

#include <cstdlib>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace
  {
    MpiSession *current = nullptr;
  }

  bool launched_by_mpi()
  {
    // Each launcher sets its rank or size in the environment of every process it starts.
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE", "MPI_LOCALNRANKS"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  MpiSession::MpiSession(int &argc_, char **&argv_)
    : argc(argc_)
    , argv(argv_)
  {
    if (current != nullptr)
      throw std::logic_error("MpiSession: a program has one MPI session");
    if (launched_by_mpi())
      start();
    current = this; // after a start that may throw: no session is left registered by a failed constructor
  }

  MpiSession::~MpiSession()
  {
    mpi.reset();
    current = nullptr;
  }

  void MpiSession::start()
  {
    if (!mpi && !dealii::Utilities::MPI::job_supports_mpi())
      mpi = std::make_unique<dealii::Utilities::MPI::MPI_InitFinalize>(argc, argv,
                                                                       dealii::numbers::invalid_unsigned_int);
  }

  MPI_Comm mpi_world()
  {
    if (current != nullptr)
      current->start();
    if (!dealii::Utilities::MPI::job_supports_mpi())
      throw std::runtime_error("MPI is not initialised: the program needs a cases::MpiSession (or a "
                               "dealii::Utilities::MPI::MPI_InitFinalize object) for the distributed models");
    return MPI_COMM_WORLD;
  }
} // namespace gradcontact::cases
