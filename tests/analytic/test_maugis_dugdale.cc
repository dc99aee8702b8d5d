// The Maugis-Dugdale reference (analytic/maugis_dugdale.h) against its two classical limits, which are
// written out here: JKR (Johnson, Kendall, Roberts 1971) for lambda -> inf, P = A^3 - sqrt(6 A^3) with the
// pull-offs -3/2 (force) and -5/6 (displacement, F = -5/6 pi dgamma R), and DMT (Derjaguin, Muller, Toporov
// 1975) for lambda -> 0, P = -2 at pull-off.
#include <analytic/batch.h>
#include <analytic/errors.h>
#include <analytic/maugis_dugdale.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace md = gradcontact::maugis_dugdale;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using gradcontact::Control;
namespace batch = gradcontact::batch;
namespace
{
  constexpr double pi = 3.14159265358979323846;
}

TEST_CASE("Maugis-Dugdale at large lambda is JKR", "[analytic]")
{
  // The contact branch: the MD correction falls like 1/lambda^(2/3) or faster; at lambda = 1000 below 1e-3.
  for (const double A : {0.5, 1.0, 1.5})
    CHECK_THAT(md::state(1000, A).P, WithinAbs(A * A * A - std::sqrt(6 * A * A * A), 2e-3));
  const auto force = md::pull_off(1000, Control::force);
  CHECK_THAT(force.state.P, WithinRel(-1.5, 1e-3));
  CHECK_THAT(force.state.A, WithinRel(std::cbrt(1.5), 2e-3)); // A_c^3 = 3/2
  const auto disp = md::pull_off(1000, Control::displacement);
  REQUIRE(disp.exists);
  CHECK_THAT(disp.state.P, WithinRel(-5.0 / 6, 2e-3));
  // The error falls with lambda.
  CHECK(std::abs(md::pull_off(100, Control::force).state.P + 1.5) >
        std::abs(md::pull_off(1000, Control::force).state.P + 1.5));
}

TEST_CASE("Maugis-Dugdale at small lambda is DMT", "[analytic]")
{
  CHECK_THAT(md::pull_off(1e-3, Control::force).state.P, WithinRel(-2.0, 1e-3));
  CHECK(std::abs(md::pull_off(0.01, Control::force).state.P + 2) <
        std::abs(md::pull_off(0.1, Control::force).state.P + 2));
  // No jump under displacement control: the contact shrinks to nothing.
  CHECK_FALSE(md::pull_off(1e-3, Control::displacement).exists);
  // The vanishing contact is the A -> 0 end of the branch.
  for (const double lambda : {0.1, 1.0})
    {
      const auto end = md::vanishing_contact(lambda);
      const auto s   = md::state(lambda, 1e-7);
      CHECK_THAT(s.P, WithinRel(end.P, 1e-5));
      CHECK_THAT(s.zone, WithinRel(end.zone, 1e-5));
    }
  // Force control: the pull-off lies between DMT and JKR, monotone in lambda.
  double previous = -2;
  for (const double lambda : {0.05, 0.2, 0.5, 1.0, 2.0, 5.0})
    {
      const double P = md::pull_off(lambda, Control::force).state.P;
      CHECK(P > previous);
      CHECK(P < -1.5);
      previous = P;
    }
}

TEST_CASE("Maugis-Dugdale: bad input names the parameter", "[analytic]")
{
  CHECK_THROWS_WITH(md::pull_off(0, Control::force), Catch::Contains("lambda = 0"));
  CHECK_THROWS_WITH(md::pull_off(1e4, Control::force), Catch::Contains("[1e-3, 1e3]"));
  CHECK_THROWS_WITH(md::state(1, -1), Catch::Contains("A = -1"));
  CHECK_THROWS_AS(md::tabor_parameter(1, std::nan(""), 1, 1), gradcontact::DomainError);
}

TEST_CASE("The maugis_dugdale eval case shall give Maugis' pull-off in SI units, JKR and DMT at its ends",
          "[analytic]")
{
  // Its two limits written out here: JKR (Johnson, Kendall, Roberts 1971) for a rigid sphere on E* = E/(1 - nu^2),
  // F_c = -3/2 pi dgamma R and a_c = (9 pi dgamma R^2 / (8 E*))^{1/3} under force control; DMT (Derjaguin, Muller,
  // Toporov 1975) F_c = -2 pi dgamma R.
  const double E = 1e9, nu = 0.3, R = 5e-3, dgamma = 0.05, E_star = E / (1 - nu * nu);
  const auto request = [&](const std::string &quantity, const double sigma, const std::string &control) {
    return nlohmann::json{{"case", "maugis_dugdale"},
                          {"quantity", quantity},
                          {"material", {{"E0", E}, {"c0", 1e-3}, {"k", 0}, {"nu", nu}}},
                          {"geometry", {{"R", R}}},
                          {"dgamma", dgamma},
                          {"sigma_th", sigma},
                          {"control", control}};
  };
  const auto eval = [&](const std::string &quantity, const double sigma, const std::string &control = "force") {
    return batch::evaluate(batch::parse(request(quantity, sigma, control)));
  };
  // lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^{1/3}: sigma_0 of lambda = 1000 and 1e-3
  const double unit = std::cbrt(9 * R / (2 * pi * dgamma * E_star * E_star));
  CHECK_THAT(eval("tabor_parameter", 2e7), WithinRel(2e7 * unit, 1e-14));
  const double large = 1000 / unit, small = 1.0001e-3 / unit;
  CHECK_THAT(eval("critical_force", large), WithinRel(-1.5 * pi * dgamma * R, 1e-3));
  CHECK_THAT(eval("critical_radius", large), WithinRel(std::cbrt(9 * pi * dgamma * R * R / (8 * E_star)), 2e-3));
  CHECK_THAT(eval("critical_force", small), WithinRel(-2 * pi * dgamma * R, 1e-3));
  // Displacement control at small lambda has no jump; a graded medium is not Maugis'.
  CHECK_THROWS_WITH(eval("critical_depth", small, "displacement"),
                    Catch::Contains("control = displacement") && Catch::Contains("no jump"));
  nlohmann::json graded = request("critical_force", large, "force");
  graded["material"]["k"] = 0.5;
  CHECK_THROWS_WITH(batch::evaluate(batch::parse(graded)), Catch::Contains("material.k = 0.5") && Catch::Contains("0"));
  CHECK_THROWS_WITH(eval("critical_force", -1.0), Catch::Contains("sigma_th = -1"));
  CHECK_THROWS_WITH(eval("critical_force", 2e3 / unit), Catch::Contains("sigma_th") && Catch::Contains("[1e-3, 1e3]"));
}
