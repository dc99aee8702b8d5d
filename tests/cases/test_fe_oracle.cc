// The FE model as an eval oracle (cases/tools/fe_oracle.h): its answers against the closed forms of the chapter
// (analytic/, an independent path), its reuse of one unit state across materials, radii and profiles by the
// scaling of the header, and its refusals.
#include <cases/tools/fe_oracle.h>

#include <analytic/batch.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>
#include <string>

using namespace gradcontact;
using namespace gradcontact::cases;
using json = nlohmann::json;
using Catch::Matchers::Contains;

namespace
{
  json paraboloid(const std::string &quantity, const double E0, const double c0, const double k, const double a,
                  const double R)
  {
    return {{"case", "paraboloid"},
            {"quantity", quantity},
            {"material", {{"E0", E0}, {"c0", c0}, {"k", k}, {"nu", 0.3}}},
            {"geometry", {{"R", R}}},
            {"a", a}};
  }

  double closed_form(const json &request) { return batch::evaluate(batch::parse(request)); }

  json with_fe(json request, const double tolerance)
  {
    request["method"] = "fe";
    request["tolerance"] = tolerance;
    return request;
  }
} // namespace

TEST_CASE("The FE oracle shall answer force, depth, pressure and displacement within its tolerance, one unit "
          "state serving every material, radius and paraboloid",
          "[cases]")
{
  const double k = GENERATE(-0.5, 0.5);
  CAPTURE(k);
  FeOracle oracle;
  // Two materials, radii and profiles of the same (k, nu): one FE state (the scaling of the header).
  for (const auto &[E0, c0, a, R] : {std::tuple{1e9, 1e-3, 1e-4, 1e-2}, std::tuple{3e7, 2e-2, 7e-3, 0.4}})
    for (const auto &[quantity, r] : {std::pair{"force", 0.}, std::pair{"depth", 0.}, std::pair{"pressure", 0.5},
                                      std::pair{"displacement", 2.}})
      {
        json request = paraboloid(quantity, E0, c0, k, a, R);
        if (r > 0)
          request["r"] = r * a;
        CAPTURE(request.dump());
        const FeOracle::Answer fe = oracle.evaluate(with_fe(request, 1e-5));
        const double exact = closed_form(request);
        const double error = std::abs(fe.value - exact) / std::abs(exact);
        // The contract (fem/accuracy/accuracy.h): the answer within the tolerance asked, its estimate within it too.
        CHECK(error < 1e-5);
        CHECK(fe.relative_error_estimate <= 1e-4);
        CHECK(fe.error_estimate > 0);
        // The estimate bounds the true error within 3x, except w(r) at k > 0: the surface map's discretisation leaves
        // it an error that uniform refinement does not reduce, near this tolerance, which the ladder cannot see (the
        // accuracy bench reports it).
        if (!(std::string(quantity) == "displacement" && k > 0))
          CHECK(error <= 3 * fe.error_estimate / std::abs(exact));
        CHECK(fe.dofs > 0);
      }
  CHECK(oracle.states_solved() == 1);
  CHECK(oracle.requests() == 8);
  // Outside the contact the pressure is exactly 0.
  json outside = paraboloid("pressure", 1e9, 1e-3, k, 1e-4, 1e-2);
  outside["r"] = 2e-4;
  CHECK(oracle.evaluate(with_fe(outside, 1e-5)).value == 0);
}

