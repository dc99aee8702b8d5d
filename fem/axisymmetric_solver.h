// Axisymmetric (Fourier mode 0) linear elasticity of a graded half-space with frictionless normal
// contact of rigid indenters: the FE reference of gradcontact (issue 3).
//
// Geometry and unknowns. The meridian plane (r, z), z into the material, is the deal.II dim = 2 domain
// with x = r, y = z (fem/mesh.h). The displacement is u = (u_r, u_z), with u_z > 0 into the material.
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
// the pressure p(r) oscillates, fem/README.md). With q = lambda div u, div u = tr eps = d u_r/dr + u_r/r
// + d u_z/dz, the unknowns (u, q) in FE_Q(p)^2 x FE_Q(p-1) solve the symmetric saddle-point problem
//   \int [ 2 mu (eps_rr eps_rr + eps_zz eps_zz + eps_tt eps_tt) + mu gamma_rz gamma_rz ](u, v) r dr dz
//     + \int q div v r dr dz = l(v)                      for all v,
//   \int s div u r dr dz - \int s q / lambda r dr dz = 0  for all s,
// with 1/lambda = (1 + nu)(1 - 2 nu) / (nu E(z)) = 0 at nu = 1/2 (the incompressible limit, and with
// E = E0 z / c0 the Gibson medium 9.42). Eliminating q gives back a(u, v); at the discrete solution
// U.AU = a(u, u) + \int q div u r = the strain energy, so the energy check, the reactions and every
// surface quantity below are the same expressions on the displacement DoFs of the larger system.
// UMFPACK factorises the indefinite matrix (pivoting). Boundary conditions: u_r = 0 on the axis (r = 0);
// u = 0 on the truncation boundary at L; on z = 0 either traction free, a prescribed pressure, or the
// rigid indenter. The cells touching z = 0 are integrated with a Gauss-Jacobi rule exact for z^s times a
// polynomial when E ~ z^s there (fem/gauss_jacobi.h).
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
//
// Force. From the reaction, F = 2 pi sum_{i in contact} (A u - b)_i = 2 pi [a(u, phi) - l(phi)] with phi
// the sum of the contact z-basis functions (1 on the contact); issue 3 measured it 1000x more accurate
// than integrating sigma_zz. The pressure p(r) is recovered consistently from the same nodal reactions,
// M p = R with M the r-weighted mass matrix of the contact line.
//
// Everything that does not depend on the load (mesh, DoFs, constraints, sparsity, stiffness matrix and
// the UMFPACK factorisations) is built once, in the constructor or on first use, and reused by every
// call of run().
#ifndef GRADCONTACT_FEM_AXISYMMETRIC_SOLVER_H
#define GRADCONTACT_FEM_AXISYMMETRIC_SOLVER_H

