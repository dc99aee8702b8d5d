// gradcontact/cases: the one runner.
//
// A scene is data; the runner is code. Scene kinds so far:
//   *.jsonl  analytic check: each line is an eval request (analytic/README.md) plus optional
//            "name", "tolerance" (relative, default 1e-9) and "abs_floor"; the runner evaluates the
//            closed form and the numerical MDR for it and reports their difference.
// Reports go to <reports>/<scene>/ (errors.csv, errors.md) and <reports>/summary.md, written under a
// temporary name and renamed at the end, so that a failed run leaves no half-written report.
#pragma once

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact run` with its arguments; returns the exit code (non-zero when a comparison fails).
  int run(const std::vector<std::string> &args);
} // namespace gradcontact::cases
