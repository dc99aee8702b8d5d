#include <fem/direct_system.h>
#include <fem/discretization.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace gradcontact::fem
{
  using namespace dealii;

  void DirectSystem::reinit(const DoFHandler<2> &dof_handler, const AffineConstraints<double> &constraints_,
                            std::unique_ptr<FarFieldRings> far_field_)
  {
    constraints = &constraints_;
    far_field   = std::move(far_field_);
    exterior    = Exterior();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints_, false);
    if (far_field)
      for (const auto i : far_field->boundary_dofs())
        for (const auto j : far_field->boundary_dofs())
          dsp.add(i, j);
    sparsity_pattern.copy_from(dsp);
    stiffness.reinit(sparsity_pattern);
    eliminated.clear();
    free_solver.reset();
    prescribed_solver.reset();
    prescribed.clear();
  }



  void DirectSystem::set_prescribed_dofs(const std::vector<types::global_dof_index> &dofs)
  {
    prescribed = dofs;
    // Rows and columns of P zeroed, diagonal kept: the eliminated matrix stays symmetric.
    eliminated.reinit(sparsity_pattern);
    eliminated.copy_from(stiffness);
    for (const auto i : prescribed)
      for (auto entry = eliminated.begin(i); entry != eliminated.end(i); ++entry)
        if (entry->column() != i)
          {
            eliminated.set(entry->column(), i, 0.0);
            entry->value() = 0.0;
          }
    prescribed_solver.reset();
  }



  const SparseDirectUMFPACK &DirectSystem::factorization(const bool prescribe, double &seconds)
  {
    std::unique_ptr<SparseDirectUMFPACK> &solver = prescribe ? prescribed_solver : free_solver;
    seconds                                      = 0;
    if (!solver)
      {
        const auto start = std::chrono::steady_clock::now();
        solver           = std::make_unique<SparseDirectUMFPACK>();
        solver->initialize(prescribe ? eliminated : stiffness);
        seconds = seconds_since(start);
      }
    return *solver;
  }



  namespace
  {
    /// Columns of unit loads per CHOLMOD solve: n x 128 doubles (90 MB at 90k DoFs) at a time.
    constexpr unsigned int inverse_block_columns = 128;

    /// CHOLMOD's workspace, finished on every exit.
    struct CholmodCommon
    {
      cholmod_common common;
      CholmodCommon() { cholmod_start(&common); }
      ~CholmodCommon() { cholmod_finish(&common); }
    };
  } // namespace



  FullMatrix<double> DirectSystem::inverse_block(const std::vector<types::global_dof_index> &rows)
  {
    const unsigned int n = stiffness.m(), m = rows.size();
    FullMatrix<double> result(m, m);
    {
      std::vector<types::global_dof_index> sorted(rows);
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw std::invalid_argument("DirectSystem::inverse_block: a row is listed twice");
      if (!sorted.empty() && sorted.back() >= n)
        throw std::invalid_argument("DirectSystem::inverse_block: row " + std::to_string(sorted.back()) +
                                    " outside the matrix of " + std::to_string(n) + " rows");
    }
    if (m == 0)
      return result;

    CholmodCommon cm;
    cholmod_common *c = &cm.common;
    c->print          = 0; // a matrix that is not positive definite is handled below, not printed
    // A is symmetric: its CSR rows are its CSC columns; CHOLMOD reads the upper triangle (stype = 1), the entries
    // (i, j) with i <= j of column j.
    std::size_t nnz = 0;
    for (unsigned int j = 0; j < n; ++j)
      for (auto entry = stiffness.begin(j); entry != stiffness.end(j); ++entry)
        nnz += entry->column() <= j;
    if (nnz > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw std::invalid_argument("DirectSystem::inverse_block: " + std::to_string(nnz) +
                                  " entries exceed CHOLMOD's 32-bit indices");
    cholmod_sparse *A = cholmod_allocate_sparse(n, n, nnz, /*sorted*/ 0, /*packed*/ 1, /*stype*/ 1, CHOLMOD_REAL, c);
    if (!A)
      throw std::runtime_error("DirectSystem::inverse_block: CHOLMOD cannot allocate the matrix (" + std::to_string(nnz) +
                               " entries)");
    auto *Ap = static_cast<int *>(A->p);
    auto *Ai = static_cast<int *>(A->i);
    auto *Ax = static_cast<double *>(A->x);
    std::size_t k = 0;
    for (unsigned int j = 0; j < n; ++j)
      {
        Ap[j] = static_cast<int>(k);
        for (auto entry = stiffness.begin(j); entry != stiffness.end(j); ++entry)
          if (entry->column() <= j)
            {
              Ai[k]   = static_cast<int>(entry->column());
              Ax[k++] = entry->value();
            }
      }
    Ap[n] = static_cast<int>(k);

    cholmod_factor *L = cholmod_analyze(A, c);
    bool            positive_definite = L && cholmod_factorize(A, L, c) && c->status == CHOLMOD_OK;
    cholmod_free_sparse(&A, c);
    if (!positive_definite)
      {
        // Not positive definite (or CHOLMOD failed): one back substitution of the LU factorisation per row.
        if (L)
          cholmod_free_factor(&L, c);
        double                     unused = 0;
        const SparseDirectUMFPACK &direct = factorization(false, unused);
        Vector<double>             u(n);
        for (unsigned int j = 0; j < m; ++j)
          {
            u          = 0;
            u[rows[j]] = 1;
            direct.solve(u); // the unconstrained rows read below need no distribution of the constraints
            for (unsigned int i = 0; i < m; ++i)
              result(i, j) = u[rows[i]];
          }
        return result;
      }
    for (unsigned int first = 0; first < m; first += inverse_block_columns)
      {
        const unsigned int columns = std::min(inverse_block_columns, m - first);
        cholmod_dense     *B       = cholmod_zeros(n, columns, CHOLMOD_REAL, c);
        if (!B)
          {
            cholmod_free_factor(&L, c);
            throw std::runtime_error("DirectSystem::inverse_block: CHOLMOD cannot allocate " + std::to_string(columns) +
                                     " right-hand sides");
          }
        auto *Bx = static_cast<double *>(B->x);
        for (unsigned int j = 0; j < columns; ++j)
          Bx[static_cast<std::size_t>(j) * B->d + rows[first + j]] = 1;
        cholmod_dense *X = cholmod_solve(CHOLMOD_A, L, B, c);
        cholmod_free_dense(&B, c);
        if (!X)
          {
            cholmod_free_factor(&L, c);
            throw std::runtime_error("DirectSystem::inverse_block: the CHOLMOD solve failed (status " +
                                     std::to_string(c->status) + ")");
          }
        const auto *Xx = static_cast<const double *>(X->x);
        for (unsigned int j = 0; j < columns; ++j)
          for (unsigned int i = 0; i < m; ++i)
            result(i, first + j) = Xx[static_cast<std::size_t>(j) * X->d + rows[i]];
        cholmod_free_dense(&X, c);
      }
    cholmod_free_factor(&L, c);
    return result;
  }



  Vector<double> DirectSystem::solve(const bool prescribe, const std::vector<double> &g, const Vector<double> &b,
                                     Vector<double> &reaction, double &factorize_seconds)
  {
    const SparseDirectUMFPACK &direct = factorization(prescribe, factorize_seconds);
    const unsigned int         n      = stiffness.m();

    // rhs = b - A g_ext off P, A_ii g_i on P.
    Vector<double> u(n), rhs(b);
    if (prescribe)
      {
        Vector<double> g_ext(n), Ag(n);
        for (unsigned int i = 0; i < prescribed.size(); ++i)
          g_ext[prescribed[i]] = g[i];
        stiffness.vmult(Ag, g_ext);
        rhs -= Ag;
        for (unsigned int i = 0; i < prescribed.size(); ++i)
          rhs[prescribed[i]] = eliminated.diag_element(prescribed[i]) * g[i];
      }
    u = rhs;
    direct.solve(u);
    constraints->distribute(u);

    reaction.reinit(n);
    stiffness.vmult(reaction, u);
    reaction -= b;
    return u;
  }



  double DirectSystem::energy(const Vector<double> &u) const
  {
    Vector<double> u_free(u), Au(u.size());
    constraints->set_zero(u_free);
    stiffness.vmult(Au, u_free);
    return u_free * Au;
  }
} // namespace gradcontact::fem
