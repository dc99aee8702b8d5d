// gradcontact/cases: the normal scenes (SceneKind::normal): the FE model of the graded half-space against the
// closed form and/or the numerical MDR, one FE solve per refinement level shared by every quantity and
// reference that needs it; the analytic ones (References/fem = false: the closed form against the numerical
// MDR); and the candidate ones (a user's closed forms for a profile against the numerical MDR and the FE model).
#ifndef GRADCONTACT_CASES_FE_SCENE_H
#define GRADCONTACT_CASES_FE_SCENE_H

#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// A profile of the normal FE model over r: the contact pressure p(r) or the surface displacement w(r).
  enum class Profile
  {
    pressure,
    displacement
  };
  /// The profile's eval quantity: "pressure", "displacement".
  std::string to_string(Profile p);
  /// The profile whose eval quantity is `name`; none for another quantity.
  std::optional<Profile> profile_of(const std::string &name);
  /// The same for a name read from a request (a figure's JSON): another name is an error naming `where` and it.
  Profile profile_named(const std::string &name, const std::string &where);

  /// FE samples of a profile at radii r/a, for figures: x = r/a, y = the FE value divided by the closed form's
  /// `normaliser` (an eval quantity of the same scene, at r = normaliser_r_over_a a when it is a profile) and
  /// multiplied by pi a^2 when `per_area`.
  struct FeProfile
  {
    std::vector<double> x, y;
  };
  FeProfile fe_profile(const Scene &scene, Profile quantity, const std::vector<double> &radii_over_a,
                       const std::string &normaliser, double normaliser_r_over_a, bool per_area);

  /// Each runs a scene of its kind (decide_kind) and writes its plots and tables into `folder` (which the
  /// caller makes atomically); a scene of another kind is an error.
  SceneResult run_normal_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
  SceneResult run_analytic_scene(const Scene &scene, const std::filesystem::path &folder);
} // namespace gradcontact::cases

#endif
