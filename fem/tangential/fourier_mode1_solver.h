// Fourier mode n = 1 of linear elasticity of the graded half-space: a load in x on an axisymmetric
// body, solved on the same meridian (r, z) mesh as the axisymmetric solver (tangential contact).
//
// Geometry and unknowns. deal.II dim = 2 with x = r, y = z, z into the material (fem/grid/mesh.h). The
// displacement of a load in x (the plane theta = 0 contains e_x) has the form
//   u_r = U(r, z) cos(theta),   u_theta = -V(r, z) sin(theta),   u_z = W(r, z) cos(theta),
// with three meridian fields (U, V, W) = FE_Q(p)^3, components 0, 1, 2. A rigid translation delta e_x is
// U = V = delta, W = 0; on the surface u_x = U cos^2 + V sin^2 and u_y = (U - V) sin cos.
//
// Strains. With the cylindrical strains of u and the theta derivatives carried out,
//   eps_rr = U_{,r} c,  eps_zz = W_{,z} c,  eps_tt = (U - V)/r c,  gamma_rz = (U_{,z} + W_{,r}) c,
//   gamma_rt = -[(U - V)/r + V_{,r}] s,  gamma_tz = -[V_{,z} + W/r] s,      c = cos(theta), s = sin(theta).
// Define the meridian strain vector B(U, V, W) = (eps_rr, eps_zz, eps_tt, gamma_rz, gamma_rt, gamma_tz)
// without the c and s factors (signs do not matter: each term is squared or multiplied by its twin).
// Since \int_0^{2 pi} cos^2 = \int_0^{2 pi} sin^2 = pi, the strain energy of the 3D body is pi times the
// meridian bilinear form
//   a(u, v) = \int_\Omega [ lambda tr B(u) tr B(v) + 2 mu (B_rr B_rr + B_zz B_zz + B_tt B_tt)
//                          + mu (B_rz B_rz + B_rt B_rt + B_tz B_tz) ] r dr dz,
// tr B = B_rr + B_zz + B_tt, lambda(z) = E(z) nu / ((1 + nu)(1 - 2 nu)), mu(z) = E(z) / (2 (1 + nu)).
// Rigid modes check it: the translation (U = V = delta, W = 0) and the rotation about y
// (U = V = omega z, W = -omega r) give B = 0.
//
// Loads. A surface traction of the same angular form, t_r = T_r cos, t_theta = -T_theta sin, does the
// work pi \int_{z=0} (T_r U + T_theta V) r dr. A tangential traction tau(r) e_x is
// t = tau (cos e_r - sin e_theta), i.e. T_r = T_theta = tau:
//   l(v) = \int_{z=0} tau(r) (v_U + v_V) r dr                (work and forces: pi times meridian values)
// The force in x of the traction (T_r, T_theta) is F_x = pi \int (T_r + T_theta) r dr, so from the
// nodal reactions R = A u - b of the prescribed U- and V-DoFs (partition of unity on the contact),
//   F_x = pi sum_{i in U, V on r <= a} R_i.
//
// Boundary conditions. Axis r = 0 (single-valuedness of a mode-1 field: u_z = W cos must not depend on
// theta there, and u_r e_r + u_theta e_theta = (U cos^2 + V sin^2) e_x + (U - V) sin cos e_y must be a
// constant vector): W = 0 and U = V, the latter an AffineConstraints line V_i = U_i. Far field
// (boundary id far_field): U = V = W = 0, or the exterior condensed onto it (DiscretizationParameters::far_field,
// fem/elasticity/far_field.h; the meshes of fem/grid/mesh.h only). Surface z = 0: a rigid tangential flat punch or a prescribed
// tangential traction; W is always free and the normal traction zero (no normal load).
//
// Loads (TangentialLoad):
//   flat_punch   u_x = delta, u_y = 0 on r <= a, i.e. U = V = delta there, W free (frictionless in z),
//                traction free outside; F_x and K_T = F_x / delta. For k = 0 this is Mindlin's problem:
//                the traction tau = F_x / (2 pi a sqrt(a^2 - r^2)) in x gives u_x = const, u_y = 0 on
//                the disc, so K_T = 8 G a / (2 - nu) exactly; the MDR gives K_T = 2 cT0 a^{1+k} /
//                ((1 + k) c0^k), cT0 = h_T E0 (9.78)-(9.79).
//   traction     tau(r) in x on r <= radius (any function; e.g. the Ciavarella-Jaeger traction of
//                partial slip, tau = mu [p(r; a) - p(r; c)] (9.80)); the surface displacement and its
//                statistics over the stick zone r <= c: the area mean of u_x (the theory's u^(0)),
//                the spread (max - min of u_x over the disc) / mean and max |u_y| / mean, with
//                max_theta u_x = max(U, V), min_theta u_x = min(U, V), max_theta |u_y| = |U - V| / 2 and
//                mean u_x = (2 / c^2) \int_0^c (U + V)/2 r dr.
//
// Quadrature: the stiffness uses the rules of graded_elasticity.h (Gauss-Jacobi in the cells at z = 0
// when E ~ z^s there); the traction integrals are split at `radius` and at the breakpoints of tau
// (a kink such as the stick radius c) and graded geometrically toward them, 8 Gauss points per piece,
// also on the faces next to one (within two face lengths; fem/elasticity/surface_trace.h, traction_integrals).
//
// Check. Every run compares pi u.Au with the work of the loads (prescribed displacements and
// tractions); above 1e-6 the result is marked unreliable.
#ifndef GRADCONTACT_FEM_FOURIER_MODE1_SOLVER_H
#define GRADCONTACT_FEM_FOURIER_MODE1_SOLVER_H

