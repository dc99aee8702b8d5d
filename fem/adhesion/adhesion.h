// Adhesive (JKR) contact from the FE model alone: energy release rate, force-depth-radius curves and
// critical states. Nothing here comes from the MDR or any closed form.
//
// The JKR superposition (chapter 9.2, 9.45-9.49, and Johnson-Kendall-Roberts 1971). At contact radius a,
// the adhesive state is the non-adhesive state of that radius (the depth d_n(a) at which the contact edge
// carries no force, force F_n(a); AxisymmetricSolver LoadType::indenter) minus a rigid flat-punch
// translation delta of the contact zone r <= a:
//   d(a) = d_n(a) - delta(a),      F(a) = F_n(a) - K(a) delta(a),
// with K(a) the flat-punch stiffness of radius a. The flat-punch part alone carries the edge singularity,
// so the energy released per unit contact area at fixed displacement is (Griffith, area A = pi a^2)
//   G(a) = (delta^2 / 2) dK/dA = delta^2 K'(a) / (4 pi a),
// and equilibrium G = dgamma (the work of adhesion) gives delta(a) = sqrt(4 pi a dgamma / K'(a)).
// For the power-law medium K(a) = K(1) a^(1+k) (dimensional analysis: E ~ z^k scales out), so
// a K'/K = 1 + k: `scaling_exponent` reports this measured ratio as the check of the FE G(a).
//
// K'(a) is the derivative of the FE stiffness itself: the FE model is solved at several contact radii
// (each with its own mesh graded toward its edge) and ln K, ln d_n, ln F_n are interpolated by the
// polynomial through the `fit_points` solved radii nearest the point of interest, in s = ln a. For the
// power law these logarithms are linear in s, for any smooth E(z) the interpolation error falls as the
// solved radii close in on the point (the critical search adds radii where it needs them).
//
// Critical states (pull-off). Force control: the minimum of F(a); displacement control: the minimum of
// d(a) (the state where dF/da or dd/da vanishes, beyond which the contact separates unstably). A
// secant-like search: minimise the interpolated curve, solve the FE model at the minimiser, refit with
// the nearest radii, until the minimiser moves less than `radius_tolerance` (relative). When the curve
// has no minimum (e.g. the power-law profile with 2 n + k - 1 <= 0) the search walks off to ever larger
// or smaller radii and stops with a "no critical state" error instead of a number.
//
// The concave punch f = -h0 r^2 / a^2 (9.64-9.68) keeps its radius a (complete contact): the rim depth
// d = d0 + h0 and force along the unloading path are d0 = d_n - delta, F = F_n - K delta. It separates at
// the periphery when G = dgamma (delta = sqrt(4 pi a dgamma / K')) or at the centre when the tensile
// stress there reaches sigma_th, p(0) = p_n(0) - delta p_1(0) = -sigma_th (p_1 the unit flat-punch
// pressure); the smaller delta (larger rim depth) governs.
#ifndef GRADCONTACT_FEM_ADHESION_H
#define GRADCONTACT_FEM_ADHESION_H

