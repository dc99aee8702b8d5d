// The linear system of a serial FE model solved by a sparse direct method, with a fixed set P of
// DoFs whose values can be prescribed (a rigid indenter's contact zone, a tangential punch):
//   A u = b + R,  u_i = g_i on P (prescribed solves) or R = 0 (free solves),
// R the reactions, non-zero on P only. P is eliminated symmetrically: a copy of A has the rows and
// columns of P zeroed and its diagonal kept, the right-hand side is b - A g_ext off P and
// A_ii g_i on P. Both matrices are factorised on first use and kept, so every further load case costs
// one back substitution. A is condensed with the model's homogeneous constraints (hanging nodes, axis,
// far field): the rows of constrained DoFs carry their diagonal entry only.
//
// The factorisation. The displacement formulation's matrices are symmetric positive definite: a supernodal
// Cholesky factorisation (CHOLMOD, SuiteSparse; Chen, Davis, Hager and Rajamanickam, ACM TOMS 35 (2008) 22). A matrix
// that is not positive definite (the mixed formulation's saddle point) is factorised by UMFPACK's LU instead (Davis,
// ACM TOMS 30 (2004) 196) with the symmetric strategy: an ordering of A + A^T (the matrix is symmetric) and a
// preference for diagonal pivots, taking an off-diagonal one where the diagonal is too small (the saddle point's
// pressure block, zero at nu = 1/2). Its factors fill far less than the unsymmetric strategy's column ordering,
// which keeps the finer levels of the mixed formulation within the contract's memory budget; the refinement below
// makes up for pivots the diagonal preference chooses less stably.
//
// Every solve is refined against the true residual (DirectSystem::refine): u += A^{-1}(b - A u), the residual summed
// as accurately as in twice the working precision, until the correction is at the rounding of u or stops halving. So
// a solve is backward stable even where the factorisation's pivots are not, its answer does not depend on the
// rounding of the BLAS kernel the machine picks, and its forward error is not the condition number times the working
// precision (the stiff surface of k near -1 and the saddle point near nu = 1/2 make that large). The reactions
// R = A u - b are summed the same way: on a stiff surface their rows cancel large terms.
//
// That summation is exact to rounding, but A's entries are not: each is rounded, so a row's entries no longer sum to
// zero over a rigid translation t (A t = 0 in exact arithmetic in every row whose cells are all elastic), and row i
// of a solve carries a spurious load delta_i u_i, |delta_i| ~ eps sum_j |A_ij|. Under the stiff surface of E ~ z^s,
// s < 0, the rows at the contact edge hold entries of order E(h) p^4 over cells of size h, far above the force they
// transmit, and a punch's force moved far more than physically when nu moved in its last digits. With a translation
// given (set_translation), two things remove that:
// - every row that annihilates t within rounding gets an anchor a_i (its largest entry over t), and the residuals of
//   the refinement and the reactions take r_i = b_i - sum_j A_ij (u_j - u_(a_i) t_j): the residual of A with
//   delta_i removed, so the refinement converges to the solution of that exactly translation-invariant matrix (A's
//   factorisation serves as the preconditioner);
// - a prescribed solve takes the unknown v = u - c t, c the prescribed value of the stiffest prescribed row, under
//   the load b - c A t (A t non-zero only in the rows without an anchor, which the far field or a clamped boundary
//   grounds): v is stored to the rounding of its own size, small where the entries are large (zero on a flat punch),
//   so the reactions, products of those entries with v, keep their digits.
//
// The energy check of fem/grid/discretization.h compares u.Au, over the unconstrained DoFs, with the work
// of the loads.
#ifndef GRADCONTACT_FEM_DIRECT_SYSTEM_H
#define GRADCONTACT_FEM_DIRECT_SYSTEM_H

#include <fem/elasticity/far_field.h>

#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <vector>

namespace gradcontact::fem
{
  class DirectSystem
  {
  public:
    DirectSystem();
    ~DirectSystem(); // not copied or moved (its matrices hold a pointer to its sparsity pattern)

    /// The sparsity of `dof_handler` under `constraints` (kept by reference: it must outlive this). With the rings
    /// of a condensed far field (fem/elasticity/far_field.h; kept), their truncation-boundary DoFs are coupled to each other
    /// and assemble adds the exterior's stiffness.
    void reinit(const dealii::DoFHandler<2> &dof_handler, const dealii::AffineConstraints<double> &constraints,
                std::unique_ptr<FarFieldRings> far_field = nullptr);

