// The accuracy contract of fem/accuracy/accuracy.h: the Richardson estimate on known sequences, the choice of ladder and its
// levels, the ladders against the classical (k = 0) closed forms of Hertz and Boussinesq (independent of the graded
// chapter and of the MDR) and, on a stiff surface, against the chapter's paraboloid as typed from the text
// (written_out.h), the rounding probe, their refusals and input checks.
#include <fem/accuracy/accuracy.h>
#include <fem/modulus/modulus.h>

#include "written_out.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace gradcontact::fem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace
{
  /// q_l = 1 + c rho^l for l = 0 .. n - 1: the exact error of the last is c rho^(n-1).
  std::vector<double> geometric(const double c, const double rho, const unsigned int n)
  {
    std::vector<double> v;
    for (unsigned int l = 0; l < n; ++l)
      v.push_back(1 + c * std::pow(rho, l));
    return v;
  }
} // namespace

TEST_CASE("The Richardson estimate shall equal the tail of a geometric sequence whose ratio it observes, and bound "
          "it where the ratio is faster than assumed",
          "[fem][quick]")
{
  const double c = 1e-3;
  for (const double rho : {0.3, 0.6})
    {
      CAPTURE(rho);
      const std::vector<double> v = geometric(c, rho, 4);
      const Estimated           e = estimate(v, 0.25, 1.0);
      CHECK_THAT(e.ratio, WithinRel(rho, 1e-9));
      CHECK_THAT(e.error, WithinRel(c * std::pow(rho, 3), 1e-9));
    }
  // Faster than the assumed 0.25: the estimate stays above the tail, within the efficiency asked (10x).
  const std::vector<double> fast = geometric(c, 0.1, 3);
  const Estimated           e    = estimate(fast, 0.25, 1.0);
  const double              tail = c * 0.01;
  CHECK(e.error >= tail);
  CHECK(e.error <= 10 * tail);
  // Two levels: the assumed ratio.
  CHECK_THAT(estimate({1.1, 1.01}, 0.25, 1.0).error, WithinRel(0.09 / 3, 1e-9));
  // One level: no estimate.
  CHECK(std::isinf(estimate({1.0}, 0.25, 1.0).error));
}

TEST_CASE("A change between two levels that is near zero by accident shall not pass for convergence", "[fem][quick]")
{
  // Two levels on opposite sides of the limit 1: the last change is 1e-9, the one before 0.1.
  const Estimated e = estimate({1.05, 0.95, 0.950000001}, 0.25, 1.0);
  CHECK(e.error >= 0.25 * 0.25 * 0.1 * 0.99);
  // The hp ladder's smaller accident factor: a change of 1e-9 after 0.1 still counts as 4e-3 (with the ratio of
  // levels that oscillate, the changes having opposite signs).
  const Estimated hp = estimate({1.05, 0.95, 0.950000001}, hp_assumed_ratio(0.0), 1.0, hp_accident);
  CHECK_THAT(hp.error, WithinRel(hp_accident * 0.1 * oscillation_ratio / (1 - oscillation_ratio), 1e-6));
}

