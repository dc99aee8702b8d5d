// The cell integrals of the axisymmetric graded half-space, shared by the serial solver
// (fem/axisymmetric_solver.h) and the distributed one (fem/distributed_solver.h), so both assemble the
// same discrete operator.
//
// Stiffness. With the strain vector of a shape function, B = (eps_rr, eps_zz, eps_tt, gamma_rz),
//   eps_rr = d u_r / dr, eps_zz = d u_z / dz, eps_tt = u_r / r, gamma_rz = d u_r / dz + d u_z / dr,
// and lambda = c_lambda E(z), mu = c_mu E(z), c_lambda = nu / ((1 + nu)(1 - 2 nu)), c_mu = 1 / (2 (1 + nu)),
//   K_ij = \int_cell [ lambda tr B_i tr B_j + 2 mu (B_i,rr B_j,rr + B_i,zz B_j,zz + B_i,tt B_j,tt)
//                      + mu B_i,rz B_j,rz ] r dr dz.
// Quadrature per cell: QGauss(degree + extra) in the bulk; QIterated copies of it where a jump of E
// crosses the cell; in the cells with a face on z = 0, when E ~ z^s there (s != 0), Gauss-Jacobi across
// that face, whose weights contain xi^s (xi the reference distance from the face), so that the integrand
// is E(z) / xi^s, a regular function (fem/gauss_jacobi.h).
//
// Mixed formulation (fe with a third, pressure component q in FE_Q(p-1); fem/axisymmetric_solver.h):
//   K_uu = \int [ 2 mu (B_i,rr B_j,rr + B_i,zz B_j,zz + B_i,tt B_j,tt) + mu B_i,rz B_j,rz ] r dr dz,
//   K_uq = \int tr B_i psi_j r dr dz,   K_qq = - \int psi_i psi_j / lambda r dr dz,
// each block with the rule that is exact or regular for its integrand: K_uu (carries E) with the rule
// above; K_uq (polynomial, no E) with plain Gauss (QIterated across a jump), since Gauss-Jacobi would
// leave the integrand divided by xi^s; K_qq (carries 1/E ~ z^{-s}) with Gauss-Jacobi of exponent -s in
// the surface cells, integrand xi^s / E(z) regular there. K_qq vanishes at nu = 1/2.
//
// Surface load. p(r) = p0 on the faces with boundary id `contact`, pushing into the material (+z):
//   b_i = \int_face p0 phi_{i,z} r dr.
#ifndef GRADCONTACT_FEM_ELASTICITY_ASSEMBLY_H
#define GRADCONTACT_FEM_ELASTICITY_ASSEMBLY_H

#include <fem/modulus.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <vector>

namespace gradcontact::fem
{
  struct DiscretizationParameters;

  /// The homogeneous constraints every load shares, added to `constraints` (which the caller has
  /// cleared, and reinit'ed on the relevant DoFs in parallel) and closed: hanging nodes, u_r = 0 on the
  /// axis, u = 0 on the truncation boundary.
  void make_homogeneous_constraints(const dealii::DoFHandler<2> &dof_handler, const dealii::Mapping<2> &mapping,
                                    const dealii::FESystem<2> &fe, dealii::AffineConstraints<double> &constraints);

  /// K_cell of a(u, v) for the vector FE (u_r, u_z), or of the mixed form for (u_r, u_z, q) when `fe`
  /// has three components. Holds the FEValues objects of the three rule types; one object per thread
  /// of assembly.
  class CellStiffness
  {
  public:
    CellStiffness(const Material &material, const dealii::FESystem<2> &fe, const dealii::Mapping<2> &mapping,
                  const DiscretizationParameters &discretization);

    /// The cell matrix (full, symmetric), valid until the next call.
    const dealii::FullMatrix<double> &matrix(const dealii::DoFHandler<2>::active_cell_iterator &cell);

  private:
    const Material                             material;
    const dealii::FESystem<2>                 &fe;
    const double                               s; ///< surface exponent of E
    const std::vector<double>                  jumps;
    std::unique_ptr<dealii::FEValues<2>>       regular, subdivided;
    std::array<std::unique_ptr<dealii::FEValues<2>>, 4> surface; ///< per reference face on z = 0
    std::array<std::vector<double>, 4>         distance;         ///< xi_q per surface rule
    dealii::FullMatrix<double>                 cell_matrix;
    std::vector<std::array<double, 4>>         B;

    // Mixed formulation only.
    const bool   mixed;
    const double inverse_lambda_factor; ///< 1/lambda = this / E: (1 + nu)(1 - 2 nu) / nu (0 at nu = 1/2)
    std::array<std::unique_ptr<dealii::FEValues<2>>, 4> surface_inverse; ///< Gauss-Jacobi, exponent -s
    std::array<std::vector<double>, 4>         distance_inverse;
    std::vector<double>                        trace, psi;
    void add_mixed_blocks(const dealii::DoFHandler<2>::active_cell_iterator &cell, bool straddles,
                          unsigned int surface_face);
  };

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