#include <fem/mesh.h>
#include <fem/modulus.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// Which unknowns the axisymmetric solver uses (header comment above).
  enum class Formulation
  {
    displacement, ///< (u_r, u_z) in FE_Q(p); -1 < nu < 1/2; locks as nu -> 1/2
    mixed,        ///< (u_r, u_z) in FE_Q(p), q = lambda div u in FE_Q(p-1); 0 < nu <= 1/2, p >= 2
    automatic     ///< mixed for nu >= automatic_mixed_threshold, else displacement
  };

  /// `automatic` switches to the mixed formulation from this nu on (measured, fem/README.md "Mixed
  /// formulation", k = 0, degree 3: at nu = 0.45 the mixed flat-punch force error is 5.7e-7 against
  /// 1.3e-6, the paraboloid p(r) 3.7e-6 against 1.6e-6; from nu = 0.49 on the mixed one wins both).
  inline constexpr double automatic_mixed_threshold = 0.45;

  struct DiscretizationParameters
  {
    unsigned int degree = 3;                  ///< FE_Q degree, 1..4 (of the displacement; 2..4 when mixed)
    unsigned int extra_quadrature_points = 2; ///< points per direction: degree + this
    unsigned int discontinuity_subdivisions = 8; ///< QIterated copies in cells crossing a jump of E
    Formulation  formulation = Formulation::displacement;

    void validate() const;
  };

  /// The formulation used for Poisson ratio nu: displacement or mixed (never automatic). Throws
  /// std::invalid_argument when the result is mixed and the degree is 1 (FE_Q(0) does not exist).
  Formulation resolve_formulation(const DiscretizationParameters &discretization, double nu);

  /// For the solvers without the mixed formulation (distributed, Fourier mode 1): throws
  /// std::invalid_argument "<where>: not supported with the mixed formulation" when
  /// resolve_formulation gives mixed.
  void require_displacement_formulation(const DiscretizationParameters &discretization, double nu,
                                        const std::string &where);

  /// A mesh and a discretisation chosen together.
  struct Settings
  {
    MeshParameters           mesh;
    DiscretizationParameters discretization;
  };

  /// The measured cheapest settings (fem/README.md, "Flat-punch accuracy") for a modulus E ~ z^s at the
  /// surface and a wanted relative force error. force_tolerance >= 1e-6: degree 3, h_edge = 1e-5 a,
  /// rings g = 1.15 (flat punch 3.8e-7 / 7.9e-7 / 2.1e-6 for k = -0.5 / 0 / 0.5). Below: degree 4,
  /// h_edge = 1e-6 a, h_far = 4 a, g = 1.3 (k = 0: 5.2e-8 in about 2 s; k = -0.5: 1.1e-7 in 6 s; k = 0.5
  /// stays near 1e-6, limited by the u_z ~ z^{1-k} surface layer), and z-halvings only under r <= a.
  Settings recommended_settings(double contact_radius, double surface_exponent, double force_tolerance);

  /// A rigid axisymmetric indenter profile f(r), f(0) = 0, z into the material.
  struct Profile
  {
    enum class Shape
    {
      paraboloid,        ///< f = r^2 / (2 R)                (9.24)
      cone,              ///< f = r tan(theta)               (9.18)
      power_law,          ///< f = A r^n                      (9.27)
      concave_paraboloid, ///< f = -h0 r^2 / a^2, r <= a      (9.31)
      custom              ///< any convex f(r) given as a function (a user's candidate profile)
    };
    Shape  shape     = Shape::paraboloid;
    double R         = 1.0;
    double tan_theta = 0.0;
    double n         = 2.0;
    double A         = 0.0;
    double h0        = 0.0;

    static Profile paraboloid(double R);
    static Profile cone(double tan_theta);
    static Profile power_law(double n, double A);
    static Profile concave_paraboloid(double h0);
    /// Any convex profile with f(0) = 0; `growth_exponent` (f ~ r^n) only seeds the depth and force
    /// searches of indenter_depth and indenter_force.
    static Profile custom(std::function<double(double)> f, double growth_exponent);
    std::function<double(double)> function; ///< custom: f(r)
    double growth_exponent = 2.0;           ///< custom

    /// f(r); `a` is the punch radius (used by the concave paraboloid only).
    double operator()(double r, double a) const;
    /// The power n of f ~ r^n (2, 1, n; 2 for the concave paraboloid).
    double exponent() const;
    void   validate() const;
  };

  enum class LoadType
  {
    flat_punch,       ///< prescribed depth d on r <= a
    indenter,         ///< curved indenter, contact radius a (mesh), depth found
    indenter_depth,   ///< curved indenter at a given depth, contact radius found on the same mesh
    indenter_force,   ///< curved indenter at a given force, depth and contact radius found
    concave_punch,    ///< concave paraboloid, centre displacement d0, complete contact checked
    constant_pressure ///< p0 on r <= a
  };

  struct LoadCase
  {
    LoadType type     = LoadType::flat_punch;
    double   depth    = 0.0; ///< d (flat punch, indenter_depth) or d0 (concave punch)
    double   force    = 0.0; ///< F_N (indenter_force)
    Profile  profile;        ///< indenter and concave punch
    double   pressure = 0.0; ///< p0 (constant pressure)

    void validate() const;
  };

  /// Only what is asked for is computed.
  struct OutputRequest
  {
    std::vector<double> pressure_radii;     ///< sample p(r) here (r <= a)
    std::vector<double> displacement_radii; ///< sample w(r) = u_z(r, 0) here (any r <= L)
    std::string         vtu_file;           ///< write the fields here when not empty
  };

  struct Sample
  {
    double r;
    double value;
  };

  struct Timings
  {
    double mesh = 0, setup = 0, assemble = 0; ///< once per solver (copied into every result)
    double factorize = 0;                     ///< this run (0 if the factorisation was reused)
    double solve = 0, postprocess = 0;        ///< this run
  };

  struct Result
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

    /// Contact consistency: the most tensile contact node of fem/contact_check.h relative to the
    /// largest nodal force (>= -1e-3 when consistent) and the smallest gap outside the contact relative
    /// to the depth (>= -1e-3 when consistent).
    double min_relative_contact_force = 0;
    double min_relative_gap           = 0;
    bool   consistent_contact         = true; ///< both checks passed (complete contact for the concave punch)
    std::string message;                      ///< what failed, if anything

    /// |2 pi u.Au - work of the loads| / (2 pi u.Au): a solver-garbage detector (ill-conditioning).
    double energy_mismatch = 0;
    bool   reliable        = true; ///< energy_mismatch small enough (else `message` says why)

    unsigned int n_dofs  = 0; ///< all DoFs (displacement and, when mixed, pressure)
    unsigned int n_cells = 0;
    Formulation  formulation = Formulation::displacement; ///< the one used (never automatic)
    MeshInfo     mesh;
    Timings      time;
  };

  class AxisymmetricSolver
  {
  public:
    /// Builds mesh, DoFs, constraints and the stiffness matrix. Throws std::invalid_argument on bad input.
    AxisymmetricSolver(const Material &material, const MeshParameters &mesh,
                       const DiscretizationParameters &discretization);
    ~AxisymmetricSolver();

    /// Solves one load case, reusing everything load independent.
    Result run(const LoadCase &load, const OutputRequest &outputs = {});

    unsigned int n_dofs() const { return dof_handler.n_dofs(); }
    /// displacement or mixed (resolved from DiscretizationParameters::formulation and nu).
    Formulation formulation() const { return used_formulation; }
    const dealii::Triangulation<2> &get_triangulation() const { return triangulation; }

  private:
    struct SurfaceFace
    {
      double                                 r0, r1;
      bool                                   contact;
      std::vector<double>                    r;    ///< support points of the z-DoFs, ascending
      std::vector<dealii::types::global_dof_index> dofs; ///< the z-DoFs in the same order
    };

    void make_grid();
    void setup_system();
    void assemble_system();
    const dealii::SparseDirectUMFPACK &factorization(bool contact_constrained, double &seconds);
    /// u with u_z = g on the contact DoFs (if contact_constrained) and load b; reactions into R.
    dealii::Vector<double> solve(bool contact_constrained, const std::vector<double> &g,
                                 const dealii::Vector<double> &b, dealii::Vector<double> &reaction,
                                 double &factorize_seconds);
    dealii::Vector<double> pressure_load(double p0) const;
    std::vector<double>    recover_pressure(const dealii::Vector<double> &reaction, double edge) const;
    double evaluate_on_surface(const std::vector<double> &nodal, double r, double contact_edge = -1) const;

    /// Depth or force control on this mesh: the contact set {r <= r_j}, r_j a surface vertex, is found
    /// by a bracketing search over j; each trial is the radius-controlled state of that set, built from
    /// the contact-constrained factorisation by a small dense correction (see the .cc).
    struct TrialSet
    {
      unsigned int                                 vertex;   ///< index into surface_vertex_r
      std::vector<dealii::types::global_dof_index> active;   ///< surface z-DoFs in contact
      dealii::Vector<double> U1, U2;   ///< u = d U1 + U2
      dealii::Vector<double> AU1, AU2; ///< A U1, A U2 (contact forces on `active`)
      double depth = 0;                ///< d at which the edge node carries no force
      double F1 = 0, F2 = 0;           ///< F(d) / (2 pi) = d F1 + F2
    };
    TrialSet trial_set(unsigned int vertex, const Profile &profile, const dealii::Vector<double> &u1,
                       const dealii::Vector<double> &u2, const dealii::Vector<double> &Au1,
                       const dealii::Vector<double> &Au2);
    /// The column for modifying the surface z-DoF `dof`: prescribed value 1 (dof in the contact
    /// zone of the mesh) or unit point load (outside), all other contact DoFs held at 0. Cached.
    const std::pair<dealii::Vector<double>, dealii::Vector<double>> &column(dealii::types::global_dof_index dof);
    void   output_results(const dealii::Vector<double> &u, const std::string &filename) const;

    const Material                 material;
    const MeshParameters           mesh_parameters;
    const DiscretizationParameters discretization;
    const Formulation              used_formulation; ///< displacement or mixed

    dealii::Triangulation<2>  triangulation;
    MeshInfo                  mesh_info;
    const dealii::FESystem<2> fe;
    dealii::DoFHandler<2>     dof_handler;
    const dealii::MappingQ1<2> mapping;

    dealii::AffineConstraints<double> constraints; ///< hanging nodes, axis, far field (homogeneous)
    dealii::SparsityPattern           sparsity_pattern;
    dealii::SparseMatrix<double>      stiffness;             ///< A (unconstrained on the surface)
    dealii::SparseMatrix<double>      contact_stiffness;     ///< A with the contact z-DoFs eliminated
    std::unique_ptr<dealii::SparseDirectUMFPACK> free_solver, contact_solver;

    std::vector<dealii::types::global_dof_index> contact_dofs; ///< z-DoFs on r <= a, ascending r
    std::vector<double>                          contact_r;
    std::vector<SurfaceFace>                     surface_faces; ///< ascending r
    std::vector<double>                          dof_r;         ///< r of every DoF (support point)
    std::vector<dealii::types::global_dof_index> surface_dofs;  ///< z-DoFs on z = 0, ascending r
    std::vector<double>                          surface_vertex_r; ///< vertices on z = 0, ascending
    /// (column, A column) per modified surface DoF, load independent (TrialSet).
    std::map<dealii::types::global_dof_index, std::pair<dealii::Vector<double>, dealii::Vector<double>>> columns;
    Timings                                      setup_time;
  };
} // namespace gradcontact::fem

#endif
