// gradcontact/cases: the Coulomb sphere on the 3D graded half-space (model part; fem/tangential/coulomb_contact_3d.h)
// against the chapter's tangential theory, one loading path: normal loading to the depth d with friction mu_normal,
// then friction mu and a tangential displacement to delta_A, and optionally one cycle to -delta_A and back (9.80-9.86).
//
// At every step the FE state is compared with the closed forms for the half-space (analytic/tangential.h):
//  - the end of the normal loading: F_z against F_N(a), a the contact radius of d (9.24 family);
//  - loading: F_x(delta) against Cattaneo-Mindlin for the graded sphere (9.80), relative to F_x;
//  - unloading and reloading: F_x(delta) against the hysteresis loop (9.84, u_A from 9.85), relative to F_A;
//  - the stick zone along the rays +x, -x, +y (fem::zone_shape) against the stick radius c of 9.80 on loading
//    and the reversal radius b of 9.81 on the branches (inside b nothing slips in a step); its departure from
//    a disc (the spread of the three rays) and the slip direction's largest angle to x;
//  - the loop area (Simpson's rule over the branches' steps) against the dissipated energy (9.86, as
//    tangential::dissipated_energy states it for a rigid sphere on one graded body), and the same rule on the
//    closed-form loop, which measures the rule's own error.
// The closed forms assume the decoupling of the normal and tangential problems (exact for k = 0 with nu = 1/2
// and for Holl's ratio nu = 1/(2 + k)), Cattaneo-Mindlin's tangential traction along the load (not exact: the
// slip in the annulus has a y part; the idealised reference, fem::along_load, takes the assumption onto the FE body)
// and the half-space (the FE body is truncated at L): elsewhere the differences are what friction's coupling does,
// the map's content (cases/validation/map_coulomb_3d_sphere.prm, runners/fe_coulomb_3d.h).
#ifndef GRADCONTACT_CASES_COULOMB_SPHERE_H
#define GRADCONTACT_CASES_COULOMB_SPHERE_H

#include "model/coulomb_body.h"

#include <analytic/states.h>

#include <fem/tangential/coulomb_contact_3d.h>

