// gradcontact/cases: adhesive (JKR) scenes. The FE model's own critical states (fem/adhesion.h: energy
// release rate from the FE flat-punch stiffness, JKR superposition, minimum of F(a) or d(a)) against the
// closed forms (9.50-9.74) and the numerical MDR; the optimal profile of constant tensile stress from the FE
// surface under p = -sigma_th.
#pragma once

#include "report.h"
#include "scene.h"

#include <filesystem>

namespace gradcontact::cases
{
  /// Runs an adhesive scene (Scene::adhesion enabled) and writes its plots and tables into `folder`.
  SceneResult run_adhesion_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases
