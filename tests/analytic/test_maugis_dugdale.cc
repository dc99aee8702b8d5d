// The Maugis-Dugdale reference (analytic/maugis_dugdale.h) against its two classical limits, which are
// written out here: JKR (Johnson, Kendall, Roberts 1971) for lambda -> inf, P = A^3 - sqrt(6 A^3) with the
// pull-offs -3/2 (force) and -5/6 (displacement, F = -5/6 pi dgamma R), and DMT (Derjaguin, Muller, Toporov
// 1975) for lambda -> 0, P = -2 at pull-off.
#include <analytic/batch.h>
#include <analytic/errors.h>
#include <analytic/adhesion.h>
#include <analytic/maugis_dugdale.h>
#include <analytic/mdr.h>
#include <analytic/normal.h>

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
  // Displacement control at small lambda has no jump.
  CHECK_THROWS_WITH(eval("critical_depth", small, "displacement"),
                    Catch::Contains("control = displacement") && Catch::Contains("no jump"));
  // A graded medium: the MDR solution, at large sigma_th the chapter's JKR pull-off (9.55-9.56), and its Tabor
  // parameter C Delta_l(a_c) / h_0 written out (Delta_l of 9.45 at the JKR radius a_c).
  nlohmann::json graded = request("critical_force", 1e4 * large, "force");
  graded["material"]["k"] = 0.5;
  const auto medium = gradcontact::medium(gradcontact::GradedHalfSpace{E, 1e-3, 0.5, nu});
  const auto jkr    = gradcontact::jkr::critical_state(medium, gradcontact::Paraboloid{R}, dgamma, Control::force);
  CHECK_THAT(batch::evaluate(batch::parse(graded)), WithinRel(jkr.force, 1e-4));
  graded["quantity"] = "tabor_parameter";
  const double C     = std::cbrt((9 / (2 * pi)) / (std::pow(2 * pi, 1.5) * std::sqrt(9 * pi / 8)));
  CHECK_THAT(batch::evaluate(batch::parse(graded)),
             WithinRel(C * gradcontact::jkr::delta_ell(medium, dgamma, jkr.radius) * 1e4 * large / dgamma, 1e-13));
  CHECK_THROWS_WITH(eval("critical_force", -1.0), Catch::Contains("sigma_th = -1"));
  CHECK_THROWS_WITH(eval("critical_force", 2e3 / unit), Catch::Contains("sigma_th") && Catch::Contains("[1e-3, 1e3]"));
}

// The graded half-space (the MDR solution of maugis_dugdale.h) against paths that share none of its algebra:
// Maugis' closed form at k = 0, the numerical MDR engine (mdr.h: the zone's foundation from its pressure by 9.13,
// the gap and the force of the whole foundation by 9.11-9.12), the chapter's JKR (9.53-9.56, 9.58-9.61) at large
// sigma_0, and the rigid limit (DMT: -2 pi dgamma R) at small sigma_0.
namespace
{
  constexpr double E0 = 1e9, c0 = 1e-3, nu = 0.3, R = 5e-3, dgamma = 0.05;
  gradcontact::Medium graded(const double k) { return gradcontact::medium(gradcontact::GradedHalfSpace{E0, c0, k, nu}); }
  /// sigma_0 of Maugis' lambda on E* = E0 / (1 - nu^2) (the k = 0 Tabor parameter, used here as a scale only).
  double strength(const double lambda)
  {
    const double E_star = E0 / (1 - nu * nu);
    return lambda / std::cbrt(9 * R / (2 * pi * dgamma * E_star * E_star));
  }
} // namespace

TEST_CASE("Maugis-Dugdale on a graded medium: at k = 0 it is Maugis' closed form", "[analytic]")
{
  const double E_star = E0 / (1 - nu * nu);
  const auto   sc     = md::scales(dgamma, R, E_star);
  for (const double lambda : {0.05, 0.3, 1.0, 3.0, 30.0})
    {
      const md::Dugdale law{strength(lambda), dgamma};
      for (const double A : {0.05, 0.5, 1.0, 2.0})
        {
          const auto ref = md::state(lambda, A);
          const auto s   = md::state(graded(0), gradcontact::Paraboloid{R}, law, A * sc.length);
          CHECK_THAT(s.zone_radius / s.radius, WithinRel(ref.m, 1e-12));
          CHECK_THAT(s.force, WithinRel(ref.P * sc.force, 1e-12));
          CHECK_THAT(s.depth, WithinAbs(ref.Delta * sc.depth, 1e-12 * sc.depth));
        }
      const auto end = md::vanishing_contact(graded(0), gradcontact::PowerLaw{2, 1 / (2 * R)}, law);
      CHECK_THAT(end.zone_radius, WithinRel(md::vanishing_contact(lambda).zone * sc.length, 1e-12));
      CHECK_THAT(end.force, WithinRel(md::vanishing_contact(lambda).P * sc.force, 1e-12));
      for (const Control control : {Control::force, Control::displacement})
        {
          const auto ref = md::pull_off(lambda, control);
          const auto p   = md::pull_off(graded(0), gradcontact::Paraboloid{R}, law, control);
          REQUIRE(p.exists == ref.exists);
          CHECK(p.at_vanishing_contact == ref.at_vanishing_contact);
          // The minimum's value: F under force control, d under displacement control (F moves with its location).
          if (ref.exists && control == Control::force)
            CHECK_THAT(p.state.force, WithinRel(ref.state.P * sc.force, 1e-12));
          if (ref.exists && control == Control::displacement)
            CHECK_THAT(p.state.depth, WithinRel(ref.state.Delta * sc.depth, 1e-12));
        }
    }
}

