// gradcontact/cases: running a .prm scene: the FE model of the graded half-space against the closed
// form and/or the numerical MDR, one FE solve shared by every quantity and reference that needs it.
#pragma once

#include "report.h"
#include "scene.h"

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

  /// Runs the scene and writes its report into `folder` (which the caller makes atomically).
  SceneResult run_prm_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases
