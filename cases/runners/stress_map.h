// gradcontact/cases: the map of the largest stresses below a sphere (Map/parameter = largest stress).
//
// For every k of Map/k values (Material/k when empty) and nu of Map/nu values (Material/nu when empty), the
// paraboloid pressed to a contact radius: the largest shear and the largest von Mises stress below it, over
// p_m = F / (pi a^2), and their depths and radii over a, from the FE at the scene's Discretization/force tolerance (the
// accuracy contract's ladder and the search of model/fe_stress.h) and from the closed form of the power law (the
// graded Boussinesq field superposed over the contact pressure, analytic/subsurface.h). Both are scale free in E0, c0,
// a and R (the normalised field depends on k, nu and the grading's length over a alone), so each side solves the unit
// problem.
// - On the power law (k >= 0: on k < 0 the skin's stresses grow without bound toward the surface) a row passes when
//   the FE is within 3x its own estimate of the closed form, the contract's promise of reliability.
// - On a real grading (Material/modulus = shifted power law, z0 / a, which takes k < 0 too, its surface modulus
//   being finite; or coating, H / a) the FE is the reference, over its own p_m, with the surface in its search where
//   the surface modulus is finite. Its sharp check is k = 0, a homogeneous body, where the closed form is exact and
//   the row is checked as above; elsewhere the table gives its deviation from the power law's closed form.
// A refusal names its limit and fails the row. Writes map.csv and map.md (one table) and the scene's errors table.
#ifndef GRADCONTACT_CASES_STRESS_MAP_H
#define GRADCONTACT_CASES_STRESS_MAP_H

#include "report/map_pipeline.h"
#include "scene/scene.h"

#include <memory>

namespace gradcontact::cases
{
  /// The strategy (report/map_pipeline.h) of the map of Map/parameter = largest stress.
  std::unique_ptr<MapStrategy> stress_map_strategy(const Scene &s);
} // namespace gradcontact::cases

#endif
