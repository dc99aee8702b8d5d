// gradcontact/cases: the chapter's figures as analytic curves (`gradcontact figures`).
//
// A figure is data (cases/figures/*.json); one plotter draws them all. Each curve sweeps one request key
// (r, a, Fx, ...) and plots x against y, where each of x and y is the swept value or an eval request
// (analytic/README.md) evaluated at it, optionally scaled and divided by another request's value.
//   {"name", "title", "xlabel", "ylabel", "logx", "logy",
//    "curves": [{"title", "sweep": {"key", "from", "to", "points", "log"},
//                "x": {"sweep": true, "scale": 1} | {"request": {...}, "scale": s, "divide_by": {...}},
//                "y": ... }
//              | {"title", "fe": {"scene": "cases/default/x.prm", "set": ["Material/k=0.5"],
//                                 "quantity": "pressure"|"displacement", "radii": [r/a, ...],
//                                 "normaliser": eval quantity of the scene, "normaliser_r": r/a,
//                                 "per_area": times pi a^2}}]}
// Output: reports/figures/<name>.png/.svg with the data and the gnuplot script.
#ifndef GRADCONTACT_CASES_FIGURES_H
#define GRADCONTACT_CASES_FIGURES_H

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact figures <file.json|folder> [--reports DIR]`; returns the exit code.
  int figures(const std::vector<std::string> &args);
} // namespace gradcontact::cases

#endif
