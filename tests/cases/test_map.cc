// Applicability maps (cases/fe_map.h): the threshold read from a map, and a small map run end to end.
#include "scene_files.h"

#include <cases/fe_map.h>
#include <cases/runner.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

TEST_CASE("The threshold of a map shall be where a power-law decay of the deviation crosses it", "[cases]")
{
  // |deviation| = 0.3 (ratio)^-0.5 crosses 1e-2 at ratio (0.3/1e-2)^2 = 900, between 100 and 1000: the
  // log-log interpolation is exact for a power law.
  const std::vector<double> ratios{1, 10, 100, 1000, 1e4};
  std::vector<double> deviations;
  for (const double r : ratios)
    deviations.push_back(-0.3 / std::sqrt(r));
  const auto crossing = threshold_ratio(ratios, deviations, 1e-2);
  REQUIRE(crossing.has_value());
  CHECK(*crossing == Approx(900).epsilon(1e-12));
  CHECK(threshold_cell(ratios, deviations, 1e-2, true) == ">= 900");
  // Within at every ratio, and never within.
  const auto every = threshold_ratio(ratios, deviations, 1.);
  REQUIRE(every.has_value());
  CHECK(*every == 1.);
  CHECK(threshold_cell(ratios, deviations, 1., true) == "at every ratio (from 1)");
  CHECK_FALSE(threshold_ratio(ratios, deviations, 1e-3).has_value());
  CHECK(threshold_cell(ratios, deviations, 1e-3, true) == "not within it up to 10000");
  // A deviation that comes back above the threshold at a larger ratio moves the answer past it.
  deviations[3] = 0.5;
  const auto past = threshold_ratio(ratios, deviations, 0.1);
  REQUIRE(past.has_value());
  CHECK(*past > 1000.);
  CHECK_THROWS_WITH(threshold_ratio({1, 2}, {0.1}, 0.01), Catch::Contains("2 ratios and 1 deviations"));
}

TEST_CASE("A coating map shall read its threshold toward a/H -> 0", "[cases]")
{
  // |deviation| = 0.3 (a/H)^0.5 (a coating is the power law as a/H -> 0): within 1e-2 when
  // a/H <= (1e-2 / 0.3)^2 = 1/900.
  const std::vector<double> ratios{1e-4, 1e-3, 1e-2, 0.1, 1};
  std::vector<double> deviations;
  for (const double r : ratios)
    deviations.push_back(0.3 * std::sqrt(r));
  const std::string at = threshold_cell(ratios, deviations, 1e-2, false);
  REQUIRE(at.rfind("<= ", 0) == 0);
  CHECK(std::stod(at.substr(3)) == Approx(1. / 900).epsilon(1e-5)); // format() keeps 6 digits
  CHECK(threshold_cell(ratios, deviations, 1., false) == "at every ratio (up to 1)");
  CHECK(threshold_cell(ratios, deviations, 1e-4, false) == "not within it down to 0.0001");
}

TEST_CASE("A map scene shall check the power law itself and write the map, its thresholds and plots", "[cases]")
{
  const TemporaryFolder folder("gradcontact-map");
  const fs::path scene = folder.path() / "small_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0.5\nend\n"
                          "subsection Load\n  set type = flat punch\n  set a = 1e-4\n  set depth = 1e-6\nend\n"
                          "subsection Discretization\n  set degree = 1\n  set force tolerance = 1e-3\nend\n"
                          "subsection Tolerances\n  set force = 1e-2\n  set pressure = 1e-1\nend\n"
                          "subsection Map\n  set parameter = coating thickness\n  set ratios = 0.01, 1\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "small_map";
  for (const char *file : {"errors.csv", "map.csv", "map.md"})
    CHECK(fs::exists(out / file));
  const std::string md = testing::read_text(out / "map.md");
  CHECK(md.find("| 0.01 |") != std::string::npos);
  CHECK(md.find("within 1 % when a/H |") != std::string::npos);
  // A coating 100 a thick is the power law within a few per cent at most; one a / 1 thick is far from it.
  // map.csv: k, a/H, the force deviation, ...; rows in ascending a/H (thick coating first).
  const auto csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[0][0] == "k");
  CHECK(csv[0][1] == "a_over_H");
  CHECK(csv[0][2] == "force_deviation");
  const auto force_deviation = [](const std::vector<std::string> &row) { return std::stod(row.at(2)); };
  const auto &thick = csv[1], &thin = csv[2];
  CHECK(std::abs(force_deviation(thick)) < std::abs(force_deviation(thin)));
}

TEST_CASE("A map scene with a load it cannot map shall be an error naming the entries", "[cases]")
{
  const TemporaryFolder folder("gradcontact-map-bad");
  const fs::path scene = folder.path() / "bad_map.prm";
  std::ofstream(scene) << "subsection Load\n  set type = constant pressure\nend\n"
                          "subsection Map\n  set parameter = surface depth\n  set ratios = 1\nend\n";
  CHECK_THROWS_WITH(read_scene(scene.string(), {}), Catch::Contains("bad_map.prm") && Catch::Contains("Map/parameter") &&
                                                  Catch::Contains("constant pressure"));
}
