// Convergence studies of the axisymmetric model: one struct in, a table of rows out, so that
// the runner (cases/) writes convergence reports and the [verification] tests assert observed orders
// from the same code.
//
// h refinement: level l uses MeshParameters::global_refinements = first_level + l (every cell halved
// l times, including the edge-graded and far-field cells); the mesh size is h_l = 2^{-l}.
// p refinement: level l uses DiscretizationParameters::degree = first_level + l on the same mesh.
// The observed order at row i >= 2 is the least-squares slope of log|error| against log(h) (h) or
// against the degree (p: the error then falls like exp(-order * p), so the order is the rate
// -d ln|error| / dp) over rows i-2, i-1, i: the last three levels, as the style guide asks.
#ifndef GRADCONTACT_FEM_CONVERGENCE_H
#define GRADCONTACT_FEM_CONVERGENCE_H

#include <fem/bodies/axisymmetric_solver.h>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  enum class Refinement
  {
    h, ///< global refinements first_level, first_level + 1, ...
    p  ///< degrees first_level, first_level + 1, ... (<= 4)
  };

  /// What a study computes at each level: a scalar of the Result.
  enum class StudyQuantity
  {
    force,       ///< Result::force
    depth,       ///< Result::depth
    displacement ///< w(r) at `radius` (Result::displacement)
  };

  struct ConvergenceStudy
  {
    Material                 material;
    Settings                 base;      ///< mesh and discretisation of level 0 (before first_level)
    LoadCase                 load;
    Refinement               refinement  = Refinement::h;
    unsigned int             first_level = 0; ///< refinements (h) or degree (p) of the first row
    unsigned int             n_levels    = 3; ///< >= 1; orders need >= 3
    StudyQuantity            quantity    = StudyQuantity::force;
    double                   radius      = 0; ///< for StudyQuantity::displacement
    double                   reference   = 0; ///< exact value (from an independent source), != 0

    void validate() const;
  };

  struct ConvergenceRow
  {
    unsigned int level;   ///< global refinements (h) or degree (p)
    unsigned int n_dofs;
    double       h;       ///< 2^{-refinements} (h), 1 / degree (p)
    double       value;
    double       error;   ///< value / reference - 1
    double       order;   ///< fitted over this row and the two before; NaN in the first two rows
    double       seconds; ///< wall time of the level (mesh to post-processing)
    bool         reliable;
  };

  /// Runs the levels in turn. Throws std::invalid_argument on bad input (naming the member).
  std::vector<ConvergenceRow> run_convergence_study(const ConvergenceStudy &study);

  /// The least-squares slope of log|y| against x over the last three points (x = log h for h studies).
  double observed_order(const std::vector<double> &x, const std::vector<double> &y);

  /// A Markdown table of the rows (level, DoFs, value, error, order, time).
  void write_markdown(std::ostream &out, const ConvergenceStudy &study, const std::vector<ConvergenceRow> &rows);
} // namespace gradcontact::fem

#endif
