// Axisymmetric (Fourier mode 0) linear elasticity of a graded half-space with frictionless normal
// contact of rigid indenters: the FE reference of gradcontact.
//
// Geometry and unknowns. The meridian plane (r, z), z into the material, is the deal.II dim = 2 domain
// with x = r, y = z (fem/grid/mesh.h). The displacement is u = (u_r, u_z), with u_z > 0 into the material.
//
// Weak form. With the strains of an axisymmetric field
//   eps_rr = d u_r / dr,  eps_zz = d u_z / dz,  eps_tt = u_r / r,  gamma_rz = d u_r / dz + d u_z / dr,
// and the Lame parameters of the pointwise modulus, lambda(z) = E(z) nu / ((1 + nu)(1 - 2 nu)),
// mu(z) = E(z) / (2 (1 + nu)),
//   a(u, v) = \int_\Omega [ lambda tr eps(u) tr eps(v) + 2 mu (eps_rr eps_rr + eps_zz eps_zz + eps_tt eps_tt)
//                          + mu gamma_rz(u) gamma_rz(v) ] r dr dz,
//   l(v)    = \int_{z=0} p(r) v_z r dr.
// Forces are 2 pi times the meridian-plane quantities.
//
// Mixed (displacement-pressure, Taylor-Hood) formulation, DiscretizationParameters::formulation. As nu
// -> 1/2 the term lambda tr eps tr eps locks the displacement elements (the force survives at degree 3,
// the pressure p(r) oscillates, fem/doc/model.md, "Mixed formulation"). With q = lambda div u,
// div u = tr eps = d u_r/dr + u_r/r + d u_z/dz, the unknowns (u, q) in FE_Q(p)^2 x FE_Q(p-1) solve the
// symmetric saddle-point problem
//   \int [ 2 mu (eps_rr eps_rr + eps_zz eps_zz + eps_tt eps_tt) + mu gamma_rz gamma_rz ](u, v) r dr dz
//     + \int q div v r dr dz = l(v)                      for all v,
//   \int s div u r dr dz - \int s q / lambda r dr dz = 0  for all s,
// with 1/lambda = (1 + nu)(1 - 2 nu) / (nu E(z)) = 0 at nu = 1/2 (the incompressible limit, and with
// E = E0 z / c0 the Gibson medium 9.42). Eliminating q gives back a(u, v); at the discrete solution
// U.AU = a(u, u) + \int q div u r = the strain energy, so the energy check, the reactions and every
// surface quantity below are the same expressions on the displacement DoFs of the larger system.
// UMFPACK's LU factorises the indefinite matrix (pivoting; fem/linear_algebra/direct_system.h). Boundary conditions: u_r = 0 on the axis (r = 0);
// u = 0 on the truncation boundary at L; on z = 0 either traction free, a prescribed pressure, or the
// rigid indenter. The cells touching z = 0 are integrated with a Gauss-Jacobi rule exact for z^s times a
// polynomial when E ~ z^s there (fem/base/gauss_jacobi.h).
//
// Loads (LoadCase):
//   flat_punch         u_z = d on r <= a, no shear; force F(d) (9.16).
//   indenter           rigid profile f(r) (paraboloid, cone, power law) under contact-radius control: the
//                      contact zone is r <= a (a = MeshParameters::contact_radius, a mesh node). With
//                      u = d u1 + u2, u1 the unit flat punch and u2 the solution for u_z = -f(r) on r <= a,
//                      the depth is the one at which the edge node just carries no force,
//                      R_edge(d) = d R1_edge + R2_edge = 0: the discrete state in which the node at a is
//                      exactly at the transition between contact and separation (the active set of a
//                      primal-dual active-set solution at that depth). Then F = d F1 + F2 (9.20, 9.26,
//                      9.30). Every contact node is checked for compression and every free node for a
//                      non-negative gap; a violation is reported, not hidden.
//   concave_punch      f = -h0 r^2 / a^2 pressed to centre displacement d0 (9.31-9.35); complete contact is
//                      checked (p >= 0 everywhere in r <= a) and reported.
//   constant_pressure  p = p0 on r <= a (9.37-9.40); the depth reported is the centre displacement w_c.
//   A cohesion (LoadCase::cohesion, indenter and constant pressure) adds a uniform tension sigma_0 on
//   r <= c, integrated exactly on the faces (split at c, which need not be a node): for the indenter the
//   edge condition then says that the contact pressure p + sigma_0 vanishes at the edge node (the total
//   traction is continuous at a, as in the Maugis-Dugdale model); F includes -pi c^2 sigma_0 and p(r) is
//   the total traction.
//
// Force. From the reaction, F = 2 pi sum_{i in contact} (A u - b)_i = 2 pi [a(u, phi) - l(phi)] with phi
// the sum of the contact z-basis functions (1 on the contact); far more accurate than integrating
// sigma_zz, whose stress is the derivative of the field and singular at the edge. The pressure p(r) is
// recovered consistently from the same nodal reactions, M p = R with M the r-weighted mass matrix of the
// contact line.
//
// Everything that does not depend on the load (mesh, DoFs, constraints, sparsity, stiffness matrix and
// the factorisations) is built once, in the constructor or on first use, and reused by every
// call of run().
#ifndef GRADCONTACT_FEM_AXISYMMETRIC_SOLVER_H
#define GRADCONTACT_FEM_AXISYMMETRIC_SOLVER_H

