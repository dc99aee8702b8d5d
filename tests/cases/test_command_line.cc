// The command line (cases/command_line.h): every command answers --help with its own usage and exit code 0.
#include <cases/command_line.h>

#include <catch2/catch.hpp>

#include <sstream>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("Every command shall print its own usage on --help and exit with 0", "[cases]")
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

TEST_CASE("The usage shall list every command, and an unknown command shall be an error naming it", "[cases]")
{
  std::ostringstream out;
  CHECK(command_line({"--help"}, out) == 0);
  for (const std::string &name : command_names())
    CHECK_THAT(out.str(), Contains("  " + name + " "));
  std::ostringstream empty;
  CHECK(command_line({}, empty) == 2);
  REQUIRE_THROWS_WITH(command_line({"bnech"}, out), Contains("unknown command 'bnech'") && Contains("bench"));
}
