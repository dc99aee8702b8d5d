// Tests of the Dugdale cohesive-zone FE, fem/cohesive_zone.h. References: the Maugis-Dugdale solution at
// k = 0 (analytic/maugis_dugdale.h, Maugis 1992; nothing of the FE), the DMT limit -2 pi dgamma R of a rigid
// sphere, and the chapter's JKR critical states (analytic/adhesion.h, 9.55-9.56) at large lambda.
#include <fem/cohesive_zone.h>
#include <fem/modulus.h>

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/maugis_dugdale.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>

using namespace gradcontact::fem;
namespace md = gradcontact::maugis_dugdale;

namespace
{
  constexpr double nu = 0.3, E0 = 1.0, c0 = 1.0, R = 1.0, dgamma = 1e-3;
  constexpr double pi = 3.14159265358979323846;

  Material power_law_material(const double k)
  {
    return Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  }
  CohesiveContact::SettingsFunction test_settings(const double k, const unsigned int degree)
  {
    return [k, degree](const double a) {
      Settings s              = recommended_settings(a, k, 1e-5);
      s.discretization.degree = degree;
      return s;
    };
  }
} // namespace

TEST_CASE("cohesive probe: Maugis-Dugdale at k = 0", "[slow]")
{
  const double E_star = E0 / (1 - nu * nu);
  const auto   sc     = md::scales(dgamma, R, E_star);
  for (const double lambda : {0.1, 0.5, 2.0})
    {
      // sigma_0 from lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^{1/3}
      const double sigma0 = lambda / std::cbrt(9 * R / (2 * pi * dgamma * E_star * E_star));
      const auto   ref    = md::pull_off(lambda, gradcontact::Control::force);
      for (const unsigned int degree : {2u, 3u})
        {
          CohesiveContact contact(power_law_material(0), Profile::paraboloid(R), DugdaleLaw{sigma0, dgamma},
                                  test_settings(0, degree));
          const auto c = contact.critical_state(AdhesionControl::force, ref.state.A * sc.length * 1.1);
          std::cout << "lambda=" << lambda << " p=" << degree << " F/(pi w R)=" << c.state.force / sc.force
                    << " ref=" << ref.state.P << " err=" << (c.state.force / sc.force - ref.state.P) / ref.state.P
                    << " A=" << c.state.radius / sc.length << " refA=" << ref.state.A
                    << " m=" << c.state.zone_radius / c.state.radius << " refm=" << ref.state.m
                    << " states=" << c.states_solved << " dofs=" << c.max_dofs << " s=" << c.seconds
                    << " consistent=" << c.state.consistent << " " << c.state.message << "\n";
        }
    }
}