#include <fem/linear_algebra/direct_system.h>
#include <fem/grid/discretization.h>
#include <fem/bodies/loads.h>
#include <fem/grid/mesh.h>
#include <fem/modulus/modulus.h>
#include <fem/elasticity/stress_recovery.h>
#include <fem/elasticity/surface_trace.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gradcontact::fem
{
  struct Result : RunReport
  {
    double force          = 0; ///< F_N, compressive positive
    double contact_radius = 0; ///< a (the mesh's under contact-radius control; found under depth or
                               ///< force control, linearly interpolated between the last node in
                               ///< contact and the first one out)
    double edge_node_radius = 0;  ///< r of the outermost surface vertex in contact
    unsigned int active_set_size = 0; ///< surface z-DoFs in contact
    unsigned int iterations      = 0; ///< trial contact sets (depth or force control), else 0
    double depth          = 0; ///< d; d0 for the concave punch; w_c for constant pressure
    std::vector<Sample> pressure;     ///< p(r), compressive positive
    std::vector<Sample> displacement; ///< w(r) = u_z(r, 0), into the material positive
    /// The recovered stresses at OutputRequest::stress_points, in its order (fem/elasticity/stress_recovery.h).
    std::vector<StressValue> stress;

    /// Contact consistency: the most tensile contact node of fem/base/contact_check.h relative to the
    /// largest nodal force (>= -1e-3 when consistent) and the smallest gap outside the contact relative
    /// to the depth (>= -1e-3 when consistent).
    double min_relative_contact_force = 0;
    double min_relative_gap           = 0;
    bool   consistent_contact         = true; ///< both checks passed (complete contact for the concave punch)

    Formulation formulation = Formulation::displacement; ///< the one used (never automatic)
  };

  /// The free surface z = 0 as a linear map of normal nodal loads (a traction that depends on the gap, e.g. the
  /// smooth adhesion law of fem/adhesion/smooth_cohesion.h): C_ij = u_z at dofs[i] under a unit nodal force (+z, into the
  /// material) at dofs[j], no contact zone held. The surface z-DoFs that the constraints fix (the clamped far
  /// field) are left out: they stay at zero.
  struct SurfaceFlexibility
  {
    std::vector<SurfaceFace>                     faces; ///< all faces on z = 0, ascending r
    std::vector<dealii::types::global_dof_index> dofs;  ///< the unconstrained surface z-DoFs, ascending r
    std::vector<double>                          r;     ///< their radii
    dealii::FullMatrix<double>                   matrix;
    double                                       seconds = 0; ///< factorisation and the dofs.size() solves
  };

  class AxisymmetricSolver
  {
  public:
    /// Builds mesh, DoFs, constraints and the stiffness matrix. Throws std::invalid_argument on bad input.
    /// `refinement`: extra surface refinement toward points that are no mesh nodes (e.g. the end c of a
    /// cohesive zone, where the traction jumps).
    AxisymmetricSolver(const Material &material, const MeshParameters &mesh,
                       const DiscretizationParameters &discretization, const SurfaceRefinement &refinement = {});
    ~AxisymmetricSolver();

    /// Solves one load case, reusing everything load independent.
    Result run(const LoadCase &load, const OutputRequest &outputs = {});

    /// The flexibility of the free surface (DirectSystem::inverse_block: block solves with the Cholesky factor of A
    /// that run() shares). Throws std::logic_error when a surface z-DoF is constrained other than to zero.
    SurfaceFlexibility surface_flexibility();

    unsigned int n_dofs() const { return dof_handler.n_dofs(); }
    /// The memory its factorisations and matrices hold (DirectSystem::factor_bytes and the stress fit's mass
    /// matrix; 0 before the first run).
    std::size_t factor_bytes() const { return system.factor_bytes() + (stress_fit ? stress_fit->bytes() : 0); }
    /// displacement or mixed (resolved from DiscretizationParameters::formulation and nu).
    Formulation formulation() const { return used_formulation; }
    const dealii::Triangulation<2> &get_triangulation() const { return triangulation; }

  private:
    /// The solved state of one load case, before its checks and outputs.
    struct State
    {
      dealii::Vector<double> u, reaction; ///< displacement, reactions A u - b
      std::vector<dealii::types::global_dof_index> active; ///< prescribed surface z-DoFs (contact)
      std::vector<double> g;            ///< their prescribed values
      double work         = 0;          ///< work of the prescribed displacements and loads, per 2 pi
      bool   constrained  = true;       ///< a rigid contact (false: a prescribed pressure)
      double contact_edge = 0;          ///< radius of the outermost contact node
    };

    void make_grid();
    void setup_system();
    void assemble_system();

    /// The load cases on the mesh's contact zone r <= a (flat punch, indenter, concave punch), a
    /// prescribed pressure, and depth or force control (the contact set searched over the vertices).
    State solve_radius_controlled(const LoadCase &load, Result &result);
    State solve_pressure(const LoadCase &load, Result &result);
    State solve_depth_or_force_controlled(const LoadCase &load, Result &result);
    /// The energy check and, for a contact, the sign check of the contact forces and the gap outside.
    void check(const LoadCase &load, const State &state, Result &result) const;
    /// p(r), w(r) and the VTU file, as asked.
    void sample(const LoadCase &load, const State &state, const OutputRequest &outputs, Result &result) const;

    dealii::Vector<double> pressure_load(double p0) const;
    /// The nodal forces of the cohesion's tension (zero vector when none).
    dealii::Vector<double> cohesion_load(const Cohesion &cohesion) const;
    double evaluate_on_surface(const std::vector<double> &nodal, double r, double contact_edge = -1) const;

    /// Depth or force control on this mesh: the contact set {r <= r_j}, r_j a surface vertex, is found
    /// by a bracketing search over j (ContactSetSearch in the .cc); each trial is the radius-controlled
    /// state of that set, built from the contact-constrained factorisation by a small dense correction.
    struct TrialSet
    {
      unsigned int                                 vertex;   ///< index into surface_vertex_r
      std::vector<dealii::types::global_dof_index> active;   ///< surface z-DoFs in contact
      dealii::Vector<double> U1, U2;   ///< u = d U1 + U2
      dealii::Vector<double> AU1, AU2; ///< A U1, A U2 (contact forces on `active`)
      double depth = 0;                ///< d at which the edge node carries no force
      double F1 = 0, F2 = 0;           ///< F(d) / (2 pi) = d F1 + F2
    };
    class ContactSetSearch;
    TrialSet trial_set(unsigned int vertex, const Profile &profile, const dealii::Vector<double> &u1,
                       const dealii::Vector<double> &u2, const dealii::Vector<double> &Au1,
                       const dealii::Vector<double> &Au2);
    /// The column for modifying the surface z-DoF `dof`: prescribed value 1 (dof in the contact
    /// zone of the mesh) or unit point load (outside), all other contact DoFs held at 0. Cached.
    const std::pair<dealii::Vector<double>, dealii::Vector<double>> &column(dealii::types::global_dof_index dof);
    /// The VTU file: displacements, the mixed pressure, E per cell and, when given, the recovered stresses.
    void   output_results(const dealii::Vector<double> &u, const StressRecovery *stresses,
                          const std::string &filename) const;

    const Material                 material;
    const MeshParameters           mesh_parameters;
    const DiscretizationParameters discretization;
    const SurfaceRefinement        refinement;
    const Formulation              used_formulation; ///< displacement or mixed

    dealii::Triangulation<2>  triangulation;
    MeshInfo                  mesh_info;
    const dealii::FESystem<2> fe;
    dealii::DoFHandler<2>     dof_handler;
    const dealii::MappingQ1<2> mapping;

    dealii::AffineConstraints<double> constraints; ///< hanging nodes, axis, far field (homogeneous)
    DirectSystem                      system;      ///< A, and A with the contact z-DoFs eliminated

    std::vector<dealii::types::global_dof_index> contact_dofs; ///< z-DoFs on r <= a, ascending r
    std::vector<double>                          contact_r;
    std::vector<SurfaceFace>                     surface_faces; ///< ascending r; dofs[1]: the z-DoFs
    std::vector<double>                          dof_r;         ///< r of every DoF (support point)
    std::vector<dealii::types::global_dof_index> surface_dofs;  ///< z-DoFs on z = 0, ascending r
    std::vector<double>                          surface_vertex_r; ///< vertices on z = 0, ascending
    /// (column, A column) per modified surface DoF, load independent (TrialSet).
    std::map<dealii::types::global_dof_index, std::pair<dealii::Vector<double>, dealii::Vector<double>>> columns;
    /// The radius-controlled indenter's load-independent parts, u = d u1 + u_f + u_t: u1 (u_z = 1 on the contact),
    /// u_f (u_z = -f(r) there) of the last profile, kept so that further runs with the same profile and another
    /// cohesion (a cohesive zone's end searched on one mesh) cost one back substitution, for u_t.
    struct IndenterBasis
    {
      std::vector<double>    profile_values; ///< -f(r) at the contact DoFs (the key)
      dealii::Vector<double> u1, reaction1, u_f, reaction_f;
    };
    std::unique_ptr<IndenterBasis> indenter_basis;
    /// The stress recovery's load-independent part, made on the first run that asks for stresses.
    mutable std::unique_ptr<StressFit> stress_fit;
    Timings                                      setup_time;
  };
} // namespace gradcontact::fem

#endif
