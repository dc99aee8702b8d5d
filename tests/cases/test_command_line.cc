// The command line (cases/app/command_line.h): every command answers --help with its own usage and exit code 0;
// MPI starts at once under an MPI launcher only (cases/model/mpi_session.h).
#include <cases/app/command_line.h>
#include <cases/model/mpi_session.h>

#include <deal.II/base/mpi.h>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("Every command shall print its own usage on --help and exit with 0", "[cases][quick]")
{
  const std::vector<std::string> names = command_names();
  REQUIRE(names == std::vector<std::string>{"eval", "run", "sweep", "figures", "bench", "stress"});
  for (const std::string &name : names)
    for (const std::string flag : {"--help", "-h"})
      {
        CAPTURE(name, flag);
        std::ostringstream out;
        CHECK(command_line({name, flag}, out) == 0);
        CHECK_THAT(out.str(), StartsWith("usage: gradcontact " + name + " "));
        // its own usage, not the whole list
        for (const std::string &other : names)
          if (other != name)
            CHECK_THAT(out.str(), !Contains("gradcontact " + other + " "));
      }
  // an option after other arguments too
  std::ostringstream out;
  CHECK(command_line({"bench", "--quick", "--help"}, out) == 0);
  CHECK_THAT(out.str(), StartsWith("usage: gradcontact bench"));
}

TEST_CASE("The usage shall list every command, and an unknown command shall be an error naming it", "[cases][quick]")
{
  std::ostringstream out;
  CHECK(command_line({"--help"}, out) == 0);
  for (const std::string &name : command_names())
    CHECK_THAT(out.str(), Contains("  " + name + " "));
  std::ostringstream empty;
  CHECK(command_line({}, empty) == 2);
  REQUIRE_THROWS_WITH(command_line({"bnech"}, out), Contains("unknown command 'bnech'") && Contains("bench"));
}

TEST_CASE("The command line shall start MPI at once only under an MPI launcher, and refuse a distributed model "
          "without MPI by name",
          "[cases][quick]")
{
  // The variables by which Open MPI, PMIx, MPICH/Hydra and Slurm's PMI mark the processes they start.
  const std::vector<std::string> launcher_variables{"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE",
                                                    "MPI_LOCALNRANKS"};
  std::vector<std::pair<std::string, std::string>> saved;
  for (const std::string &name : launcher_variables)
    if (const char *value = std::getenv(name.c_str()))
      saved.emplace_back(name, value);
  for (const std::string &name : launcher_variables)
    unsetenv(name.c_str());
  CHECK_FALSE(launched_by_mpi());
  for (const std::string &name : launcher_variables)
    {
      CAPTURE(name);
      setenv(name.c_str(), "2", 1);
      CHECK(launched_by_mpi());
      unsetenv(name.c_str());
    }
  for (const auto &[name, value] : saved)
    setenv(name.c_str(), value.c_str(), 1);

  // This test program has no MpiSession and never starts MPI: the distributed scenes' communicator is refused
  // with a message saying what is missing.
  REQUIRE_FALSE(dealii::Utilities::MPI::job_supports_mpi());
  CHECK_THROWS_WITH(mpi_world(), Contains("MPI is not initialised") && Contains("MpiSession"));
}