    /// Assembles A from the cell matrices of `cell_integrand` (any class with matrix(cell), e.g.
    /// CellStiffness) over all active cells, condensed with the constraints, plus the stiffness of the condensed
    /// far field given to reinit (from the same cell integrand), then fixes P = `prescribed_dofs`.
    template <class CellIntegrand>
    void assemble(const dealii::DoFHandler<2> &dof_handler, CellIntegrand &cell_integrand,
                  const std::vector<dealii::types::global_dof_index> &prescribed_dofs)
    {
      std::vector<dealii::types::global_dof_index> local_dof_indices(dof_handler.get_fe().n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(local_dof_indices);
          constraints->distribute_local_to_global(cell_integrand.matrix(cell), local_dof_indices, stiffness);
        }
      exterior = condense_exterior(far_field.get(), cell_integrand);
      for (unsigned int i = 0; i < exterior.dofs.size(); ++i)
        for (unsigned int j = 0; j < exterior.dofs.size(); ++j)
          stiffness.add(exterior.dofs[i], exterior.dofs[j], exterior.stiffness(i, j));
      set_prescribed_dofs(prescribed_dofs);
    }

    /// The condensed far field's stiffness and diagnostics (empty when the far field is clamped).
    const Exterior &far_field_exterior() const { return exterior; }

    /// A, to be assembled (condensed with the constraints) before set_prescribed_dofs.
    dealii::SparseMatrix<double>       &matrix() { return stiffness; }
    const dealii::SparseMatrix<double> &matrix() const { return stiffness; }
    const dealii::SparsityPattern      &sparsity() const { return sparsity_pattern; }

    /// Fixes P (unconstrained DoFs) and builds the eliminated copy of A; drops cached factorisations.
    void set_prescribed_dofs(const std::vector<dealii::types::global_dof_index> &dofs);
    const std::vector<dealii::types::global_dof_index> &prescribed_dofs() const { return prescribed; }

    /// Solves with u = g on P (`prescribe`, g in the order of prescribed_dofs()) or without (g unused),
    /// load b (condensed: zero in the rows of constrained DoFs). Returns u with the constraints
    /// distributed; `reaction` = A u - b. `factorize_seconds`: the time of a factorisation done now, else 0.
    dealii::Vector<double> solve(bool prescribe, const std::vector<double> &g, const dealii::Vector<double> &b,
                                 dealii::Vector<double> &reaction, double &factorize_seconds);

    /// The block of A^{-1} on `rows` (unconstrained DoFs, no two alike): result(i, j) = u_{rows[i]} under a unit
    /// load at rows[j], no DoF prescribed (a surface flexibility). The Cholesky factor of A solves for the unit
    /// loads in blocks of columns with dense (BLAS-3) triangular solves, far cheaper than one sparse back
    /// substitution per row. A matrix that is not positive definite (the mixed formulation) falls back to those
    /// back substitutions.
    dealii::FullMatrix<double> inverse_block(const std::vector<dealii::types::global_dof_index> &rows);

    /// A rigid translation of the model: t_j = 1 on the DoFs of the translated component, 0 elsewhere (header: the
    /// residuals of the rows it annihilates are summed from displacement differences). After assemble, before solve;
    /// kept.
    void set_translation(const dealii::Vector<double> &t);

    /// u.Au over the unconstrained DoFs (the constrained rows of A hold dummy diagonal entries).
    double energy(const dealii::Vector<double> &u) const;
    /// |u|.|A||u| over the unconstrained DoFs: the scale of the rounding of energy(u) and of the work of the
    /// reactions (each a sum of products of A's entries with u's).
    double energy_magnitude(const dealii::Vector<double> &u) const;

    /// Whether the factorisation of the free (prescribe = false) or eliminated matrix is the Cholesky one (false
    /// before it is made).
    bool cholesky(bool prescribe) const;

    /// The memory a solve holds (bytes): the factorisations made so far (CHOLMOD's in use, UMFPACK's numeric object
    /// and its copy of the matrix) and the sparse matrices they factorise, whose size high degrees raise as fast.
    std::size_t factor_bytes() const;

  private:
    /// The factorisation of one matrix: Cholesky, or LU when it is not positive definite (header).
    class Factorization;
    const Factorization &factorization(bool prescribe, double &seconds);
    /// residual(u, r): r = rhs - A u of the system refined.
    using Residual = std::function<void(const dealii::Vector<double> &, dealii::Vector<double> &)>;
    /// Iterative refinement of u with the factorisation of A, the rows `fixed` kept.
    void refine(const Factorization &direct, const Residual &residual,
                const std::vector<dealii::types::global_dof_index> &fixed, dealii::Vector<double> &u) const;

    const dealii::AffineConstraints<double>     *constraints = nullptr;
    dealii::SparsityPattern                      sparsity_pattern;
    dealii::SparseMatrix<double>                 stiffness, eliminated;
    std::unique_ptr<Factorization>               free_solver, prescribed_solver;
    std::vector<dealii::types::global_dof_index> prescribed;
    std::unique_ptr<FarFieldRings>               far_field;
    Exterior                                     exterior;
    dealii::Vector<double>                       translation, grounded; ///< t, and A t where no anchor (header)
    std::vector<dealii::types::global_dof_index> anchor;      ///< per row; invalid where the row does not annihilate t
  };
} // namespace gradcontact::fem

#endif
