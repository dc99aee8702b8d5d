// Coulomb frictional contact of a rigid indenter on the 3D half-space model, solved exactly on the
// surface: the normal contact (Signorini) and the friction law with a free slip direction, node by node,
// no assumption about the stick zone's shape or the slip direction.
//
// Surface problem. The body is linear, so the displacements of the candidate surface nodes are
// u = C F, C the surface compliance (HalfSpace3DSolver::surface_compliance: one solve per nodal force
// component with the factorisation of the far-field-clamped body) and F the nodal forces the indenter
// exerts on the half body: F_i = (Q_x, Q_y, P), P > 0 pressing into the material (+z). The unknowns of
// the symmetry plane's u_y (zero) are left out. The rigid indenter, profile f(r), is at depth d (z into the
// material) and tangential position delta e_x. With the previous converged step marked 0:
//   gap        g_i = f(r_i) - d + u_z,i >= 0,  P_i >= 0,  P_i g_i = 0;
//   slip       s_i = (u_t,i - u_t,i^0) - (delta - delta^0) e_x (the body's surface relative to the indenter);
//   friction   |Q_i| <= mu P_i; |Q_i| < mu P_i => s_i = 0; else Q_i = -mu P_i s_i / |s_i| (Q_i opposes s_i).
// Nodal forces and the nodal Coulomb law: the consistent nodal forces of a FE_Q(p) face are positive for a
// positive traction for the Lagrange elements used, so P_i >= 0 and |Q_i| <= mu P_i are the discrete
// Signorini and Coulomb conditions (the usual node-to-rigid-surface discretisation).
//
// Solver: the primal-dual active set method of Hueber, Stadler and Wohlmuth (SIAM J. Sci. Comput. 30 (2008)
// 572-596) on the surface unknowns: with z_i = Q_i - c s_i and c the stiffness scale 1 / mean(C_zz),
//   node i is in contact when P_i - c g_i > 0, sticks when |z_i| <= mu (P_i - c g_i), slips otherwise with
//   direction t_i = z_i / |z_i| (Q_i = mu P_i t_i);
// each iteration solves the dense linear system of the current sets (LAPACK LU), with the slip law
// Q = mu P t(z) linearised at the current iterate including the derivative of the direction (a
// semi-smooth Newton step; on the symmetry plane the direction is +-x and the law linear); it stops when the
// sets do not change and the directions move by less than `direction_tolerance`, each weighted by its node's
// normal force over the largest (a node with a force near round-off has a direction near round-off). The iteration
// counts are reported; a step that does not converge in `max_iterations` says so (converged = false) and
// is not used as the start of the next step's increments.
//
// Control: depth (d given) or force (F_z of the whole body given, d an unknown). F_x, F_z are the whole body's
// (twice the half's).
#ifndef GRADCONTACT_FEM_COULOMB_CONTACT_3D_H
#define GRADCONTACT_FEM_COULOMB_CONTACT_3D_H

#include <fem/bodies/surface_compliance_3d.h>
#include <fem/bodies/loads.h>

