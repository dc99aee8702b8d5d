#include "runners/run_scene.h"

#include "runners/candidate.h"
#include "runners/fe_adhesion.h"
#include "runners/fe_cohesive.h"
#include "runners/fe_coulomb_3d.h"
#include "runners/fe_map.h"
#include "runners/fe_scene.h"
#include "runners/fe_tangential.h"
#include "runners/stress_map.h"

#include <stdexcept>
#include <string>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

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
          if (scene.map.parameter == MapParameters::Parameter::coulomb_3d)
            return run_coulomb_map(scene, folder, verbose);
          if (scene.map.parameter == MapParameters::Parameter::largest_stress)
            return run_stress_map(scene, folder, verbose);
          if (scene.map.parameter == MapParameters::Parameter::tabor_parameter)
            {
              MapShard all;
              return run_cohesive_map(scene, folder, verbose, all);
            }
          return run_map_scene(scene, folder, verbose);
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
