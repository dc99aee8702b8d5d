// The ring stress on a real grading (cases/model/fe_stress.h, cases/tools/ring_stress.h): a thin skin of finite
// modulus E_s over the power law carries, in plane stress, the strains the body below imposes, so its surface radial
// stress tends to E_s / E(z) times the power law's sigma_rr(r, z) at the surface as the skin thins (z0 / a -> 0).
#include <cases/model/fe_stress.h>

#include <analytic/batch.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

using namespace gradcontact;
using namespace gradcontact::cases;

namespace
{
  /// The power law's surface strain ratio sigma_rr(r, z) / E(z) / p_m at z -> 0 below the unit sphere (E0 = c0 = 1):
  /// the ratio at z = 1e-9 (r - 1) (its approach is linear in z, so the rest is below 1e-8 of it).
  double power_law_strain(const double k, const double nu, const double r)
  {
    const nlohmann::json body = {{"case", "paraboloid"}, {"material", {{"E0", 1.0}, {"c0", 1.0}, {"k", k}, {"nu", nu}}},
                                 {"geometry", {{"R", 1.0}}}, {"a", 1.0}};
    nlohmann::json force = body, stress = body;
    force["quantity"]    = "force";
    const double z       = 1e-9 * (r - 1);
    stress.update({{"quantity", "stress"}, {"component", "rr"}, {"r", r}, {"z", z}});
    return batch::evaluate(batch::parse(stress)) / std::pow(z, k) / (batch::evaluate(batch::parse(force)) / M_PI);
  }
}

TEST_CASE("The surface stress of a thin soft skin shall tend to its modulus times the power law's surface strain",
          "[cases]")
{
  // E0 ((z + z0)/c0)^k, k = 0.5, below the unit sphere: the skin's correction to the prediction is O(z0 / a) at
  // least (its membrane stiffness departs from the power law's by a share of order z0 / a), so a skin 10/3 times
  // thinner leaves at most a third of the deviation; each deviation is bounded by adding the FE's estimate.
  const double              k = 0.5, nu = 0.3;
  const std::vector<double> radii = {1.5, 2.0};
  std::vector<double>       deviation[2]; // z0 = 1e-2 a, 3e-3 a
  for (const int thin : {0, 1})
    {
      const double              z0 = thin ? 3e-3 : 1e-2;
      UnitSphere                sphere(MaterialParameters::Modulus::shifted_power_law, k, nu, z0, 1e-3, 2.0);
      const SurfaceRadialStress fe = surface_radial_stress(sphere, radii);
      CAPTURE(z0, fe.run.limit);
      REQUIRE(fe.run.met);
      for (std::size_t i = 0; i < radii.size(); ++i)
        {
          const double predicted = power_law_strain(k, nu, radii[i]) * std::pow(z0, k);
          deviation[thin].push_back((std::abs(fe.sigma_rr[i].value - predicted) + fe.sigma_rr[i].error) / predicted);
        }
    }
  CAPTURE(deviation[0], deviation[1]);
  CHECK(deviation[1][0] <= deviation[0][0] / 3);
  for (const double d : deviation[1])
    CHECK(d <= 5e-3);
}
