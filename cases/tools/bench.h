// gradcontact/cases: work-precision benchmarks (`gradcontact bench`, `./vv bench`).
//
// Analytic part: nanoseconds per evaluation of every closed-form family and milliseconds per
// numerical MDR quantity, each with its worst relative error against the 34-digit references of
// tests/data/references.jsonl (an independent mpmath evaluation of the MDR integrals). Several
// repetitions; minimum and median are reported with the machine and the build.
//
// Accuracy part (cases/tools/accuracy_bench.h): the accuracy contract of fem/accuracy/accuracy.h over a grid of k, nu, profiles
// and asked tolerances and over random held-out requests: true error / asked, the estimate's reliability and
// efficiency, the cost per k.
//
// FE part (cases/tools/fe_bench.h): the deal.II model's error against wall time and DoFs, degrees 1-4 on a
// ladder of meshes, flat punch and paraboloid at k = -0.5, 0, 0.5; peer part: the same scenes in
// FreeFem++ (cases/peers/freefem), when FreeFem++ is on PATH, and the ratios of the two.
#ifndef GRADCONTACT_CASES_BENCH_H
#define GRADCONTACT_CASES_BENCH_H

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact bench [--part analytic|fe|peer|oracle|accuracy|all] [--quick] [--reports DIR] [--references FILE]
  /// [--repeat N] [--fe-repeat N] [--peer-scripts DIR] [--scene LIST]`; returns the exit code. `oracle` times
  /// batches of FE eval requests (cases/tools/fe_oracle.h) against their error; `peer` runs
  /// the FE part too (the ratios need both); `--quick` is the small FE set (k = 0, degrees 1-2, two levels
  /// of the normal scenes, the coarsest of the adhesive and tangential ones, one repetition) for the smoke
  /// test and the small accuracy grid; `--scene` (comma-separated) runs only those FE scenes, and their report replaces
  /// the FE report. Writes reports/benchmarks/ through a temporary folder. Returns 1 when the accuracy part finds a
  /// broken promise (cases/tools/accuracy_bench.h).
  int bench(const std::vector<std::string> &args);
} // namespace gradcontact::cases

#endif
