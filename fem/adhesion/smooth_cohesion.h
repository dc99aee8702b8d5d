// Adhesion with a smooth traction-separation law on the graded half-space: the Lennard-Jones law, solved by
// Newton on the FE surface and followed along its whole equilibrium path (approach, snap-in, pull-off under force
// and displacement control). No contact constraint and no JKR or Dugdale assumption: repulsion is the law's own
// branch. Nothing here comes from the MDR or a closed form.
//
// The law (the 6-12 potential integrated over two half-spaces; Muller, Yushchenko and Derjaguin, J. Colloid
// Interface Sci. 77 (1980) 91-101; Greenwood, Proc. R. Soc. Lond. A 453 (1997) 1277-1297, eq. 2.1):
//   sigma(h) = 8 dgamma / (3 eps) [ (eps / h)^3 - (eps / h)^9 ],   attraction positive,
// zero at the equilibrium separation h = eps, largest, 16 dgamma / (9 sqrt 3 eps), at h = 3^{1/6} eps, and
// \int_eps^inf sigma dh = dgamma. Below h = eps / 2 (a repulsion of about 1300 times the largest attraction, never
// reached by an equilibrium of this suite) it continues linearly, so that a Newton trial cannot produce NaN.
// With sigma_0 = its largest stress, Maugis' Tabor parameter of the Dugdale law (fem/adhesion/cohesive_zone.h) becomes
// lambda = 1.16 mu, mu = (R dgamma^2 / (E*^2 eps^3))^{1/3} Tabor's (k = 0).
//
// The equations. The gap between the rigid indenter z = d - f(r) and the surface z = w(r) is
// h(r) = f(r) - d + w(r) (as in fem/adhesion/cohesive_zone.h), the traction sigma(h) pulls the surface toward the
// indenter (-z), the force on the indenter is F = -2 pi \int sigma(h) r dr (compressive positive). The FE
// surface is condensed: w = C b(w) with C the flexibility of the free surface z-DoFs
// (AxisymmetricSolver::surface_flexibility, exact for the FE model: one back substitution per surface DoF) and
// b_i = -\int sigma(h) phi_i r dr (Gauss on every surface face out to the truncation radius, so no traction is
// cut off inside L). Newton on this dense system of the surface DoFs; its Jacobian
// I - C db/dw is assembled face by face.
//
// The path. Under displacement control F(d) is S-shaped at large Tabor parameters (snap-in on approach, a jump
// off the surface on retraction); under force control F has a minimum; and at large Tabor parameters the central
// gap h_c = h(0) = f(0) - d + w(0) folds too (at lambda = 10 a Newton iteration in h_c stalls at the fold). So the
// path is followed by pseudo-arclength continuation (Keller, in Applications of Bifurcation Theory, Academic Press
// 1977, 359-384): the unknowns x = (w, d), the metric |dx|^2 = dd^2 + dh_c^2 + |dw|^2 / n (the plane (h_c, d) alone
// degenerates where the contact grows at nearly fixed d and h_c, as at lambda = 10), the constraint
// t . (x - x') = ds with t the unit tangent of the last state, a tangent predictor, a chord Newton on the bordered
// system (the last state's factorisation, its border row replaced by a Sherman-Morrison update, refactorised where
// it converges slowly and once at the solution for an exact tangent), and steps ds adapted to the factorisations and
// solves it took and to the change of d and F. It starts with the surfaces apart (h_c = start_gap eps, solved with h_c fixed). The critical states
// are the roots of dF/ds (pull-off under force control: the minimum of F) and of dd/ds (the folds of F(d):
// snap-in, the largest d on approach, and pull-off under displacement control, the smallest d after it), found by
// false position in the arclength between the path states that bracket them, each derivative exact from the
// tangent. A path that stops before its minimum of F, or whose Newton does not converge, says so (`message`)
// with its counts.
//
// Following the edge. The adhesive zone at the contact edge is about E* dgamma / sigma_0^2 wide whatever the contact
// radius (its width relative to a_c falls like lambda^-2), so a mesh fine enough for it wherever the edge passes
// (from the axis out to the zero-load radius) has surface DoFs growing like lambda^2 and a dense factorisation like
// lambda^6. For a modulus E0 (z/c0)^k (and the homogeneous one) the FE model is self-similar: the settings' mesh,
// in units of its contact radius a, scaled by s has stiffness s^{1+k} times the original's (strains 1/s, modulus
// s^k, volume s^3), so its surface flexibility is s^{-(1+k)} C at the nodes s r_i; a test checks this against FE
// models built at two radii. With `follow_edge` the path keeps the mesh's finest cells (h_edge, at a) on the
// contact edge r_e (the peak radius of the state, where the attraction is largest): it runs on the frame
// s = max(r_e, smallest_frame a) / a and moves to a new frame when r_e has left the band |r_e - s a| <= edge_band s a.
// The move: the accepted state whose edge left the band (its critical states already located in the old frame) is
// interpolated onto the new frame's nodes (w beyond the old truncation radius L by its far-field decay
// w(L) (L / r)^{1+k}), and Newton finds the new frame's state on the hyperplane of that state's tangent (a step of
// zero arclength; where it does not converge, in up to 16 smaller moves). The critical states are located within a
// frame only, so that the mesh change between frames (of the order of the discretisation error) cannot be taken for
// a fold or a minimum; where a move would flip the sign of dF/ds or dd/ds (a critical state within that change) it
// waits until the next step has passed it in the old frame. No new FE solve: a move costs a Newton solve from the
// interpolated state (two factorisations, typically). The frame is state of the model: one model follows one path
// at a time (as for the law).
#ifndef GRADCONTACT_FEM_SMOOTH_COHESION_H
#define GRADCONTACT_FEM_SMOOTH_COHESION_H

