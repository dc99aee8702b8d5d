#include "model/fe_stress.h"

#include <analytic/subsurface.h>
#include <fem/modulus/modulus.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <memory>
#include <utility>
#include <vector>

namespace gradcontact::cases
{
  namespace
  {
    /// The measure `name` of the components on ladder level l.
    double on_level(const std::array<fem::Estimated, 4> &c, const std::string &name, const std::size_t l)
    {
      return stress_component(AxisymmetricStress{c[0].levels[l], c[1].levels[l], c[2].levels[l], c[3].levels[l]},
                              name);
    }

    /// The grid of the first pass of the search (the header): r/a in steps of 1/20 up to 2, z/a geometric
    /// from 1e-3 to 2.
    std::vector<fem::StressPoint> first_grid(const bool surface)
    {
      std::vector<fem::StressPoint> points;
      for (unsigned int i = 0; i <= 40; ++i)
        {
          if (surface)
            points.push_back({i / 20.0, 0.0});
          for (unsigned int j = 0; j < 30; ++j)
            points.push_back({i / 20.0, 1e-3 * std::pow(2e3, j / 29.0)});
        }
      return points;
    }

    /// A 7 x 7 grid about (r, z) with steps dr, dz, inside r >= 0, z > 0: its points, and the index of the point
    /// (r + i dr, z + j dz) at index[i + 3][j + 3] (-1 outside).
    struct LocalGrid
    {
      std::vector<fem::StressPoint> points;
      int                           index[7][7];
      double                        dr = 0, dz = 0;
    };
    LocalGrid local_grid(const double r, const double z, const double dr, const double dz, const bool surface)
    {
      LocalGrid g;
      g.dr = dr;
      g.dz = dz;
      for (int i = -3; i <= 3; ++i)
        for (int j = -3; j <= 3; ++j)
          {
            g.index[i + 3][j + 3] = -1;
            // With the surface, its row z = 0 (the point at or just above it, rounded onto it).
            const double depth = surface && std::abs(z + j * dz) <= 1e-9 * dz ? 0.0 : z + j * dz;
            if (r + i * dr >= 0 && (depth > 0 || (surface && depth == 0)))
              {
                g.index[i + 3][j + 3] = static_cast<int>(g.points.size());
                g.points.push_back({r + i * dr, depth});
              }
          }
      return g;
    }

    /// The vertex of the parabola through (-1, fm), (0, f0), (1, fp): its abscissa, within [-1, 1], and the rise of
    /// its value over f0 (0 and 0 when the three values do not bend down).
    std::pair<double, double> vertex(const double fm, const double f0, const double fp)
    {
      const double bend = fm - 2 * f0 + fp;
      if (!(bend < 0))
        return {0.0, 0.0};
      const double x = std::clamp((fm - fp) / (2 * bend), -1.0, 1.0);
      return {x, -bend * x * x / 2};
    }

    /// The largest measure on the grid of one ladder level, refined by a parabola through the grid point and its
    /// neighbours at `step` grid steps in r and in z (the measure is even in r, so r = 0 is its own mirror).
    struct Fit
    {
      double r = 0, z = 0, value = 0;
    };
    Fit fit(const LocalGrid &g, const std::function<double(int)> &measure, const int bi, const int bj, const int step)
    {
      const fem::StressPoint &b  = g.points[g.index[bi + 3][bj + 3]];
      const auto              at = [&](const int i, const int j) {
        if (i < -3 || i > 3 || j < -3 || j > 3 || g.index[i + 3][j + 3] < 0)
          return std::numeric_limits<double>::quiet_NaN();
        return measure(g.index[i + 3][j + 3]);
      };
      // On the axis the point at -step dr is the mirror of the one at +step dr.
      const auto mirrored = [&](const int i, const int j) { return b.r == 0 && i < bi ? at(2 * bi - i, j) : at(i, j); };
      const double            f0 = measure(g.index[bi + 3][bj + 3]);
      Fit                     out{b.r, b.z, f0};
      const double rm = mirrored(bi - step, bj), rp = at(bi + step, bj), zm = at(bi, bj - step), zp = at(bi, bj + step);
      if (std::isfinite(rm) && std::isfinite(rp))
        {
          const auto [x, rise] = vertex(rm, f0, rp);
          out.r += x * step * g.dr;
          out.value += rise;
        }
      if (std::isfinite(zm) && std::isfinite(zp))
        {
          const auto [x, rise] = vertex(zm, f0, zp);
          out.z += x * step * g.dz;
          out.value += rise;
        }
      return out;
    }

    /// The index of the largest measure `name` on ladder level l (the last one: -1) over a run's points.
    std::size_t argmax(const fem::ContractResult &r, const std::string &name, const std::size_t level)
    {
      std::size_t best = 0;
      for (std::size_t i = 1; i < r.stress.size(); ++i)
        if (on_level(r.stress[i], name, level) > on_level(r.stress[best], name, level))
          best = i;
      return best;
    }


