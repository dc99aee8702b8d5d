// gradcontact/cases: the convergence report of a scene with several Discretization/refinements.
//
// Each scalar the scene compares is one series: its value at every refinement level against one reference
// (the first analytic reference of the scene). The observed order p of error ~ h^p, h ~ DoFs^(-1/2) (2D),
// is fem::observed_order (fem/accuracy/convergence.h): the least-squares slope over the last three levels.
// Written into the report folder: convergence.csv, convergence.md and, with plots, the error against DoFs
// and against run time of each series (convergence-<i>-dofs, convergence-<i>-time).
#ifndef GRADCONTACT_CASES_CONVERGENCE_REPORT_H
#define GRADCONTACT_CASES_CONVERGENCE_REPORT_H

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// One level of a refinement study.
  struct Level
  {
    unsigned int refinement;
    unsigned int dofs;
    double seconds;
    double value;
    double error; ///< relative, against the reference of the study
  };

  /// The relative error |value - reference| / |reference|.
  double relative_error(double value, double reference);

  /// The observed order p of error ~ h^p with h = DoFs^(-1/2), fitted by fem::observed_order over the last
  /// three levels with a positive error; NaN when fewer than three such levels exist (two points do not
  /// show whether the error is in its asymptotic range).
  double observed_order(const std::vector<Level> &levels);

  /// One quantity of the study.
  struct ConvergenceSeries
  {
    std::string quantity;
    double reference = 0.;
    std::vector<Level> levels;
  };

  /// convergence.csv and convergence.md in `folder` (and plots when `plots`): `scene` names the report,
  /// `reference` the reference the errors are measured against ("closed form", ...).
  void write_convergence(const std::filesystem::path &folder, const std::string &scene, const std::string &reference,
                         const std::vector<ConvergenceSeries> &series, bool plots);
} // namespace gradcontact::cases

#endif
