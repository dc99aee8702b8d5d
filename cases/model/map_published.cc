#include "model/map_published.h"

#include "report/report.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace
  {
    using Type = LoadParameters::Type;

    /// n of the profile A r^n; 0 for the flat punch (no contact-radius law).
    double profile_exponent(const Scene &s)
    {
      switch (s.load.type)
        {
          case Type::paraboloid:
            return 2.;
          case Type::cone:
            return 1.;
          case Type::power_law:
            return s.load.n;
          default:
            return 0.;
        }
    }

    /// An exponent within this of the homogeneous one counts as equal to it: the map's deviations carry FE errors
    /// of about 1e-4 (the "FE resolution" line of map.md), which move N by about that much per decade of a/w.
    constexpr double exponent_resolution = 1e-3;

    const char *citation = "D. Lee, J.R. Barber, M.D. Thouless, \"Indentation of an elastic half space with material "
                           "properties varying with depth\", Int. J. Eng. Sci. 47 (2009) 1274-1283";
  } // namespace

  std::vector<LoadExponent> load_exponents(const double n, const std::vector<double> &ratios,
                                           const std::vector<double> &force, const std::vector<double> &radius)
  {
    if (ratios.size() != force.size() || ratios.size() != radius.size())
      throw std::invalid_argument("load_exponents: " + std::to_string(ratios.size()) + " ratios, " +
                                  std::to_string(force.size()) + " force and " + std::to_string(radius.size()) +
                                  " radius deviations (need the same number)");
    if (!(n > 0.))
      throw std::invalid_argument("load_exponents: profile exponent n = " + format(n) + " must be in (0, inf)");
    std::vector<LoadExponent> out;
    for (std::size_t i = 0; i + 1 < ratios.size(); ++i)
      {
        const double dln_d =
          n * (std::log(ratios[i + 1] / ratios[i]) - std::log1p(radius[i + 1]) + std::log1p(radius[i]));
        const double dln_F = (n + 1.) / n * dln_d + std::log1p(force[i + 1]) - std::log1p(force[i]);
        out.push_back({ratios[i], ratios[i + 1], dln_F / dln_d});
      }
    return out;
  }

  std::string published_comparison(const Scene &s, const std::vector<double> &ratios, const std::vector<double> &force,
                                   const std::vector<double> &radius)
  {
    const double m = s.material.surface_modulus_ratio;
    std::ostringstream md;
    md << "### Published comparison\n\n"
       << citation << ", computed by FE the indentation of half-spaces whose modulus decreases with depth (a uniform "
       << "stiff layer, an inverse power law truncated to a finite surface value, an error-function grading) and found "
       << "that in all cases the load-displacement relation is closer to linear than in the homogeneous case (their "
       << "abstract). This map has m = E(0)/E0 = " << format(m)
       << (m > 1. ? " (a stiff skin, their case)" : m < 1. ? " (a soft skin: the paper has no such case)" : " (homogeneous)")
       << ".\n\n";
    if (ratios.size() < 2)
      return md.str() + "Fewer than two points were solved: no trend.\n\n";
    const double n = profile_exponent(s);
    if (n == 0.)
      {
        // The flat punch: F is linear in d for any E(z); the trend is in the stiffness, F/d = 2 E_app a / (1 - nu^2).
        bool decreasing = true, increasing = true;
        for (std::size_t i = 0; i + 1 < force.size(); ++i)
          {
            decreasing = decreasing && force[i + 1] <= force[i];
            increasing = increasing && force[i + 1] >= force[i];
          }
        md << "For the flat punch F is linear in d for any grading; the apparent modulus E_app / E0 = 1 + force deviation "
           << "(Sneddon's punch on E0 at the FE depth) goes from " << format(1. + force.front()) << " at a/w = "
           << format(ratios.front()) << " to " << format(1. + force.back()) << " at a/w = " << format(ratios.back())
           << " (limits m = " << format(m) << " as a/w -> 0 and 1 as a/w -> inf), "
           << (decreasing ? "decreasing monotonically" : increasing ? "increasing monotonically" : "not monotonically")
           << ".\n\n";
        return md.str();
      }
    const double homogeneous = (n + 1.) / n;
    md << "At a fixed width w the map is a load-displacement curve (the scaling of cases/model/map_published.h): the exponent "
       << "N = d ln F / d ln d between consecutive points, against " << format(homogeneous) << " for the homogeneous "
       << "half-space (profile exponent n = " << format(n) << ").\n\n| a/w | N |\n|---|---|\n";
    const std::vector<LoadExponent> exponents = load_exponents(n, ratios, force, radius);
    std::size_t below = 0, above = 0;
    const LoadExponent *lowest = &exponents.front(), *highest = &exponents.front();
    for (const LoadExponent &e : exponents)
      {
        md << "| " << format(e.ratio_low) << " - " << format(e.ratio_high) << " | " << format(e.exponent) << " |\n";
        below += e.exponent < homogeneous - exponent_resolution;
        above += e.exponent > homogeneous + exponent_resolution;
        lowest = e.exponent < lowest->exponent ? &e : lowest;
        highest = e.exponent > highest->exponent ? &e : highest;
      }
    md << "\nHere N is " << (above == 0 && below > 0 ? "below" : below == 0 && above > 0 ? "above" : "on both sides of")
       << " " << format(homogeneous) << " (beyond " << format(exponent_resolution) << ") on " << (above == 0 ? below : above)
       << " of " << exponents.size() << " intervals, lowest " << format(lowest->exponent) << " (a/w = "
       << format(lowest->ratio_low) << " - " << format(lowest->ratio_high) << "), highest " << format(highest->exponent)
       << " (a/w = " << format(highest->ratio_low) << " - " << format(highest->ratio_high) << "): ";
    if (m > 1.)
      md << (above == 0 && below > 0 ? "closer to linear than the homogeneous half-space, as published"
                                     : "NOT the published trend (N should not exceed the homogeneous exponent for a stiff skin)");
    else
      md << (above > 0 && below == 0 ? "farther from linear than the homogeneous half-space, the opposite of the stiff skin"
                                     : "no single trend");
    md << ".\n\n";
    return md.str();
  }
} // namespace gradcontact::cases