TEST_CASE("The ladder shall be hp where the modulus has no jumps and uniform where it has; an hp level shall raise "
          "the degree and refine the edge, the axis and the surface map's floor with it",
          "[fem][quick]")
{
  const auto power = [](const double k) { return Material{std::make_shared<PowerLawModulus>(1.0, 1.0, k), 0.3}; };
  const auto coating = [](const double k) { return Material{std::make_shared<CoatingModulus>(1.0, 1.0, k, 0.2), 0.3}; };
  CHECK(contract_ladder(power(0.0)) == Ladder::hp);
  CHECK(contract_ladder(power(0.5)) == Ladder::hp);
  CHECK(contract_ladder(power(-0.5)) == Ladder::hp);
  CHECK(contract_ladder(power(-0.95)) == Ladder::hp);
  CHECK(contract_ladder(coating(0.5)) == Ladder::uniform);
  CHECK(contract_ladder(coating(-0.5)) == Ladder::uniform);

  const Settings base = contract_settings(1.0, power(0.5), 1e-6);
  CHECK(base.discretization.degree == hp_first_degree);
  CHECK(base.discretization.surface_map.enabled);
  Settings graded = base;
  graded.mesh.axis_refinements = 12;
  const Settings two = ladder_settings(graded, Ladder::hp, 2);
  CHECK(two.discretization.degree == hp_first_degree + 2);
  CHECK(two.mesh.edge_refinements == base.mesh.edge_refinements + 2 * hp_edge_step);
  CHECK(two.mesh.axis_refinements == 12 + 2 * hp_axis_step);
  CHECK(two.mesh.global_refinements == base.mesh.global_refinements);
  // The floor of the map is the edge cell: h_edge halved by every edge refinement.
  CHECK_THAT(two.discretization.surface_map.floor,
             WithinRel(base.mesh.h_edge * std::pow(0.5, two.mesh.edge_refinements), 1e-12));
  CHECK_THROWS_WITH(ladder_settings(base, Ladder::hp, max_contract_degree), Contains("level") && Contains("degree"));

  const Settings stiff = contract_settings(1.0, coating(-0.5), 1e-6);
  const Settings one   = ladder_settings(stiff, Ladder::uniform, 1);
  CHECK(one.mesh.global_refinements == stiff.mesh.global_refinements + 1);
  CHECK(one.discretization.degree == stiff.discretization.degree);
}

TEST_CASE("The hp ladder shall refuse for no convergence only after two changes in a row that do not fall, the uniform "
          "ladder after one",
          "[fem][quick]")
{
  const double tolerance = 1e-6;
  // Changes 1e-1, 1e-2, 9e-3 (ratio 0.9), then 8.5e-3 (ratio 0.94).
  const std::vector<double> values = {1.0, 1.1, 1.11, 1.119, 1.1275};
  const auto run = [&](const Material &material, std::size_t n) {
    LadderRecord record(material, contract_settings(1.0, material, tolerance), tolerance);
    bool stopped = false;
    for (std::size_t l = 0; l < n && !stopped; ++l)
      stopped = record.add({{"force", values[l], 1, false, 1, true}}, 1000); // no growth: no DoF budget verdict
    return std::pair{stopped, record.limit()};
  };
  const Material smooth{std::make_shared<PowerLawModulus>(1.0, 1.0, 0.5), 0.3};
  REQUIRE(contract_ladder(smooth) == Ladder::hp);
  CHECK_FALSE(run(smooth, 4).first); // one change that does not fall: the next level decides
  const auto [stopped, limit] = run(smooth, 5);
  CHECK(stopped);
  CHECK_THAT(limit, Contains("no convergence") && Contains("force"));

  const Material coating{std::make_shared<CoatingModulus>(1.0, 1.0, 0.5, 0.2), 0.3};
  REQUIRE(contract_ladder(coating) == Ladder::uniform);
  const auto [uniform_stopped, uniform_limit] = run(coating, 4);
  CHECK(uniform_stopped);
  CHECK_THAT(uniform_limit, Contains("no convergence"));
}

