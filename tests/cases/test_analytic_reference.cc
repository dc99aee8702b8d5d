// The scene -> analytic request builder (cases/model/analytic_reference.h): each problem reads the scene's load
// as the chapter's case, checked against requests written out by hand in the JSON vocabulary of
// analytic/README.md (an independent path to the same evaluator).
#include "scene_files.h"

#include <cases/model/analytic_reference.h>

#include <analytic/batch.h>

#include <catch2/catch.hpp>

#include <cstdio>
#include <string>

using namespace gradcontact;
using namespace gradcontact::cases;
using Catch::Contains;
using Catch::Matchers::WithinRel;
using testing::scene_with;

namespace
{
  const std::string material = R"("material":{"E0":1e9,"c0":1e-3,"k":0.5,"nu":0.3})";

  std::vector<std::string> with_material(std::vector<std::string> entries)
  {
    for (const char *entry : {"Material/E0=1e9", "Material/c0=1e-3", "Material/k=0.5", "Material/nu=0.3"})
      entries.push_back(entry);
    return entries;
  }

  /// 17 significant digits: the double itself.
  std::string exact(const double x)
  {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
  }

  double value_of(const std::string &line) { return batch::evaluate(batch::parse(line)); }
} // namespace

TEST_CASE("The normal reference of a paraboloid under force control shall be at the contact radius of that force",
          "[cases][quick]")
{
  const Scene s = scene_with(with_material({"Load/type=paraboloid", "Load/R=0.01", "Load/control=force",
                                            "Load/force=0.02"}));
  const AnalyticReference closed(s, batch::Method::closed_form, AnalyticReference::Problem::normal);
  const double a = value_of(R"({"case":"paraboloid","quantity":"contact_radius",)" + material +
                            R"(,"geometry":{"R":0.01},"F":0.02})");
  CHECK(closed.radius() == a);
  CHECK_THAT(closed.get("force"), WithinRel(0.02, 1e-12));
  const double r = 0.5 * a;
  CHECK(closed.at("pressure", r) == value_of(R"({"case":"paraboloid","quantity":"pressure",)" + material +
                                             R"(,"geometry":{"R":0.01},"a":)" + exact(a) + R"(,"r":)" + exact(r) + "}"));
  // The numerical MDR solves its own contact radius for the same force.
  const AnalyticReference numeric(s, batch::Method::numerical_mdr, AnalyticReference::Problem::normal);
  CHECK_THAT(numeric.radius(), WithinRel(a, 1e-9));
  CHECK(numeric.label() == "numerical MDR");
  CHECK(closed.label() == "closed form");
}

TEST_CASE("The adhesive reference of a cone shall be the JKR power law n = 1", "[cases][quick]")
{
  const Scene s = scene_with(
    with_material({"Load/type=cone", "Load/tan theta=0.2", "Adhesion/work of adhesion=0.05"}));
  const AnalyticReference closed(s, batch::Method::closed_form, AnalyticReference::Problem::adhesive);
  for (const auto &[control, name] : {std::pair{Control::force, "force"}, std::pair{Control::displacement, "displacement"}})
    {
      CAPTURE(name);
      const double expected =
        value_of(R"({"case":"jkr_power_law","quantity":"critical_force",)" + material +
                 R"(,"geometry":{"n":1,"A":0.2},"dgamma":0.05,"control":")" + name + "\"}");
      CHECK(closed.get("critical_force", input::control(control)) == expected);
    }
  // The control is the comparison's input, not the scene's: without it the request is incomplete.
  CHECK_THROWS_WITH(closed.get("critical_force"), Contains("control: missing"));
}

TEST_CASE("The tangential reference shall carry the scene's sphere and friction to any case", "[cases][quick]")
{
  const Scene s = scene_with(with_material({"Load/type=paraboloid", "Load/R=0.01", "Load/a=1e-4",
                                            "Tangential/study=partial slip", "Friction/coefficient=0.4"}));
  const AnalyticReference closed(s, batch::Method::closed_form, AnalyticReference::Problem::tangential);
  const std::string sphere = material + R"(,"geometry":{"R":0.01},"a":1e-4,"mu":0.4)";
  const double FA = 0.5 * 0.4 * value_of(R"({"case":"paraboloid","quantity":"force",)" + material +
                                         R"(,"geometry":{"R":0.01},"a":1e-4})");
  const auto at = [FA](const Branch branch, const double Fx) {
    return [=](batch::Request &q) {
      q.FA = FA;
      q.branch = branch;
      q.Fx = Fx;
    };
  };
  CHECK(closed.get("oscillating_sphere", "tangential_displacement", at(Branch::unloading, -0.25 * FA)) ==
        value_of(R"({"case":"oscillating_sphere","quantity":"tangential_displacement",)" + sphere +
                 R"(,"FA":)" + exact(FA) + R"(,"branch":"unloading","Fx":)" + exact(-0.25 * FA) + "}"));
  CHECK(closed.get("coefficients", "alpha", {}) ==
        value_of(R"({"case":"coefficients","quantity":"alpha",)" + material + "}"));
  CHECK(closed.get("flat_punch", "force", [](batch::Request &q) { q.d = 1e-7; }) ==
        value_of(R"({"case":"flat_punch","quantity":"force",)" + material + R"(,"a":1e-4,"d":1e-7})"));
}

TEST_CASE("A reference for a scene whose modulus is not the power law shall say it uses the power-law "
          "idealisation",
          "[cases][quick]")
{
  const AnalyticReference power(scene_with(with_material({"Load/type=flat punch"})), batch::Method::closed_form,
                                AnalyticReference::Problem::normal);
  CHECK(power.label() == "closed form");
  CHECK_FALSE(power.idealised());
  const AnalyticReference layered(scene_with(with_material({"Load/type=flat punch", "Material/modulus=layered"})),
                                  batch::Method::numerical_mdr, AnalyticReference::Problem::normal);
  CHECK(layered.idealised());
  CHECK(layered.label() == "numerical MDR (power-law idealisation E0, c0, k)");
}
