// gradcontact/cases: a scene runner under Discretization/accuracy = contract (fem/accuracy/accuracy.h). The runner's FE study
// runs once per level of the ladder until the estimate of every FE value it compared is within Discretization/force
// tolerance, or the ladder names its limit. Only the last level's rows stay, each with the asked tolerance, its
// estimate and the verdict; a refusal adds a failed "FE contract" row that names the limit.
#ifndef GRADCONTACT_CASES_FE_CONTRACT_H
#define GRADCONTACT_CASES_FE_CONTRACT_H

#include "report/report.h"

#include <fem/accuracy/accuracy.h>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace gradcontact::cases
{
  /// What one level of a runner's study hands to the contract.
  struct LadderLevel
  {
    std::vector<fem::LadderValue>                    values; ///< every FE value compared, in the same order per level
    std::vector<std::pair<std::size_t, std::size_t>> rows;   ///< (row of the result, index in values)
    unsigned int                                     dofs = 0; ///< the level's largest DoF count

    /// Records an FE value about to be compared (scale: what its relative error divides by).
    void value(const std::string &name, const double fe, const double scale)
    {
      values.push_back({name, fe, std::abs(scale), false});
    }
    /// Records that `row` (an index into SceneResult::rows) compares the last value.
    void row(const std::size_t row) { rows.emplace_back(row, values.size() - 1); }
  };

  /// Solves level `level` into `out` (appending its rows to the result); false when its FE failed (a row says why).
  using LevelSolver = std::function<bool(unsigned int level, LadderLevel &out)>;

  /// The ladder of `material` whose level 0 is `level0` (fem::contract_settings, the runner's own choices applied),
  /// at `tolerance`. `discard` is called when a level's rows give way to the next one's (the runner drops its plot
  /// points there).
  void run_on_ladder(const fem::Material &material, const fem::Settings &level0, double tolerance, bool verbose,
                     SceneResult &result, const LevelSolver &solve, const std::function<void()> &discard = {});
} // namespace gradcontact::cases

#endif
