// Requirement: `gradcontact eval` shall answer one JSON line per request, in order, echo the id as
// given, report every bad request as an error line naming the parameter, and never stop at one.
#include <analytic/batch.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace gradcontact;
using Catch::Contains;
using nlohmann::json;

namespace
{
  const std::string material = R"("material":{"E0":1e9,"c0":1e-3,"k":0.5,"nu":0.3})";
}

TEST_CASE("eval answers in order and survives bad lines", "[analytic]")
{
  std::istringstream in(
    R"({"id":"first","case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":0.01},"a":1e-4})" "\n"
    "not json at all\n"
    "\n"
    R"({"id":3,"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":-1},"a":1e-4})" "\n"
    R"({"id":[4,5],"case":"teapot","quantity":"force",)" + material + "}\n"
    R"({"id":6,"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":0.01},"a":1e-4,"method":"numerical_mdr"})" "\n");
  std::ostringstream out;
  const int errors = batch::evaluate_stream(in, out);
  CHECK(errors == 3);
  std::istringstream lines(out.str());
  std::vector<json> answers;
  for (std::string line; std::getline(lines, line);)
    answers.push_back(json::parse(line));
  REQUIRE(answers.size() == 5);
  CHECK(answers[0]["id"] == "first");
  CHECK(answers[0]["value"].get<double>() > 0.);
  CHECK(answers[1]["id"].is_null());
  CHECK_THAT(answers[1]["error"].get<std::string>(), Contains("not valid JSON"));
  CHECK(answers[2]["id"] == 3);
  CHECK_THAT(answers[2]["error"].get<std::string>(), Contains("R = -1"));
  CHECK(answers[3]["id"] == json::array({4, 5}));
  CHECK_THAT(answers[3]["error"].get<std::string>(), Contains("teapot") && Contains("paraboloid"));
  CHECK(answers[4]["id"] == 6);
  CHECK_THAT(answers[4]["value"].get<double>(),
             Catch::Matchers::WithinRel(answers[0]["value"].get<double>(), 1e-12));
}

TEST_CASE("eval names missing, unknown and mistyped entries", "[analytic]")
{
  const auto error_of = [](const std::string &line) {
    const batch::Answer a = batch::evaluate(line);
    REQUIRE_FALSE(a.ok);
    return a.error;
  };
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":0.01}})"),
             Contains("a: missing"));
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":0.01},"a":1e-4,"dgama":1})"),
             Contains("unknown key 'dgama'"));
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":"big"},"a":1e-4})"),
             Contains("geometry.R") && Contains("must be a number"));
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"traction",)" + material + R"(,"geometry":{"R":0.01},"a":1e-4})"),
             Contains("quantity = 'traction'") && Contains("valid: "));
  CHECK_THAT(error_of(R"({"case":"jkr_paraboloid","quantity":"critical_force",)" + material +
                      R"(,"geometry":{"R":0.01},"dgamma":0.05,"control":"torque"})"),
             Contains("control = 'torque'"));
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"force","material":{"E0":1e9,"c0":1e-3,"k":0.5,"nu":0.3,"G":1},"geometry":{"R":0.01},"a":1e-4})"),
             Contains("material.G"));
  CHECK_THAT(error_of(R"({"case":"paraboloid","quantity":"force",)" + material + R"(,"geometry":{"R":0.01},"a":1e-4,"method":"guess"})"),
             Contains("method = 'guess'"));
}

TEST_CASE("eval answers are valid JSON with round-trip values", "[analytic]")
{
  const batch::Answer a = batch::evaluate(
    R"({"id":1,"case":"flat_punch","quantity":"force",)" + material + R"(,"a":1e-4,"d":1e-6})");
  REQUIRE(a.ok);
  const json j = json::parse(batch::to_json(a));
  CHECK(j["value"].get<double>() == a.value); // 17 significant digits round-trip exactly
}

TEST_CASE("The batch shall name the request whose result overflows, not report an internal error", "[analytic]")
{
  // F of a paraboloid grows like E0 a^{3+k} / R: E0 = 1e307, a = 1e3 m, R = 1e-6 m is far past 1.8e308.
  const std::string request = R"({"id": 7, "case": "paraboloid", "quantity": "force", )"
                              R"("material": {"E0": 1e307, "c0": 1e-3, "k": 0.5, "nu": 0.3}, )"
                              R"("geometry": {"R": 1e-6}, "a": 1e3})";
  const batch::Answer a = batch::evaluate(request);
  CAPTURE(a.error);
  REQUIRE_FALSE(a.ok);
  CHECK_THAT(a.error, Catch::Contains("case 'paraboloid', quantity 'force'") && Catch::Contains("non-finite") &&
                        Catch::Contains("1e+307") && Catch::Contains("\"a\":1000"));
  CHECK(a.error.find("internal error") == std::string::npos);
  CHECK(a.id_json == "7");
  // The same inputs two orders of magnitude smaller evaluate to a finite force.
  const batch::Answer small = batch::evaluate(
    R"({"case": "paraboloid", "quantity": "force", "material": {"E0": 1e9, "c0": 1e-3, "k": 0.5, "nu": 0.3}, )"
    R"("geometry": {"R": 1e-2}, "a": 1e-4})");
  CHECK(small.ok);
  CHECK(std::isfinite(small.value));
  // The prepared form gives the same error.
  CHECK_THROWS_WITH(batch::prepare(batch::parse(request))(), Catch::Contains("non-finite") && Catch::Contains("paraboloid"));
}