TEST_CASE("Maugis-Dugdale on a graded medium: its zone, gap and force are those of the numerical MDR", "[analytic]")
{
  namespace mdr = gradcontact::mdr;
  // (The engine's quadrature of w(c) at k = 0.7 is good to 1e-5 only: the end point's power -k.)
  for (const double k : {-0.5, 0.3, 0.5})
    for (const double n : {2.0, 4.0})
      {
        const auto   m = graded(k);
        const double A = n == 2 ? 1 / (2 * R) : 2e9;
        const gradcontact::PowerLaw profile{n, A};
        const double a_jkr = gradcontact::jkr::critical_state(m, profile, dgamma, Control::force).radius;
        const md::Dugdale law{strength(1.0) * std::pow(a_jkr / c0, k), dgamma};
        const auto   s = md::state(m, profile, law, 0.8 * a_jkr);
        const double a = s.radius, c = s.zone_radius;
        INFO("k = " << k << ", n = " << n << ", c / a = " << c / a);
        REQUIRE(c > a);
        // The zone's foundation is that of the tension sigma_0 on r < c (9.13 by quadrature), at x > a.
        const auto tension = mdr::from_pressure([&](double) { return -law.sigma0; }, m, c);
        const auto zone    = [&](const double x) { return tension.w(x); };
        // The whole foundation: the indentation on x < a, the zone beyond, continuous at a.
        const double      kappa = gradcontact::kappa(n, k);
        mdr::Foundation   whole;
        whole.a  = c;
        whole.w  = [&](const double x) { return x < a ? s.depth - kappa * A * std::pow(x, n) : zone(x); };
        whole.gauss_jacobi  = false;
        whole.edge_exponent = tension.edge_exponent; // (1-k)/2 at c
        whole.edge_free     = [&](const double x) {
          return x < a ? whole.w(x) / std::pow(c * c - x * x, whole.edge_exponent) : tension.edge_free(x);
        };
        CHECK_THAT(s.depth - kappa * A * std::pow(a, n), WithinRel(zone(a), 1e-9));
        // The gap at c is h_0, and the force is 9.11 of the whole foundation.
        const double gap = A * std::pow(c, n) - s.depth + mdr::displacement(whole, m, c);
        CHECK_THAT(gap, WithinRel(dgamma / law.sigma0, 1e-6));
        CHECK_THAT(mdr::force_nested(whole, m), WithinRel(s.force, 1e-8));
      }
}

