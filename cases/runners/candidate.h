// gradcontact/cases: a user's candidate closed forms (the Candidate section of a scene), the expressions they are
// written in, and the adhesive and tangential families.
//
// A candidate of the normal family (d(a), F(a), p(r, a), w(r, a) of non-adhesive contact) is run by fe_scene.h. The
// adhesive family (JKR: d(a) and F_N(a) on the adhesive branch, p(r, a), the critical state) and the tangential
// family (Ciavarella-Jaeger: K_T(a), F_x(c, a), u0(c, a), c(F_x, a), the dissipated energy W(F_A, a), u0 on the
// unloading and reloading branches) are checked here against the numerical MDR of the same profile, over a range
// of the varied quantity: contact radii, stick radii, forces, amplitudes. The references are the MDR engine's own
// (analytic/mdr.h: the adhesive foundation w1D(a) = -Delta_l(a) of 9.46 and its critical state by a search of the
// minimum, not 9.48; analytic/mdr_contact.h: PartialSlip), never the chapter's closed forms. With References/fem
// the same candidates meet the FE models at a few points, with Tolerances/*: the adhesive FE of fem/adhesion/adhesion.h
// (its own energy release rate and critical search, the profile a custom indenter) and the Fourier mode-1 FE of
// fem/tangential/fourier_mode1_solver.h (K_T of the tangential flat punch; u0 and F_x under the theory's traction). With
// Adhesion/law = Dugdale or Lennard-Jones the adhesive family also meets the finite-range FE (fem/adhesion/cohesive_zone.h,
// fem/adhesion/smooth_cohesion.h): rows "(JKR idealisation)", how far the candidate's JKR form is from that adhesive.
//
// Every curve gets a table (candidate_<quantity>.csv: x, candidate, MDR, deviation), a plot of candidate and MDR
// against the varied quantity, and a row per point; the largest deviation and where it occurs go into the scene's
// description.
#ifndef GRADCONTACT_CASES_CANDIDATE_H
#define GRADCONTACT_CASES_CANDIDATE_H

#include "scene/expression.h"
#include "report/report.h"
#include "scene/scene.h"

#include <analytic/mdr.h>

#include <deal.II/base/point.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The names a candidate's expressions may use: E0, c0, k, nu, pi; the chapter's coefficients of the material,
  /// h_N (9.5), h_T (9.79), beta, C, cN0 = c_N0 (9.4), cT0 = c_T0 and alpha = cN0 / cT0 (9.78); dgamma
  /// (Adhesion/work of adhesion) and mu (Friction/coefficient); then Candidate/constants, which may
  /// override them.
  std::map<std::string, double> candidate_constants(const Scene &scene);

  /// A candidate's expression of dim variables (cases/scene/expression.h), named by its entry. value() throws
  /// std::domain_error naming Candidate/`entry`, the expression and the point where it is not a finite number.
  template <int dim>
  class CandidateFunction
  {
  public:
    CandidateFunction(const std::string &entry, const std::vector<std::string> &variables,
                      const std::string &expression, const std::map<std::string, double> &constants);
    double value(const dealii::Point<dim> &p) const;

  private:
    std::string entry;
    Expression expression;
  };

  /// The expression of Candidate/`entry` over `variables` (comma-separated, dim of them). A syntax or name error
  /// is std::invalid_argument naming Candidate/`entry`, the expression, the column and the available names.
  template <int dim>
  std::shared_ptr<const CandidateFunction<dim>> parse_candidate_expression(const std::string &entry,
                                                                          const std::string &variables,
                                                                          const std::string &expression,
                                                                          const std::map<std::string, double> &constants);

  /// Candidate/profile for the MDR: f, and f' and f'' from Candidate/profile slope and curvature, or fourth-order
  /// central differences of f where they are not given (f'' then stays empty).
  mdr::Profile candidate_profile(const Scene &scene, const std::map<std::string, double> &constants);

  /// The normal family's d(a) and F_N(a) over Candidate/range times Load/a (and at Load/a) against the numerical MDR
  /// of `profile`: a row per point, a table and a plot per curve with the FE's value at Load/a (`fe_at_a`, by
  /// quantity) as its point; the largest deviations go into result.description. A profile whose indentation pulls
  /// (F_N < 0: a sign slip in its constants) is a failed row.
  void normal_candidate_curves(const Scene &scene, const std::map<std::string, double> &constants,
                               const mdr::Profile &profile, const std::map<std::string, double> &fe_at_a,
                               const std::filesystem::path &folder, SceneResult &result);

  /// The normal family's p(r, a) and w(r, a) at Load/a against the numerical MDR at Outputs/pressure and
  /// displacement radii (r / a): a row per radius, a table and a plot each, with the FE's samples (`fe`, by quantity
  /// and r / a) as its points.
  void normal_profile_curves(const Scene &scene, const std::map<std::string, double> &constants,
                             const mdr::Profile &profile, const std::map<std::string, std::map<double, double>> &fe,
                             const std::filesystem::path &folder, SceneResult &result);

  /// Each runs a candidate scene of its family and writes its tables and plots into `folder`.
  SceneResult run_adhesive_candidate(const Scene &scene, const std::filesystem::path &folder);
  /// A candidate scene (SceneKind::candidate) of any family into `folder`.
  SceneResult run_candidate_scene(const Scene &scene, const std::filesystem::path &folder);
  SceneResult run_tangential_candidate(const Scene &scene, const std::filesystem::path &folder);
} // namespace gradcontact::cases

#endif
