// gradcontact/cases: tangential scenes (Tangential/study != none). The Fourier mode-1 FE model
// (fem/tangential/fourier_mode1_solver.h) of the graded half-space against chapter 9.3:
//   stiffness     tangential flat punch: K_T against the MDR 2 cT0 a^(1+k) / ((1+k) c0^k), cT0 = h_T E0
//                 (9.78-9.79), alpha = K_N / K_T (K_N: the normal flat punch on the same mesh) against cN0 / cT0,
//                 and at k = 0 Mindlin's K_T = 8 G a / (2 - nu);
//   partial slip  a sphere under the traction of the generalised Ciavarella-Jaeger theorem
//                 tau = mu [p(r; a) - p(r; c)] (9.77, 9.80; the theory's traction is the load by design): F_x,
//                 the mean of u_x over the stick zone r <= c against u0 (9.80), the measured assumption error
//                 (spread of u_x over the stick zone, max |u_y|, both against 0) and the curve F_x(u0) (fig. 9.32);
//   oscillation   +-F_A after loading to A: u0 on the unloading branch (9.83), the hysteresis loop (9.84,
//                 fig. 9.36), the dissipated energy per cycle (9.86 corrected, ERRATA.md; Mindlin-Deresiewicz
//                 9.87 at k = 0) and the FE surface displacement at the points A to E (figs. 9.34-9.35).
#ifndef GRADCONTACT_CASES_FE_TANGENTIAL_H
#define GRADCONTACT_CASES_FE_TANGENTIAL_H

#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>
#include <vector>

namespace gradcontact::cases
{
  /// FE points of a tangential scene in its own units, for figures: partial slip, (u0, F_x) at the stick radii
  /// c/a = i / (load steps), i = 1 .. steps - 1, and Tangential/stick radius; oscillation, the loop: the unloading
  /// branch at `load steps` forces F_A .. -F_A and the reloading branch by its symmetry u_re(F) = -u_un(-F).
  struct FeTangentialCurve
  {
    std::vector<double> displacement, force;
  };
  FeTangentialCurve fe_tangential_curve(const Scene &scene);

  /// Runs a tangential scene (Scene::tangential enabled) and writes its plots into `folder`.
  SceneResult run_tangential_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases

#endif
