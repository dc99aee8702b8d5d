// gradcontact/cases: the one runner.
//
// Scene files:
//   *.prm    a deal.II ParameterHandler scene (scene.h; *.json: the same entries), run by its SceneKind:
//            normal, analytic, candidate (cases/runners/fe_scene.h), adhesion (cases/runners/fe_adhesion.h) or tangential
//            (cases/runners/fe_tangential.h).
//   *.jsonl  an analytic check: each line an eval request (analytic/README.md) plus optional "name",
//            "tolerance" (relative, default 1e-9) and "abs_floor": closed form against numerical MDR.
// Reports go to <reports>/<scene>/ (errors.csv, errors.md, convergence.*, plots with their data and
// gnuplot scripts, parameters.prm) and <reports>/summary.md, each written under a temporary name and
// renamed when complete, so that a failed run leaves no half-written report.
#ifndef GRADCONTACT_CASES_RUNNER_H
#define GRADCONTACT_CASES_RUNNER_H

#include "runners/run_scene.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact run` with its arguments; returns the exit code (non-zero when a comparison fails).
  int run(const std::vector<std::string> &args);

  /// `gradcontact sweep <scene.prm> --over Section/key=v1,v2,... [run options]`.
  int sweep(const std::vector<std::string> &args);
} // namespace gradcontact::cases

#endif
