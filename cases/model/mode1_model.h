// gradcontact/cases: the scene's tangential FE model, the Fourier mode-1 solver of
// fem/tangential/fourier_mode1_solver.h (a tangential load tau(r) e_x on r <= a over the graded half-space; u_x,
// u_y, u_z of the cos/sin mode 1): one mesh, one factorisation, any number of tangential loads, and the normal flat
// punch on the same mesh for K_N / K_T.
#ifndef GRADCONTACT_CASES_MODE1_MODEL_H
#define GRADCONTACT_CASES_MODE1_MODEL_H

#include "scene/scene.h"

#include <fem/bodies/axisymmetric_solver.h>
#include <fem/tangential/fourier_mode1_solver.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace gradcontact::cases
{
  /// Level `level` of the accuracy contract's ladder (fem/accuracy/accuracy.h) at Load/a and Discretization/force
  /// tolerance, in the displacement formulation (mode 1 has no mixed one).
  fem::Settings mode1_contract_settings(const Scene &s, const fem::Material &material, unsigned int level);

  /// The mode-1 FE model of a scene at Load/a: the scene's mesh at its finest refinement (the condensed far field
  /// of Discretization/far field condition), or level `contract_level` of the contract's ladder; graded toward
  /// `refined_radii` by Tangential/stick levels (none: no grading).
  class Mode1Model
  {
  public:
    Mode1Model(const Scene &s, const std::vector<double> &refined_radii,
               std::optional<unsigned int> contract_level = std::nullopt);
    ~Mode1Model();

    /// The rigid tangential flat punch of radius Load/a displaced by delta along x.
    fem::TangentialResult flat_punch(double delta);
    /// tau(r) e_x on r <= a, statistics over r <= stick_radius, `kinks` the radii where tau is not smooth; u sampled
    /// at `displacement_radii`.
    fem::TangentialResult traction(const std::function<double(double)> &tau, double a, double stick_radius,
                                   const std::vector<double> &kinks,
                                   const std::vector<double> &displacement_radii = {});
    /// The partial-slip traction tau = mu [p(r; a) - p(r; c)] (9.77, 9.80) of the normal pressure p(r; b).
    fem::TangentialResult partial_slip(const std::function<double(double, double)> &pressure, double mu, double a,
                                       double c, const std::vector<double> &displacement_radii);
    /// The normal flat punch of depth d on the same mesh and discretisation.
    fem::Result normal_flat_punch(double depth) const;

    unsigned int n_dofs() const;

  private:
    fem::Material                            material;
    fem::Settings                            settings;
    std::unique_ptr<fem::FourierMode1Solver> solver;
  };
} // namespace gradcontact::cases

#endif
