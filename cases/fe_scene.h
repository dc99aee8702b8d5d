// gradcontact/cases: running a .prm scene: the FE model of the graded half-space against the closed
// form and/or the numerical MDR, one FE solve shared by every quantity and reference that needs it.
#pragma once

#include "report.h"
#include "scene.h"

#include <filesystem>

namespace gradcontact::cases
{
  /// Runs the scene and writes its report into `folder` (which the caller makes atomically).
  SceneResult run_prm_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);
} // namespace gradcontact::cases
