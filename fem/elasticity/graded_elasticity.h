// The cell integrals of linear elasticity of the graded half-space, one integrand for every FE model:
// generic over the strain operator (the axisymmetric Fourier mode 0, the Fourier mode 1 of a load in x,
// and the mixed displacement-pressure form of either), with one set of quadrature rules.
//
// Strain operator. A shape function phi of displacement component c has a strain vector
// B = (eps_1, eps_2, eps_3, gamma_1, ..., gamma_m): three normal strains first, then m engineering
// shear strains. With lambda = c_lambda E(z), mu = c_mu E(z), c_lambda = nu / ((1 + nu)(1 - 2 nu)),
// c_mu = 1 / (2 (1 + nu)) and tr B = eps_1 + eps_2 + eps_3,
//   K_ij = \int_cell [ lambda tr B_i tr B_j + 2 mu sum_n B_i,n B_j,n + mu sum_s B_i,s B_j,s ] r dr dz.
// Mode 0 (u_r, u_z), m = 1:   B = (eps_rr, eps_zz, eps_tt, gamma_rz),
//   eps_rr = d u_r / dr, eps_zz = d u_z / dz, eps_tt = u_r / r, gamma_rz = d u_r / dz + d u_z / dr.
// Mode 1 (U, V, W) of u_r = U cos, u_theta = -V sin, u_z = W cos (fem/tangential/fourier_mode1_solver.h), m = 3:
//   B = (eps_rr, eps_zz, eps_tt, gamma_rz, gamma_rt, gamma_tz) without the cos / sin factors,
//   U: (U_r, 0, U/r, U_z, U/r, 0),  V: (0, 0, -V/r, 0, V_r - V/r, V_z),  W: (0, W_z, 0, W_r, 0, W/r);
//   the integral over theta of cos^2 and sin^2 is pi, so the 3D energy is pi times the meridian form.
// Cartesian 3D (u_x, u_y, u_z), m = 3 (the distributed 3D model, fem/bodies/half_space_3d.h):
//   B = (eps_xx, eps_yy, eps_zz, gamma_xy, gamma_xz, gamma_yz), weight 1 instead of r, dim = 3.
// Each strain operator names its dimension and its volume weight (r in the meridian plane, 1 in 3D); the
// depth coordinate z is always the last one.
//
// Mixed formulation (a pressure component q = lambda div u in FE_Q(p-1) after the displacement
// components, solved for in units of S = E(a), mixed_pressure_scale; fem/bodies/axisymmetric_solver.h):
//   K_uu = \int [ 2 mu sum_n B_i,n B_j,n + mu sum_s B_i,s B_j,s ] r dr dz,
//   K_uq = S \int tr B_i psi_j r dr dz,   K_qq = - S^2 \int psi_i psi_j / lambda r dr dz,
// each block with the rule that is exact or regular for its integrand: K_uu (carries E) with the rule
// below; K_uq (polynomial, no E) with plain Gauss (QIterated across a jump), since Gauss-Jacobi would
// leave the integrand divided by xi^s; K_qq (carries 1/E ~ z^{-s}) with Gauss-Jacobi of exponent -s in
// the surface cells, integrand xi^s / E(z) regular there. K_qq vanishes at nu = 1/2.
// On a stiff surface (E ~ z^s, s < 0; depth_weighted_pressure) the in-plane stress of the skin makes
// q ~ z^s unbounded at z = 0, which no polynomial follows; there the unknown is q_hat = q / E(z) =
// (lambda / E) div u, bounded (a constant plus z^{-s}), and
//   K_uq = \int tr B_i psi_j E r dr dz,   K_qq = - \int psi_i psi_j (E / lambda) E r dr dz,
// both carrying E, with the rule of K_uu (E / lambda is a constant).
//
// Quadrature per cell: QGauss(degree + extra) in the bulk; QIterated copies of it where a jump of E
// crosses the cell; in the cells with a face on z = 0, when E ~ z^s there (s != 0), Gauss-Jacobi across
// that face, whose weights contain xi^s (xi the reference distance from the face), so that the integrand
// is E(z) / xi^s, a regular function (fem/base/gauss_jacobi.h).
//
// With the surface map (fem/modulus/surface_map.h) every cell uses the mapped gradient and volume, and a surface cell
// integrates three parts, each with its own rule: B_b.B_b E / Phi_zeta ~ zeta^0 (Gauss), the cross terms
// E ~ zeta^gamma and B_a.B_a E Phi_zeta ~ zeta^{2 gamma} (Gauss-Jacobi of exponents gamma and 2 gamma across
// the surface face), gamma = s / (1 - s); the mixed blocks likewise (zeta^0 and zeta^gamma).
//
// Surface load. p(r) = p0 on the faces with boundary id `contact`, pushing into the material (+z):
//   b_i = \int_face p0 phi_{i,z} r dr.
#ifndef GRADCONTACT_FEM_GRADED_ELASTICITY_H
#define GRADCONTACT_FEM_GRADED_ELASTICITY_H