#include <fem/bodies/axisymmetric_solver.h>

#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// The Lennard-Jones law of the header: work of adhesion and equilibrium separation.
  struct LennardJonesLaw
  {
    double work       = 0; ///< dgamma > 0
    double separation = 0; ///< eps > 0, the gap of zero traction

    /// sigma(h), attraction positive.
    double stress(double h) const;
    /// d sigma / dh.
    double slope(double h) const;
    /// 16 dgamma / (9 sqrt 3 eps), at h = 3^{1/6} eps.
    double max_stress() const;
    /// The law with this largest stress (e.g. a Dugdale sigma_0 for the same Tabor parameter) and work.
    static LennardJonesLaw with_max_stress(double max_stress, double work);
    void   validate() const;
  };

  struct SmoothCohesionParameters
  {
    double       start_gap       = 3.0;   ///< central gap of the first state / eps (the surfaces apart)
    double       first_step      = 0.05;  ///< first decrease of the central gap / eps
    double       max_step        = 0.25;  ///< largest decrease of the central gap per step / eps
    double       max_change      = 0.05;  ///< per step: |delta d| <= this (eps + |d|), |delta F| <= this max(|F|, |F_min|)
    double       stop_force      = 0.0;   ///< the path ends at the first F >= this after its minimum of F
    double       min_gap         = 0.5;   ///< ... or at this central gap / eps (the contact pressed hard)
    double       newton_tolerance = 1e-12; ///< |Newton update|_inf / eps that ends the iteration
    unsigned int max_newton      = 30;    ///< linear solves per state (one more for the tangent after a chord)
    unsigned int max_steps       = 2000;  ///< path steps (accepted and rejected)
    double       critical_tolerance = 1e-11; ///< bracket of the arclength of a critical state / eps
    unsigned int quadrature_points  = 8;     ///< Gauss points per surface face
    /// The mesh follows the contact edge (header, "Following the edge"): the model is a self-similar copy of the
    /// settings' mesh scaled so that its edge cells (at `contact_radius` s) stay at the contact edge.
    bool         follow_edge    = false;
    /// A new frame when the edge (or the smallest frame's radius) lies farther than this / the frame's radius from
    /// its centre; [1e-3, 0.5].
    double       edge_band      = 0.02;
    /// The smallest frame / the settings' contact radius, (0, 1]: the frame of the states before and just after the
    /// contact forms (its axis cells, h_surface times this, must resolve the adhesive zone there).
    double       smallest_frame = 0.25;

    void validate() const;
  };

  /// One equilibrium state.
  struct SmoothCohesionState
  {
    double       central_gap    = 0; ///< h_c = h(0)
    double       depth          = 0; ///< d
    double       force          = 0; ///< F, compressive positive
    double       contact_radius = 0; ///< outermost r with h(r) <= eps (compressive traction); 0 when none
    /// Outermost r with h(r) <= 3^{1/6} eps (inside it the attraction has passed its peak: the adhesive zone's inner
    /// end, JKR's contact radius as lambda grows); 0 when none.
    double       peak_radius    = 0;
    /// Derivatives along the path, s its arclength in the metric of the header (dd^2 + dh_c^2 + |dw|^2 / n), s
    /// growing from the surfaces apart toward the contact.
    double       gap_slope      = 0; ///< dh_c / ds
    double       depth_slope    = 0; ///< dd / ds
    double       force_slope    = 0; ///< dF / ds
    unsigned int newton_iterations = 0; ///< linear solves of the chord Newton that found this state
    unsigned int factorisations    = 0; ///< Jacobians it factorised (the last one at the state, for the tangent)
  };

  struct SmoothCohesionPath
  {
    std::vector<SmoothCohesionState> states; ///< along the path, h_c decreasing
    /// Pull-off under force control: the last minimum of F along the path (dF/ds = 0), where retraction from the
    /// contact under force control leaves it.
    bool                has_force_minimum = false;
    SmoothCohesionState force_pull_off;
    /// Snap-in on approach (the first maximum of d) and pull-off under displacement control (the last minimum of d,
    /// where retraction under displacement control jumps off): folds of F(d), dd/ds = 0; none when d grows
    /// monotonically (small Tabor parameter).
    bool                has_snap_in = false, has_depth_jump = false;
    SmoothCohesionState snap_in, depth_pull_off;

    unsigned int depth_folds = 0; ///< sign changes of dd/ds along the path
    unsigned int steps = 0, rejected_steps = 0, newton_iterations = 0, factorisations = 0, critical_evaluations = 0;
    unsigned int n_dofs = 0, surface_dofs = 0;
    unsigned int frames = 1; ///< meshes of the path (1 + the times the edge-following path moved its frame)
    double       flexibility_seconds = 0, seconds = 0;
    bool         converged = true; ///< every Newton converged and the path reached its end
    std::string  message;          ///< why not
  };

  /// The rigid limit (Derjaguin): a rigid indenter of `profile` (f(0) = 0, opening monotonically) over a rigid
  /// flat surface under `law`, F(d) = -2 pi \int_0^inf sigma(f(r) - d) r dr, compressive positive (for the
  /// paraboloid -2 pi R Phi(-d), Phi the law's work beyond a gap: Derjaguin 1934; Muller, Yushchenko and Derjaguin
  /// 1980). Composite Gauss-Legendre (24 points): one panel out to r_eps / 8 (f(r_eps) = eps), then panels doubling
  /// out to f = 1e7 eps; the tail beyond, cut, is (eps / f)^(3 - 2/n) of the force for f ~ r^n: 1e-14 for the
  /// paraboloid, 1e-7 for a cone; n <= 2/3 is refused (the integral diverges). The smallest F over d is the pull-off of every elastic
  /// half-space as the modulus grows (a DMT limit for any tip), found by Brent's method in d over [-3, -0.5] eps.
  struct RigidPullOff
  {
    double depth = 0; ///< d at the smallest F
    double force = 0; ///< the smallest F (negative: tensile)
  };
  /// F(d) of the comment above.
  double rigid_force(const LennardJonesLaw &law, const Profile &profile, double d);
  RigidPullOff rigid_pull_off(const LennardJonesLaw &law, const Profile &profile);

  /// The mesh the model is checked on (tests/fem/test_smooth_cohesion.cc): degree 2, surface cells of 2.5e-3 a at the
  /// expected contact edge a (e.g. the JKR pull-off radius) and 2.5e-2 a at the axis and at the near field's end
  /// 2.5 a (gmsh sizes twice these, halved by its subdivision), divided by `refinement`; the z-halvings of a modulus
  /// E ~ z^s (s > 0) under the whole near field (the law acts everywhere there); the condensed far field at 100 a for a
  /// power law (fem/elasticity/far_field.h), else the clamped one of recommended_settings. `edge_refinement` divides the edge's
  /// cells only (for the edge-following path at large Tabor parameters, whose adhesive zone narrows like lambda^-2).
  /// Alone, this mesh resolves the whole path up to lambda = 3 (k <= 0) and 1 (k = 0.5): beyond, its path folds at
  /// the nodes where the edge passes coarse cells (between the axis and a), which
  /// SmoothCohesionParameters::follow_edge avoids.
  Settings smooth_cohesion_settings(const Material &material, double contact_radius, double refinement = 1,
                                    double edge_refinement = 1);
  /// The largest edge_refinement of smooth_cohesion_settings.
  inline constexpr double max_edge_refinement = 64;

  class SmoothCohesiveContact
  {
  public:
    /// Builds the FE model of `settings` (its mesh must resolve the surface where the law acts; the traction is
    /// integrated out to the truncation radius) and its surface flexibility, which does not depend on the law: one
    /// model serves every law (a Tabor-parameter sweep). The profile must have f(0) = 0 and open monotonically
    /// (paraboloid, power law, cone, custom). Throws std::invalid_argument on bad input.
    SmoothCohesiveContact(const Material &material, const Profile &profile, const Settings &settings,
                          const SmoothCohesionParameters &parameters = {});
    ~SmoothCohesiveContact();

    /// The whole path of the header with its critical states, under `law`.
    SmoothCohesionPath trace(const LennardJonesLaw &law);

    /// The state at one central gap in [min_gap, start_gap] eps, followed from start_gap with the steps of trace.
    /// Throws std::runtime_error when Newton does not converge on the way.
    SmoothCohesionState state(const LennardJonesLaw &law, double central_gap);

    unsigned int n_dofs() const;
    unsigned int surface_dofs() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
  };
} // namespace gradcontact::fem

#endif