TEST_CASE("Maugis-Dugdale on a graded medium tends to the chapter's JKR at large sigma_0 and to DMT at small",
          "[analytic]")
{
  for (const double k : {-0.5, 0.5})
    {
      const auto m = graded(k);
      // JKR: the state at a given radius (9.53-9.54) and the pull-offs (9.55-9.56), for the paraboloid and n = 4.
      const gradcontact::Paraboloid sphere{R};
      const double a_jkr = gradcontact::jkr::critical_state(m, sphere, dgamma, Control::force).radius;
      double previous = 1;
      for (const double lambda : {10.0, 100.0, 1000.0})
        {
          const md::Dugdale law{strength(lambda) * std::pow(a_jkr / c0, k), dgamma};
          const auto        s = md::state(m, sphere, law, a_jkr);
          const double      deviation =
            std::abs(s.force / gradcontact::jkr::force(m, sphere, dgamma, a_jkr) - 1) +
            std::abs(s.depth / gradcontact::jkr::depth(m, sphere, dgamma, a_jkr) - 1);
          CHECK(deviation < previous / 5);
          previous = deviation;
        }
      CHECK(previous < 1e-3);
      const md::Dugdale strong{strength(1000) * std::pow(a_jkr / c0, k), dgamma};
      for (const Control control : {Control::force, Control::displacement})
        {
          const auto ref = gradcontact::jkr::critical_state(m, sphere, dgamma, control);
          const auto p   = md::pull_off(m, sphere, strong, control);
          REQUIRE(p.exists);
          CHECK_THAT(p.state.force, WithinRel(ref.force, 2e-3));
          CHECK_THAT(p.state.depth, WithinRel(ref.depth, 2e-3));
          CHECK_THAT(p.state.radius, WithinRel(ref.radius, 2e-3));
        }
      const gradcontact::PowerLaw tip{4, 2e9};
      const double a_tip = gradcontact::jkr::critical_state(m, tip, dgamma, Control::force).radius;
      const auto ref = gradcontact::jkr::critical_state(m, tip, dgamma, Control::force);
      CHECK_THAT(md::pull_off(m, tip, md::Dugdale{strength(1000) * std::pow(a_tip / c0, k), dgamma}, Control::force).state.force,
                 WithinRel(ref.force, 2e-3));
      // DMT: a rigid sphere's -2 pi dgamma R whatever k; no jump under displacement control.
      const md::Dugdale weak{strength(1e-3) * std::pow(a_jkr / c0, k), dgamma};
      CHECK_THAT(md::pull_off(m, sphere, weak, Control::force).state.force, WithinRel(-2 * pi * dgamma * R, 2e-3));
      CHECK_FALSE(md::pull_off(m, sphere, weak, Control::displacement).exists);
      // The vanishing contact: the tension sigma_0 on the disc c (its resultant), whose centre is lifted as the
      // chapter's uniform pressure -sigma_0 lowers it (9.39, normal.h).
      const auto end = md::vanishing_contact(m, gradcontact::PowerLaw{2, 1 / (2 * R)}, weak);
      CHECK_THAT(end.force, WithinRel(-pi * end.zone_radius * end.zone_radius * weak.sigma0, 1e-14));
      CHECK_THAT(end.depth, WithinRel(gradcontact::centre_displacement(
                                        m, gradcontact::UniformPressure{end.zone_radius, -weak.sigma0}),
                                      1e-13));
    }
}

TEST_CASE("Maugis-Dugdale on a graded medium: bad input names the parameter", "[analytic]")
{
  const auto m = graded(0.5);
  CHECK_THROWS_WITH(md::state(m, gradcontact::Paraboloid{R}, md::Dugdale{0, dgamma}, 1e-5), Catch::Contains("sigma0 = 0"));
  CHECK_THROWS_WITH(md::state(m, gradcontact::Paraboloid{R}, md::Dugdale{1e6, -1}, 1e-5), Catch::Contains("dgamma = -1"));
  CHECK_THROWS_WITH(md::state(m, gradcontact::Paraboloid{R}, md::Dugdale{1e6, dgamma}, std::nan("")), Catch::Contains("a = nan"));
  CHECK_THROWS_WITH(md::pull_off(m, gradcontact::PowerLaw{0.2, 1}, md::Dugdale{1e6, dgamma}, Control::force),
                    Catch::Contains("n = 0.2") && Catch::Contains("2n + k - 1"));
  gradcontact::Medium bad = m;
  bad.k = 1.5;
  CHECK_THROWS_WITH(md::state(bad, gradcontact::Paraboloid{R}, md::Dugdale{1e6, dgamma}, 1e-5), Catch::Contains("k = 1.5"));
}

TEST_CASE("The graded Tabor parameter is Maugis' at k = 0 and strength() inverts it", "[analytic]")
{
  // Maugis: lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^{1/3}, which knows nothing of the chapter's Delta_l.
  const double E_star = E0 / (1 - nu * nu);
  for (const double lambda : {0.05, 1.0, 10.0})
    CHECK_THAT(md::tabor_parameter(graded(0), gradcontact::Paraboloid{R}, md::Dugdale{strength(lambda), dgamma}),
               WithinRel(md::tabor_parameter(strength(lambda), dgamma, R, E_star), 1e-13));
  for (const double k : {-0.5, 0.5})
    {
      const gradcontact::PowerLaw tip{4, 2e9};
      const double sigma0 = md::strength(graded(k), tip, dgamma, 3.0);
      CHECK_THAT(md::tabor_parameter(graded(k), tip, md::Dugdale{sigma0, dgamma}), WithinRel(3.0, 1e-14));
    }
  CHECK_THROWS_WITH(md::strength(graded(0), gradcontact::Paraboloid{R}, dgamma, -1), Catch::Contains("lambda = -1"));
  CHECK_THROWS_WITH(md::strength(graded(0), gradcontact::PowerLaw{0.4, 1}, dgamma, 1), Catch::Contains("n = 0.4"));
}
