#include "model/fe_contract.h"

#include <iostream>
#include <string>

namespace gradcontact::cases
{
  void run_on_ladder(const fem::Material &material, const fem::Settings &level0, const double tolerance,
                     const bool verbose, SceneResult &result, const LevelSolver &solve,
                     const std::function<void()> &discard)
  {
    fem::LadderRecord record(material, level0, tolerance);
    LadderLevel       last;
    bool              last_recorded = false; // the last level's values are in the record
    std::size_t       n_values      = 0;
    while (record.next_level_allowed())
      {
        const unsigned int level     = record.levels();
        const std::size_t  first_row = result.rows.size();
        last                         = LadderLevel{};
        last_recorded                = false;
        const bool solved            = solve(level, last);
        if (!solved || (level > 0 && last.values.size() != n_values))
          {
            record.fail("level " + std::to_string(level) +
                        (solved ? " compared other quantities than the levels before" : " failed (its row says why)"));
            break;
          }
        n_values      = last.values.size();
        last_recorded = true;
        if (record.add(last.values, last.dofs) || !record.next_level_allowed())
          break;
        result.rows.erase(result.rows.begin() + static_cast<std::ptrdiff_t>(first_row), result.rows.end());
        if (discard)
          discard();
      }
    const std::string verdict = record.met() ? "held" : "refused: " + record.limit();
    for (const auto &[row, value] : last.rows)
      {
        Row &r     = result.rows.at(row);
        r.asked    = record.tolerance();
        r.estimate = last_recorded ? record.estimate(value).relative() : -1.;
        r.contract = verdict;
      }
    if (!record.met())
      result.rows.push_back(failed("FE contract", "FE (contract)", "-",
                                   "tolerance " + format(record.tolerance()) + " not reached: " + record.limit()));
    if (verbose)
      std::cerr << "  contract: " << verdict << " (" << record.levels() << " levels, degree " << record.degree()
                << ")\n";
  }
} // namespace gradcontact::cases
