#include "report/convergence_report.h"

#include "report/report.h"

#include <fem/accuracy/accuracy.h>
#include <fem/accuracy/convergence.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  namespace
  {
    /// Errors of 0 are drawn at this floor on the logarithmic axes (below double round-off of 1).
    constexpr double plot_error_floor = 1e-17;
  } // namespace

  double relative_error(const double value, const double reference)
  {
    return std::abs(value - reference) / std::abs(reference);
  }

  double observed_order(const std::vector<Level> &levels)
  {
    std::vector<double> log_h, error;
    for (const Level &l : levels)
      if (l.error > 0.)
        {
          log_h.push_back(-0.5 * std::log(static_cast<double>(l.dofs)));
          error.push_back(l.error);
        }
    if (log_h.size() < 3)
      return std::numeric_limits<double>::quiet_NaN();
    return fem::observed_order(log_h, error);
  }

  void write_convergence(const fs::path &folder, const std::string &scene, const std::string &reference,
                         const std::vector<ConvergenceSeries> &series, const bool plots)
  {
    std::ofstream csv(folder / "convergence.csv"), md(folder / "convergence.md");
    csv << "quantity,refinement,dofs,seconds,value,reference,relative_error,observed_order,change,estimate\n";
    md << "# " << scene << ": convergence\n\nErrors against the " << reference
       << "; the observed order p (error ~ h^p, h ~ DoFs^(-1/2)) is fitted over the last three levels. Next to them, "
          "what the FE knows without a reference: the relative change from the level before, and the Richardson "
          "estimate of the level's error from the changes (fem/accuracy/accuracy.h, degree-2 ratio assumed with two levels, "
          "observed from three).\n\n";
    // A reference that is an idealisation of the model (a table or another grading against the power law): its
    // error is the gap between the two, which refinement does not close.
    const bool idealisation = reference.find("idealisation") != std::string::npos;
    if (idealisation)
      md << "The reference is an idealisation of the model: the error is the gap between the two, which refinement "
            "does not close, and the order fitted to it is not the FE's. The FE's own convergence is the change and "
            "the estimate.\n\n";
    for (std::size_t i = 0; i < series.size(); ++i)
      {
        const ConvergenceSeries &q = series[i];
        const double p = observed_order(q.levels);
        md << "## " << q.quantity
           << "\n\n| refinement | DoFs | s | value | rel. error | rel. change | estimate |\n|---|---|---|---|---|---|---|\n";
        Series errors{"error against the reference", {}, {}, true}, times{errors.title, {}, {}, true};
        Series estimates{"estimate from the levels", {}, {}, true}, estimate_times{estimates.title, {}, {}, true};
        std::vector<double> values;
        for (const Level &l : q.levels)
          {
            values.push_back(l.value);
            const double scale    = std::abs(l.value);
            const double change   = values.size() > 1 ? std::abs(l.value - values[values.size() - 2]) / scale : std::nan("");
            const double estimate = values.size() > 1 ? fem::estimate(values, fem::assumed_ratio(2), scale).relative()
                                                      : std::nan("");
            md << "| " << l.refinement << " | " << l.dofs << " | " << format(l.seconds) << " | " << format(l.value)
               << " | " << format(l.error) << " | " << (values.size() > 1 ? format(change) : "-") << " | "
               << (values.size() > 1 ? format(estimate) : "-") << " |\n";
            csv << csv_quote(q.quantity) << ',' << l.refinement << ',' << l.dofs << ',' << l.seconds << ',' << l.value
                << ',' << q.reference << ',' << l.error << ',' << p << ',' << change << ',' << estimate << '\n';
            errors.x.push_back(l.dofs);
            errors.y.push_back(std::max(l.error, plot_error_floor));
            times.x.push_back(l.seconds);
            times.y.push_back(std::max(l.error, plot_error_floor));
            if (std::isfinite(estimate))
              {
                estimates.x.push_back(l.dofs);
                estimates.y.push_back(std::max(estimate, plot_error_floor));
                estimate_times.x.push_back(l.seconds);
                estimate_times.y.push_back(estimates.y.back());
              }
          }
        md << "\nObserved order over the last three levels: " << format(p)
           << (idealisation ? " (of the gap to the idealisation: not the FE's order)" : "") << "\n\n";
        if (plots)
          {
            const std::string stem = "convergence-" + std::to_string(i);
            write_plot(folder, stem + "-dofs", scene + ": " + q.quantity + " error against DoFs", "DoFs",
                       "relative error", {errors, estimates}, true, true);
            write_plot(folder, stem + "-time", scene + ": " + q.quantity + " error against run time", "seconds",
                       "relative error", {times, estimate_times}, true, true);
          }
      }
  }
} // namespace gradcontact::cases
