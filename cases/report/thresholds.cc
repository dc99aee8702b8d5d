#include "report/thresholds.h"

#include "report/report.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  std::optional<double> threshold_ratio(const std::vector<double> &ratios, const std::vector<double> &deviations,
                                        const double threshold)
  {
    if (ratios.size() != deviations.size() || ratios.empty())
      throw std::invalid_argument("threshold_ratio: " + std::to_string(ratios.size()) + " ratios and " +
                                  std::to_string(deviations.size()) + " deviations (need the same number, >= 1)");
    std::optional<std::size_t> last_outside;
    for (std::size_t i = 0; i < ratios.size(); ++i)
      if (!(std::abs(deviations[i]) <= threshold))
        last_outside = i;
    if (!last_outside)
      return ratios.front();
    const std::size_t i = *last_outside;
    if (i + 1 == ratios.size())
      return std::nullopt;
    const double d0 = std::abs(deviations[i]), d1 = std::abs(deviations[i + 1]);
    if (!(d1 > 0.) || !std::isfinite(d0) || d1 >= d0)
      return ratios[i + 1];
    const double slope = std::log(ratios[i + 1] / ratios[i]) / std::log(d1 / d0);
    return ratios[i] * std::exp(std::log(threshold / d0) * slope);
  }

  std::string threshold_cell(const std::vector<double> &ratios, const std::vector<double> &deviations,
                             const double threshold, const bool toward_large)
  {
    if (!toward_large)
      {
        // the power law is the limit ratio -> 0: read the map in 1/ratio, which grows toward it
        std::vector<double> inverse, flipped;
        for (std::size_t i = ratios.size(); i-- > 0;)
          {
            inverse.push_back(1. / ratios[i]);
            flipped.push_back(deviations[i]);
          }
        const std::optional<double> at = threshold_ratio(inverse, flipped, threshold);
        if (!at)
          return "not within it down to " + format(ratios.front());
        if (*at == inverse.front() && std::abs(flipped.front()) <= threshold)
          return "at every ratio (up to " + format(ratios.back()) + ")";
        return "<= " + format(1. / *at);
      }
    const std::optional<double> at = threshold_ratio(ratios, deviations, threshold);
    if (!at)
      return "not within it up to " + format(ratios.back());
    if (*at == ratios.front() && std::abs(deviations.front()) <= threshold)
      return "at every ratio (from " + format(ratios.front()) + ")";
    return ">= " + format(*at);
  }

  std::string percent(const double t)
  {
    std::ostringstream o;
    o << t * 100 << " %";
    return o.str();
  }

  Table threshold_table(const std::vector<std::string> &columns, const std::vector<double> &thresholds,
                        const std::string &when)
  {
    std::vector<Column> spec;
    for (const std::string &c : columns)
      spec.push_back(Column::md_only(c));
    for (const double t : thresholds)
      spec.push_back(Column::md_only("within " + percent(t) + " " + when));
    return Table(spec);
  }


  std::string friction_threshold_cell(const std::vector<double> &mus, const std::vector<double> &deviations,
                                      const std::optional<double> full_stick, const double threshold)
  {
    const bool stick_within = full_stick && std::abs(*full_stick) <= threshold;
    if (mus.empty())
      return full_stick ? (stick_within ? "at full stick" : "not at full stick") : "no point";
    const std::string finite = threshold_cell(mus, deviations, threshold, false);
    if (finite.rfind("at every ratio", 0) == 0)
      return stick_within ? "at every mu (full stick included)"
                          : "at every mu up to " + format(mus.back()) + (full_stick ? ", not at full stick" : "");
    return finite;
  }
} // namespace gradcontact::cases
