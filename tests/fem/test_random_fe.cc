// A randomized property run of the FE model: a few hundred small FE runs over random materials,
// meshes and loads must each end in finite answers or in a clear exception (std::invalid_argument naming
// a parameter, std::runtime_error explaining a failure), never NaN, inf, a hang or a crash. Failures it
// finds become regression tests in test_fem.cc / test_contact.cc.
#include <fem/bodies/axisymmetric_solver.h>
#include <fem/modulus/modulus.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

using namespace gradcontact::fem;

TEST_CASE("Random small FE runs end in finite answers or clear errors, never NaN, inf or a crash", "[slow]")
{
  constexpr unsigned int runs = 200;
  std::mt19937_64        rng(20261122);
  std::uniform_real_distribution<double> U(0., 1.);
  unsigned int finite = 0, refused = 0, flagged = 0;
  for (unsigned int i = 0; i < runs; ++i)
    {
      // Edges included on purpose: k up to +-0.95, nu up to 0.499, scales over 12 decades.
      const double k  = -0.95 + 1.9 * U(rng);
      const double nu = 0.499 * U(rng);
      const double E0 = std::pow(10., -3. + 15. * U(rng));
      const double a  = std::pow(10., -9. + 12. * U(rng));
      const double c0 = a * std::pow(10., -3. + 6. * U(rng));
      MeshParameters mesh = recommended_mesh_parameters(a, k, 1e-4);
      mesh.h_edge      = std::pow(10., -1. - 3. * U(rng));
      mesh.ring_growth = 1.3 + 1.5 * U(rng);
      DiscretizationParameters disc;
      disc.degree = 1 + static_cast<unsigned int>(2 * U(rng)); // 1 or 2: small runs
      LoadCase load;
      const int which = static_cast<int>(5 * U(rng));
      load.type  = which == 0 ? LoadType::flat_punch
                   : which == 1 ? LoadType::indenter
                   : which == 2 ? LoadType::constant_pressure
                   : which == 3 ? LoadType::concave_punch
                                : LoadType::indenter_depth;
      load.depth    = a * std::pow(10., -4. + 2. * U(rng));
      load.pressure = E0 * std::pow(10., -6. + 3. * U(rng));
      load.profile  = which == 3 ? Profile::concave_paraboloid(load.depth * U(rng))
                      : U(rng) < 0.5 ? Profile::paraboloid(a * std::pow(10., 1. + 2. * U(rng)))
                                     : Profile::power_law(0.8 + 3. * U(rng), 1e-2 * std::pow(a, -0.5));
      if (which == 4)
        load.depth = 0.5 * a * a / load.profile.R; // near the mesh's contact radius for a paraboloid
      CAPTURE(i, k, nu, E0, a, c0, mesh.h_edge, mesh.ring_growth, disc.degree, which);
      try
        {
          AxisymmetricSolver solver(Material{std::make_shared<PowerLawModulus>(E0, c0, k), nu}, mesh, disc);
          OutputRequest out;
          out.displacement_radii = {0., 0.5 * a, 2. * a};
          if (which != 2)
            out.pressure_radii = {0., 0.5 * a};
          const Result r = solver.run(load, out);
          bool ok = std::isfinite(r.force) && std::isfinite(r.depth) && std::isfinite(r.contact_radius) &&
                    std::isfinite(r.energy_mismatch);
          for (const Sample &s : r.displacement)
            ok = ok && std::isfinite(s.value);
          for (const Sample &s : r.pressure)
            ok = ok && std::isfinite(s.value);
          CHECK(ok);
          ++finite;
          if (!r.reliable || !r.consistent_contact)
            {
              ++flagged;
              CHECK(!r.message.empty()); // a flagged result says why
            }
        }
      catch (const std::invalid_argument &e)
        {
          ++refused;
          CHECK(std::string(e.what()).find("outside") != std::string::npos);
        }
      catch (const std::runtime_error &e)
        {
          ++refused;
          CHECK(!std::string(e.what()).empty());
        }
    }
  std::cout << "random FE runs: " << runs << ", finite " << finite << " (flagged " << flagged << "), refused "
            << refused << "\n";
  CHECK(finite + refused == runs);
  CHECK(finite > runs / 2); // the generator must mostly produce valid runs, or it tests nothing
}
