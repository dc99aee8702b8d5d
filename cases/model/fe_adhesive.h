// gradcontact/cases: the scene's adhesive FE models, built here so that the runners ask for states, not solvers.
//
//   - AdhesiveModel: the JKR model of fem/adhesion/adhesion.h (the energy release rate G = delta^2 K'(a)/(4 pi a)
//     from the FE flat-punch stiffness K(a) of a rigid indenter, 9.51-9.52) for the scene's indenter, work of
//     adhesion and tensile strength, on the meshes of one refinement level or of one level of the accuracy
//     contract's ladder. Its answers are the model's own small types: an adhesive state (a, d, F), a critical
//     state with what its search cost, the surface p(r), w(r) of a state.
//   - DugdaleModel: the cohesive-zone model of fem/adhesion/cohesive_zone.h (Dugdale's law sigma_0, dgamma) on the
//     same meshes, or on the plain meshes of a Tabor-parameter map; its answers are cohesive states of its own type.
//   - trace_lennard_jones: the smooth Lennard-Jones model of fem/adhesion/smooth_cohesion.h along its path;
//     LennardJonesModel, that model built once for the paths of several laws (a Tabor-parameter map's lambdas).
//   - optimal_profile_surface: the surface under the tension p = -sigma_th on r <= a (9.69-9.74).
#ifndef GRADCONTACT_CASES_FE_ADHESIVE_H
#define GRADCONTACT_CASES_FE_ADHESIVE_H

#include "model/fe_model.h"
#include "scene/scene.h"

