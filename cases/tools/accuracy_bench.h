// gradcontact/cases: the accuracy contract's benchmark (`gradcontact bench --part accuracy`).
//
// It sweeps the FE ladder of fem/accuracy/accuracy.h over a grid of gradings, Poisson ratios, profiles and asked
// tolerances, and over random held-out requests, and compares every answer with the chapter's closed forms (held
// to 1e-13 by independent references, so they act as exact):
//   - the contract: every answer's true error / asked tolerance is at most 1, or the answer is a refusal that names
//     its limit;
//   - the estimate: reliability (true error <= estimate in >= 95 % of the answers, never above 3x the estimate) and
//     efficiency (the estimate at most 10x the true error);
//   - the cost: DoFs, levels and seconds per k and tolerance (a work-precision table).
// Writes accuracy.md and accuracy.csv; the return value is the number of broken promises (an answer that misses its
// tolerance, or a refusal that does not name its limit); the estimate's reliability is a table of the report.
#ifndef GRADCONTACT_CASES_ACCURACY_BENCH_H
#define GRADCONTACT_CASES_ACCURACY_BENCH_H

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  struct AccuracyBenchOptions
  {
    /// The small grid of the ctest (the paraboloid at k = -0.9, 0, 0.9, nu = 0.3, asked 1e-3; two random requests).
    bool quick = false;
    /// The grid's k (each in (-1, 1)); empty: the default grid's. When given, the random held-out requests are not
    /// run: a sweep of a few gradings (`gradcontact bench --part accuracy --k -0.5,0.9`).
    std::vector<double> ks;
  };

  /// Runs the grid and writes accuracy.{md,csv} into `folder`; returns the number of broken promises.
  int run_accuracy_bench(const AccuracyBenchOptions &options, const std::filesystem::path &folder,
                         const std::string &machine);
} // namespace gradcontact::cases

#endif
