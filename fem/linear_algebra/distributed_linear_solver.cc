#include <fem/linear_algebra/distributed_linear_solver.h>
#include <fem/base/errors.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_cg.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <algorithm>
#include <cstdint>
#include <limits>

#include <chrono>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    [[noreturn]] void fail(const std::string &what, const double value, const std::string &range)
    {
      fem::fail("DistributedSolverParameters", what, value, range);
    }
  } // namespace



  void DistributedSolverParameters::validate() const
  {
    if (!(relative_tolerance > 0 && relative_tolerance < 1))
      fail("relative_tolerance", relative_tolerance, "(0, 1)");
    if (max_iterations < 1)
      fail("max_iterations", max_iterations, "[1, inf)");
    if (!(aggregation_threshold >= 0 && aggregation_threshold < 1))
      fail("aggregation_threshold", aggregation_threshold, "[0, 1)");
    if (smoother_sweeps < 1 || smoother_sweeps > 20)
      fail("smoother_sweeps", smoother_sweeps, "[1, 20]");
  }



  MPI_Comm require_mpi(const MPI_Comm communicator, const std::string &who)
  {
    if (!Utilities::MPI::job_supports_mpi())
      throw std::runtime_error(who + ": MPI is not initialised; the program must create a "
                                     "dealii::Utilities::MPI::MPI_InitFinalize object first");
    return communicator;
  }



  template <int dim>
  DistributedLinearSolver<dim>::DistributedLinearSolver(const DistributedSolverParameters &parameters_,
                                                        const DoFHandler<dim> &dof_handler_, const unsigned int degree_)
    : parameters((parameters_.validate(), parameters_))
    , dof_handler(dof_handler_)
    , degree(degree_)
  {}



  template <int dim>
  LinearSolveReport DistributedLinearSolver<dim>::solve(const Matrix &A, const Vector &b, Vector &u)
  {
    AssertThrow(matrix == nullptr || matrix == &A,
                ExcMessage("DistributedLinearSolver: called with another matrix than the one it factorised"));
    matrix = &A;
    LinearSolveReport report;
    const MPI_Comm    communicator = A.get_mpi_communicator();
    const auto        start        = std::chrono::steady_clock::now();
    bool              built        = false;
    if (parameters.method == DistributedSolverParameters::Method::direct)
      {
        report.solver = "Amesos_Mumps";
        if (!direct)
          {
            control = std::make_unique<SolverControl>(1, 0);
            direct  = std::make_unique<TrilinosWrappers::SolverDirect>(
              *control, TrilinosWrappers::SolverDirect::AdditionalData(false, "Amesos_Mumps"));
            direct->initialize(A);
            built = true;
          }
      }
    else
      {
        report.solver = "CG + ML AMG";
        if (!amg)
          {
            // Near-null space: the constant mode of each component (rotations are left out; the constraints
            // remove the rigid modes of the whole body anyway).
            std::vector<std::vector<bool>> constant_modes;
            DoFTools::extract_constant_modes(dof_handler, ComponentMask(), constant_modes);
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic              = true;
            data.higher_order_elements = degree > 1;
            data.aggregation_threshold = parameters.aggregation_threshold;
            data.smoother_sweeps       = parameters.smoother_sweeps;
            data.constant_modes        = constant_modes;
            amg                        = std::make_unique<TrilinosWrappers::PreconditionAMG>();
            amg->initialize(A, data);
            built = true;
          }
      }
    if (built)
      report.factorize = Utilities::MPI::max(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), communicator);

    u.reinit(A.locally_owned_range_indices(), communicator);
    if (direct)
      direct->solve(u, b);
    else
      {
        SolverControl    cg_control(parameters.max_iterations, parameters.relative_tolerance * b.l2_norm());
        SolverCG<Vector> cg(cg_control);
        try
          {
            cg.solve(A, u, b, *amg);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            std::ostringstream msg;
            msg << "DistributedLinearSolver: CG + AMG did not converge in " << e.last_step
                << " iterations (residual " << e.last_residual / b.l2_norm() << " of ||b||, wanted "
                << parameters.relative_tolerance << "); use Method::direct";
            throw std::runtime_error(msg.str());
          }
        report.iterations = cg_control.last_step();
      }
    Vector residual(A.locally_owned_range_indices(), communicator);
    A.vmult(residual, u);
    residual.sadd(-1.0, 1.0, b);
    const double norm = b.l2_norm();
    report.residual   = norm > 0 ? residual.l2_norm() / norm : residual.l2_norm();
    return report;
  }

  FullMatrix<double> inverse_on_rows(const TrilinosWrappers::SparseMatrix &A, const std::vector<types::global_dof_index> &rows)
  {
    const MPI_Comm     communicator = A.get_mpi_communicator();
    const bool         root         = Utilities::MPI::this_mpi_process(communicator) == 0;
    const unsigned int m            = rows.size();
    if (m == 0)
      throw std::invalid_argument("inverse_on_rows: no rows");
    if (static_cast<std::size_t>(m) * m > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw std::invalid_argument("inverse_on_rows: " + std::to_string(m) + " rows, more than the 46340 whose m x m block one "
                                  "MPI message can carry");
    {
      std::vector<types::global_dof_index> sorted = rows;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw std::invalid_argument("inverse_on_rows: a row is listed twice");
      if (sorted.back() >= A.m())
        throw std::invalid_argument("inverse_on_rows: row " + std::to_string(sorted.back()) + " outside the matrix of " +
                                    std::to_string(A.m()) + " rows");
    }
    if (A.m() > static_cast<types::global_dof_index>(std::numeric_limits<MUMPS_INT>::max()))
      throw std::invalid_argument("inverse_on_rows: " + std::to_string(A.m()) + " rows exceed MUMPS' 32-bit indices");

    // The locally owned rows' entries (1-based, MUMPS' convention), each process its own: MUMPS' distributed
    // assembled input (ICNTL(18) = 3), so no process holds the whole matrix.
    std::vector<MUMPS_INT> irn, jcn;
    std::vector<double>    values;
    // (Epetra's row views: deal.II's row iterator clears a cache of the matrix's width for every row.)
    const Epetra_CrsMatrix &epetra = A.trilinos_matrix();
    for (int local = 0; local < epetra.NumMyRows(); ++local)
      {
        int     n       = 0;
        double *entries = nullptr;
        int    *columns = nullptr;
        if (epetra.ExtractMyRowView(local, n, entries, columns) != 0)
          throw std::runtime_error("inverse_on_rows: cannot read row " + std::to_string(local) + " of the matrix");
        const long long row = epetra.RowMap().GID64(local);
        for (int j = 0; j < n; ++j)
          if (entries[j] != 0)
            {
              irn.push_back(static_cast<MUMPS_INT>(row + 1));
              jcn.push_back(static_cast<MUMPS_INT>(epetra.ColMap().GID64(columns[j]) + 1));
              values.push_back(entries[j]);
            }
      }

    std::vector<MUMPS_INT> schur_rows(m);
    for (unsigned int k = 0; k < m; ++k)
      schur_rows[k] = static_cast<MUMPS_INT>(rows[k] + 1);
    std::vector<double> schur(root ? static_cast<std::size_t>(m) * m : 0);

    DMUMPS_STRUC_C id{};
    id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(communicator));
    id.par          = 1; // the host works too
    id.sym          = 0; // general LU: the Schur complement comes back complete
    id.job          = -1;
    dmumps_c(&id);
    const auto check = [&](const char *phase) {
      if (id.infog[0] < 0)
        {
          const int code = id.infog[0], detail = id.infog[1];
          id.job = -2;
          dmumps_c(&id);
          throw std::runtime_error(std::string("inverse_on_rows: MUMPS ") + phase + " failed with INFOG(1) = " +
                                   std::to_string(code) + ", INFOG(2) = " + std::to_string(detail) +
                                   " (MUMPS users' guide, section 8)");
        }
    };
    check("initialisation");
    id.icntl[0]  = -1; // no error, diagnostic, global or printing output
    id.icntl[1]  = -1;
    id.icntl[2]  = -1;
    id.icntl[3]  = 0;
    id.icntl[4]  = 0;  // assembled matrix
    id.icntl[17] = 3;  // ICNTL(18): distributed, pattern and entries given at the analysis by every process
    id.icntl[18] = 1;  // ICNTL(19): the Schur complement, centralised on the host
    id.n       = static_cast<MUMPS_INT>(A.m());
    id.nnz_loc = static_cast<MUMPS_INT8>(values.size());
    id.irn_loc = irn.data();
    id.jcn_loc = jcn.data();
    id.a_loc   = values.data();
    if (root)
      {
        id.size_schur    = static_cast<MUMPS_INT>(m);
        id.listvar_schur = schur_rows.data();
        id.schur         = schur.data();
      }
    id.job = 4; // analysis and factorisation
    dmumps_c(&id);
    check("factorisation");
    id.job = -2;
    dmumps_c(&id);

    // C = S^{-1} (S by rows; symmetric for a symmetric A).
    FullMatrix<double> result(m, m);
    int                inverted = 1; // process 0 tells the others whether S was positive definite
    if (root)
      try
        {
          LAPACKFullMatrix<double> S(m, m);
          for (unsigned int k = 0; k < m; ++k)
            for (unsigned int l = 0; l < m; ++l)
              S(k, l) = schur[static_cast<std::size_t>(k) * m + l];
          S.set_property(LAPACKSupport::symmetric);
          S.compute_cholesky_factorization();
          S.invert();
          for (unsigned int k = 0; k < m; ++k)
            for (unsigned int l = 0; l < m; ++l)
              result(k, l) = S(k, l);
        }
      catch (const std::exception &)
        {
          inverted = 0;
        }
    MPI_Bcast(&inverted, 1, MPI_INT, 0, communicator);
    if (!inverted)
      throw std::runtime_error("inverse_on_rows: the Schur complement on the " + std::to_string(m) +
                               " rows is not positive definite (a rigid mode of the body left free?)");
    MPI_Bcast(&result(0, 0), static_cast<int>(static_cast<std::size_t>(m) * m), MPI_DOUBLE, 0, communicator);
    return result;
  }



  template class DistributedLinearSolver<2>;
  template class DistributedLinearSolver<3>;
} // namespace gradcontact::fem
