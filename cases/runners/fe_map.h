// gradcontact/cases: applicability maps (SceneKind::map). The chapter's closed forms assume E(z) = E0 (z/c0)^k
// from z = 0 (9.1). A real grading departs from it near the surface (a finite surface modulus, E0 ((z + z0)/c0)^k)
// or at depth (a graded coating of thickness H on a homogeneous substrate). A map runs the FE model of such a
// grading at the ratios a/z0 or a/H of the scene and several k (or, at k = 0, a/w of the error-function grading
// E0 [1 + (m - 1) erfc(z/w)], whose map.md adds a published comparison: cases/model/map_published.h), and tabulates how
// far its force, contact radius and pressure near the axis are from the power-law closed forms at the same depth,
// with the ratio beyond which they are within each threshold ("within 1 % when a/z0 >= ..." for a surface modulus,
// whose limit a/z0 -> inf is the power law, as a/w -> inf is for the error function; "a/H <= ..." for a coating,
// whose limit is a/H -> 0). Two maps drop another idealisation on the power law itself: a homogeneous elastic
// indenter of modulus E1 (the rigid indenter is E1/E0 -> inf), and Coulomb friction mu between a rigid indenter
// and the surface during loading, over several k and nu (frictionless is mu -> 0; "within 1 % when mu <= ...").
//
// Before the map is believed, the same FE model with the power law itself (where the closed forms are exact)
// must agree with them within the scene's tolerances: those are the rows of errors.csv. The map is in
// map.md / map.csv and the plots map-<quantity>.png.
#ifndef GRADCONTACT_CASES_FE_MAP_H
#define GRADCONTACT_CASES_FE_MAP_H

#include "report/map_pipeline.h"
#include "scene/scene.h"

#include <memory>

namespace gradcontact::cases
{
  /// The strategy (report/map_pipeline.h) of a map of a real grading (Map/parameter = surface depth, coating
  /// thickness, erf width), an elastic indenter (indenter modulus) or friction (friction coefficient); throws
  /// std::invalid_argument for another map (Coulomb 3D: fe_coulomb_3d.h; Tabor parameter: fe_cohesive.h; largest
  /// stress: stress_map.h).
  std::unique_ptr<MapStrategy> fe_map_strategy(const Scene &scene);
} // namespace gradcontact::cases

#endif