#include <fem/grid/discretization.h>
#include <fem/modulus/modulus.h>

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// Axisymmetric (Fourier mode 0) strains of (u_r, u_z): (eps_rr, eps_zz, eps_tt, gamma_rz).
  struct AxisymmetricStrain
  {
    static constexpr int          dim                       = 2;
    static constexpr unsigned int n_displacement_components = 2;
    static constexpr unsigned int n_shear                   = 1;
    using Vector = std::array<double, 3 + n_shear>;
    /// B of the shape function phi (gradient `grad`) of displacement component c at radius r.
    static Vector of(unsigned int c, double phi, const dealii::Tensor<1, 2> &grad, double r)
    {
      return (c == 0) ? Vector{{grad[0], 0.0, phi / r, grad[1]}} : Vector{{0.0, grad[1], 0.0, grad[0]}};
    }
    /// The volume weight of the meridian plane: dV = 2 pi r dr dz (the 2 pi is applied to forces).
    static double weight(const dealii::Point<2> &x) { return x[0]; }
  };

  /// Fourier mode-1 strains of (U, V, W) (header): (eps_rr, eps_zz, eps_tt, gamma_rz, gamma_rt, gamma_tz).
  struct Mode1Strain
  {
    static constexpr int          dim                       = 2;
    static constexpr unsigned int n_displacement_components = 3;
    static constexpr unsigned int n_shear                   = 3;
    using Vector = std::array<double, 3 + n_shear>;
    static Vector of(unsigned int c, double phi, const dealii::Tensor<1, 2> &grad, double r)
    {
      switch (c)
        {
          case 0:
            return {{grad[0], 0.0, phi / r, grad[1], phi / r, 0.0}};
          case 1:
            return {{0.0, 0.0, -phi / r, 0.0, grad[0] - phi / r, grad[1]}};
          default:
            return {{0.0, grad[1], 0.0, grad[0], 0.0, phi / r}};
        }
    }
    static double weight(const dealii::Point<2> &x) { return x[0]; }
  };

  /// Cartesian 3D strains of (u_x, u_y, u_z): (eps_xx, eps_yy, eps_zz, gamma_xy, gamma_xz, gamma_yz).
  struct CartesianStrain
  {
    static constexpr int          dim                       = 3;
    static constexpr unsigned int n_displacement_components = 3;
    static constexpr unsigned int n_shear                   = 3;
    using Vector = std::array<double, 3 + n_shear>;
    /// `r` is not used (the signature is the meridian operators').
    static Vector of(unsigned int c, double /*phi*/, const dealii::Tensor<1, 3> &g, double /*r*/)
    {
      switch (c)
        {
          case 0:
            return {{g[0], 0.0, 0.0, g[1], g[2], 0.0}};
          case 1:
            return {{0.0, g[1], 0.0, g[0], 0.0, g[2]}};
          default:
            return {{0.0, 0.0, g[2], 0.0, g[0], g[1]}};
        }
    }
    static double weight(const dealii::Point<3> &) { return 1.0; }
  };

  /// The quadrature rules of a graded cell (header): the FEValues of the bulk rule, the QIterated rule
  /// of cells crossed by a jump of E, and the Gauss-Jacobi rules of the cells on z = 0 (per reference
  /// face, for the exponent s of E and, when asked, for -s of 1/E). One object per thread of assembly.
  template <int dim>
  class GradedCellRules
  {
  public:
    /// `map_gamma` != 0: the surface cells get the rules of the surface map's parts (exponents gamma and
    /// 2 gamma, fem/modulus/surface_map.h) instead of the exponent s one.
    GradedCellRules(const Material &material, const dealii::FESystem<dim> &fe, const dealii::Mapping<dim> &mapping,
                    const DiscretizationParameters &discretization, bool inverse_rules, double map_gamma = 0.0);

    /// The rule chosen for one cell, reinit'ed on it.
    struct Choice
    {
      dealii::FEValues<dim>       *values;       ///< the rule for integrands carrying E
      const std::vector<double> *xi;           ///< Gauss-Jacobi: reference distance of each point, else null
      /// A jump of E crosses the cell, or it touches the surface z = 0 at a vertex (an edge in 3D) but has no
      /// face there. E ~ z^s is singular at that point (s < 0) or not smooth (s > 0), which neither the Gauss
      /// rule nor a face's Gauss-Jacobi rule sees; an unstructured near field has such cells where three cells
      /// meet at a surface node. `values` is then the subdivided rule (QIterated), except at a 2D surface
      /// corner: there the collapsed Gauss-Jacobi rule of that vertex (surface_corner_quadrature), whose error
      /// falls with the number of points where QIterated's stays at the singular sub-cell's share, a share
      /// that grows as s -> -1. Integrands without E take the subdivided rule (plain()).
      bool                       subdivide;
      unsigned int               surface_face; ///< face on z = 0, or numbers::invalid_unsigned_int
    };
    Choice select(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell);

    /// Bulk or QIterated rule (polynomial integrands), reinit'ed on `cell`.
    dealii::FEValues<dim> &plain(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell, bool subdivide);
    /// Gauss-Jacobi of exponent -s across `face` (integrands carrying 1/E), reinit'ed; xi in `xi`.
    dealii::FEValues<dim> &inverse(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell, unsigned int face,
                                 const std::vector<double> *&xi);

    /// Gauss-Jacobi of exponent (part + 1) gamma across `face` (the surface map's mixed, part 0, and
    /// in-plane, part 1, integrands), reinit'ed; xi in `xi`.
    dealii::FEValues<dim> &mapped(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell, unsigned int face,
                                unsigned int part, const std::vector<double> *&xi);

    double surface_exponent() const { return s; }

  private:
    const double                                       s;
    const std::vector<double>                          jumps;
    std::unique_ptr<dealii::FEValues<dim>>               regular, subdivided;
    /// 2D, s != 0: the corner rule of each reference vertex (Choice::subdivide).
    std::array<std::unique_ptr<dealii::FEValues<dim>>, 4> corner;
    std::array<std::unique_ptr<dealii::FEValues<dim>>, 2 * dim> surface, surface_inverse;
    std::array<std::vector<double>, 2 * dim>                 distance, distance_inverse;
    const bool                                             map_rules;
    std::array<std::array<std::unique_ptr<dealii::FEValues<dim>>, 2 * dim>, 2> surface_mapped;
    std::array<std::array<std::vector<double>, 2 * dim>, 2>                   distance_mapped;
  };

  /// K_cell of graded elasticity for the strain operator `Strain`; when `fe` has one component more
  /// than Strain::n_displacement_components, the last one is the pressure q of the mixed formulation.
  template <class Strain>
  class GradedElasticityCell
  {
  public:
    static constexpr int dim = Strain::dim;

    /// `contact_radius` (physical units) and `h_edge` (the mesh's edge cell / a) place the surface map of
    /// `discretization` (fem/modulus/surface_map.h).
    GradedElasticityCell(const Material &material, const dealii::FESystem<dim> &fe,
                         const dealii::Mapping<dim> &mapping, const DiscretizationParameters &discretization,
                         double contact_radius, double h_edge);

    /// The surface map (the identity when the discretisation has none).
    const SurfaceMap<dim> &surface_map() const { return map; }

    /// The cell matrix (full, symmetric), valid until the next call.
    const dealii::FullMatrix<double> &matrix(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell);

  private:
    /// Which products of the strain parts B = B_a + B_b / Phi_zeta a pass integrates (header of
    /// fem/modulus/surface_map.h): `all` the whole integrand, the others one power of zeta each.
    enum class Part
    {
      all,   ///< B.B with the whole (mapped) gradient
      zz,    ///< B_b.B_b E / Phi_zeta   ~ zeta^0
      mixed, ///< (B_a.B_b + B_b.B_a) E ~ zeta^gamma
      plane  ///< B_a.B_a E Phi_zeta     ~ zeta^{2 gamma}
    };
    /// Adds one pass over the points of `values`; the weights contain xi^{xi_exponent} when `xi` is set.
    void add_part(dealii::FEValues<dim> &values, const std::vector<double> *xi, double xi_exponent, Part part);

    /// B, tr B (whole: the mapped strain) or B_a, tr B_a and B_b, tr B_b (header of fem/modulus/surface_map.h) of shape
    /// function i at point q, and psi[i] (the pressure shape function, 0 for a displacement one).
    void strain_parts(const dealii::FEValues<dim> &values, unsigned int i, unsigned int q,
                      const typename SurfaceMap<dim>::Value &m, bool whole);
    /// The mixed blocks under the surface map: `plain` the Gauss rule reinit'ed on the cell; in a surface cell
    /// `gamma_rule` the Gauss-Jacobi rule of exponent gamma (weights with xi^gamma), else null.
    void add_mapped_mixed_blocks(dealii::FEValues<dim> &plain, dealii::FEValues<dim> *gamma_rule,
                                 const std::vector<double> *xi);
    void add_mixed_blocks(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                          const typename GradedCellRules<dim>::Choice &choice);

    const Material                      material;
    const dealii::FESystem<dim>          &fe;
    const bool                          mixed;
    const double                        inverse_lambda_factor; ///< 1/lambda = this / E (0 at nu = 1/2)
    const double                        pressure_scale;        ///< S of mixed_pressure_scale
    const bool                          weighted_pressure;     ///< depth_weighted_pressure: q / E(z) solved for
    const SurfaceMap<dim>               map;
    GradedCellRules<dim>                rules;
    dealii::FullMatrix<double>          cell_matrix;
    std::vector<typename Strain::Vector> B, B_b;
    std::vector<double>                 trace, trace_b, psi;
  };

  /// The unit of the mixed formulation's pressure unknown: the element solves for q / S with S = E(a), the
  /// modulus at the depth of the contact radius, so that its blocks K_uq S and K_qq S^2 are of the size of
  /// K_uu ~ E. Unscaled, K_uq (no E) against K_uu varies with E0 (a/c0)^k, and the direct solver's pivoting
  /// can fail on the unbalanced system (test `The mixed formulation shall solve the graded flat punch alike*`).
  double mixed_pressure_scale(const Material &material, double contact_radius);

  /// Whether the mixed formulation's pressure unknown is q / E(z) (a stiff surface, E ~ z^s with s < 0; header)
  /// rather than q / S.
  bool depth_weighted_pressure(const Material &material);

  /// The name of the mixed formulation's pressure field in output: "q" (lambda div u), or "q_over_E"
  /// ((lambda / E) div u, dimensionless) where depth_weighted_pressure holds (q is unbounded at z = 0 there).
  std::string mixed_pressure_name(const Material &material);

  /// A solution vector of the meridian element with the mixed formulation's pressure unknowns in the units of
  /// mixed_pressure_name (q = lambda div u: times mixed_pressure_scale; q / E: as solved); the
  /// displacement-only element's vector as it is.
  dealii::Vector<double> with_physical_pressure(const dealii::Vector<double> &u, const dealii::DoFHandler<2> &dof_handler,
                                                const dealii::FESystem<2> &fe, const Material &material,
                                                double contact_radius);

  /// The axisymmetric cell stiffness (mode 0, displacement or mixed).
  using CellStiffness = GradedElasticityCell<AxisymmetricStrain>;
  /// The mode-1 cell stiffness.
  using Mode1CellStiffness = GradedElasticityCell<Mode1Strain>;
  /// The 3D cell stiffness.
  using CellStiffness3D = GradedElasticityCell<CartesianStrain>;

  extern template class GradedCellRules<2>;
  extern template class GradedCellRules<3>;
  extern template class GradedElasticityCell<AxisymmetricStrain>;
  extern template class GradedElasticityCell<Mode1Strain>;
  extern template class GradedElasticityCell<CartesianStrain>;

  /// Validates the discretisation, then the material for the formulation it resolves to (which it returns).
  Formulation checked_formulation(const Material &material, const DiscretizationParameters &discretization);

  /// The element of the models whose displacement has `dim` components (the axisymmetric (u_r, u_z), the
  /// Cartesian 3D (u_x, u_y, u_z)): u in FE_Q(p)^dim, plus q in FE_Q(p - 1) for the mixed formulation (Taylor-Hood).
  template <int dim>
  dealii::FESystem<dim> displacement_pressure_element(unsigned int degree, Formulation formulation);

  /// The element of the axisymmetric (mode 0) model.
  inline dealii::FESystem<2> axisymmetric_element(const unsigned int degree, const Formulation formulation)
  {
    return displacement_pressure_element<2>(degree, formulation);
  }

  /// The homogeneous constraints every load of the axisymmetric model shares, added to `constraints`
  /// (which the caller has cleared, and reinit'ed on the relevant DoFs in parallel) and closed:
  /// hanging nodes, u_r = 0 on the axis, u = 0 on the truncation boundary (unless `clamp_far_field` is false:
  /// the condensed far field of fem/elasticity/far_field.h).
  void make_homogeneous_constraints(const dealii::DoFHandler<2> &dof_handler, const dealii::Mapping<2> &mapping,
                                    const dealii::FESystem<2> &fe, dealii::AffineConstraints<double> &constraints,
                                    bool clamp_far_field = true);

  /// b_cell of the constant pressure p0 on the `contact` faces of `cell` (zero if it has none).
  class CellPressureLoad
  {
  public:
    CellPressureLoad(const dealii::FESystem<2> &fe, const dealii::Mapping<2> &mapping,
                     const DiscretizationParameters &discretization);

    /// The cell vector, valid until the next call; `loaded` is false when the cell has no contact face.
    const dealii::Vector<double> &vector(const dealii::DoFHandler<2>::active_cell_iterator &cell, double p0,
                                         bool &loaded);

  private:
    const dealii::FESystem<2>  &fe;
    dealii::FEFaceValues<2>     face_values;
    dealii::Vector<double>      cell_rhs;
  };
} // namespace gradcontact::fem

#endif