TEST_CASE("The FE oracle shall refuse what it cannot answer, naming the entry, its value and the valid range",
          "[cases][quick]")
{
  FeOracle oracle;
  const json good = paraboloid("force", 1e9, 1e-3, 0, 1e-4, 1e-2);
  const auto refused = [&](json request) {
    try
      {
        oracle.evaluate(with_fe(std::move(request), 1e-5));
      }
    catch (const std::exception &e)
      {
        return std::string(e.what());
      }
    return std::string("not refused");
  };
  json cone_without_slope = good;
  cone_without_slope["case"] = "cone";
  CHECK_THAT(refused(cone_without_slope), Contains("geometry.tan_theta: missing"));
  json adhesive = good;
  adhesive["case"] = "jkr_paraboloid";
  CHECK_THAT(refused(adhesive), Contains("case = 'jkr_paraboloid'") && Contains("flat_punch, paraboloid, cone, power_law"));
  json beta = good;
  beta["quantity"] = "beta";
  CHECK_THAT(refused(beta), Contains("quantity = 'beta'") && Contains("force, depth, pressure, displacement"));
  json no_radius = good;
  no_radius.erase("a");
  CHECK_THAT(refused(no_radius), Contains("a: missing"));
  json tight = with_fe(good, 1e-12);
  CHECK_THROWS_WITH(oracle.evaluate(tight), Contains("tolerance = 1e-12") && Contains("[1e-8, 1e-2]"));
  json two_bodies = good;
  two_bodies["material2"] = good["material"];
  CHECK_THAT(refused(two_bodies), Contains("material2"));
  json bad_k = good;
  bad_k["material"]["k"] = 1.5;
  CHECK_THAT(refused(bad_k), Contains("k") && Contains("1.5"));
  json punch_depth = good;
  punch_depth["case"] = "flat_punch";
  punch_depth["quantity"] = "depth";
  punch_depth["d"] = 1e-6;
  CHECK_THAT(refused(punch_depth), Contains("depth") && Contains("input d"));
  json cone_tip = good;
  cone_tip["case"] = "cone";
  cone_tip["geometry"] = {{"tan_theta", 0.1}};
  cone_tip["quantity"] = "pressure";
  cone_tip["r"] = 0.;
  CHECK_THAT(refused(cone_tip), Contains("r = 0") && Contains("n + k = 1"));
  CHECK(oracle.states_solved() == 0); // every refusal before any solve
}

TEST_CASE("gradcontact eval shall answer FE and closed-form requests in order, with ids and errors", "[cases][quick]")
{
  json fe = with_fe(paraboloid("force", 1e9, 1e-3, 0, 1e-4, 1e-2), 1e-5);
  fe["id"] = "fe";
  json closed = paraboloid("force", 1e9, 1e-3, 0, 1e-4, 1e-2);
  closed["id"] = 2;
  json bad = with_fe(paraboloid("force", 1e9, 1e-3, 0, -1e-4, 1e-2), 1e-5);
  bad["id"] = 3;
  std::istringstream in(fe.dump() + "\n\n" + closed.dump() + "\n" + bad.dump() + "\nnot json\n");
  std::ostringstream out;
  FeOracle oracle;
  CHECK(evaluate_stream(in, out, oracle) == 2);
  std::istringstream lines(out.str());
  std::string line;
  std::vector<json> answers;
  while (std::getline(lines, line))
    answers.push_back(json::parse(line));
  REQUIRE(answers.size() == 4);
  CHECK(answers[0]["id"] == "fe");
  CHECK(answers[0].contains("error_estimate"));
  CHECK(std::abs(answers[0]["value"].get<double>() / answers[1]["value"].get<double>() - 1) < 1e-5);
  CHECK(answers[1]["id"] == 2);
  CHECK_FALSE(answers[1].contains("error_estimate"));
  CHECK(answers[2]["id"] == 3);
  CHECK_THAT(answers[2]["error"].get<std::string>(), Contains("a = -0.0001"));
  CHECK(answers[3].contains("error"));
}

TEST_CASE("A tolerance the FE cannot reach shall be refused with the limit that stops it, not answered", "[cases]")
{
  // nu = 1/2 at k = -0.9, asked 1e-8: the stiff skin's round-off keeps the levels' changes far above that
  // (fem/README.md, "Accuracy contract"), and the ladder stops at a budget or on changes that do not fall.
  FeOracle oracle;
  json request = paraboloid("force", 1e9, 1e-3, -0.9, 1e-4, 1e-2);
  request["material"]["nu"] = 0.5;
  CHECK_THROWS_WITH(oracle.evaluate(with_fe(request, 1e-8)),
                    Contains("does not reach tolerance 1e-08") &&
                      (Contains("budget") || Contains("no convergence") || Contains("levels")));
}

