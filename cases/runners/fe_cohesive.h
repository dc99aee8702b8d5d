// gradcontact/cases: where the chapter's JKR adhesion holds (Map/parameter = Tabor parameter). JKR (9.45-9.74)
// assumes adhesion of infinitely short range; the Dugdale cohesive zone of fem/adhesion/cohesive_zone.h has the range
// h_0 = dgamma / sigma_0. Its pull-off force against the chapter's, over the Tabor parameter lambda and k, with
// the thresholds a user reads ("within 1 % when lambda >= ...").
//
// The Tabor parameter of a graded medium: lambda = C Delta_l(a_c) / h_0 with the chapter's flat-punch pull-back
// at the force-controlled JKR pull-off (analytic/maugis_dugdale.h, tabor_parameter): Maugis' lambda at k = 0.
//
// Sharp checks (rows of errors.csv): the FE pull-off against the Maugis-Dugdale solution at every lambda
// (analytic/maugis_dugdale.h: Maugis' closed form at k = 0 for the paraboloid, the MDR solution of the graded medium
// otherwise), the force within Tolerances/force, the critical depth under displacement control within
// Tolerances/depth; for every k the deviation from JKR falls between the two largest lambda, and, for the paraboloid,
// the deviation from the DMT pull-off -2 pi dgamma R (rigid sphere, independent of the elasticity) falls between
// the two smallest.
#ifndef GRADCONTACT_CASES_FE_COHESIVE_H
#define GRADCONTACT_CASES_FE_COHESIVE_H

#include "model/maugis_dugdale_rows.h"
#include "report/map_pipeline.h"
#include "report/report.h"
#include "scene/scene.h"

#include <analytic/material.h>
#include <analytic/normal.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>

namespace gradcontact::cases
{
  /// The Lennard-Jones map's path follows the contact edge (fem::SmoothCohesionParameters::follow_edge) on
  /// fem::smooth_cohesion_settings' mesh, whose edge cells resolve the adhesive zone up to lambda = 5 (as closely
  /// as a mesh with those cells over the whole contact; test_smooth_cohesion.cc); the zone narrows like
  /// lambda^-2, so beyond lambda = 5 the edge's cells are divided by (lambda / 5)^2, rounded up to a power of 2
  /// (one model per power), and the band the edge may move in before the next frame by its square root (the
  /// graded mesh's cells grow linearly away from the edge, so that a band of a few edge cells keeps them within
  /// about twice the finest size). Throws
  /// std::invalid_argument beyond lennard_jones_largest_lambda().
  double lennard_jones_edge_refinement(double lambda);
  /// The largest lambda whose edge refinement smooth_cohesion_settings accepts (fem::max_edge_refinement).
  double lennard_jones_largest_lambda();

  /// The strategy (report/map_pipeline.h) of the Tabor-parameter map: a panel per k, a point per lambda (both
  /// controls, the path's states), each point keyed for the point cache beside the report (<reports>/.map-points/,
  /// by the scene's resolved parameters, the point and the program's build), so that jobs of `gradcontact run
  /// --map-shard i/N` (k-major, lambdas ascending) fill it in parallel and a run without it writes the report from
  /// their points. Throws std::invalid_argument for another scene.
  std::unique_ptr<MapStrategy> cohesive_map_strategy(const Scene &scene);
} // namespace gradcontact::cases

#endif
