// gradcontact/cases: the published comparison of an error-function map (Map/parameter = erf width, cases/runners/fe_map.h).
//
// D. Lee, J.R. Barber, M.D. Thouless, "Indentation of an elastic half space with material properties varying with
// depth", Int. J. Eng. Sci. 47 (2009) 1274-1283, computed by FE the indentation of half-spaces whose modulus
// decreases with depth (a uniform stiff layer, an inverse power law truncated to a finite surface value, an
// error-function grading) and state (abstract) that in all cases the load-displacement relation is closer to linear
// than in the homogeneous case. The map gives the same quantity without new solves: for an indenter A r^n on
// E(z) = E0 e(z/w), scaling all lengths by lambda scales d by lambda^n and F by lambda^(n+1), so at a fixed width
// F = a^(n+1) G(a/w) and d = a^n H(a/w), and a map over a/w at fixed a is a load-displacement curve at fixed w.
// Between two points of the map, with the deviations dF = F / F_cf(d) - 1 and da = a / a_cf(d) - 1 from the
// homogeneous closed forms F_cf ~ d^((n+1)/n), a_cf ~ d^(1/n) (k = 0),
//
//   N = d ln F / d ln d = (n+1)/n + Delta ln(1 + dF) / Delta ln d,   Delta ln d = n [Delta ln(a/w) - Delta ln(1 + da)].
#ifndef GRADCONTACT_CASES_MAP_PUBLISHED_H
#define GRADCONTACT_CASES_MAP_PUBLISHED_H

#include "scene/scene.h"

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The load-displacement exponent at a fixed width between consecutive map points (header).
  struct LoadExponent
  {
    double ratio_low = 0., ratio_high = 0.; ///< a/w at the two points
    double exponent = 0.;                   ///< N = d ln F / d ln d between them
  };

  /// N between consecutive points of `ratios` (ascending, > 0) for the profile exponent n > 0, from the force and
  /// contact-radius deviations at those points. Throws std::invalid_argument on sizes that differ or n <= 0.
  std::vector<LoadExponent> load_exponents(double profile_exponent, const std::vector<double> &ratios,
                                           const std::vector<double> &force_deviations,
                                           const std::vector<double> &radius_deviations);

  /// The markdown paragraph of map.md: the published trend and the map's (exponents N for an indenter, the apparent
  /// modulus 1 + dF for the flat punch), with the verdict. `ratios` ascending; the deviations of the solved points.
  std::string published_comparison(const Scene &scene, const std::vector<double> &ratios,
                                   const std::vector<double> &force_deviations,
                                   const std::vector<double> &radius_deviations);
} // namespace gradcontact::cases

#endif
