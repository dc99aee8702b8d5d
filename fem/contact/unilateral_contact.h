// Unilateral (Signorini) contact, frictionless or with Coulomb friction, of a rigid or elastic axisymmetric
// indenter of any profile with the graded half-space: the contact set is found, not prescribed. It may be a disc, an annulus (a concave
// punch short of complete contact), several rings (a wavy profile), or end at the indenter's own edge
// (a flat punch with rounded edges, a concave punch).
//
// Model. The meridian model of AxisymmetricSolver (the same mesh, element, quadrature and stiffness A,
// fem/bodies/axisymmetric_solver.h). The indenter surface is z = d - f(r) on 0 <= r <= R_i (its extent), d the
// depth at the axis; g(r) = d - f(r) is the displacement it imposes where it touches. The candidates are
// the surface faces with r <= min(candidate radius, R_i): their z-DoFs u_S and their vertices r_k.
//
// Contact (a mortar discretisation, as for a rigid obstacle with a piecewise linear multiplier): the
// pressure is p_h = sum_k p_k psi_k with the hat functions psi_k of the surface vertices, its nodal forces
// are lambda = D p, D_ik = \int phi_i psi_k r dr (phi_i the trace basis of u_z), and the contact
// conditions hold per vertex with the weighted gaps w = D^T (u_S - g):
//   p_k >= 0,  w_k >= 0,  p_k w_k = 0.
// A linear pressure on the vertices stays positive where the nodal forces of a degree >= 2 element change
// sign (at the axis, where the r-weight makes them vanish, and next to a steep edge). Condensed on S,
// u_S = C lambda with C = (A^{-1})_SS, so w = K p - D^T g with K = D^T C D, symmetric positive definite;
// C D takes one back-substitution per vertex with the factorisation of the free problem, built once and
// reused by every load. F_N = 2 pi 1^T lambda.
//
// Algorithm. The primal-dual active set method (Hintermueller, Ito, Kunisch, SIAM J. Optim. 13 (2003)
// 865-888; deal.II step-41) on this linear complementarity problem: with the active vertices I,
//   depth control:  K_II p_I = (D^T g)_I;
//   force control:  K_II p_I - d (D^T 1)_I = -(D^T f)_I,  1^T D p = F / (2 pi);
// then I <- {k in I : p_k >= 0} u {k not in I : w_k < 0}. Its convergence is proven for M-matrices,
// which K is not. Next to a singular edge (the corner of a punch, p ~ (a - r)^{-(1-k)/2}) a linear pressure
// alternates in sign while the force there is compressive: a run of tensile vertices inside a zone is
// released only when the forces (M p)_k of its vertices' shares sum to a tensile force (M the non-negative
// mass matrix of the hat functions); at a zone's end it is released as PDAS would. A set met before (a
// cycle) switches to the primal active-set method of Lawson and Hanson for the equivalent convex problem
// min 1/2 p^T K p - b^T p, p >= 0 (Solving Least Squares Problems, 1974, ch. 23): feasible iterates and a
// falling energy, so it ends for a symmetric positive definite K; it keeps p >= 0 at every vertex. Each
// stage stops with its counts after 50 + 4 m steps (m vertices).
//
// Elastic indenter. The indenter may be a second half-space of the meridian model with its own E(z) and nu,
// meshed like the first (same surface vertices, checked) and carrying the profile f on its surface: the
// contact of two graded bodies with the same k and c0, for which the chapter's equivalent medium (9.4) is
// exact, or a homogeneous elastic sphere of radius R >> a (k = 0, f = r^2/(2R): Hertz's idealisation of the
// sphere as a half-space, its finite size and the load's path through it are not modelled). Frictionless, both
// surfaces carry the same pressure and displace into their own body: the gap is h = f - d + u + u', with
// u' = C' D p, so that K = D^T (C + C') D and d is the approach of the two bodies' far fields.
//
// Friction. With a Coulomb coefficient mu > 0 (mu = inf: full stick) between a rigid indenter and the
// surface, the radial shear q(r) on the surface (+r outward, linear on the same vertices; q = 0 at the axis)
// enters too, and the answer depends on the loading path: the load grows from zero in `load_steps` steps
// (d_j = d (j/N)^2, F_j = F (j/N)^3: evenly spaced contact radii for a paraboloid). At each step, with the
// weighted radial displacements W = D_r^T u_r (D_r the coupling of the hats to the u_r trace) and W' those of
// the previous step, a vertex in contact sticks (W_k = W'_k: the rigid indenter does not move radially, so the
// slip increment is the surface's) with |q_k| <= mu p_k, or slips with q_k = -mu p_k sign(W_k - W'_k); a vertex
// coming into contact during a step carries no shear in that step and sticks from the next one on (when it
// touched within the step is not resolved: an error of the step's size; the points the unloaded indenter
// touches, a flat punch's face, stick from the start). The
// blocks K_zr = D^T C_zr D_r, K_rr = D_r^T C_rr D_r take one back-substitution per vertex, K_rz = K_zr^T
// (reciprocity). Each step is solved by a primal-dual active set on the contact, stick and slip sets (the
// update of Hueber, Stadler and Wohlmuth, SIAM J. Sci. Comput. 30 (2008) 572-596, in one tangential
// direction): stick where |q_k - (W_k - W'_k)/K_rr,kk| <= mu p_k, else slip in the sign of that quantity (a vertex
// kept in contact under a small tensile pressure next to an edge carries q = +-mu p, mu |p| against its slip); the
// normal update is the frictionless one. The systems are not symmetric (dense LU); a cycle or too many steps
// stops with the step, the counts and the set sizes. When the normal and radial responses decouple (a
// surface where pressure causes no radial displacement: nu = 1/(2 + k), Holl's ratio, for E ~ z^k) friction
// changes nothing.
//
// Contact edges. The outer edge of the outermost zone lies between its last vertex in contact and the
// next vertex (`edge_bracket`). Inside it: p ~ K (a - r)^{(1+s)/2} at the last two vertices (9.26, s the
// surface exponent of E), or the gaps outside, h ~ K (r - a)^{(3+s)/2}, when these are monotone; else the
// bracket's middle. `solve_remeshed` remeshes with the mesh graded toward the edge found until it moves by
// less than a tolerance, so that the bracket is the mesh's h_edge.
#ifndef GRADCONTACT_FEM_UNILATERAL_CONTACT_H
#define GRADCONTACT_FEM_UNILATERAL_CONTACT_H

