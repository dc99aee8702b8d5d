// The linear solve of the distributed models (fem/bodies/distributed_solver.h in the meridian plane,
// fem/bodies/half_space_3d.h in 3D): one matrix, its factorisation or AMG preconditioner built at the first
// solve and reused for every right-hand side after.
//
// Methods (DistributedSolverParameters::Method):
//  - direct: MUMPS through Trilinos Amesos (Amesos_Mumps; Debian's Trilinos 13.2 has it), the default:
//    it reproduces the serial direct answer to round-off on the ill-conditioned graded systems;
//  - amg_cg: CG preconditioned by Trilinos ML (smoothed aggregation, Chebyshev smoother, the constant
//    modes of every displacement component as near-null space), stopped at ||b - A u|| <= relative_tolerance
//    ||b||. The graded E (orders of magnitude of cell size, E -> 0 or infinity at z = 0) degrades it: the
//    iteration counts are in the table of `./vv scaling` (reports/benchmarks/mpi_scaling.md). A CG that
//    does not converge throws with its iteration count and residual.
#ifndef GRADCONTACT_FEM_DISTRIBUTED_LINEAR_SOLVER_H
#define GRADCONTACT_FEM_DISTRIBUTED_LINEAR_SOLVER_H

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/lac/full_matrix.h>

#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  struct DistributedSolverParameters
  {
    enum class Method
    {
      direct, ///< Amesos_Mumps (distributed sparse LU)
      amg_cg  ///< CG + Trilinos ML AMG
    };
    Method       method                = Method::direct;
    double       relative_tolerance    = 1e-12; ///< amg_cg: ||b - A u|| <= this ||b||, (0, 1)
    unsigned int max_iterations        = 20000; ///< amg_cg: CG iterations, >= 1
    double       aggregation_threshold = 1e-4;  ///< amg_cg: ML drop tolerance, [0, 1)
    unsigned int smoother_sweeps       = 2;     ///< amg_cg: Chebyshev sweeps, [1, 20]

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  /// `communicator`, after checking that MPI is up (p4est and Trilinos need it even on one process); throws
  /// std::runtime_error naming `who` otherwise.
  MPI_Comm require_mpi(MPI_Comm communicator, const std::string &who);

  /// What one solve did.
  struct LinearSolveReport
  {
    std::string  solver;         ///< "Amesos_Mumps" or "CG + ML AMG"
    unsigned int iterations = 0; ///< CG iterations (0: direct)
    double       residual   = 0; ///< ||b - A u|| / ||b||
    double       factorize  = 0; ///< seconds spent on the factorisation or preconditioner in this call (0: reused)
  };

  /// The solver of one fixed matrix. Collective: every process of the matrix's communicator calls solve().
  template <int dim>
  class DistributedLinearSolver
  {
  public:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;
    using Matrix = dealii::TrilinosWrappers::SparseMatrix;

    /// `dof_handler` gives the constant modes for AMG, `degree` > 1 tells ML about higher-order elements.
    DistributedLinearSolver(const DistributedSolverParameters &parameters, const dealii::DoFHandler<dim> &dof_handler,
                            unsigned int degree);

    /// u = A^{-1} b (u is reinit'ed on A's row partition). A must be the same matrix at every call.
    LinearSolveReport solve(const Matrix &A, const Vector &b, Vector &u);

  private:
    const DistributedSolverParameters                              parameters;
    const dealii::DoFHandler<dim>                                 &dof_handler;
    const unsigned int                                             degree;
    const Matrix                                                  *matrix = nullptr;
    std::unique_ptr<dealii::SolverControl>                         control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>        direct;
    std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG>     amg;
  };

  /// The block of A^{-1} on the unknowns `rows` (global indices, the same list on every process), on every process:
  /// result(k, l) = (A^{-1})_{rows[k], rows[l]}. A^{-1} restricted to them is the inverse of the Schur complement
  /// S = A_rr - A_ro A_oo^{-1} A_or, which MUMPS forms while it factorises A_oo (ICNTL(19), MUMPS users' guide
  /// 5.5, section 5.14), so the block costs one factorisation instead of a solve per row. Every process hands MUMPS
  /// its own rows (distributed assembled input, ICNTL(18) = 3) and takes part in the factorisation; the block comes
  /// back on process 0 and is broadcast.
  /// Throws std::runtime_error with MUMPS' error code when it fails, std::invalid_argument for an empty or repeated
  /// row. A must be symmetric positive definite on `rows` (S is inverted by Cholesky).
  dealii::FullMatrix<double> inverse_on_rows(const dealii::TrilinosWrappers::SparseMatrix &A,
                                             const std::vector<dealii::types::global_dof_index> &rows);

  extern template class DistributedLinearSolver<2>;
  extern template class DistributedLinearSolver<3>;
} // namespace gradcontact::fem

#endif