#include <mpi.h>

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gradcontact::cases
{
  /// Which model a path runs on the same surface compliance.
  enum class CoulombPathKind
  {
    fe,        ///< the FE model (coupled, free slip directions)
    decoupled, ///< fem::without_coupling
    idealised  ///< fem::without_coupling of fem::along_load (the chapter's assumptions)
  };
  /// "fe", "decoupled", "idealised".
  std::string to_string(CoulombPathKind kind);

  struct CoulombSphereStep
  {
    std::string         phase; ///< normal, loading, unloading, reloading
    CoulombPathKind     path = CoulombPathKind::fe; ///< the model of the path the step belongs to
    fem::CoulombState3D state; ///< stored without the per-node vectors
    fem::ZoneShape3D    shape;
    double theory_force_x = std::numeric_limits<double>::quiet_NaN(); ///< 9.80 or 9.84 at delta
    double theory_stick   = std::numeric_limits<double>::quiet_NaN(); ///< c (9.80) or b (9.81) at delta
  };

  /// One loading path of the FE model and its comparisons with the chapter (NaN where not compared).
  struct CoulombPath
  {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<CoulombSphereStep> steps;
    bool         converged      = true; ///< every step
    std::string  message;               ///< of the first step that did not converge
    unsigned int normal_slip    = 0;    ///< the most slipping nodes in a step of the normal loading
    unsigned int max_iterations = 0;    ///< of one step
    double force_z_deviation = nan; ///< F_z / F_N(a) - 1 after the normal loading
    double loading_deviation = nan; ///< max |F_x / F_x(9.80) - 1| over the loading steps
    double branch_deviation  = nan; ///< max |F_x - F_x(9.84)| / F_A over the unloading and reloading steps
    double stick_deviation   = nan; ///< max over tangential steps and rays |c_ray - c| / a(d)
    double stick_resolution  = nan; ///< the largest bracket half-width / a(d) among those
    double out_of_round      = nan; ///< max over tangential steps of the spread of c over the rays / a(d)
    double slip_angle        = 0;   ///< the largest angle of a slipping node's force to x, radians (tangential steps)
    double slip_force_y      = 0;   ///< max over tangential steps of sum |Q_y| / sum |Q| over the slipping nodes
    double energy            = nan; ///< the loop area (Simpson's rule over the branches' steps)
    /// The work of friction over the cycle, sum of mu P |s| over the steps' slip increments: the dissipated
    /// energy without the quadrature of a loop whose branches have a kink wherever a node starts to slip.
    double friction_work     = nan;
    double closure           = nan; ///< |F_x at delta_A after the cycle / on loading - 1|
  };

  struct CoulombSphereResult
  {
    static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    unsigned long long dofs = 0;
    unsigned int       surface_nodes = 0, unknowns = 0, processes = 0;
    double             compliance_seconds = 0, seconds = 0, memory_mb = 0; ///< memory: peak of the largest process
    double a_theory = nan, force_n_theory = nan, force_a_theory = nan; ///< a(d), F_N(a), F_A = F_x(delta_A) (9.80)
    double energy_theory = nan; ///< 9.86
    double energy_rule   = nan; ///< Simpson's rule on the closed-form loop at the FE's points / 9.86 - 1
    CoulombPath fe;             ///< the FE model
    /// With decoupled_reference: the same path with fem::without_coupling(C), and the FE model against it:
    /// the coupling's effect on the same discrete body (NaN where not compared).
    CoulombPath decoupled;
    double coupling_force_z = nan; ///< F_z / F_z(decoupled) - 1 after the normal loading
    double coupling_loading = nan; ///< max |F_x / F_x(decoupled) - 1| over the loading steps
    double coupling_branch  = nan; ///< max |F_x - F_x(decoupled)| / F_x(decoupled, delta_A) over the branches
    double coupling_energy  = nan; ///< loop area / decoupled loop area - 1
    double coupling_stick   = nan; ///< max over tangential steps and rays |c_ray - c_ray(decoupled)| / a(d)
    /// With idealised_reference: the path on fem::without_coupling(fem::along_load(C)) against the chapter (at a
    /// decoupled pairing, the FE's discretisation and truncation alone), and the decoupled path against it: the
    /// effect of the slip direction that Cattaneo-Mindlin fixes along x (needs decoupled_reference).
    CoulombPath idealised;
    double direction_loading = nan; ///< max |F_x(decoupled) / F_x(idealised) - 1| over the loading steps
    double direction_branch  = nan; ///< max |F_x(decoupled) - F_x(idealised)| / F_x(idealised, delta_A), branches
    double direction_energy  = nan; ///< decoupled loop area / idealised loop area - 1
  };

  /// Runs the case's paths on a prepared surface (collective); std::invalid_argument when it is of another k or nu.
  CoulombSphereResult
  run_coulomb_sphere(MPI_Comm communicator, const CoulombSphereCase &c, const CoulombSphereSurface &prepared,
                     const std::function<void(const CoulombSphereStep &, const fem::SurfaceCompliance3D &)> &on_step = {});

  /// Runs the case on `communicator` (collective; MPI must be initialised). `on_step` (every process) sees
  /// each step as it is solved, with its per-node vectors (fem::write_surface_vtu) and the compliance it was
  /// solved on; the stored steps keep none. A step that does not converge stops the path (converged = false,
  /// message).
  CoulombSphereResult
  run_coulomb_sphere(MPI_Comm communicator, const CoulombSphereCase &c,
                     const std::function<void(const CoulombSphereStep &, const fem::SurfaceCompliance3D &)> &on_step = {});

  /// One tangential step of a rigid indenter's 3D Coulomb path: the FE's displacement delta and force F_x, its stick
  /// radius (the mean of the brackets of the rays that have nodes: none when no ray has one) with the largest
  /// bracket half-width, and the work of friction of the step (add_friction_work).
  struct CoulombIndenterStep
  {
    Branch                branch        = Branch::loading;
    double                delta         = 0, force_x = 0;
    std::optional<double> stick_radius;
    double                stick_half_width = 0;
    double                friction_work    = 0;
  };

  /// The stick radius of `step` and its bracket's half-width; a runtime_error when no ray of the stick zone has a
  /// surface node of the 3D mesh.
  std::pair<double, double> fe_stick_radius(const CoulombIndenterStep &step);

  /// The path of a rigid `indenter` on the 3D body of `body` (collective), friction body.mu throughout: normal loading
  /// to body.depth in `steps` steps, then to delta_A = body.delta in as many, and the cycle to -delta_A and back (twice
  /// as many each way). Returns the tangential steps; the first step that does not converge ends the path with a
  /// runtime_error naming its phase, d and delta. `dofs`: of the 3D body.
  std::vector<CoulombIndenterStep> run_coulomb_indenter(MPI_Comm communicator, const CoulombSphereCase &body,
                                                        const fem::Profile &indenter, unsigned int steps,
                                                        unsigned int &dofs);
} // namespace gradcontact::cases

#endif
