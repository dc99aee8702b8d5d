// gradcontact/cases: the start of every scene runner (model part).
#ifndef GRADCONTACT_CASES_SCENE_START_H
#define GRADCONTACT_CASES_SCENE_START_H

#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>

namespace gradcontact::cases
{
  /// The result of a scene before its rows (name, description, kind), with the scene's resolved entries
  /// written to parameters.prm in `folder`: the start of every scene runner.
  SceneResult started(const Scene &scene, const std::filesystem::path &folder);
} // namespace gradcontact::cases

#endif
