// gradcontact/cases: the chapter's figures as analytic curves with checked FE points (`gradcontact figures`).
//
// A figure is data (cases/figures/*.json); one plotter draws them all. Each analytic curve sweeps one request key
// (r, a, Fx, ...) and plots x against y, where each of x and y is the swept value or an eval request
// (analytic/README.md) evaluated at it, optionally scaled, less a fixed request ("minus", scaled alike) and
// divided by another request's value.
//   {"name", "figure": "9.11", "caption": "...", "title", "xlabel", "ylabel", "logx", "logy",
//    "curves": [{"title", "sweep": {"key", "from", "to", "points", "log"},
//                "x": {"sweep": true, "scale": 1} | {"request": {...}, "scale": s, "minus": {...}, "divide_by": {...}},
//                "y": ... }
//              | {"title", "fe": {"scene": "cases/default/x.prm", "set": ["Material/k=0.5"],
//                                 "quantity": "pressure"|"displacement", "radii": [r/a, ...],
//                                 "normaliser": eval quantity of the scene, "normaliser_r": r/a,
//                                 "per_area": times pi a^2}, "check": {...}}
//              | {"title", "fe_adhesion": {"scene", "set", "variants": [[...], ...], "control": "force"|"displacement",
//                                          "a_over_ac": [a/a_c, ...], "pressure_radii": [r/a, ...],
//                                          "x": {"quantity": "radius"|"depth"|"force"|"k"|"r"|"pressure", "scale",
//                                                "divide_by"}, "y": ...}, "check": {...}}
//                (r and pressure: the FE pressure profile of each adhesive state at the pressure radii, r/a in [0, 1))
//              | {"title", "fe_tangential": {...}, "check": {...}}
//              | {"title", "fe_map": {"scene": map scene (a Map section), "set", "where": {column: value, ...},
//                                     "x": column, "y": column}, "check": {...}}
//                (the rows of the map's map.csv whose columns equal "where"; the map report of a `gradcontact run`
//                 in <reports>/<scene name>/ is reused when its parameters.prm is the scene's resolved one, else the
//                 map runs into <reports>/figures/maps/)
//              | {"title", "points": {"x": [...], "y": [...]}, "check": {...}}]}
// A coordinate may also be {"value": v}, a constant (e.g. FE / closed form = 1 where the closed form holds).
// A point set may carry "scale_x", "scale_y" and "offset_y": x -> x scale_x, y -> y scale_y + offset_y.
// {"title", "prescribed": {"x": [...], "y": [...]}} draws an input of the figure (a load history) as a line;
// it is not a result and carries no check.
// Every point set (FE, or tabulated "points") carries
//   "check": {"curves": [titles of analytic curves of the figure], "tolerance": t, "why": "reason for t"}
// or, in a validation figure, {"curves", "measured": true, "why"}: the deviation from the closed form is the
// result (a map), tabulated and never failed on its size, only when not finite or off the drawn curve.
// Checked points:
// each point is compared with the closed form at the same abscissa: the analytic curve's parameter t is
// solved for x(t) = x_point (bisection between the drawn samples that bracket it; exact when x is the swept
// value), then y(t) is evaluated, not interpolated. Where several branches or listed curves bracket the
// abscissa, the one closest in y is the point's reference. The error is |y - y_ref| / max|y| of that drawn
// curve (pressures vanish at the contact edge, so a pointwise relative error would be meaningless there);
// a point fails when the error exceeds t, and when its abscissa lies outside the drawn range of every listed
// curve by more than t times the curve's x-extent (a truncated curve cannot hide a point; a point at the end
// of a curve, e.g. the turning point of a loop, may carry an FE error in its abscissa).
// Output: reports/figures/<name>.png/.svg with the data and the gnuplot script, <name>.csv/.md with one row
// per checked point, <name>.summary.json, and reports/figures/index.md listing every figure drawn into the
// folder so far (the chapter's, numbered 9.x, those beyond it, S.x, then the validation figures); each written under a
// temporary name and renamed when complete. FE point sets are cached in reports/figures/cache/ by the scene's
// resolved parameters, the point set's request and the program's build, so an unchanged figure redraws without the
// FE.
#ifndef GRADCONTACT_CASES_FIGURES_H
#define GRADCONTACT_CASES_FIGURES_H

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact figures <file.json|folder> [--reports DIR] [--no-cache]`; returns 0 when every checked
  /// point is within its tolerance and inside its curve's drawn range, else 1 (every figure is still drawn).
  int figures(const std::vector<std::string> &args);
} // namespace gradcontact::cases

#endif