TEST_CASE("The rounding probe shall add twice its change, the factor divided out where a quantity scales, and unmake "
          "a met ladder that it moves beyond the tolerance",
          "[fem][quick]")
{
  const Material material{std::make_shared<PowerLawModulus>(1.0, 1.0, -0.5), 0.3};
  const Settings base = contract_settings(1.0, material, 1e-3);
  // Three hp levels converging by a hundredth per level: met at 1e-3 before the probe.
  const auto levels = [&](LadderRecord &record) {
    for (const double d : {1e-3, 1e-5, 1e-7})
      record.add({{"force", 1 + d, 1, false, 1, true}, {"w(2)", 2 + 2 * d, 2, false, 2, false}}, 1000);
  };
  const double factor = rounding_probe_factor;
  LadderRecord small(material, base, 1e-3);
  levels(small);
  REQUIRE(small.met());
  const double force_tail = small.estimate(0).error, w_tail = small.estimate(1).error;
  // The force scales with the modulus, w(2) does not: changes of 1e-4 and 3e-4 once the factor is divided out.
  small.add_rounding({{"force", factor * (1 + 1e-7 + 1e-4), 1, false, 1, true},
                      {"w(2)", 2 + 2e-7 - 3e-4, 2, false, 2, false}},
                     factor);
  CHECK_THAT(small.estimate(0).error, WithinRel(force_tail + rounding_safety * 1e-4, 1e-6));
  CHECK_THAT(small.estimate(1).error, WithinRel(w_tail + rounding_safety * 3e-4, 1e-6));
  CHECK(small.met());

  LadderRecord large(material, base, 1e-3);
  levels(large);
  large.add_rounding({{"force", factor * (1 + 1e-7), 1, false, 1, true}, {"w(2)", 2 + 2e-7 + 2e-3, 2, false, 2, false}},
                     factor);
  CHECK_FALSE(large.met());
  CHECK_THAT(large.limit(), Contains("rounding") && Contains("w(2)"));
  CHECK_THROWS_WITH(large.add_rounding({{"force", 1, 1, false, 1, true}}, factor), Contains("quantities"));

  // Only a stiff surface is probed; the probe's modulus is the base's times the factor.
  CHECK(probes_rounding(material));
  CHECK_FALSE(probes_rounding(Material{std::make_shared<PowerLawModulus>(1.0, 1.0, 0.5), 0.3}));
  const ScaledModulus scaled(material.modulus, factor);
  CHECK_THAT(scaled.value(0.37), WithinRel(factor * material.modulus->value(0.37), 1e-15));
  CHECK_THAT(scaled.average(0.1, 0.4), WithinRel(factor * material.modulus->average(0.1, 0.4), 1e-15));
  CHECK(scaled.surface_exponent() == -0.5);
  CHECK_THROWS_WITH(ScaledModulus(material.modulus, 0.0), Contains("factor") && Contains("(0, inf)"));
}

TEST_CASE("The contract shall deliver the asked tolerance at k = 0 against Hertz and Boussinesq, with an estimate "
          "that bounds the true error within 3x",
          "[fem][quick]")
{
  const double nu = 0.3, E_star = 1 / (1 - nu * nu);
  Material     material{std::make_shared<PowerLawModulus>(1.0, 1.0, 0.0), nu};
  const double tolerance = 1e-3;
  ContractSolver solver(material, contract_settings(1.0, material, tolerance), tolerance);

  // Hertz (R = 1, a = 1): F = 4 E* a^3 / (3 R), d = a^2 / R. Boussinesq's flat punch: F = 2 E* a d.
  LoadCase sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(1.0);
  const ContractResult h = solver.run(sphere);
  REQUIRE(h.met);
  CHECK(h.limit.empty());
  const double force_error = std::abs(h.force.value / (4 * E_star / 3) - 1);
  const double depth_error = std::abs(h.depth.value - 1);
  CHECK(force_error <= tolerance);
  CHECK(depth_error <= tolerance);
  CHECK(force_error <= 3 * h.force.relative());
  CHECK(depth_error <= 3 * h.depth.relative());
  CHECK(h.level_dofs.size() >= 3); // the hp ladder's estimates take three levels

  LoadCase punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = 1.0;
  const ContractResult p = solver.run(punch);
  REQUIRE(p.met);
  const double punch_error = std::abs(p.force.value / (2 * E_star) - 1);
  CHECK(punch_error <= tolerance);
  CHECK(punch_error <= 3 * p.force.relative());
}

