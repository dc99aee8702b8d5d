// gradcontact/cases: the Maugis-Dugdale references of a Dugdale cohesive zone (model part): the rows that check an
// FE pull-off against Maugis' closed form on the homogeneous half-space (Maugis, J. Colloid Interface Sci. 150 (1992)
// 243) and against the graded Maugis-Dugdale solution by the MDR (analytic/maugis_dugdale.h), the strength of a
// Tabor parameter, and the Tabor parameter from which the graded pull-off is within a threshold of the chapter's JKR
// pull-off (9.56-9.68).
#ifndef GRADCONTACT_CASES_MAUGIS_DUGDALE_ROWS_H
#define GRADCONTACT_CASES_MAUGIS_DUGDALE_ROWS_H

#include "report/report.h"

#include <analytic/adhesion.h>
#include <analytic/material.h>
#include <analytic/maugis_dugdale.h>
#include <analytic/normal.h>

#include <optional>
#include <string>
#include <variant>

namespace gradcontact::cases
{
  /// A profile of the chapter's JKR closed forms.
  using JkrProfile = std::variant<gradcontact::Paraboloid, gradcontact::PowerLaw>;

  /// The chapter's JKR critical state of `profile` (9.56-9.68).
  gradcontact::jkr::CriticalState jkr_critical(const gradcontact::Medium &m, const JkrProfile &profile, double dgamma,
                                               gradcontact::Control control);

  /// The profile as the tip A r^n of the graded Maugis-Dugdale functions (a paraboloid is n = 2).
  gradcontact::PowerLaw as_tip(const JkrProfile &profile);

  /// The graded Maugis-Dugdale pull-off of `profile` at sigma_0 = `strength` (analytic/maugis_dugdale.h).
  gradcontact::maugis_dugdale::GradedPullOff graded_pull_off(const gradcontact::Medium &medium,
                                                             const JkrProfile &profile, double strength, double dgamma,
                                                             bool force_control);

  /// The Dugdale strength sigma_0 that gives the Tabor parameter `lambda` (header) for the medium, profile and
  /// work of adhesion (maugis_dugdale::strength).
  double cohesive_strength(double lambda, const gradcontact::Medium &medium, const JkrProfile &profile, double dgamma);

  /// The sharp check of a Dugdale pull-off on the homogeneous half-space (paraboloid, k = 0): Maugis-Dugdale's
  /// pull-off force (force control) or critical depth (displacement control, the quantity its search finds
  /// accurately); a failed row when only one of the FE (`fe_instability`) and Maugis-Dugdale has an instability,
  /// none when neither has. lambda in [1e-3, 1e3].
  std::optional<Row> maugis_dugdale_row(double lambda, bool force_control, bool fe_instability, double force, double depth,
                         double dgamma, double R, double E_star, const std::string &metric, const std::string &method,
                         double force_tolerance, double depth_tolerance, unsigned int dofs, double seconds);

  /// The same check on the graded medium, for any k and profile: the Maugis-Dugdale solution of E0 (z/c0)^k by
  /// the MDR (analytic/maugis_dugdale.h; Maugis' closed form at k = 0) at sigma_0 = `strength`. Where only one side
  /// has a displacement-controlled jump, its depth against the other's where the contact vanishes. Throws the
  /// solution's DomainError (e.g. a tip with 2n + k - 1 <= 0).
  std::optional<Row> graded_maugis_dugdale_row(const gradcontact::Medium &medium, const JkrProfile &profile,
                                               double strength, double dgamma, bool force_control, bool fe_instability,
                                               double force, double depth, const std::string &metric,
                                               const std::string &method, double force_tolerance,
                                               double depth_tolerance, unsigned int dofs, double seconds);

  /// The smallest lambda from which the graded Maugis-Dugdale pull-off (force or displacement control) stays within
  /// `threshold` of the chapter's JKR pull-off at every larger lambda up to 1e3 (no jump under displacement control
  /// counts as 100 %): a scan of 4 lambdas per decade from 1e-2, then TOMS 748 on the last crossing. nullopt when
  /// it is not within at 1e3; 1e-2 when it is within everywhere.
  std::optional<double> graded_maugis_dugdale_threshold(const gradcontact::Medium &medium, const JkrProfile &profile,
                                                        double dgamma, bool force_control, double threshold);
} // namespace gradcontact::cases

#endif
