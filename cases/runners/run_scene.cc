#include "runners/run_scene.h"

#include "runners/candidate.h"
#include "runners/fe_adhesion.h"
#include "runners/fe_cohesive.h"
#include "runners/fe_coulomb_3d.h"
#include "runners/fe_map.h"
#include "runners/fe_scene.h"
#include "runners/fe_tangential.h"
#include "runners/stress_map.h"

#include "model/scene_start.h"

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  namespace
  {
    /// The strategy of a map scene's kind: the one place a map's Map/parameter chooses what runs.
    std::unique_ptr<MapStrategy> map_strategy(const Scene &scene)
    {
      using Parameter = MapParameters::Parameter;
      switch (scene.map.parameter)
        {
          case Parameter::coulomb_3d:
            return coulomb_map_strategy(scene);
          case Parameter::largest_stress:
            return stress_map_strategy(scene);
          case Parameter::tabor_parameter:
            return cohesive_map_strategy(scene);
          case Parameter::surface_depth:
          case Parameter::coating_thickness:
          case Parameter::erf_width:
          case Parameter::indenter_modulus:
          case Parameter::friction_coefficient:
            return fe_map_strategy(scene);
          case Parameter::none:
            break;
        }
      throw std::invalid_argument("run_map_scene: scene " + scene.file + " has no Map/parameter");
    }
  } // namespace

  SceneResult run_map_scene(const Scene &scene, const fs::path &folder, const bool verbose, MapShard &shard)
  {
    require_kind(scene, SceneKind::map, "run_map_scene");
    const std::unique_ptr<MapStrategy> map = map_strategy(scene);
    const auto  start  = std::chrono::steady_clock::now();
    SceneResult result = started(scene, folder);
    run_map(*map, MapRun{folder, scene.resolved, scene.outputs.plots, verbose}, shard, result);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

  /// Runs a .prm (or .json) scene by its kind (scene.h).
  SceneResult run_scene(const Scene &scene, const fs::path &folder, const bool verbose)
  {
    switch (scene.kind)
      {
        case SceneKind::normal:
          return run_normal_scene(scene, folder, verbose);
        case SceneKind::analytic:
          return run_analytic_scene(scene, folder);
        case SceneKind::candidate:
          return run_candidate_scene(scene, folder);
        case SceneKind::adhesion:
          return run_adhesion_scene(scene, folder, verbose);
        case SceneKind::tangential:
          return run_tangential_scene(scene, folder, verbose);
        case SceneKind::map:
          {
            MapShard all;
            return run_map_scene(scene, folder, verbose, all);
          }
      }
    throw std::logic_error("run_scene: scene " + scene.file + " has no kind");
  }

  namespace
  {
    /// The parameters a scene ran with, under every plot's title: the medium, and the FE's degree where the FE runs.
    /// A map varies them itself and gets none.
    std::string plot_subtitle(const Scene &s)
    {
      if (s.kind == SceneKind::map)
        return "";
      using Modulus = MaterialParameters::Modulus;
      const MaterialParameters &m = s.material;
      std::string line = "E(z) " + to_string(m.modulus);
      if (m.modulus == Modulus::power_law || m.modulus == Modulus::layered || m.modulus == Modulus::coating)
        line += ", k = " + format(m.k);
      line += ", nu = " + format(m.nu);
      if (s.references.fem)
        line += ", FE degree " + std::to_string(s.discretization.degree);
      return line;
    }
  } // namespace

  SceneResult run_report(const Scene &scene, const fs::path &reports, const bool verbose)
  {
    const PlotSubtitle subtitle(plot_subtitle(scene));
    SceneResult s;
    atomic_folder(reports / scene.info.name, [&](const fs::path &tmp) {
      s = run_scene(scene, tmp, verbose);
      write_errors(s, tmp);
    });
    return s;
  }
} // namespace gradcontact::cases
