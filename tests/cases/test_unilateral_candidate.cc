// A user's closed forms against the unilateral FE (Load/contact = unilateral with a Candidate): the entries it
// needs, and a tabulated indenter end to end, checked against the chapter's paraboloid (9.24-9.26, written out
// here from the MDR by hand, not taken from the analytic library).
#include "scene_files.h"

#include <cases/app/runner.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <string>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using testing::scene_with;
using testing::TemporaryFolder;

TEST_CASE("A unilateral candidate shall be a candidate scene, and its entries shall be checked together", "[cases][quick]")
{
  CHECK(scene_with({"Load/contact=unilateral", "Load/control=depth", "Candidate/profile=r^2/0.02",
                    "Candidate/force=1"})
          .kind == SceneKind::candidate);
  CHECK(scene_with({"Load/contact=unilateral", "Load/control=depth", "Candidate/profile table=f.csv",
                    "Candidate/outer radius=1e-4"})
          .kind == SceneKind::candidate);
  REQUIRE_THROWS_WITH(scene_with({"Candidate/profile table=f.csv", "Candidate/force=1"}),
                      Contains("Candidate/profile table needs Load/contact = unilateral"));
  REQUIRE_THROWS_WITH(scene_with({"Load/contact=unilateral", "Load/control=depth", "Candidate/profile=r^2",
                                  "Candidate/profile table=f.csv", "Candidate/force=1"}),
                      Contains("both set"));
  REQUIRE_THROWS_WITH(scene_with({"Candidate/profile=r^2/0.02", "Candidate/inner radius=0"}),
                      Contains("need Load/contact = unilateral"));
  REQUIRE_THROWS_WITH(scene_with({"Load/contact=unilateral", "Load/control=depth", "Candidate/profile=r^2/0.02",
                                  "Candidate/force=1", "References/fem=false"}),
                      Contains("against the FE only"));
  REQUIRE_THROWS_WITH(scene_with({"Load/contact=unilateral", "Load/control=contact radius",
                                  "Candidate/profile=r^2/0.02", "Candidate/force=1"}),
                      Contains("Load/control must be depth or force"));
}

TEST_CASE("A tabulated paraboloid shall press like the paraboloid's closed form under unilateral contact", "[cases]")
{
  // f = r^2 / (2 R) tabulated every a/500 up to 2 a (linear interpolation: at most h^2 / (8 R), 1e-6 of d), k = 0.5.
  // By the MDR (9.2) g(x) = x^2 / ((1 + k) R): at depth d the contact radius is a = sqrt((1 + k) R d) and
  // F = 4 cN0 a^{3+k} / ((1 + k)^2 (3 + k) R c0^k) (the candidate's expressions below).
  const TemporaryFolder folder("gradcontact-table-indenter");
  const double a = 1e-4, R = 5e-3, k = 0.5;
  {
    std::ofstream table(folder.path() / "paraboloid.csv");
    table << "# r [m], f [m]\nr,f\n";
    table.precision(17);
    for (int j = 0; j <= 1000; ++j)
      {
        const double r = j * a / 500;
        table << r << ", " << r * r / (2 * R) << '\n';
      }
  }
  const double d = a * a / ((1 + k) * R);
  const fs::path scene = folder.path() / "table_paraboloid.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0.5\nend\n"
                          "subsection Load\n  set contact = unilateral\n  set control = depth\n  set a = 1e-4\n"
                          "  set depth = " << d << "\nend\n"
                          "subsection Candidate\n  set profile table = paraboloid.csv\n  set constants = R = 5e-3\n"
                          "  set force = 4 * cN0 * ((1 + k) * R * d)^((3 + k) / 2) / ((1 + k)^2 * (3 + k) * R * c0^k)\n"
                          "  set outer radius = sqrt((1 + k) * R * d)\n  set inner radius = 0\nend\n"
                          "subsection Discretization\n  set degree = 2\nend\n"
                          "subsection Tolerances\n  set force = 2e-4\n  set contact radius = 1e-4\nend\n";
  const fs::path reports = folder.path() / "reports";
  CHECK(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const auto csv = testing::read_csv(reports / "table_paraboloid" / "errors.csv");
  // Degree 2: the force and the outer radius within the scene's tolerances, the inner radius 0; every row passes.
  REQUIRE(csv.size() == 4); // header, force, outer radius, inner radius
  for (std::size_t i = 1; i < csv.size(); ++i)
    {
      CAPTURE(csv[i][0], csv[i][7]);
      CHECK(csv[i][9] == "pass");
    }
  // A line that is not two numbers is an error naming the file and the line, and leaves no report.
  std::ofstream(folder.path() / "paraboloid.csv", std::ios::app) << "0.0003, oops\n";
  CHECK_THROWS_WITH(run({scene.string(), "--reports", (folder.path() / "bad").string(), "--quiet"}),
                    Contains("paraboloid.csv") && Contains("line 1004") && Contains("is not two numbers r, f"));
  CHECK_FALSE(fs::exists(folder.path() / "bad" / "table_paraboloid"));
}
