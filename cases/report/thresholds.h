// gradcontact/cases: the thresholds of an applicability map's tables (report part): from which ratio of a map the
// deviations from an idealisation stay within a threshold, and the cells and heads of map.md that say so.
#ifndef GRADCONTACT_CASES_THRESHOLDS_H
#define GRADCONTACT_CASES_THRESHOLDS_H

#include "report/table.h"

#include <optional>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The smallest ratio from which every deviation at a larger ratio of the list is within `threshold`:
  /// log-log interpolation between the last ratio outside and the next one (|deviation| ~ C ratio^-m there).
  /// `ratios` ascending. Empty when the largest ratio is still outside; ratios.front() when none is.
  std::optional<double> threshold_ratio(const std::vector<double> &ratios, const std::vector<double> &deviations,
                                        double threshold);

  /// The text of one threshold cell of map.md: ">= X" (toward_large: the power law is the limit ratio -> inf),
  /// "<= X" (the limit ratio -> 0), "at every ratio (...)" or "not within it ...". `ratios` ascending.
  std::string threshold_cell(const std::vector<double> &ratios, const std::vector<double> &deviations, double threshold,
                             bool toward_large);

  /// The threshold cell of a friction map (the idealisation is mu -> 0): threshold_cell over the finite mu
  /// (ascending), with full stick (mu = inf, when solved) read on its own: "at every mu (full stick included)".
  std::string friction_threshold_cell(const std::vector<double> &mus, const std::vector<double> &deviations,
                                      std::optional<double> full_stick, double threshold);

  /// A threshold as map.md writes it: 0.01 -> "1 %".
  std::string percent(double t);

  /// A threshold table of map.md, empty: the columns `columns` (what a row is about: k, a control, a quantity),
  /// then one "within <t> <when>" per threshold, whose cells are threshold_cell's texts. Markdown only (map.csv
  /// holds the points the thresholds are read from).
  Table threshold_table(const std::vector<std::string> &columns, const std::vector<double> &thresholds,
                        const std::string &when);
} // namespace gradcontact::cases

#endif
