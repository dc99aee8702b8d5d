// The convergence report of a scene (cases/report/convergence_report.h): the observed order of known error
// sequences, and the files written.
#include "scene_files.h"

#include <cases/report/convergence_report.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace
{
  /// Levels whose DoFs grow 4x per level (h halves) and whose error is C h^p exactly.
  std::vector<Level> levels_of_order(const double p, const unsigned int n)
  {
    std::vector<Level> levels;
    for (unsigned int l = 0; l < n; ++l)
      {
        const unsigned int dofs = 1000u << (2 * l);
        const double h = 1. / std::sqrt(static_cast<double>(dofs));
        levels.push_back({l, dofs, 1. + l, 1. + 3. * std::pow(h, p), 3. * std::pow(h, p)});
      }
    return levels;
  }

  /// Round-off of the least-squares slope of logarithms of exact powers.
  constexpr double order_tolerance = 1e-12;
} // namespace

TEST_CASE("The observed order shall be the exponent of error ~ h^p over the last three levels", "[cases][quick]")
{
  const double p = GENERATE(1., 2., 3.5);
  CAPTURE(p);
  CHECK_THAT(observed_order(levels_of_order(p, 3)), WithinRel(p, order_tolerance));
  // only the last three levels count: a pre-asymptotic first level does not change it
  std::vector<Level> levels = levels_of_order(p, 4);
  levels.front().error *= 100.;
  CHECK_THAT(observed_order(levels), WithinRel(p, order_tolerance));
}

TEST_CASE("Fewer than three levels with an error shall have no observed order", "[cases][quick]")
{
  CHECK(std::isnan(observed_order(levels_of_order(2., 2))));
  std::vector<Level> levels = levels_of_order(2., 3);
  levels[1].error = 0.; // exact: log 0 is no data point
  CHECK(std::isnan(observed_order(levels)));
}

TEST_CASE("The convergence report shall have one row per quantity and level, with its order", "[cases][quick]")
{
  const testing::TemporaryFolder folder("gradcontact-convergence");
  const std::vector<ConvergenceSeries> series = {{"force", 1., levels_of_order(2., 3)},
                                                 {"pull-off force, force control", 1., levels_of_order(1., 3)}};
  write_convergence(folder.path(), "scene", "closed form", series, false);
  std::ifstream csv(folder.path() / "convergence.csv");
  std::vector<std::string> lines;
  for (std::string line; std::getline(csv, line);)
    lines.push_back(line);
  REQUIRE(lines.size() == 1 + 6);
  CHECK_THAT(lines[0], Contains("quantity,refinement,dofs,seconds,value,reference,relative_error,observed_order,"
                                "change,estimate"));
  // Order 2 halves h per level, so the values 1 + 3 h^2 are a geometric series of ratio 1/4, the degree-2 ratio the
  // estimate assumes: its Richardson tail is the error itself (relative to the value, 1 + error).
  {
    std::vector<std::string> fields;
    std::stringstream row(lines[3]);
    for (std::string field; std::getline(row, field, ',');)
      fields.push_back(field);
    REQUIRE(fields.size() == 10);
    const double error = std::stod(fields[6]), estimate = std::stod(fields[9]);
    CHECK_THAT(estimate, WithinRel(error / (1 + error), 1e-5)); // the CSV keeps six digits
  }
  // a quantity with a comma stays one CSV field
  CHECK_THAT(lines[4], Contains("\"pull-off force, force control\",0,1000,"));
  std::ifstream md(folder.path() / "convergence.md");
  std::stringstream text;
  text << md.rdbuf();
  CHECK_THAT(text.str(), Contains("## force") && Contains("## pull-off force, force control") &&
                           Contains("Errors against the closed form"));
}
