// gradcontact/cases: adhesive (JKR) scenes. The FE model's own critical states (fem/adhesion/adhesion.h: energy
// release rate from the FE flat-punch stiffness, JKR superposition, minimum of F(a) or d(a)) against the
// closed forms (9.50-9.74) and the numerical MDR; the optimal profile of constant tensile stress from the FE
// surface under p = -sigma_th.
#ifndef GRADCONTACT_CASES_FE_ADHESION_H
#define GRADCONTACT_CASES_FE_ADHESION_H

#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>
#include <vector>

namespace gradcontact::cases
{
  /// FE adhesive states of the scene's curved profile at a = x a_c, a_c the FE critical radius (force or
  /// displacement control), for figures. With `pressure_radii` (r / a, each in [0, 1)), also the pressure of
  /// each state, p(r) = p_n(r) - delta p_1(r) (the JKR superposition of fem/adhesion/adhesion.h; for the paraboloid the
  /// closed form is 9.53 at that a): pressure[i][j] at r = pressure_radii[j] radius[i], one more FE solve per
  /// state. p(r) is singular at the contact edge r = a (like (1 - r^2/a^2)^(-(1-k)/2)) and zero beyond it, so
  /// r / a = 1 and beyond are refused, before any FE solve.
  struct FeAdhesiveCurve
  {
    std::vector<double> radius, depth, force;
    std::vector<std::vector<double>> pressure; ///< empty without pressure radii
  };
  FeAdhesiveCurve fe_adhesive_curve(const Scene &scene, const std::vector<double> &a_over_ac, bool force_control,
                                    const std::vector<double> &pressure_radii = {});

  /// Runs an adhesive scene (Scene::adhesion enabled) and writes its plots and tables into `folder`.
  SceneResult run_adhesion_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases

#endif
