// gradcontact/cases: where the chapter's JKR adhesion holds (Map/parameter = Tabor parameter). JKR (9.45-9.74)
// assumes adhesion of infinitely short range; the Dugdale cohesive zone of fem/cohesive_zone.h has the range
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

#include "report.h"
#include "scene.h"

#include <analytic/material.h>
#include <analytic/normal.h>

#include <filesystem>
#include <optional>
#include <string>
#include <variant>

namespace gradcontact::cases
{
  /// A profile of the chapter's JKR closed forms.
  using JkrProfile = std::variant<gradcontact::Paraboloid, gradcontact::PowerLaw>;

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

  /// The Dugdale strength sigma_0 that gives the Tabor parameter `lambda` (header) for the medium, profile and
  /// work of adhesion (maugis_dugdale::strength).
  double cohesive_strength(double lambda, const gradcontact::Medium &medium, const JkrProfile &profile, double dgamma);

  /// The sharp check of a Dugdale pull-off on the homogeneous half-space (paraboloid, k = 0): Maugis-Dugdale's
  /// pull-off force (force control) or critical depth (displacement control, the quantity its search finds
  /// accurately); a failed row when only one of the FE (`fe_instability`) and Maugis-Dugdale has an instability,
  /// none when neither has. lambda in [1e-3, 1e3].
  std::optional<Row> maugis_dugdale_row(double lambda, bool force_control, bool fe_instability, double force, double depth,
                         double dgamma, double R, double E_star, const std::string &metric, const std::string &method,
                         double force_tolerance, double depth_tolerance, unsigned int dofs, double seconds);

  /// The same check on the graded medium, for any k and profile: the Maugis-Dugdale solution of E0 (z/c0)^k by
  /// the MDR (analytic/maugis_dugdale.h; Maugis' closed form at k = 0) at sigma_0 = `strength`. Where only one side
  /// has a displacement-controlled jump, its depth against the other's where the contact vanishes. Throws the
  /// solution's DomainError (e.g. a tip with 2n + k - 1 <= 0).
  std::optional<Row> graded_maugis_dugdale_row(const gradcontact::Medium &medium, const JkrProfile &profile,
                                               double strength, double dgamma, bool force_control, bool fe_instability,
                                               double force, double depth, const std::string &metric,
                                               const std::string &method, double force_tolerance,
                                               double depth_tolerance, unsigned int dofs, double seconds);

  /// The smallest lambda from which the graded Maugis-Dugdale pull-off (force or displacement control) stays within
  /// `threshold` of the chapter's JKR pull-off at every larger lambda up to 1e3 (no jump under displacement control
  /// counts as 100 %): a scan of 4 lambdas per decade from 1e-2, then TOMS 748 on the last crossing. nullopt when
  /// it is not within at 1e3; 1e-2 when it is within everywhere.
  std::optional<double> graded_maugis_dugdale_threshold(const gradcontact::Medium &medium, const JkrProfile &profile,
                                                        double dgamma, bool force_control, double threshold);

  /// The (k, lambda) points of a map that one job computes: those at positions j (k-major, lambdas ascending) with
  /// j % count == index; the counts of the run.
  struct MapShard
  {
    unsigned int index = 0, count = 1;
    unsigned int computed = 0, cached = 0, skipped = 0; ///< solved here, read from the point cache, left to others
  };

  /// The Tabor-parameter map into `folder`. Every (k, lambda) point (both controls, the path's states) goes to a
  /// point cache beside the report (<reports>/.map-points/, keyed by the scene's resolved parameters, the point and
  /// the program's build) and is read from it when there: jobs of `gradcontact run --map-shard i/N` fill it in
  /// parallel, and a run without it writes the report from their points. With `shard` of count > 1 the points of
  /// other shards that are not cached are left out and the report is partial (the runner discards it).
  SceneResult run_cohesive_map(const Scene &scene, const std::filesystem::path &folder, bool verbose, MapShard &shard);
} // namespace gradcontact::cases

#endif
