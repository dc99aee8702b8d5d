// The subsurface stresses' speed and accuracy (analytic/subsurface.h): time per point and error of the
// superposition of the graded Boussinesq field over the flat punch's and the paraboloid's pressures, at k = -0.9 ...
// 0.9, nu = 0.3, on points from the surface layer (z = 1e-4 a) to 2 a deep, inside and outside the contact.
//
//   bench_stress_speed [--points n]      (the rule's points per panel, default that of SuperpositionRule)
//
// The error of a point is its difference from the same superposition with 32 points per panel (whose panels resolve
// the kernel to rounding), relative to the largest |sigma| of the point; at k = 0 the paraboloid's axis is also
// compared with Huber's Hertz field (Johnson, Contact Mechanics, 1985, eq. 3.45). It prints a Markdown table per
// depth, to be read against the target of the stress quantities: a point well under the cost of an FE solve, at an
// error of 1e-10.
#include <analytic/subsurface.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace gradcontact;

namespace
{
  double largest(const AxisymmetricStress &s)
  {
    return std::max({std::abs(s.rr), std::abs(s.zz), std::abs(s.tt), std::abs(s.rz)});
  }

  double difference(const AxisymmetricStress &a, const AxisymmetricStress &b)
  {
    return std::max({std::abs(a.rr - b.rr), std::abs(a.zz - b.zz), std::abs(a.tt - b.tt), std::abs(a.rz - b.rz)});
  }

  struct Cell
  {
    double seconds = 0, error = 0;
    int    points  = 0;
  };

  /// Time and worst error of the points at depth z (all radii) for one load.
  Cell measure(const PointLoadField &field, const AxisymmetricPressure &load, const double z,
               const SuperpositionRule &rule)
  {
    Cell c;
    for (const double rho : {0., 0.5, 0.9, 0.99, 1.1, 2.})
      {
        const double r  = rho * load.a;
        const auto   t0 = std::chrono::steady_clock::now();
        const auto   s  = subsurface_stress(field, load, r, z, rule);
        c.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const auto reference = subsurface_stress(field, load, r, z, SuperpositionRule{32});
        c.error = std::max(c.error, difference(s, reference) / largest(reference));
        ++c.points;
      }
    return c;
  }

  /// The paraboloid's axis at k = 0 against Huber's closed form, worst relative error over depths.
  double huber_error(const SuperpositionRule &rule)
  {
    const double nu = 0.3, a = 1e-3;
    const Medium m  = medium(GradedHalfSpace{2e9, 1e-3, 0., nu});
    const auto   load = contact_pressure(m, Paraboloid{0.05}, a);
    const double p0   = load.smooth(0);
    const PointLoadField field(0., nu);
    double               worst = 0;
    for (const double zeta : {1e-4, 1e-2, 0.1, 0.48, 2.})
      {
        const auto   s  = subsurface_stress(field, load, 0., zeta * a, rule);
        const double zz = -p0 / (1 + zeta * zeta);
        const double rr = -p0 * ((1 + nu) * (1 - zeta * std::atan(1 / zeta)) - 0.5 / (1 + zeta * zeta));
        worst = std::max({worst, std::abs(s.zz - zz) / p0, std::abs(s.rr - rr) / p0});
      }
    return worst;
  }
}

int main(int argc, char **argv)
{
  SuperpositionRule rule;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--points") == 0 && i + 1 < argc)
      rule.points = static_cast<unsigned>(std::atoi(argv[++i]));
    else
      {
        std::fprintf(stderr, "usage: bench_stress_speed [--points n]\n");
        return 2;
      }
  const double a = 1e-3, nu = 0.3;
  std::printf("# Subsurface stresses: time per point and error (%u points per panel)\n\n", rule.points);
  std::printf("Error: against 32 points per panel, relative to the point's largest |sigma|, worst over r/a = 0, 0.5, "
              "0.9, 0.99, 1.1, 2. Paraboloid at k = 0 against Huber on the axis: %.1e of p0.\n\n",
              huber_error(rule));
  std::printf("| load | k | z/a | ms per point | error |\n|---|---|---|---|---|\n");
  for (const bool punch : {true, false})
    for (const double k : {-0.9, -0.5, 0., 0.5, 0.9})
      {
        const Medium         m = medium(GradedHalfSpace{2e9, 1e-3, k, nu});
        const PointLoadField field(k, nu);
        const auto load = punch ? contact_pressure(m, FlatPunch{a}, 1e-6) : contact_pressure(m, Paraboloid{0.05}, a);
        for (const double zeta : {1e-4, 1e-2, 0.1, 0.5, 2.})
          {
            const Cell c = measure(field, load, zeta * a, rule);
            std::printf("| %s | %.1f | %g | %.2f | %.1e |\n", punch ? "flat punch" : "paraboloid", k, zeta,
                        1e3 * c.seconds / c.points, c.error);
          }
      }
  return 0;
}