#include <fem/linear_algebra/direct_system.h>
#include <fem/grid/discretization.h>
#include <fem/grid/mesh.h>
#include <fem/modulus/modulus.h>
#include <fem/elasticity/surface_trace.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  enum class TangentialLoadType
  {
    flat_punch, ///< rigid translation delta in x of the disc r <= a (the mesh's contact radius)
    traction    ///< prescribed tau(r) e_x on r <= radius
  };

  struct TangentialLoad
  {
    TangentialLoadType            type = TangentialLoadType::flat_punch;
    double                        displacement = 0; ///< delta (flat punch), non-zero
    std::function<double(double)> traction;         ///< tau(r) (traction), finite on [0, radius]
    double                        radius = 0;       ///< loaded zone r <= radius (traction), > 0
    std::vector<double>           breakpoints;      ///< radii in (0, radius) where tau has a kink
    double stick_radius = 0; ///< c: stick-zone statistics over r <= c when in (0, radius]; 0: none

    /// U = V = delta on the contact r <= a.
    static TangentialLoad flat_punch(double delta);
    /// tau(r) e_x on r <= radius; statistics over r <= stick_radius (0 for none).
    static TangentialLoad profile(std::function<double(double)> tau, double radius, double stick_radius = 0,
                                  std::vector<double> breakpoints = {});
    /// The partial-slip traction of the generalised Ciavarella-Jaeger theorem (9.77), (9.80),
    ///   tau(r) = mu [p(r; a) - p(r; c)],  p(r; b) = pressure(r, b) (0 for r > b),
    /// with the stick zone r <= c. Throws std::invalid_argument for mu <= 0, a <= 0, c outside (0, a].
    static TangentialLoad partial_slip(std::function<double(double r, double contact_radius)> pressure,
                                       double mu, double a, double c);

    void validate() const;
  };

  struct TangentialOutputRequest
  {
    std::vector<double> displacement_radii; ///< sample U, V, W on z = 0 here
    std::string         vtu_file;           ///< write the meridian fields here when not empty
  };

  /// The meridian fields on z = 0 at r: u_x = U at theta = 0, u_x = V at theta = 90 degrees.
  struct SurfaceDisplacement
  {
    double r, U, V, W;
  };

  /// Statistics of u_x, u_y over the stick zone r <= c (relative to the mean of u_x).
  struct StickZoneDisplacement
  {
    double radius = 0;          ///< c
    double mean_ux = 0;         ///< (2 / c^2) \int_0^c (U + V)/2 r dr: the theory's u^(0)
    double relative_spread = 0; ///< (max u_x - min u_x) / mean_ux over the disc
    double relative_max_uy = 0; ///< max |u_y| / mean_ux = max |U - V| / (2 mean_ux)
    double min_U = 0, max_U = 0, min_V = 0, max_V = 0;
  };

  struct TangentialResult : RunReport
  {
    double force        = 0; ///< F_x = pi sum R (flat punch) or pi \int 2 tau r dr (traction)
    double displacement = 0; ///< delta (flat punch); mean u_x over the stick zone (traction), else 0
    double stiffness    = 0; ///< K_T = F_x / delta (flat punch)
    std::vector<SurfaceDisplacement> surface;
    StickZoneDisplacement            stick;
  };

  class FourierMode1Solver
  {
  public:
    /// The meridian mesh of fem/grid/mesh.h (the same as AxisymmetricSolver's for the same parameters).
    FourierMode1Solver(const Material &material, const MeshParameters &mesh,
                       const DiscretizationParameters &discretization, const SurfaceRefinement &refinement = {});
    /// Any meridian mesh in physical units whose boundary faces carry the ids of fem/base/boundary_ids.h
    /// (axis on r = 0, contact/free_surface on z = 0, far_field where u = 0), e.g. the truncated cylinder
    /// [0, R] x [0, H] of the 3D verification. The contact radius is the largest r of a `contact` face.
    FourierMode1Solver(const Material &material, const dealii::Triangulation<2> &mesh,
                       const DiscretizationParameters &discretization);
    ~FourierMode1Solver();

    TangentialResult run(const TangentialLoad &load, const TangentialOutputRequest &outputs = {});

    unsigned int                    n_dofs() const { return dof_handler.n_dofs(); }
    double                          contact_radius() const { return a; }
    const dealii::Triangulation<2> &get_triangulation() const { return triangulation; }

  private:
    void make_grid(const MeshParameters &mesh, const SurfaceRefinement &refinement);
    /// `mesh`: the parameters of a mesh of fem/grid/mesh.h (its rings, for the condensed far field), else null.
    void setup_system(const MeshParameters *mesh = nullptr);
    void assemble_system();
    /// The width of the contact face that ends at the contact edge / a (the surface map's floor).
    double edge_cell() const;
    dealii::Vector<double> traction_load(const TangentialLoad &load) const;
    /// The two loads: each solves u, fills the force of `result` and returns the work of the load (per pi).
    double solve_punch(const TangentialLoad &load, dealii::Vector<double> &u, TangentialResult &result);
    double solve_traction(const TangentialLoad &load, dealii::Vector<double> &u, TangentialResult &result);
    /// The outputs asked for: the stick-zone statistics, surface samples, VTU.
    void sample(const TangentialLoad &load, const dealii::Vector<double> &u, const TangentialOutputRequest &outputs,
                TangentialResult &result) const;
    /// Field `component` (0 U, 1 V, 2 W) of the nodal vector on z = 0 at r.
    double surface_value(const dealii::Vector<double> &u, unsigned int component, double r) const;
    StickZoneDisplacement stick_zone(const dealii::Vector<double> &u, double c) const;
    void output_results(const dealii::Vector<double> &u, const std::string &filename) const;

    const Material                 material;
    const DiscretizationParameters discretization;

    dealii::Triangulation<2>   triangulation;
    MeshInfo                   mesh_info;
    double                     a = 0; ///< contact radius (largest r of a contact face)
    const dealii::FESystem<2>  fe;
    dealii::DoFHandler<2>      dof_handler;
    const dealii::MappingQ1<2> mapping;

    dealii::AffineConstraints<double> constraints; ///< hanging nodes, axis (W = 0, V = U), far field
    DirectSystem                      system; ///< A (meridian, without the pi), and A with the punch DoFs eliminated

    std::vector<dealii::types::global_dof_index> punch_dofs; ///< free U, V DoFs on r <= a
    std::vector<SurfaceFace>                     surface_faces; ///< ascending r; dofs: U, V, W
    Timings                                      setup_time;
  };
} // namespace gradcontact::fem

#endif