TEST_CASE("A tolerance beyond the DoF budget shall be refused, naming the budget; bad input shall name the entry",
          "[fem][quick]")
{
  Material      material{std::make_shared<PowerLawModulus>(1.0, 1.0, 0.0), 0.3};
  AccuracyBudget budget;
  budget.max_dofs = 60000;
  ContractSolver solver(material, contract_settings(1.0, material, 1e-8), 1e-8, budget);
  LoadCase       punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = 1.0;
  const ContractResult r = solver.run(punch);
  CHECK_FALSE(r.met);
  CHECK_THAT(r.limit, Contains("DoF budget") && Contains("max_dofs = 60000"));

  CHECK_THROWS_WITH(contract_settings(1.0, material, 0.0), Contains("tolerance") && Contains("[1e-9, 0.1]"));
  // Level 2's factorisation, predicted from the growth of levels 0 and 1, does not fit into the budget even alone
  // (max_factor_bytes below; the levels below give way to it first).
  AccuracyBudget memory;
  memory.max_factor_bytes = 1e6;
  ContractSolver small(material, contract_settings(1.0, material, 1e-8), 1e-8, memory);
  const ContractResult m = small.run(punch);
  CHECK_FALSE(m.met);
  CHECK_THAT(m.limit, Contains("memory budget") && Contains("level 2's factorisation") && Contains("max_factor_bytes"));
  AccuracyBudget no_memory;
  no_memory.max_factor_bytes = 0;
  CHECK_THROWS_WITH(ContractSolver(material, contract_settings(1.0, material, 1e-3), 1e-3, no_memory),
                    Contains("max_factor_bytes") && Contains("[1e6, inf)"));
  AccuracyBudget one_level;
  one_level.max_levels = 1;
  CHECK_THROWS_WITH(ContractSolver(material, contract_settings(1.0, material, 1e-3), 1e-3, one_level),
                    Contains("max_levels") && Contains("[2, 6]"));
}

TEST_CASE("The hp ladder shall deliver 1e-7 at k = 0 against Hertz and Boussinesq, the pressure and the surface "
          "displacement included, with estimates that bound the true errors within 3x",
          "[fem]")
{
  const double nu = 0.3, E_star = 1 / (1 - nu * nu);
  Material     material{std::make_shared<PowerLawModulus>(1.0, 1.0, 0.0), nu};
  const double tolerance = 1e-7;
  ContractSolver solver(material, contract_settings(1.0, material, tolerance, 2.0), tolerance);

  // Boussinesq's flat punch (a = d = 1): F = 2 E* a d; p(r) = E* d / (pi sqrt(a^2 - r^2)); outside,
  // w(r) = (2 d / pi) arcsin(a / r) (Johnson, Contact Mechanics, 1985, eqs. 3.35-3.36).
  LoadCase punch;
  punch.type  = LoadType::flat_punch;
  punch.depth = 1.0;
  OutputRequest out;
  out.pressure_radii     = {0.5};
  out.displacement_radii = {2.0};
  const ContractResult p = solver.run(punch, out);
  INFO(p.limit);
  REQUIRE(p.met);
  const double pi     = std::acos(-1.0);
  const double errors[] = {std::abs(p.force.value / (2 * E_star) - 1),
                           std::abs(p.pressure[0].value / (E_star / (pi * std::sqrt(0.75))) - 1),
                           std::abs(p.displacement[0].value / (2 / pi * std::asin(0.5)) - 1)};
  const Estimated *estimates[] = {&p.force, &p.pressure[0], &p.displacement[0]};
  for (int i = 0; i < 3; ++i)
    {
      CAPTURE(i, errors[i], estimates[i]->relative());
      // The pressure's scale is max |p| sampled, here p(0.5) itself.
      CHECK(errors[i] <= tolerance);
      CHECK(errors[i] <= 3 * estimates[i]->relative());
    }

  // Hertz (R = a = 1): F = 4 E* / 3, d = 1.
  LoadCase sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(1.0);
  const ContractResult h = solver.run(sphere);
  INFO(h.limit);
  REQUIRE(h.met);
  const double force_error = std::abs(h.force.value / (4 * E_star / 3) - 1), depth_error = std::abs(h.depth.value - 1);
  CHECK(force_error <= tolerance);
  CHECK(depth_error <= tolerance);
  CHECK(force_error <= 3 * h.force.relative());
  CHECK(depth_error <= 3 * h.depth.relative());
}