#include <analytic/states.h>
#include <fem/adhesion/adhesion.h>
#include <fem/adhesion/cohesive_zone.h>
#include <fem/adhesion/smooth_cohesion.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gradcontact::cases
{
  /// The FE settings of the adhesive searches at any contact radius a (they solve at many): with
  /// `on_contract_ladder` false, the scene's settings (fe_settings, the condensed far field) at the uniform
  /// refinement `level`; with it true, level `level` of the ladder of fem/accuracy/accuracy.h at
  /// Discretization/force tolerance, graded toward the axis for a cone's tip.
  fem::SettingsAtRadius adhesive_settings(const Scene &s, const fem::Material &material, unsigned int level,
                                          bool on_contract_ladder);

  /// The FE's control of an adhesive critical state.
  fem::AdhesionControl fe_control(Control control);

  /// An adhesive state of the FE: contact radius, depth (at r = 0; the rim's for the concave punch) and force.
  struct AdhesivePoint
  {
    double radius = 0, depth = 0, force = 0;
    double delta            = 0; ///< the flat-punch pull-back
    double scaling_exponent = 0; ///< a K'(a) / K(a) (1 + k for the power law)
  };

  /// A critical (pull-off) state and what its search cost.
  struct AdhesiveCriticalPoint
  {
    AdhesivePoint state;
    unsigned int  max_dofs     = 0;
    unsigned int  radii_solved = 0; ///< FE radii solved so far (cumulative over the model)
    double        fe_seconds   = 0; ///< FE time so far (cumulative)
  };

  /// An adhesive state with its surface samples: p(r) on r <= a and w(r).
  struct AdhesiveSurface
  {
    AdhesivePoint            state;
    std::vector<fem::Sample> pressure, displacement;
  };

  /// The JKR FE of an adhesive scene (header): Adhesion/work of adhesion dgamma, tensile strength sigma_th, the
  /// search's stencil (Adhesion/stencil ratio, local stencil); under the contract the critical search ends far below
  /// the asked tolerance, since the ladder cannot see its own stopping error (the same on every level).
  class AdhesiveModel
  {
  public:
    /// The scene's indenter (Load/type) on the meshes of adhesive_settings(s, ..., level, on_contract_ladder).
    AdhesiveModel(const Scene &s, unsigned int level, bool on_contract_ladder);
    /// A custom rigid indenter (a candidate's profile) on the scene's meshes at its finest level.
    AdhesiveModel(const Scene &s, const fem::Profile &indenter);
    ~AdhesiveModel();

    /// The adhesive state at contact radius a.
    AdhesivePoint state(double a);
    /// Pull-off of a curved profile under `control`, searched from the radius a0.
    AdhesiveCriticalPoint critical_state(Control control, double a0);
    /// The flat or concave punch of radius a: separation at the periphery (G = dgamma).
    AdhesiveCriticalPoint periphery_state(double a);
    /// The concave punch of radius a: the centre reaches the tensile strength.
    AdhesiveCriticalPoint centre_state(double a);
    /// h0 at which the concave punch's two mechanisms coincide.
    double transition_h0(double a);
    /// The state at contact radius a with p(r) and w(r) at the given radii (one more FE solve).
    AdhesiveSurface surface(double a, const std::vector<double> &pressure_radii,
                            const std::vector<double> &displacement_radii);
    /// The same for a given pull-back delta (the centre mechanism of the concave punch).
    AdhesiveSurface surface_at_delta(double a, double delta, const std::vector<double> &pressure_radii,
                                     const std::vector<double> &displacement_radii);

  private:
    double                                dgamma, tensile_strength;
    std::unique_ptr<fem::AdhesiveContact> contact;
  };

  /// A state of a cohesive zone: contact radius a, the zone's outer end c, depth d and force F (tensile negative), the
  /// DoFs of its last mesh and its seconds; `consistent` false when a check of fem/adhesion/cohesive_zone.h fails,
  /// `message` saying which.
  struct CohesivePoint
  {
    double       radius = 0, zone_radius = 0, depth = 0, force = 0;
    unsigned int n_dofs  = 0;
    double       seconds = 0;
    bool         consistent = true;
    std::string  message;
  };

  /// A pull-off of a cohesive zone and what its search cost; `at_vanishing_contact`: the walk reached the smallest
  /// radius without a minimum, `state` the smallest-radius state solved before it.
  struct CohesiveCriticalPoint
  {
    CohesivePoint state;
    bool          at_vanishing_contact = false;
    unsigned int  states_solved = 0, max_dofs = 0;
    double        seconds = 0;
  };

  /// The cohesive-zone FE of an adhesive paraboloid or power-law scene under Dugdale's law of strength sigma_0 and
  /// Adhesion/work of adhesion, on the meshes of adhesive_settings(s, ..., level, on_contract_ladder).
  class DugdaleModel
  {
  public:
    DugdaleModel(const Scene &s, double sigma0, unsigned int level, bool on_contract_ladder);
    /// A custom rigid indenter (a candidate's profile) under Adhesion/cohesive strength, on the scene's meshes at its
    /// finest level.
    DugdaleModel(const Scene &s, const fem::Profile &indenter);
    /// The scene's indenter under sigma_0 on the meshes of fe_settings at the uniform refinement `level` as they are
    /// (no condensed far field): a body of a Tabor-parameter map, one model per lambda.
    static DugdaleModel on_plain_meshes(const Scene &s, double sigma0, unsigned int level);
    DugdaleModel(DugdaleModel &&) noexcept;
    ~DugdaleModel();

    /// The state of contact radius a (solved on first use, cached).
    CohesivePoint state(double a);

    /// Pull-off under `control`, the walk started at the radius a0.
    CohesiveCriticalPoint critical_state(Control control, double a0);

    /// Every state solved so far, ascending in the contact radius asked for (the first of each pair).
    std::vector<std::pair<double, CohesivePoint>> states() const;

  private:
    explicit DugdaleModel(std::unique_ptr<fem::CohesiveContact> contact);
    std::unique_ptr<fem::CohesiveContact> contact;
  };

  /// The equilibrium path of a rigid `indenter` under the smooth Lennard-Jones law (repulsion included, its largest
  /// attraction Adhesion/cohesive strength, its work Adhesion/work of adhesion), from the surfaces apart through
  /// snap-in and both pull-offs to `stop_force`, on meshes for the critical radius `critical_radius` at the scene's
  /// finest level. The adhesive zone narrows as the cohesive strength grows: a path whose F(d) folds at the nodes
  /// (the edge's cells too coarse for the zone) or that does not converge is traced again with the edge's cells
  /// halved, up to fem::max_edge_refinement.
  struct LennardJonesTrace
  {
    fem::SmoothCohesionPath path;
    double                  separation = 0; ///< the law's equilibrium separation
    std::string             failure;        ///< why no path converged (empty when one did)

    /// The path's state at contact radius a: linear between the two states of the contact branch whose peak radii
    /// (the adhesive zone's inner end, JKR's a as the Tabor parameter grows) bracket a, the last such pair along the
    /// path (the branch toward the pressed contact, past the jumps of snap-in); its depth shifted by the law's
    /// equilibrium separation (the approach beyond the touching of the surfaces, JKR's depth).
    AdhesivePoint state(double a) const;
    /// The pull-off under `control` (its radius the peak radius, its depth shifted as in state()); an error when the
    /// path has none.
    AdhesivePoint pull_off(Control control) const;
    /// Whether the path has a pull-off under `control` (a minimum of F; a jump of d).
    bool has_pull_off(Control control) const;
    /// Every state of the path: its peak radius (the adhesive zone's inner end), its depth shifted as in state().
    std::vector<AdhesivePoint> states() const;
    unsigned int  n_dofs() const { return path.n_dofs; }
    double        seconds() const { return path.seconds; }
  };
  LennardJonesTrace trace_lennard_jones(const Scene &s, const fem::Profile &indenter, double critical_radius,
                                        double stop_force);

  /// The smooth Lennard-Jones FE of the scene's indenter (Load/type) built once for the paths of several laws: its
  /// mesh graded toward `critical_radius` and refined 2^level times, the edge's cells `edge_refinement` times finer
  /// (fem::smooth_cohesion_settings), the path following the contact edge.
  class LennardJonesModel
  {
  public:
    LennardJonesModel(const Scene &s, double critical_radius, unsigned int level, double edge_refinement);
    ~LennardJonesModel();

    /// The path under the law of largest attraction `strength` and work `dgamma`; a trace that throws is a path that
    /// did not converge, its message the error's (`failure` stays empty).
    LennardJonesTrace trace(double strength, double dgamma);

  private:
    std::unique_ptr<fem::SmoothCohesiveContact> contact;
  };

  /// The pull-off of the scene's rigid indenter under the Lennard-Jones law of largest attraction `strength` and
  /// Adhesion/work of adhesion (Derjaguin's integral of the law over the tip, minimised in the depth).
  double rigid_lennard_jones_pull_off(const Scene &s, double strength);

  /// The surface under p = -sigma_th (Adhesion/tensile strength) on r <= Load/a at Outputs/displacement radii, the
  /// optimal profile's FE (9.69-9.74): f_opt(r) = w_c - w(r).
  struct TensionSurface
  {
    unsigned int             dofs     = 0;
    bool                     reliable = true;
    std::string              message; ///< why the solve is not reliable
    double                   centre_displacement = 0; ///< w_c = w(0)
    std::vector<fem::Sample> displacement;
  };
  TensionSurface optimal_profile_surface(const Scene &s, unsigned int level, bool on_contract_ladder);
} // namespace gradcontact::cases

#endif
