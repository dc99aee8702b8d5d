// gradcontact/cases: applicability maps (SceneKind::map). The chapter's closed forms assume E(z) = E0 (z/c0)^k
// from z = 0 (9.1). A real grading departs from it near the surface (a finite surface modulus, E0 ((z + z0)/c0)^k)
// or at depth (a graded coating of thickness H on a homogeneous substrate). A map runs the FE model of such a
// grading at the ratios a/z0 or a/H of the scene and several k (or, at k = 0, a/w of the error-function grading
// E0 [1 + (m - 1) erfc(z/w)], whose map.md adds a published comparison: cases/map_published.h), and tabulates how
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

#include "report.h"
#include "scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The smallest ratio from which every deviation at a larger ratio of the list is within `threshold`:
  /// log-log interpolation between the last ratio outside and the next one (|deviation| ~ C ratio^-m there).
  /// `ratios` ascending. Empty when the largest ratio is still outside; ratios.front() when none is.
  std::optional<double> threshold_ratio(const std::vector<double> &ratios, const std::vector<double> &deviations,
                                        double threshold);

  /// The text of one threshold cell of map.md: ">= X" (toward_large: the power law is the limit ratio -> inf),
  /// "<= X" (the limit ratio -> 0), "at every ratio (...)" or "not within it ...". `ratios` ascending.
  std::string threshold_cell(const std::vector<double> &ratios, const std::vector<double> &deviations, double threshold,
                             bool toward_large);

  /// The threshold cell of a friction map (the idealisation is mu -> 0): threshold_cell over the finite mu
  /// (ascending), with full stick (mu = inf, when solved) read on its own: "at every mu (full stick included)".
  std::string friction_threshold_cell(const std::vector<double> &mus, const std::vector<double> &deviations,
                                      std::optional<double> full_stick, double threshold);

  /// A threshold as map.md writes it: 0.01 -> "1 %".
  std::string percent(double t);

  /// The head of a threshold table of map.md: "| c1 | c2 | within 1 % <when> | ... |" and its rule line.
  std::string threshold_table_head(const std::vector<std::string> &columns, const std::vector<double> &thresholds,
                                   const std::string &when);

  SceneResult run_map_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases

#endif
