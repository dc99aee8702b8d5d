// gradcontact/cases: the normal scenes (SceneKind::normal): the FE model of the graded half-space against the
// closed form and/or the numerical MDR, one FE solve per refinement level shared by every quantity and
// reference that needs it; the analytic ones (References/fem = false: the closed form against the numerical
// MDR); and the candidate ones (a user's closed forms for a profile against the numerical MDR and the FE model).
#ifndef GRADCONTACT_CASES_FE_SCENE_H
#define GRADCONTACT_CASES_FE_SCENE_H

#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>

namespace gradcontact::cases
{
  /// FE samples of a profile (quantity "pressure" or "displacement") at radii r/a, for figures: x = r/a,
  /// y = the FE value divided by the closed form's `normaliser` (an eval quantity of the same scene,
  /// at r = normaliser_r_over_a a when it needs r) and multiplied by pi a^2 when `per_area`.
  struct FeProfile
  {
    std::vector<double> x, y;
  };
  FeProfile fe_profile(const Scene &scene, const std::string &quantity, const std::vector<double> &radii_over_a,
                       const std::string &normaliser, double normaliser_r_over_a, bool per_area);

  /// Each runs a scene of its kind (decide_kind) and writes its plots and tables into `folder` (which the
  /// caller makes atomically); a scene of another kind is an error.
  SceneResult run_normal_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
  SceneResult run_analytic_scene(const Scene &scene, const std::filesystem::path &folder);
} // namespace gradcontact::cases

#endif