#include <deal.II/base/point.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  enum class NodeStatus
  {
    separated = 0,
    stick     = 1,
    slip      = 2
  };

  struct CoulombParameters
  {
    double       mu                  = 0.3;   ///< friction coefficient, >= 0 (infinity: full stick)
    unsigned int max_iterations      = 200;   ///< active-set iterations per step, >= 1
    /// Largest change of a slip direction at convergence, weighted by the node's normal force over the largest
    /// one (the change of the nodal forces it makes, relative), (0, 1).
    double       direction_tolerance = 1e-10;
    /// A node changes its set only when its criterion is violated by more than this times the largest nodal
    /// normal force, [0, 1e-3): the accuracy to which the contact and stick zones are found.
    double       set_tolerance       = 1e-9;

    void validate() const;
  };

  struct CoulombState3D
  {
    double depth = 0, delta = 0;         ///< d and the indenter's tangential position
    double force_x = 0, force_z = 0;     ///< whole body
    unsigned int n_contact = 0, n_stick = 0, n_slip = 0;
    unsigned int iterations = 0;          ///< active-set iterations of this step
    bool         converged  = false;
    std::string  message;                 ///< why not converged
    std::vector<NodeStatus>            status;       ///< per node
    std::vector<std::array<double, 3>> nodal_force;  ///< (Q_x, Q_y, P) per node, half body
    std::vector<std::array<double, 3>> displacement; ///< u per node
    std::vector<std::array<double, 2>> slip;         ///< s per node (this step's increment)
  };

  /// Where the boundary of a zone (contact or stick) crosses one ray of surface nodes from the axis: between
  /// the outermost node of the ray in the zone and the next node of the ray beyond it.
  struct RayBracket
  {
    unsigned int nodes   = 0; ///< nodes on the ray (0: the mesh has none there, nothing is measured)
    bool         empty   = true; ///< no node of the ray is in the zone
    double       inside  = 0; ///< r of the outermost node in the zone (0: the axis node, or none when empty)
    double       outside = std::numeric_limits<double>::infinity(); ///< r of the next node of the ray (inf: none)
    /// nodes of the ray inside `inside` that are not in the zone (0 for a disc on this ray)
    unsigned int holes   = 0;
    /// The boundary's estimate, the middle of the bracket (`inside` when no node lies beyond; 0 when empty).
    double radius() const { return empty ? 0.0 : std::isfinite(outside) ? 0.5 * (inside + outside) : inside; }
    /// Half the bracket: the resolution of radius() (0 when no node lies beyond or the zone is empty).
    double half_width() const { return !empty && std::isfinite(outside) ? 0.5 * (outside - inside) : 0.0; }
  };

  /// The assumptions of the Ciavarella-Jaeger theory (a stick disc about the axis, slip parallel to the load)
  /// measured on a state: the contact zone (in contact vs separated) and the stick zone (no slip increment in
  /// the step vs slip) along the rays +x and -x (on the symmetry plane) and +y, and the slip directions.
  struct ZoneShape3D
  {
    enum Ray
    {
      plus_x  = 0,
      minus_x = 1,
      plus_y  = 2
    };
    std::array<RayBracket, 3> contact, stick;
    double stick_outer = 0; ///< the largest r of a sticking node (0: none sticks)
    double slip_inner  = std::numeric_limits<double>::infinity(); ///< the smallest r of a slipping node
    /// The largest angle between a slipping node's tangential force and the x axis, radians in [0, pi/2]
    /// (0: every slipping node is loaded along +-x).
    double slip_angle  = 0;
    /// sum |Q_y| / sum |Q| over the slipping nodes: the force-weighted departure of the slip direction from x
    /// (the largest angle is a node's, possibly one with a force at round-off level near the contact edge).
    double slip_force_y = 0;
  };

  /// The shape of the contact and stick zones of `state` on the nodes of `surface`. A node lies on a ray when
  /// its distance from the ray's line is below 1e-9 of the largest node radius.
  ZoneShape3D zone_shape(const SurfaceCompliance3D &surface, const CoulombState3D &state);

  /// The surface compliance without the normal-tangential coupling: the entries of C that give u_z from
  /// tangential forces and u_x, u_y from normal forces set to zero. The contact problem with it is the
  /// idealisation of the chapter's tangential theory (decoupled normal and tangential problems, 9.3.1) on the
  /// same discrete, truncated body: a reference that shares the FE model's discretisation and truncation, so
  /// that the difference from it is the coupling's effect alone.
  SurfaceCompliance3D without_coupling(const SurfaceCompliance3D &surface);

  /// The surface compliance without the y force unknowns: every node's tangential force is along x (Q_y = 0) and
  /// only its x displacement sticks, as on the symmetry plane. With a load in x this is Cattaneo-Mindlin's
  /// assumption (Mindlin, J. Appl. Mech. 16 (1949) 259-268): the tangential traction everywhere parallel to the
  /// load. In the half-space their traction q_x = mu p(a) - mu p(c) gives a rigid u_x and u_y = 0 inside c, so it
  /// solves the contact problem restricted to Q_y = 0 exactly, and with without_coupling at a decoupled pairing the
  /// FE model restricted so converges to 9.80-9.86; what it does not satisfy is Coulomb's slip direction in the
  /// annulus (the slip there has a y part). The free-direction model against this one is that approximation's
  /// effect.
  SurfaceCompliance3D along_load(const SurfaceCompliance3D &surface);

  /// Writes the surface state to `filename` (VTK XML unstructured grid, one vertex per node, the half body
  /// mirrored to the whole disc by y -> -y) for ParaView: point data status (0 separated, 1 stick, 2 slip), the
  /// nodal forces Q (Q_x, Q_y, P), the mean tractions Q / area (shear) and P / area (pressure), u and this step's
  /// slip. Throws std::runtime_error naming the file when it cannot be written, std::invalid_argument for a state
  /// of another surface.
  void write_surface_vtu(const SurfaceCompliance3D &surface, const CoulombState3D &state, const std::string &filename);

  class CoulombContact3D
  {
  public:
    CoulombContact3D(const SurfaceCompliance3D &surface, const Profile &profile, const CoulombParameters &parameters);

    /// One step from the last converged state to depth d and tangential position delta.
    CoulombState3D step_depth(double depth, double delta);
    /// One step to the whole body's normal force F_z (> 0) and tangential position delta.
    CoulombState3D step_force(double force_z, double delta);
    /// Forgets the loading history (the unloaded, unslipped state).
    void reset();
    /// Changes mu for the next steps (e.g. frictionless normal loading, then friction before shearing).
    void set_friction(double mu);

    const SurfaceCompliance3D &surface() const { return compliance; }

  private:
    CoulombState3D solve(bool force_control, double target, double delta);

    const SurfaceCompliance3D compliance;
    const Profile             profile;
    CoulombParameters         parameters;
    std::vector<double>       f;             ///< f(r_i)
    double                    c = 1;         ///< the stiffness scale of the set updates
    CoulombState3D            last;          ///< the last converged state
    std::vector<std::array<double, 2>> direction; ///< slip directions of the last iterate
  };
} // namespace gradcontact::fem

#endif