TEST_CASE("On a stiff surface (k = -0.75) the punch's force shall fall with the degree on one mesh and not move with a "
          "rounding-size change of nu",
          "[fem]")
{
  // Two checks that need no reference. The degrees of one mesh span nested spaces, and under a prescribed depth the
  // force is the strain energy's 2 U / d, which the Galerkin solution over-estimates by less in a larger space: the
  // force falls with the degree. And nu moved by 1e-10 moves the force by about 1e-10 (F ~ E / (1 - nu^2) near k = 0).
  // Both failed while the reactions of the stiff rows at the contact edge carried the rounding of A's entries times
  // u (DirectSystem): the force rose with the degree and moved with nu far beyond 1e-10.
  const auto force = [](const double nu, const unsigned int degree) {
    const Material material{std::make_shared<PowerLawModulus>(1.0, 1.0, -0.75), nu};
    Settings       s = contract_settings(1.0, material, 1e-6);
    s.mesh.surface_layer_thickness = 1e-2; // cells of 1e-2 a on the surface: no thinner layer
    s.discretization.degree        = degree;
    LoadCase punch;
    punch.type  = LoadType::flat_punch;
    punch.depth = 1.0;
    AxisymmetricSolver solver(material, s.mesh, s.discretization);
    const Result       r = solver.run(punch, OutputRequest{});
    REQUIRE(r.reliable);
    return r.force;
  };
  const double f4 = force(0.3, 4), f5 = force(0.3, 5), f6 = force(0.3, 6);
  CAPTURE(f4, f5, f6);
  CHECK(f5 < f4);
  CHECK(f6 < f5);
  const double moved = force(0.3 + 1e-10, 6);
  CAPTURE(moved);
  CHECK(std::abs(moved / f6 - 1) < 2e-8);
}

TEST_CASE("On a stiff surface (k = -0.9) the contract's paraboloid shall meet 1e-6 against (9.26), with estimates "
          "that include the rounding probe and bound the true errors",
          "[fem]")
{
  // The hp ladder on k < 0 reaches degrees whose answers carry the rounding of the stiff cells' entries; the probe
  // (the last level again with the modulus and the loads scaled) measures it and adds it to the estimates.
  const double k = -0.9, nu = 0.3, tolerance = 1e-6;
  const Material material{std::make_shared<PowerLawModulus>(1.0, 1.0, k), nu};
  ContractSolver solver(material, contract_settings(1.0, material, tolerance), tolerance);
  LoadCase       sphere;
  sphere.type    = LoadType::indenter;
  sphere.profile = Profile::paraboloid(1.0);
  const ContractResult r = solver.run(sphere);
  CAPTURE(r.limit, r.level_dofs.size(), r.force.value, r.depth.value, r.force.rounding, r.depth.rounding);
  CHECK(r.met);
  CHECK(r.force.rounding > 0);
  CHECK(r.force.error >= rounding_safety * r.force.rounding);
  // (9.26) at a = R = E0 = c0 = 1: F = 4 h_N / ((1 - nu^2)(1 + k)^2 (k + 3)), d = 1 / (1 + k).
  const double force_error = std::abs(r.force.value / testing::paraboloid_force(k, nu, 1, 1, 1, 1) - 1);
  const double depth_error = std::abs(r.depth.value * (1 + k) - 1);
  CAPTURE(force_error, depth_error, r.force.relative(), r.depth.relative());
  CHECK(force_error <= tolerance);
  CHECK(force_error <= r.force.relative());
  CHECK(depth_error <= tolerance);
  CHECK(depth_error <= r.depth.relative());
}