#include <fem/bodies/axisymmetric_solver.h>

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  struct AdhesionParameters
  {
    double       stencil_ratio    = 1.05; ///< first radii a0 q^-1, a0, a0 q; and the local stencil
    unsigned int fit_points       = 3;    ///< radii in each interpolation (2..5)
    double       radius_tolerance = 1e-6; ///< relative move of the critical radius that ends the search
    unsigned int max_iterations   = 25;   ///< FE solves at new radii per critical search
    bool         local_stencil    = true; ///< finish with radii a_c q^+-1 so the fit is local to a_c

    void validate() const;
  };

  /// The FE data of one contact radius: one mesh, one factorisation, two or three back-substitutions.
  struct RadiusState
  {
    double a         = 0;
    double stiffness = 0; ///< K(a): flat-punch force per depth
    double depth     = 0; ///< d_n(a), the displacement at r = 0 of the non-adhesive state (0: flat punch)
    double force     = 0; ///< F_n(a) (0: flat punch)
    double punch_centre_pressure   = 0; ///< p_1(0), unit flat punch
    double profile_centre_pressure = 0; ///< p_n(0)
    unsigned int n_dofs  = 0;
    double       seconds = 0;
  };

  /// A point of an adhesive curve.
  struct AdhesiveState
  {
    double radius = 0, depth = 0, force = 0;
    double delta = 0;            ///< the flat-punch pull-back
    double stiffness = 0;        ///< K(a)
    double stiffness_slope = 0;  ///< K'(a)
    double scaling_exponent = 0; ///< a K'(a) / K(a) (1 + k for the power law)
  };

  enum class AdhesionControl
  {
    force,
    displacement
  };

  struct AdhesiveCriticalState
  {
    AdhesiveState state;          ///< the critical (pull-off) state; depth: d at r = 0, rim depth for the concave punch
    unsigned int  radii_solved = 0; ///< FE models solved so far (cumulative over this object)
    unsigned int  iterations   = 0; ///< search steps of this critical state
    unsigned int  max_dofs     = 0;
    double        fe_seconds   = 0; ///< FE time so far (cumulative)
    double        search_shift = 0; ///< relative move of a_c caused by the final local stencil
  };

  class AdhesiveContact
  {
  public:
    using SettingsFunction = SettingsAtRadius;

    /// `profile`: the indenter; std::nullopt for the flat punch. `settings(a)` gives the mesh and the
    /// discretisation of the model of contact radius a.
    AdhesiveContact(const Material &material, const std::optional<Profile> &profile, SettingsFunction settings,
                    const AdhesionParameters &parameters = {});

    /// The FE data of contact radius a (solved on first use, cached).
    const RadiusState &state(double a);

    /// The adhesive state at contact radius a for the work of adhesion dgamma > 0.
    AdhesiveState adhesive_state(double a, double dgamma);

    /// The energy release rate at the contact edge for a flat-punch pull-back delta: delta^2 K'/(4 pi a).
    double energy_release_rate(double a, double delta);

    /// Pull-off of a curved profile (paraboloid, power law, cone): search from the radius a0.
    AdhesiveCriticalState critical_state(double dgamma, AdhesionControl control, double a0);

    /// The flat punch or the concave punch of radius a: separation at the periphery (G = dgamma).
    AdhesiveCriticalState periphery_state(double a, double dgamma);
    /// The concave punch of radius a: the centre reaches the tensile strength sigma_th.
    AdhesiveCriticalState centre_state(double a, double dgamma, double sigma_th);
    /// h0 at which the two mechanisms of the concave punch coincide (the states scale linearly with h0).
    double transition_h0(double a, double dgamma, double sigma_th);

    /// The adhesive state at contact radius a with its surface profiles (one more FE solve at a):
    /// p(r) = p_n(r) - delta p_1(r) (r <= a) and w(r) = w_n(r) - delta w_1(r) (9.53-9.54 for the paraboloid).
    struct Profiles
    {
      AdhesiveState       state;
      std::vector<Sample> pressure, displacement;
    };
    Profiles profiles(double a, double dgamma, const std::vector<double> &pressure_radii,
                      const std::vector<double> &displacement_radii);
    /// The same for a given pull-back delta (e.g. the centre mechanism of the concave punch).
    Profiles profiles_at_delta(double a, double delta, const std::vector<double> &pressure_radii,
                               const std::vector<double> &displacement_radii);

    unsigned int radii_solved() const { return nodes.size(); }

  private:
    /// ln K, ln d_n, ln F_n and their s-derivatives at s = ln a from the nearest solved radii.
    struct Local
    {
      double lnK = 0, dlnK = 0, d2lnK = 0;
      double depth = 0, force = 0; ///< d_n, F_n (interpolated in ln for curved profiles)
    };
    Local         interpolate(double s) const;
    AdhesiveState evaluate(double s, double dgamma) const;
    void          ensure_stencil(double s);
    AdhesiveCriticalState summary(const AdhesiveState &state, unsigned int iterations) const;
    double        concave_offset() const; ///< h0 for the concave punch (rim = centre + h0), else 0

    const Material                  material;
    const std::optional<Profile>    profile;
    const SettingsFunction          settings;
    const AdhesionParameters        parameters;
    std::map<double, RadiusState>   nodes; ///< by s = ln a
  };
} // namespace gradcontact::fem

#endif