#include <fem/linear_algebra/direct_system.h>
#include <fem/grid/discretization.h>
#include <fem/bodies/loads.h>
#include <fem/modulus/modulus.h>
#include <fem/elasticity/surface_trace.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// A rigid axisymmetric indenter for unilateral contact: its surface is z = d - f(r) for r <= extent.
  struct Indenter
  {
    std::function<double(double)> f;                                       ///< the profile f(r)
    double extent = std::numeric_limits<double>::infinity();               ///< the indenter's radius R_i
    std::string name = "indenter";                                         ///< for messages

    /// A profile of loads.h; the concave paraboloid ends at its radius a.
    static Indenter of(const Profile &profile, double a);
    /// f from a table (r_j, f_j), r ascending from 0, linear in between; the extent is the last r_j.
    static Indenter table(std::vector<double> r, std::vector<double> f);
    /// The same from a file of rows r, f (fem/base/table_file.h), e.g. a measured profile; errors name the file.
    static Indenter from_csv(const std::string &file);
    void validate() const;
  };

  enum class ContactControl
  {
    depth, ///< d given
    force  ///< F_N given, d found
  };

  /// Coulomb friction between the rigid indenter and the surface during loading (see the header).
  struct Friction
  {
    double       coefficient = 0;  ///< mu in [0, inf]: 0 frictionless (one solve, no path), inf full stick
    unsigned int load_steps  = 24; ///< steps of the loading path from zero (mu > 0)
    bool         enabled() const { return coefficient > 0; }
  };

  struct UnilateralLoad
  {
    Indenter       indenter;
    Friction       friction;
    ContactControl control = ContactControl::depth;
    double         depth   = 0; ///< d (depth control)
    double         force   = 0; ///< F_N > 0 (force control)
    void           validate() const;
  };

  /// One contact zone between nodes: r_in = 0 for a disc.
  struct ContactZone
  {
    double r_in  = 0; ///< innermost node in contact
    double r_out = 0; ///< outermost node in contact
  };

  struct UnilateralResult : RunReport
  {
    double depth = 0; ///< d (given or found)
    double force = 0; ///< F_N = 2 pi sum lambda
    /// Ascending r; zones less than 1e-3 r apart are one (next to a smooth edge the linear pressure
    /// alternates in sign over a few vertices of the edge grading).
    std::vector<ContactZone> zones;
    /// The outer edge of the outermost zone: between its last vertex in contact and the next vertex
    /// (`edge_bracket`): the pressure or the gap estimate when one applies, else the bracket's middle;
    /// the indenter's extent when the contact reaches it.
    double                    outer_edge = 0;
    std::pair<double, double> edge_bracket{0, 0};
    bool                      edge_at_extent = false;
    /// The two estimates inside the bracket (NaN when the data do not allow one): from the pressures of
    /// the last two vertices in contact, and from the gaps of the next two nodes outside.
    double edge_from_pressure = std::numeric_limits<double>::quiet_NaN();
    double edge_from_gap      = std::numeric_limits<double>::quiet_NaN();
    unsigned int active_nodes = 0, candidate_nodes = 0;
    unsigned int iterations   = 0; ///< active-set steps (PDAS and the monotone method together)
    unsigned int monotone_steps = 0; ///< of which by the monotone method, after a cycle of PDAS
    std::vector<Sample> pressure; ///< p(r), linear between the vertices; radii beyond the contact are left out (message)
    std::vector<Sample> displacement;   ///< w(r) = u_z(r, 0) of the half-space
    std::vector<Sample> indenter_displacement; ///< the elastic indenter's w'(r), into the indenter (empty: rigid)
    std::vector<Sample> nodal_gap;      ///< h at the candidate nodes (0 in contact)
    std::vector<Sample> nodal_force;    ///< 2 pi lambda at the candidate nodes: the force of each node's ring
    std::vector<Sample> radial_displacement; ///< u_r(r, 0) at the displacement radii

    /// With friction (else empty or NaN): the shear q(r) on the half-space at the pressure radii inside the
    /// contact (+r outward, linear between the vertices); the radius of the stick zone around the axis
    /// (between its last stick vertex and the next vertex, the middle; the outer edge when the contact sticks
    /// to its edge; NaN when the axis is not in contact, e.g. an annulus); the vertices in contact that stick
    /// (with those that came into contact in the last step), slip outward (q < 0) and inward (q > 0); one point
    /// per load step.
    std::vector<Sample> shear;
    double              stick_radius = std::numeric_limits<double>::quiet_NaN();
    unsigned int        stick_nodes = 0, slip_outward_nodes = 0, slip_inward_nodes = 0;
    struct PathPoint
    {
      double       depth = 0, force = 0, outer_edge = 0, stick_radius = 0;
      unsigned int iterations = 0;
    };
    std::vector<PathPoint> path;
  };

  class UnilateralContactSolver
  {
  public:
    /// The mesh of `mesh` (graded toward its contact radius, the expected edge), refined toward
    /// `refinement` (e.g. an inner edge), and the candidates r <= candidate_radius (physical units).
    /// `indenter_body`: none for a rigid indenter; else the indenter is a second half-space of this
    /// material (its own E(z) and nu) on the same mesh, whose surface carries the profile f (see the
    /// header: two graded bodies, 9.4, or a homogeneous sphere of radius R >> a).
    /// Throws std::invalid_argument on bad input.
    UnilateralContactSolver(const Material &material, const MeshParameters &mesh,
                            const DiscretizationParameters &discretization, double candidate_radius,
                            const SurfaceRefinement &refinement = {},
                            const std::optional<Material> &indenter_body = std::nullopt);
    ~UnilateralContactSolver();

    /// Solves one load. std::runtime_error when the active set does not settle (counts in the
    /// message) or the contact reaches the candidate radius.
    UnilateralResult run(const UnilateralLoad &load, const OutputRequest &outputs = {});

    /// Replaces the indenter (none: rigid) and resets its modulus factor to 1; the half-space, its factorisation
    /// and its surface compliance are kept (only the new indenter is meshed and factorised).
    void set_indenter_body(const std::optional<Material> &indenter_body);

    /// Scales the elastic indenter's modulus by `factor` in (0, inf] (its compliance by 1/factor; exact in
    /// linear elasticity at a fixed Poisson ratio; inf: the rigid indenter): one solver serves a sweep of the
    /// indenter's modulus. 1 at construction; std::invalid_argument without an elastic indenter.
    void set_indenter_modulus_factor(double factor);

    unsigned int n_dofs() const;
    unsigned int n_candidates() const { return half_space->candidates.size(); }
    bool         elastic_indenter() const { return indenter != nullptr; }

  private:
    /// One half-space of the meridian model: mesh, element, the stiffness A (factorised once) and the
    /// candidates of its contact surface.
    struct Body
    {
      Body(const Material &material, const MeshParameters &mesh, const DiscretizationParameters &discretization,
           double candidate_radius, const SurfaceRefinement &refinement, const std::string &name);
      ~Body();
      /// The candidates' displacements under the nodal forces of column k of D (one back-substitution).
      dealii::Vector<double> response(const dealii::FullMatrix<double> &D, unsigned int k, double &factorize_seconds);
      /// (A^{-1})_SS D, column by column.
      dealii::FullMatrix<double> compliance(const dealii::FullMatrix<double> &D, double &factorize_seconds);
      /// The response to hats on another body's vertices (the meshes need not match): with D_b the coupling
      /// of those hats to this body's trace (hat_coupling), K = D_b^T A^{-1} D_b (the weighted displacements,
      /// symmetrised) and the displacements at `radii`. Columns from `first_column` on are computed; the
      /// others are copied from `previous` (the same hats).
      struct HatCompliance
      {
        SurfaceCoupling            coupling;
        dealii::FullMatrix<double> K;        ///< m x m
        dealii::FullMatrix<double> at_radii; ///< n x m
      };
      HatCompliance hat_compliance(const std::vector<double> &vertex_r, const std::vector<double> &radii,
                                   unsigned int n_gauss, double &factorize_seconds, unsigned int first_column = 0,
                                   const HatCompliance *previous = nullptr);
      /// The field under the nodal forces `values` on `dofs`, with the energy check.
      dealii::Vector<double> field(const std::vector<dealii::types::global_dof_index> &dofs,
                                   const std::vector<double> &values, EnergyCheck &check);

      const std::string                 name; ///< "half-space" or "indenter", for messages
      const Material                    material;
      const double                      contact_radius, h_edge; ///< the mesh's (they place the surface map)
      const Formulation                 used_formulation;
      dealii::Triangulation<2>          triangulation;
      MeshInfo                          mesh_info;
      const dealii::FESystem<2>         fe;
      dealii::DoFHandler<2>             dof_handler;
      const dealii::MappingQ1<2>        mapping;
      dealii::AffineConstraints<double> constraints;
      DirectSystem                      system; ///< A; no prescribed DoFs (contact enters as nodal forces)
      std::vector<SurfaceFace>                     surface_faces;
      std::vector<dealii::types::global_dof_index> candidates;  ///< surface z-DoFs, ascending r
      std::vector<double>                          candidate_r; ///< their radii
      SurfaceCoupling                              coupling;    ///< D and M of every candidate
      Timings                                      time;
    };

    struct ActiveSetSolution
    {
      std::vector<bool>   active;
      std::vector<double> p, lambda, u, weighted_gap; ///< at the candidates (u: the gap's displacement, both bodies)
      double              depth = 0;
      unsigned int        iterations = 0, monotone_steps = 0;
      /// With friction: the vertex shears, their nodal forces on shear.coupling.dofs, the state of each vertex
      /// (0 stick or free, +1 / -1 slip with q = +mu p / -mu p) and the path.
      std::vector<double>                    q, lambda_r;
      std::vector<int>                       slip;
      std::vector<UnilateralResult::PathPoint> path;
    };
    /// The condensed problem on the leading candidates.
    struct SurfaceOperator
    {
      dealii::FullMatrix<double> D;  ///< coupling of the vertex pressures to the nodal forces
      dealii::FullMatrix<double> CD; ///< (A^{-1})_SS D of the half-space: its surface displacements of each vertex pressure
      dealii::FullMatrix<double> K_half_space; ///< D^T C D
      Body::HatCompliance        indenter; ///< the elastic indenter's at its unscaled modulus (empty: rigid)
      dealii::FullMatrix<double> K;  ///< K_half_space + indenter.K / factor
      dealii::FullMatrix<double> M;  ///< the vertex mass matrix (forces of the vertices' shares of p)
    };
    /// The radial shear of the same vertices (friction): its coupling D_r to the u_r trace (the rows of
    /// constrained DoFs zero), and the blocks of the header; column 0 (the axis, q = 0) is zero.
    struct ShearOperator
    {
      SurfaceCoupling            coupling;
      dealii::FullMatrix<double> Cz;   ///< u_z at the candidates of each vertex shear (n x m)
      dealii::FullMatrix<double> K_zr; ///< D^T Cz: the weighted gaps of each vertex shear
      dealii::FullMatrix<double> K_rr; ///< D_r^T C_rr D_r: the weighted radial displacements of each vertex shear
      dealii::FullMatrix<double> K_rz; ///< K_zr^T: the weighted radial displacements of each vertex pressure
    };
    /// The operator of the candidates the indenter can reach (r <= its extent).
    SurfaceOperator   surface_operator(const Indenter &indenter);
    /// The shear operator of `op`'s vertices (of every candidate: built once and kept).
    ShearOperator     shear_operator(const SurfaceOperator &op);
    ActiveSetSolution solve_frictional(const UnilateralLoad &load, const SurfaceOperator &op, const ShearOperator &shear,
                                       const std::vector<double> &f) const;
    /// C D + the indenter's displacements at the candidates / factor: the gap's displacements of each vertex pressure.
    dealii::FullMatrix<double> gap_compliance(const SurfaceOperator &op) const;
    /// K of `op` at the current factor.
    void combine(SurfaceOperator &op) const;
    ActiveSetSolution solve_active_set(const UnilateralLoad &load, const SurfaceOperator &op,
                                       const std::vector<double> &f) const;
    /// The frictionless problem of solve_active_set on the candidate vertices: the state of an active set and the
    /// monotone method that ends a cycle of PDAS (unilateral_contact.cc).
    class ActiveSetProblem;
    /// The frictional problem of solve_frictional: the state of the contact and stick sets at one load, their
    /// update within a load step and the path's points (frictional_contact.cc).
    class FrictionalProblem;
    /// The frictionless update of the contact set (PDAS with the rule for tensile runs at a singular edge, see
    /// the header): the vertices that violate their condition switch; equal to `active` when none does.
    static std::vector<bool> next_contact_set(const std::vector<bool> &active, const std::vector<double> &p,
                                              const std::vector<double> &weighted_gap, const dealii::FullMatrix<double> &M,
                                              double w_scale);
    /// D^T 1 and D^T f (the weighted unit depth and profile) and f at the vertices (the geometric overlap).
    struct WeightedProfile
    {
      dealii::Vector<double> D1, Df;
      std::vector<double>    f_vertex;
    };
    WeightedProfile weighted_profile(const SurfaceOperator &op, const UnilateralLoad &load,
                                     const std::vector<double> &f) const;
    /// The scale of the weighted gaps of a state (round-off below gap_zero times it counts as zero).
    double gap_scale(const SurfaceOperator &op, const ActiveSetSolution &s, const dealii::Vector<double> &D1) const;
    void              edges(const UnilateralLoad &load, const ActiveSetSolution &s, const std::vector<double> &f,
                            UnilateralResult &result) const;
    void sample(const dealii::Vector<double> &u, const dealii::Vector<double> *u_indenter, const std::vector<double> &p,
                const std::vector<double> &q, const OutputRequest &outputs, UnilateralResult &result) const;

    const DiscretizationParameters discretization;
    const MeshParameters           mesh_parameters;  ///< the half-space's (the indenter's derives from it)
    const double                   candidate_radius;
    const SurfaceRefinement        refinement;
    std::unique_ptr<Body>          half_space;
    std::unique_ptr<Body>          indenter; ///< null: a rigid indenter
    double                         indenter_factor = 1;
    double                         candidate_limit = 0;
    SurfaceOperator                all;       ///< the operator of every candidate
    std::unique_ptr<ShearOperator> all_shear; ///< its shear operator, when a frictional load asked for it
    Timings                        setup_time;
  };

  /// How solve_remeshed remeshes.
  struct Remeshing
  {
    double       tolerance        = 1e-6; ///< relative change of the edge that ends it
    unsigned int max_meshes       = 6;
    double       candidate_factor = 1.6;  ///< candidate radius / the mesh's radius, > 1
    std::optional<Material> indenter_body; ///< an elastic indenter (UnilateralContactSolver); none: rigid
  };

  /// Solves `load` on meshes graded toward the outer edge found, starting at `first_radius`, until the
  /// edge moves by less than the tolerance or twice the mesh's h_edge (relative), or after max_meshes
  /// meshes (then `reliable` is false and the message lists the edges). Settings give everything else
  /// (the mesh's contact radius is replaced). The result of the last mesh; its message records the
  /// sequence of edges.
  UnilateralResult solve_remeshed(const Material &material, const Settings &settings, const UnilateralLoad &load,
                                  double first_radius, const OutputRequest &outputs = {},
                                  const Remeshing &remeshing = {});
} // namespace gradcontact::fem

#endif