TEST_CASE("A typed request shall give the value of its JSON line, and name an input it lacks", "[analytic]")
{
  batch::Request q;
  q.case_name = "jkr_paraboloid";
  q.quantity = "contact_radius";
  q.material = GradedHalfSpace{1e9, 1e-3, 0.5, 0.3};
  q.geometry.R = 0.01;
  q.dgamma = 0.05;
  q.F = 1e-3;
  for (const batch::Method method : {batch::Method::closed_form, batch::Method::numerical_mdr})
    {
      q.method = method;
      const std::string line = batch::to_json(q).dump();
      CAPTURE(line);
      const batch::Answer a = batch::evaluate(line);
      REQUIRE(a.ok);
      CHECK(batch::evaluate(q) == a.value);
      CHECK(batch::evaluate(batch::parse(line)) == a.value);
    }
  // The closed form and the numerical MDR agree on the stable branch.
  q.method = batch::Method::closed_form;
  const double closed = batch::evaluate(q);
  q.method = batch::Method::numerical_mdr;
  CHECK_THAT(batch::evaluate(q), Catch::Matchers::WithinRel(closed, 1e-9));
  q.geometry.R.reset();
  CHECK_THROWS_WITH(batch::evaluate(q), Contains("geometry.R: missing") && Contains("jkr_paraboloid"));
  q.geometry.R = 0.01;
  q.F.reset();
  q.control = Control::force;
  q.quantity = "critical_force";
  q.method = batch::Method::closed_form;
  CHECK(batch::evaluate(q) < 0.);
  q.control.reset();
  CHECK_THROWS_WITH(batch::evaluate(q), Contains("control: missing"));
}

TEST_CASE("eval names the valid choices of a mistyped branch or mechanism", "[analytic]")
{
  const batch::Answer a = batch::evaluate(
    R"({"case":"oscillating_sphere","quantity":"traction",)" + material +
    R"(,"geometry":{"R":0.01},"a":1e-4,"mu":0.3,"FA":1e-3,"Fx":0,"r":0,"branch":"sideways"})");
  REQUIRE_FALSE(a.ok);
  CHECK_THAT(a.error, Contains("branch = 'sideways'") && Contains("unloading"));
}

TEST_CASE("eval takes the adhesive's range (h0 or z0) for the Tabor parameter of maugis_dugdale", "[analytic][quick]")
{
  // k = 0, E* = E0 / (1 - nu^2). Tabor's mu = (R dgamma^2 / (E*^2 z0^3))^(1/3), and Maugis's lambda = 1.1570 mu for
  // the Dugdale stress matched to the Lennard-Jones law's largest stress (Maugis 1992; Johnson and Greenwood, J.
  // Colloid Interface Sci. 192 (1997) 326, where the factor is quoted as 1.16).
  const double E0 = 1e9, nu = 0.3, R = 1e-3, dgamma = 0.05, z0 = 3e-10;
  const std::string base = R"({"case":"maugis_dugdale","quantity":"tabor_parameter","material":{"E0":1e9,"c0":1e-3,"k":0,"nu":0.3},"geometry":{"R":1e-3},"dgamma":0.05,)";
  const auto value = [](const std::string &line) {
    const batch::Answer a = batch::evaluate(line);
    INFO(batch::to_json(a));
    REQUIRE(a.ok);
    return a.value;
  };
  const double E_star = E0 / (1 - nu * nu);
  const double mu     = std::cbrt(R * dgamma * dgamma / (E_star * E_star * z0 * z0 * z0));
  CHECK_THAT(value(base + R"("z0":3e-10})"), Catch::Matchers::WithinRel(1.1570 * mu, 1e-4));
  // The Dugdale range h0: sigma_0 h0 = dgamma.
  CHECK_THAT(value(base + R"("h0":2e-10})"), Catch::Matchers::WithinRel(value(base + R"("sigma_th":2.5e8})"), 1e-14));
  const auto error = [](const std::string &line) {
    const batch::Answer a = batch::evaluate(line);
    REQUIRE_FALSE(a.ok);
    return a.error;
  };
  CHECK_THAT(error(base + R"("z0":3e-10,"h0":2e-10})"), Contains("not both"));
  CHECK_THAT(error(base + R"("z0":3e-10,"sigma_th":1e8})"), Contains("sigma_th") && Contains("not both"));
  CHECK_THAT(error(base + R"("z0":-1})"), Contains("z0") && Contains("-1"));
  CHECK_THAT(error(R"({"case":"jkr_concave","quantity":"critical_force","h0":1e-9})"), Contains("'maugis_dugdale' only"));
}
