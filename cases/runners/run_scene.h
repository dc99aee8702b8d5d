// gradcontact/cases: the runners' one entry (runner part): a scene run by the runner of its kind (decide_kind in
// scene.h), and its report written atomically.
#ifndef GRADCONTACT_CASES_RUN_SCENE_H
#define GRADCONTACT_CASES_RUN_SCENE_H

#include "report/map_pipeline.h"
#include "report/report.h"
#include "scene/scene.h"

#include <filesystem>

namespace gradcontact::cases
{
  /// Runs `scene` by its kind into `folder` (which the caller makes atomically).
  SceneResult run_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose);

  /// Runs a map scene (SceneKind::map) into `folder` through the map pipeline (report/map_pipeline.h) with the
  /// strategy of its Map/parameter; `shard`: the points this job solves (a shard's report is not written).
  SceneResult run_map_scene(const Scene &scene, const std::filesystem::path &folder, bool verbose, MapShard &shard);

  /// Runs `scene` by its kind and writes its report to <reports>/<scene name>/ atomically (as `gradcontact run`
  /// does for one scene, without the summary); used by `gradcontact figures` for the maps it draws.
  SceneResult run_report(const Scene &scene, const std::filesystem::path &reports, bool verbose);
} // namespace gradcontact::cases

#endif
