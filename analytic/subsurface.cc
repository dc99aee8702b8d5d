#include <analytic/errors.h>
#include <analytic/subsurface.h>

#include <numerics/gauss_jacobi.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace gradcontact
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    double edge_factor(const double a, const double rho, const double e)
    {
      return std::pow((a - rho) * (a + rho) / (a * a), e);
    }

    /// Appends the breakpoints after `lo` that grade [lo, hi] toward `point` (outside or at an end of the panel).
    void grade_panel(std::vector<double> &out, const double lo, const double hi, const double point, const double floor)
    {
      std::vector<double> inner;
      if (point >= hi)
        for (double end = hi; end > lo;)
          {
            const double width = std::max(point - end, floor);
            if (end - lo <= width || (point == hi && end == hi && floor == 0))
              break;
            end -= width;
            inner.push_back(end);
          }
      else if (point <= lo)
        for (double start = lo; start < hi;)
          {
            const double width = std::max(start - point, floor);
            if (hi - start <= width || (point == lo && start == lo && floor == 0))
              break;
            start += width;
            inner.insert(inner.begin(), start); // kept ascending below
          }
      std::sort(inner.begin(), inner.end());
      out.insert(out.end(), inner.begin(), inner.end());
      out.push_back(hi);
    }

    /// Splits the panels of `breaks` (sorted) until each is no wider than its distance to `point`, or than `floor`
    /// near it: panels graded geometrically (ratio 2) toward a point where the integrand is singular or peaks, so that
    /// each panel's integrand is analytic in a fixed neighbourhood. A panel ending at `point` is left (its end-point
    /// singularity is the rule's weight).
    void grade_toward(std::vector<double> &breaks, const double point, const double floor)
    {
      std::vector<double> out{breaks.front()};
      for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        {
          double lo = breaks[i], hi = breaks[i + 1];
          if (lo < point && point < hi)
            {
              grade_panel(out, lo, point, point, floor);
              lo = point;
            }
          grade_panel(out, lo, hi, point, floor);
        }
      breaks = out;
    }

    /// The angular integral int_0^2pi of the unit point-force field of a source at radius rho, turned into the
    /// field point's frame: {rr, zz, tt, rz}.
    AxisymmetricStress ring(const PointLoadField &field, const double rho, const double r, const double z,
                            const detail::GaussJacobiRule &legendre)
    {
      // The kernel peaks at phi = 0 over a width of order sqrt((r - rho)^2 + z^2) / sqrt(r rho).
      std::vector<double> breaks{0., pi};
      if (r * rho > 0)
        {
          const double width = std::sqrt(((r - rho) * (r - rho) + z * z) / (r * rho));
          for (double w = width; w < pi; w *= 2)
            breaks.push_back(w);
        }
      std::sort(breaks.begin(), breaks.end());
      AxisymmetricStress s;
      for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        {
          const double lo = breaks[i], h = breaks[i + 1] - lo;
          for (std::size_t q = 0; q < legendre.size(); ++q)
            {
              const double phi = lo + h * legendre.node[q], w = 2 * h * legendre.weight[q]; // 2: phi in (pi, 2pi)
              // The offset from the source to the field point, in the field point's frame (x along its radius).
              const double dx = r - rho * std::cos(phi), dy = rho * std::sin(phi);
              const double d  = std::hypot(dx, dy);
              const AxisymmetricStress g = field.stress(1., d, z);
              const double c = d > 0 ? dx / d : 1., sn = d > 0 ? dy / d : 0.;
              s.rr += w * (g.rr * c * c + g.tt * sn * sn);
              s.tt += w * (g.rr * sn * sn + g.tt * c * c);
              s.zz += w * g.zz;
              s.rz += w * g.rz * c;
            }
        }
      return s;
    }

    void accumulate(AxisymmetricStress &s, const AxisymmetricStress &g, const double w)
    {
      s.rr += w * g.rr;
      s.zz += w * g.zz;
      s.tt += w * g.tt;
      s.rz += w * g.rz;
    }
  } // namespace

  AxisymmetricPressure contact_pressure(const Medium &m, const FlatPunch &punch, const double d)
  {
    const double p = pressure(m, punch, d, 0.) ; // (a^2)^((k-1)/2) cN0 d / (pi c0^k) at the centre
    return {punch.a, (m.k - 1) / 2, [p](double) { return p; }};
  }

  AxisymmetricPressure contact_pressure(const Medium &m, const Paraboloid &paraboloid, const double a)
  {
    const double p = pressure(m, paraboloid, a, 0.);
    return {a, (1 + m.k) / 2, [p](double) { return p; }};
  }

  AxisymmetricPressure contact_pressure(const Medium &m, const PowerLaw &profile, const double a)
  {
    return contact_pressure(a, (1 + m.k) / 2, [m, profile, a](const double rho) { return pressure(m, profile, a, rho); });
  }

  AxisymmetricPressure contact_pressure(const double a, const double edge_exponent,
                                        std::function<double(double)> pressure)
  {
    check::positive("contact_pressure", "a", a);
    check::open_interval("contact_pressure", "edge exponent", edge_exponent, -1., 1e3);
    return {a, edge_exponent, [a, edge_exponent, p = std::move(pressure)](const double rho) {
              return p(rho) / edge_factor(a, rho, edge_exponent);
            }};
  }

  AxisymmetricPressure contact_pressure(const UniformPressure &load)
  {
    check::positive("contact_pressure", "a", load.a);
    check::finite("contact_pressure", "p0", load.p0);
    const double p = load.p0;
    return {load.a, 0., [p](double) { return p; }};
  }

  AxisymmetricStress subsurface_stress(const PointLoadField &field, const AxisymmetricPressure &load, const double r,
                                       const double z, const SuperpositionRule &rule)
  {
    const char *fn = "subsurface_stress";
    check::positive(fn, "a", load.a);
    check::open_interval(fn, "edge exponent", load.edge_exponent, -1., 1e3);
    check::non_negative(fn, "r", r);
    check::positive(fn, "z", z);
    if (rule.points < 2 || rule.points > 64)
      check::fail(fn, "points", rule.points, "is outside [2, 64]");
    const double a = load.a, e = load.edge_exponent;
    const detail::GaussJacobiRule legendre = detail::gauss_jacobi_rule(rule.points, 1., 1.);
    const detail::GaussJacobiRule edge     = detail::gauss_jacobi_rule(rule.points, 1 + e, 1.);

    // Panels in rho: graded toward r (the kernel's peak) and toward the edge (the pressure's singularity, and the
    // field point's distance to it).
    std::vector<double> breaks{0., a};
    grade_toward(breaks, std::min(r, a), std::max(z, 1e-15 * a) / 2);
    grade_toward(breaks, a, 0.);

    AxisymmetricStress s;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
      {
        const double lo = breaks[i], hi = breaks[i + 1];
        if (hi < a)
          for (std::size_t q = 0; q < legendre.size(); ++q)
            {
              const double rho = lo + (hi - lo) * legendre.node[q];
              const double w   = (hi - lo) * legendre.weight[q] * rho * load.smooth(rho) * edge_factor(a, rho, e);
              accumulate(s, ring(field, rho, r, z, legendre), w);
            }
        else
          {
            // The last panel in u = 1 - rho^2/a^2 in [0, U], rho drho = a^2/2 du, with the weight u^e in the rule.
            const double U = (a - lo) * (a + lo) / (a * a);
            for (std::size_t q = 0; q < edge.size(); ++q)
              {
                const double u = U * edge.node[q], rho = a * std::sqrt(1 - u);
                const double w = a * a / 2 * std::pow(U, 1 + e) * edge.weight[q] * load.smooth(rho);
                accumulate(s, ring(field, rho, r, z, legendre), w);
              }
          }
      }
    return s;
  }

  double measure(const AxisymmetricStress &s, const StressMeasure m)
  {
    if (m == StressMeasure::von_mises)
      return std::sqrt(((s.rr - s.zz) * (s.rr - s.zz) + (s.zz - s.tt) * (s.zz - s.tt) + (s.tt - s.rr) * (s.tt - s.rr)) /
                         2 +
                       3 * s.rz * s.rz);
    const double centre = (s.rr + s.zz) / 2, radius = std::hypot((s.rr - s.zz) / 2, s.rz);
    return (std::max(centre + radius, s.tt) - std::min(centre - radius, s.tt)) / 2;
  }

  double stress_component(const AxisymmetricStress &s, const std::string &name)
  {
    if (name == "von_mises")
      return measure(s, StressMeasure::von_mises);
    if (name == "max_shear")
      return measure(s, StressMeasure::max_shear);
    const double centre = (s.rr + s.zz) / 2, radius = std::hypot((s.rr - s.zz) / 2, s.rz);
    const std::map<std::string, double> components = {{"rr", s.rr},
                                                      {"zz", s.zz},
                                                      {"tt", s.tt},
                                                      {"rz", s.rz},
                                                      {"principal_max", std::max(centre + radius, s.tt)},
                                                      {"principal_min", std::min(centre - radius, s.tt)}};
    const auto found = components.find(name);
    if (found == components.end())
      throw DomainError("component = '" + name + "' must be one of " + check::keys(components) +
                        ", von_mises, max_shear");
    return found->second;
  }



  StressMaximum largest_stress(const PointLoadField &field, const AxisymmetricPressure &load, const StressMeasure m)
  {
    const char *fn = "largest_stress";
    if (field.k() < 0)
      check::fail(fn, "k", field.k(),
                  "must be >= 0: on k < 0 the surface layer's radial and hoop stresses grow like (z/r)^k as z -> 0, "
                  "so the largest stress is unbounded at the surface (ask the stress at a depth instead)");
    if (load.edge_exponent < 0)
      check::fail(fn, "edge exponent", load.edge_exponent,
                  "must be >= 0: the pressure's edge singularity (flat punch, JKR) makes the stress at the contact "
                  "edge unbounded");
    const double a = load.a;
    const auto   value = [&](const double r, const double z) {
      return measure(subsurface_stress(field, load, r, z), m);
    };
    StressMaximum best{-1, 0, 0};
    for (double r = 0; r <= 2 * a * (1 + 1e-12); r += a / 20)
      for (double z = 1e-3 * a; z <= 2 * a * (1 + 1e-12); z *= 1.25)
        if (const double v = value(r, z); v > best.value)
          best = {v, r, z};
    // Pattern search: try the four neighbours at the current step, move to the best, halve the step when none is
    // better.
    for (double step = a / 40; step > 1e-5 * a;)
      {
        StressMaximum next = best;
        for (const auto &[dr, dz] : {std::pair{1., 0.}, std::pair{-1., 0.}, std::pair{0., 1.}, std::pair{0., -1.}})
          {
            const double r = best.r + dr * step, z = best.z + dz * std::min(step, best.z / 2);
            if (r < 0 || z <= 0)
              continue;
            if (const double v = value(r, z); v > next.value)
              next = {v, r, z};
          }
        if (next.value > best.value)
          best = next;
        else
          step /= 2;
      }
    return best;
  }
} // namespace gradcontact