    /// The maximum of the last grid (largest()): the parabolic fit about its best point on the finest level, with
    /// the estimates of the header.
    FeStressMaximum located(const fem::ContractResult &result, const LocalGrid &g, const std::string &name)
    {
      const std::size_t levels = result.level_dofs.size(), i = argmax(result, name, levels - 1);
      int               bi = 0, bj = 0;
      for (int x = 0; x < 7; ++x)
        for (int y = 0; y < 7; ++y)
          if (g.index[x][y] == static_cast<int>(i))
            bi = x - 3, bj = y - 3;
      const auto level = [&](const std::size_t l) {
        return [&result, &name, l](const int k) { return on_level(result.stress[k], name, l); };
      };
      const Fit finest = fit(g, level(levels - 1), bi, bj, 1), coarse_grid = fit(g, level(levels - 1), bi, bj, 2);
      const Fit below  = levels > 1 ? fit(g, level(levels - 2), bi, bj, 1) : finest;
      FeStressMaximum m;
      m.at_point = stress_measure(result.stress[i], name);
      m.value    = m.at_point;
      m.value.error += std::abs(finest.value - m.value.value) + std::abs(finest.value - coarse_grid.value);
      m.value.value = finest.value;
      m.r.value     = finest.r;
      m.r.error     = std::max(std::abs(finest.r - coarse_grid.r), std::abs(finest.r - below.r));
      m.r.scale     = 1;
      m.z.value     = finest.z;
      m.z.error     = std::max(std::abs(finest.z - coarse_grid.z), std::abs(finest.z - below.z));
      m.z.scale     = finest.z;
      if (finest.z == 0)
        {
          // On the surface, the search's boundary: the place is known to the last grid's step in depth.
          m.z.error = std::max(m.z.error, g.dz);
          m.z.scale = 1;
        }
      return m;
    }
  } // namespace

  /// The component `name` of the estimated stress and its error bound (the header's propagation to the measures).
  fem::Estimated stress_measure(const std::array<fem::Estimated, 4> &c, const std::string &name)
  {
    const std::map<std::string, std::size_t> own = {{"rr", 0}, {"zz", 1}, {"tt", 2}, {"rz", 3}};
    if (const auto found = own.find(name); found != own.end())
      return c[found->second];
    fem::Estimated e;
    e.value = stress_component(AxisymmetricStress{c[0].value, c[1].value, c[2].value, c[3].value}, name);
    e.scale = c[0].scale;
    const double F = std::sqrt(c[0].error * c[0].error + c[1].error * c[1].error + c[2].error * c[2].error +
                               2 * c[3].error * c[3].error);
    e.error = name == "von_mises" ? std::sqrt(1.5) * F : F;
    return e;
  }



  std::vector<FeStressMaximum> largest_fe_stresses(fem::ContractSolver &solver, const fem::LoadCase &load,
                                                   const std::vector<std::string> &names, const bool surface)
  {
    fem::OutputRequest outputs;
    outputs.stress_points            = first_grid(surface);
    const fem::ContractResult first  = solver.run(load, outputs);
    std::vector<FeStressMaximum> out;
    for (const std::string &name : names)
      {
        fem::StressPoint best = outputs.stress_points.at(argmax(first, name, first.level_dofs.size() - 1));
        LocalGrid        g;
        g.dr = 1 / 20.0;
        g.dz = std::max(best.z, 1e-3) * (std::pow(2e3, 1 / 29.0) - 1);
        fem::OutputRequest  local;
        fem::ContractResult result;
        for (unsigned int pass = 0; pass < 4; ++pass)
          {
            g                   = local_grid(best.r, best.z, g.dr / 3, g.dz / 3, surface);
            local.stress_points = g.points;
            result              = solver.run(load, local);
            best = local.stress_points.at(argmax(result, name, result.level_dofs.size() - 1));
          }
        out.push_back(located(result, g, name));
        out.back().run = std::move(result);
      }
    return out;
  }



  FeStressMaximum largest_fe_stress(fem::ContractSolver &solver, const fem::LoadCase &load, const std::string &name)
  {
    return largest_fe_stresses(solver, load, {name}, false).front();
  }



  std::vector<FeStressMaximum> largest_fe_stresses(UnitSphere &sphere, const std::vector<std::string> &names)
  {
    return largest_fe_stresses(sphere.solver(), sphere.load(), names, sphere.finite_surface());
  }



  UnitSphere::UnitSphere(const MaterialParameters::Modulus modulus, const double k, const double nu,
                         const double length, const double tolerance, const double largest_radius)
  {
    fem::Material material;
    material.nu = nu;
    switch (modulus)
      {
        case MaterialParameters::Modulus::power_law:
          material.modulus = std::make_shared<fem::PowerLawModulus>(1.0, 1.0, k);
          break;
        case MaterialParameters::Modulus::shifted_power_law:
          material.modulus = std::make_shared<fem::ShiftedPowerLawModulus>(1.0, 1.0, k, length);
          break;
        case MaterialParameters::Modulus::coating:
          material.modulus = std::make_shared<fem::CoatingModulus>(1.0, 1.0, k, length);
          break;
        default:
          throw std::invalid_argument("UnitSphere: Material/modulus must be power law, shifted power law or coating");
      }
    surface          = modulus == MaterialParameters::Modulus::shifted_power_law;
    indenter.type    = fem::LoadType::indenter;
    indenter.profile = fem::Profile::paraboloid(1.0);
    contract = std::make_unique<fem::ContractSolver>(
      material, fem::contract_settings(1.0, material, tolerance, largest_radius), tolerance);
  }

  UnitSphere::~UnitSphere() = default;



  SurfaceRadialStress surface_radial_stress(UnitSphere &sphere, const std::vector<double> &radii)
  {
    fem::OutputRequest outputs;
    for (const double r : radii)
      outputs.stress_points.push_back({r, 0.0});
    SurfaceRadialStress out;
    out.run = sphere.solver().run(sphere.load(), outputs);
    out.p_m = out.run.result.force / M_PI;
    for (const auto &c : out.run.stress)
      {
        fem::Estimated e = c[0];
        e.value /= out.p_m;
        e.error /= out.p_m;
        e.scale /= out.p_m;
        for (double &v : e.levels)
          v /= out.p_m;
        out.sigma_rr.push_back(e);
      }
    return out;
  }
} // namespace gradcontact::cases
