// gradcontact/cases: the map of the 3D Coulomb sphere (Map/parameter = Coulomb 3D) against the chapter's
// tangential theory: every body of the map, its paths (model/coulomb_sphere.h) and the map's report.
#ifndef GRADCONTACT_CASES_FE_COULOMB_3D_H
#define GRADCONTACT_CASES_FE_COULOMB_3D_H

#include "report/map_pipeline.h"
#include "scene/scene.h"

#include <memory>

namespace gradcontact::cases
{
  /// The strategy (report/map_pipeline.h) of the map of Map/parameter = Coulomb 3D: for every k of Map/k values and nu of Map/nu values (and
  /// Holl's ratio nu = 1/(2 + k) for k >= 0 with Map/Holl ratio) and every mu of Map/values (Friction/coefficient
  /// when empty; the mu of one body share its surface compliance), the case above with the sphere of Load/R, the mesh
  /// graded toward Load/a (4 sectors, h_edge = a/100, rings of at most a/40 inside the contact, candidate nodes
  /// within 1.15 a, L = Discretization/far field or 1000 a for k >= 0 and 1e5 a for k < 0), loaded to the chapter's depth of contact radius a, then to the chapter's delta_A of F_A =
  /// Tangential/amplitude mu F_N and one cycle, in Tangential/load steps, with the decoupled reference. The map
  /// (map.md, map.csv, map-<quantity>.png) is the coupling's effect (the FE model against its decoupled self);
  /// the decoupled path against the chapter is the FE's floor, split into the idealised path (also along_load)
  /// against the chapter and the decoupled path against the idealised one (the slip direction's effect, its own
  /// threshold table and map-slip_direction-<quantity>.png).
  /// errors.csv: the sharp checks at Holl's ratio (decoupled: the coupling vanishes, and the FE and its idealised
  /// path meet 9.24, 9.80, 9.84, 9.86 within Tolerances/force), and a failed row for every path that did not
  /// converge. Holl's ratio at k = 0 is nu = 1/2, run with the mixed formulation.
  /// The report is written by the root process only. Throws std::invalid_argument for another scene.
  std::unique_ptr<MapStrategy> coulomb_map_strategy(const Scene &scene);
} // namespace gradcontact::cases

#endif