TEST_CASE("gradcontact eval shall give the same answers line by line as from the whole input", "[cases][quick]")
{
  std::string input;
  for (const double r : {0.0, 0.5})
    {
      json p = with_fe(paraboloid("pressure", 1e9, 1e-3, 0, 1e-4, 1e-2), 1e-3);
      p["r"] = r * 1e-4;
      p["id"] = r;
      input += p.dump() + "\n";
    }
  json force = with_fe(paraboloid("force", 1e9, 1e-3, 0, 1e-4, 1e-2), 1e-3);
  force["id"] = "F";
  input += force.dump() + "\nnot json\n";
  std::vector<std::vector<json>> answers;
  for (const EvalReading reading : {EvalReading::per_line, EvalReading::whole_input})
    {
      std::istringstream in(input);
      std::ostringstream out;
      FeOracle           oracle;
      CHECK(evaluate_stream(in, out, oracle, reading) == 1);
      std::istringstream lines(out.str());
      answers.emplace_back();
      for (std::string line; std::getline(lines, line);)
        answers.back().push_back(json::parse(line));
    }
  REQUIRE(answers[0].size() == 4);
  REQUIRE(answers[1].size() == 4);
  // Both readings within the asked tolerance of the same limit: p relative to the largest |p| sampled (p(0)).
  const auto value = [&](const std::size_t reading, const std::size_t i) { return answers[reading][i]["value"].get<double>(); };
  for (std::size_t i = 0; i < 3; ++i)
    {
      CAPTURE(i, answers[0][i].dump(), answers[1][i].dump());
      CHECK(answers[0][i]["id"] == answers[1][i]["id"]);
      CHECK(answers[0][i]["formulation"] == "displacement");
      const double scale = std::abs(value(1, i < 2 ? 0 : 2));
      CHECK(std::abs(value(0, i) - value(1, i)) <= 2e-3 * scale);
    }
  CHECK(answers[0][3].contains("error"));
}



TEST_CASE("The FE oracle shall answer stresses and the largest shear within their estimates, and refuse what has none",
          "[cases]")
{
  // The paraboloid at k = 0.5 (the surface map's layer) and its stresses: a component, a measure whose estimate is
  // carried from the components', the largest shear and its depth, against the closed-form superposition.
  FeOracle   oracle;
  const json base = paraboloid("stress", 1e9, 1e-3, 0.5, 1e-4, 1e-2);
  const auto at   = [&](const char *component, const double r, const double z) {
    json q         = base;
    q["component"] = component;
    q["r"]         = r;
    q["z"]         = z;
    return q;
  };
  for (const json &q : {at("zz", 0, 0.5e-4), at("rr", 1.2e-4, 1e-6), at("von_mises", 0.5e-4, 0.3e-4)})
    {
      const FeOracle::Answer fe = oracle.evaluate(with_fe(q, 1e-4));
      const double           cf = closed_form(q);
      CAPTURE(q.dump(), fe.value, cf, fe.error_estimate);
      CHECK(fe.relative_error_estimate <= 1e-4);
      CHECK(std::abs(fe.value - cf) <= 3 * fe.error_estimate);
    }
  for (const char *quantity : {"max_stress", "max_stress_depth"})
    {
      json q         = base;
      q["quantity"]  = quantity;
      q["component"] = "max_shear";
      const FeOracle::Answer fe = oracle.evaluate(with_fe(q, 1e-4));
      const double           cf = closed_form(q);
      CAPTURE(quantity, fe.value, cf, fe.error_estimate);
      CHECK(std::abs(fe.value - cf) <= 3 * fe.error_estimate);
    }
  json bad = at("rr", 0, 0);
  CHECK_THROWS_WITH(oracle.evaluate(with_fe(bad, 1e-5)), Contains("z = 0; valid: (0, inf)"));
  bad              = base;
  bad["quantity"]  = "max_stress";
  bad["component"] = "rr";
  CHECK_THROWS_WITH(oracle.evaluate(with_fe(bad, 1e-5)), Contains("valid: von_mises, max_shear"));
  bad["component"]        = "von_mises";
  bad["material"]["k"]    = -0.3;
  CHECK_THROWS_WITH(oracle.evaluate(with_fe(bad, 1e-5)), Contains("valid: k >= 0"));
}
