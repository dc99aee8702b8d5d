#include <fem/linear_algebra/direct_system.h>
#include <fem/grid/discretization.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <cholmod.h>
#include <umfpack.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    /// CHOLMOD's workspace, finished on every exit.
    struct CholmodCommon
    {
      cholmod_common common;
      CholmodCommon()
      {
        cholmod_start(&common);
        common.print = 0; // a matrix that is not positive definite is handled by the caller, not printed
        // AMD alone (Amestoy, Davis and Duff, SIAM J. Matrix Anal. Appl. 17 (1996) 886): CHOLMOD's default also tries
        // METIS and keeps the sparser factor, an analysis that costs more than it saves on the meridian meshes, whose
        // graded rings AMD orders well (`fem_study` prints the analysis and factorisation times).
        common.nmethods           = 1;
        common.method[0].ordering = CHOLMOD_AMD;
        // Supernodal always: its LL^T stops at the first pivot <= 0. CHOLMOD's automatic choice takes the simplicial
        // LDL^T for small matrices, which without pivoting only stops at an exactly zero pivot and would factorise a
        // small indefinite matrix (the mixed formulation's) unstably instead of leaving it to the LU.
        common.supernodal = CHOLMOD_SUPERNODAL;
      }
      ~CholmodCommon() { cholmod_finish(&common); }
      CholmodCommon(const CholmodCommon &) = delete;
      CholmodCommon &operator=(const CholmodCommon &) = delete;
    };

    /// UMFPACK's sparse LU (Davis, ACM TOMS 30 (2004) 196) of a square matrix that is not positive definite (the mixed
    /// formulation's saddle point), with its controls set here: the symmetric strategy (an ordering of A + A^T and a
    /// preference for diagonal pivots, off-diagonal ones where the saddle point's pressure block needs them; header),
    /// rows scaled by their largest entry, and no refinement of its own: the caller refines against its own residual
    /// until the backward error stops falling (DirectSystem::refine).
    class UmfpackLU
    {
    public:
      explicit UmfpackLU(const SparseMatrix<double> &A)
        : n(A.m())
      {
        // Compressed columns of A: column j holds A(i, j) for every row i with an entry in column j, rows ascending.
        std::vector<SuiteSparse_long> count(n + 1, 0);
        for (unsigned int i = 0; i < n; ++i)
          for (auto entry = A.begin(i); entry != A.end(i); ++entry)
            ++count[entry->column() + 1];
        Ap.assign(count.begin(), count.end());
        for (unsigned int j = 0; j < n; ++j)
          Ap[j + 1] += Ap[j];
        Ai.resize(Ap[n]);
        Ax.resize(Ap[n]);
        std::vector<SuiteSparse_long> next(Ap.begin(), Ap.end() - 1);
        for (unsigned int i = 0; i < n; ++i) // rows in ascending order: each column's rows come out sorted
          for (auto entry = A.begin(i); entry != A.end(i); ++entry)
            {
              const auto k = next[entry->column()]++;
              Ai[k]        = i;
              Ax[k]        = entry->value();
            }
        equilibrate();
        umfpack_dl_defaults(control);
        control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
        control[UMFPACK_SCALE]    = UMFPACK_SCALE_NONE; // equilibrated above
        control[UMFPACK_IRSTEP]   = 0;
        double info[UMFPACK_INFO];
        void  *symbolic = nullptr;
        check(umfpack_dl_symbolic(n, n, Ap.data(), Ai.data(), Ax.data(), &symbolic, control, info), "symbolic");
        const SuiteSparse_long status = umfpack_dl_numeric(Ap.data(), Ai.data(), Ax.data(), symbolic, &numeric,
                                                           control, info);
        umfpack_dl_free_symbolic(&symbolic);
        check(status, "numeric");
        numeric_bytes = info[UMFPACK_NUMERIC_SIZE] * info[UMFPACK_SIZE_OF_UNIT];
      }

      /// The numeric object and the copy of the matrix.
      std::size_t bytes() const
      {
        return static_cast<std::size_t>(numeric_bytes) + (Ap.size() + Ai.size()) * sizeof(SuiteSparse_long) +
               Ax.size() * sizeof(double);
      }

      ~UmfpackLU()
      {
        if (numeric)
          umfpack_dl_free_numeric(&numeric);
      }

      UmfpackLU(const UmfpackLU &) = delete;
      UmfpackLU &operator=(const UmfpackLU &) = delete;

      /// x <- A^{-1} x = D_c (D_r A D_c)^{-1} D_r x.
      void solve(Vector<double> &x) const
      {
        Vector<double> b(x);
        for (SuiteSparse_long i = 0; i < n; ++i)
          b[i] *= row_scale[i];
        double info[UMFPACK_INFO];
        check(umfpack_dl_solve(UMFPACK_A, Ap.data(), Ai.data(), Ax.data(), x.begin(), b.begin(), numeric, control,
                               info),
              "solve");
        for (SuiteSparse_long j = 0; j < n; ++j)
          x[j] *= column_scale[j];
      }

    private:
      /// Scales the rows and columns of the copy to a largest entry of about 1 each (Ruiz, "A scaling algorithm to
      /// equilibrate both rows and columns norms in matrices", RAL-TR-2001-034: D_r A D_c, each step dividing by the
      /// square roots of the rows' and columns' largest entries). A stiff thin skin over a soft bulk (k < 0) puts
      /// entries many orders apart in one matrix; scaling rows alone leaves the columns of the pivot search unequal.
      void equilibrate()
      {
        constexpr unsigned int steps = 8;
        row_scale.assign(n, 1.0);
        column_scale.assign(n, 1.0);
        std::vector<double> row_max(n), column_max(n);
        for (unsigned int step = 0; step < steps; ++step)
          {
            std::fill(row_max.begin(), row_max.end(), 0.0);
            std::fill(column_max.begin(), column_max.end(), 0.0);
            for (SuiteSparse_long j = 0; j < n; ++j)
              for (SuiteSparse_long k = Ap[j]; k < Ap[j + 1]; ++k)
                {
                  const double x = std::abs(Ax[k]);
                  row_max[Ai[k]] = std::max(row_max[Ai[k]], x);
                  column_max[j]  = std::max(column_max[j], x);
                }
            for (SuiteSparse_long i = 0; i < n; ++i)
              {
                row_max[i]    = row_max[i] > 0 ? 1 / std::sqrt(row_max[i]) : 1.0;
                column_max[i] = column_max[i] > 0 ? 1 / std::sqrt(column_max[i]) : 1.0;
                row_scale[i] *= row_max[i];
                column_scale[i] *= column_max[i];
              }
            for (SuiteSparse_long j = 0; j < n; ++j)
              for (SuiteSparse_long k = Ap[j]; k < Ap[j + 1]; ++k)
                Ax[k] *= row_max[Ai[k]] * column_max[j];
          }
      }

      /// A failed UMFPACK step (a singular matrix included: its solve would divide by zero) is an error naming the step.
      static void check(const SuiteSparse_long status, const char *step)
      {
        if (status != UMFPACK_OK)
          throw std::runtime_error(std::string("DirectSystem: UMFPACK's ") + step + " step failed (status " +
                                   std::to_string(status) + (status == UMFPACK_WARNING_singular_matrix ?
                                                               ": the matrix is singular)" : ")"));
      }

      SuiteSparse_long              n;
      std::vector<SuiteSparse_long> Ap, Ai;
      std::vector<double>           Ax;
      std::vector<double>           row_scale, column_scale; ///< D_r, D_c of equilibrate
      double                        control[UMFPACK_CONTROL];
      void                         *numeric       = nullptr;
      double                        numeric_bytes = 0;
    };
  } // namespace



  class DirectSystem::Factorization
  {
  public:
    /// Cholesky when A is positive definite, else LU.
    explicit Factorization(const SparseMatrix<double> &A)
      : A_norm(A.linfty_norm())
    {
      if (!factorize_cholesky(A))
        lu = std::make_unique<UmfpackLU>(A);
    }

    ~Factorization()
    {
      if (factor)
        cholmod_free_factor(&factor, &workspace.common);
    }

    Factorization(const Factorization &) = delete;
    Factorization &operator=(const Factorization &) = delete;

    bool cholesky() const { return factor != nullptr; }

    std::size_t bytes() const { return lu ? lu->bytes() : workspace.common.memory_inuse; }

    /// |A|_inf of the factorised matrix (the scale of the backward error).
    double matrix_norm() const { return A_norm; }

    /// x <- A^{-1} x (no refinement: DirectSystem::solve refines).
    void solve(Vector<double> &x) const
    {
      if (lu)
        {
          lu->solve(x);
          return;
        }
      cholmod_dense b = dense_view(x.begin(), x.size(), 1);
      cholmod_dense *X = cholmod_solve(CHOLMOD_A, factor, &b, &workspace.common);
      if (!X)
        throw std::runtime_error("DirectSystem: the CHOLMOD solve failed (status " +
                                 std::to_string(workspace.common.status) + ")");
      std::copy_n(static_cast<const double *>(X->x), x.size(), x.begin());
      cholmod_free_dense(&X, &workspace.common);
    }

    /// The columns of `columns` (n x m, column-major) replaced by A^{-1} times them (Cholesky only).
    void solve_columns(std::vector<double> &columns, const std::size_t n, const std::size_t m) const
    {
      Assert(factor, ExcInternalError());
      cholmod_dense b = dense_view(columns.data(), n, m);
      cholmod_dense *X = cholmod_solve(CHOLMOD_A, factor, &b, &workspace.common);
      if (!X)
        throw std::runtime_error("DirectSystem::inverse_block: the CHOLMOD solve failed (status " +
                                 std::to_string(workspace.common.status) + ")");
      std::copy_n(static_cast<const double *>(X->x), n * m, columns.begin());
      cholmod_free_dense(&X, &workspace.common);
    }

  private:
    /// A CHOLMOD view of n x m doubles, column-major (not owned).
    static cholmod_dense dense_view(double *data, const std::size_t n, const std::size_t m)
    {
      cholmod_dense b{};
      b.nrow  = n;
      b.ncol  = m;
      b.nzmax = n * m;
      b.d     = n;
      b.x     = data;
      b.z     = nullptr;
      b.xtype = CHOLMOD_REAL;
      b.dtype = CHOLMOD_DOUBLE;
      return b;
    }

    /// false (and no factor) when A is not positive definite or CHOLMOD cannot factorise it (e.g. more entries
    /// than its 32-bit indices hold).
    bool factorize_cholesky(const SparseMatrix<double> &A)
    {
      cholmod_common *c = &workspace.common;
      const unsigned int n = A.m();
      // A is symmetric: its CSR rows are its CSC columns; CHOLMOD reads the upper triangle (stype = 1), the entries
      // (i, j) with i <= j of column j.
      std::size_t nnz = 0;
      for (unsigned int j = 0; j < n; ++j)
        for (auto entry = A.begin(j); entry != A.end(j); ++entry)
          nnz += entry->column() <= j;
      if (nnz > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return false;
      cholmod_sparse *S = cholmod_allocate_sparse(n, n, nnz, /*sorted*/ 0, /*packed*/ 1, /*stype*/ 1, CHOLMOD_REAL, c);
      if (!S)
        return false;
      auto *Sp = static_cast<int *>(S->p);
      auto *Si = static_cast<int *>(S->i);
      auto *Sx = static_cast<double *>(S->x);
      std::size_t k = 0;
      for (unsigned int j = 0; j < n; ++j)
        {
          Sp[j] = static_cast<int>(k);
          for (auto entry = A.begin(j); entry != A.end(j); ++entry)
            if (entry->column() <= j)
              {
                Si[k]   = static_cast<int>(entry->column());
                Sx[k++] = entry->value();
              }
        }
      Sp[n] = static_cast<int>(k);
      factor = cholmod_analyze(S, c);
      const bool positive_definite =
        factor && cholmod_factorize(S, factor, c) && c->status == CHOLMOD_OK && factor->is_ll;
      cholmod_free_sparse(&S, c);
      if (!positive_definite && factor)
        cholmod_free_factor(&factor, c);
      return positive_definite;
    }

    double                               A_norm;
    mutable CholmodCommon                workspace;
    cholmod_factor                      *factor = nullptr;
    std::unique_ptr<UmfpackLU>           lu;
  };



  DirectSystem::DirectSystem()  = default;
  DirectSystem::~DirectSystem() = default;

  bool DirectSystem::cholesky(const bool prescribe) const
  {
    const auto &solver = prescribe ? prescribed_solver : free_solver;
    return solver && solver->cholesky();
  }



  std::size_t DirectSystem::factor_bytes() const
  {
    if (!free_solver && !prescribed_solver)
      return 0;
    return (free_solver ? free_solver->bytes() : 0) + (prescribed_solver ? prescribed_solver->bytes() : 0) +
           stiffness.memory_consumption() + eliminated.memory_consumption() + sparsity_pattern.memory_consumption();
  }

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



  const DirectSystem::Factorization &DirectSystem::factorization(const bool prescribe, double &seconds)
  {
    std::unique_ptr<Factorization> &solver = prescribe ? prescribed_solver : free_solver;
    seconds                                = 0;
    if (!solver)
      {
        const auto start = std::chrono::steady_clock::now();
        solver           = std::make_unique<Factorization>(prescribe ? eliminated : stiffness);
        seconds          = seconds_since(start);
      }
    return *solver;
  }



  namespace
  {
    /// Columns of unit loads per CHOLMOD solve: n x 128 doubles at a time, so that the block's memory grows with n
    /// only, not with the number of columns asked for.
    constexpr unsigned int inverse_block_columns = 128;
  } // namespace



  namespace
  {
    /// s + t = a + b exactly (Knuth's TwoSum).
    inline void two_sum(const double a, const double b, double &s, double &t)
    {
      s             = a + b;
      const double z = s - a;
      t             = (a - (s - z)) + (b - z);
    }

    /// r = b - A u, each row's sum as accurate as if computed in twice the working precision and rounded (Ogita, Rump
    /// and Oishi, "Accurate sum and dot product", SIAM J. Sci. Comput. 26 (2005) 1955, algorithm Dot2: TwoProduct
    /// by a fused multiply-add, TwoSum for the sum). A residual in working precision is polluted by eps |A| |u|,
    /// which the back substitution amplifies by the condition number; the accurate one lets refinement converge to
    /// the solution rounded to working precision while the condition number stays well below 1 / eps (Higham,
    /// Accuracy and Stability of Numerical Algorithms, 2nd ed., sec. 12.1).
    void accurate_residual(const SparseMatrix<double> &A, const Vector<double> &u, const Vector<double> &b,
                           Vector<double> &r)
    {
      for (unsigned int i = 0; i < A.m(); ++i)
        {
          double sum = b[i], compensation = 0;
          for (auto entry = A.begin(i); entry != A.end(i); ++entry)
            {
              const double p = -entry->value() * u[entry->column()];
              const double p_error = std::fma(-entry->value(), u[entry->column()], -p);
              double       s, t;
              two_sum(sum, p, s, t);
              sum = s;
              compensation += t + p_error;
            }
          r[i] = sum + compensation;
        }
    }

    /// A row annihilates the translation when its entries sum to at most this times their magnitudes over it: the
    /// rounding of the entries (a few eps each), far below the sum of a row that the far field or a clamped
    /// neighbour grounds.
    constexpr double translation_free_rows = 1e-11;

    /// r = b - A u as accurate_residual, except in the rows with an anchor a_i (DirectSystem::set_translation), whose
    /// products take u_j - u_(a_i) t_j in place of u_j: the residual of A with those rows' sums over t made exactly 0.
    /// No anchors (an empty `anchor`, no translation): accurate_residual.
    void anchored_residual(const SparseMatrix<double> &A, const Vector<double> &t,
                           const std::vector<types::global_dof_index> &anchor, const Vector<double> &u,
                           const Vector<double> &b, Vector<double> &r)
    {
      if (anchor.empty())
        {
          accurate_residual(A, u, b, r);
          return;
        }
      for (unsigned int i = 0; i < A.m(); ++i)
        {
          const double shift = anchor[i] == numbers::invalid_dof_index ? 0.0 : u[anchor[i]];
          double       sum = b[i], compensation = 0;
          for (auto entry = A.begin(i); entry != A.end(i); ++entry)
            {
              const double value   = u[entry->column()] - shift * t[entry->column()];
              const double p       = -entry->value() * value;
              const double p_error = std::fma(-entry->value(), value, -p);
              double       s, e;
              two_sum(sum, p, s, e);
              sum = s;
              compensation += e + p_error;
            }
          r[i] = sum + compensation;
        }
    }

    /// Refinement stops when a correction is below this times |u| (the solution rounded to working precision).
    constexpr double refinement_target = 4 * std::numeric_limits<double>::epsilon();
    /// At most this many refinement steps; a step whose correction is not at most half the one before ends it.
    constexpr unsigned int max_refinement_steps = 10;
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

    double               unused = 0;
    const Factorization &direct = factorization(false, unused);
    if (!direct.cholesky())
      {
        // Not positive definite: one refined solve of the LU factorisation per row.
        Vector<double> u(n), unit(n);
        for (unsigned int j = 0; j < m; ++j)
          {
            unit          = 0;
            unit[rows[j]] = 1;
            u             = unit;
            direct.solve(u);
            // the unconstrained rows read below need no distribution of the constraints
            const auto residual = [&](const Vector<double> &x, Vector<double> &r) {
              accurate_residual(stiffness, x, unit, r);
            };
            refine(direct, residual, {}, u);
            for (unsigned int i = 0; i < m; ++i)
              result(i, j) = u[rows[i]];
          }
        return result;
      }
    std::vector<double> block;
    for (unsigned int first = 0; first < m; first += inverse_block_columns)
      {
        const unsigned int columns = std::min(inverse_block_columns, m - first);
        block.assign(static_cast<std::size_t>(n) * columns, 0.0);
        for (unsigned int j = 0; j < columns; ++j)
          block[static_cast<std::size_t>(j) * n + rows[first + j]] = 1;
        direct.solve_columns(block, n, columns);
        for (unsigned int j = 0; j < columns; ++j)
          for (unsigned int i = 0; i < m; ++i)
            result(i, first + j) = block[static_cast<std::size_t>(j) * n + rows[i]];
      }
    return result;
  }



  void DirectSystem::refine(const Factorization &direct, const Residual &residual,
                            const std::vector<types::global_dof_index> &fixed, Vector<double> &u) const
  {
    // Iterative refinement with an accurate residual (Higham, ch. 12; Moler, J. ACM 14 (1967) 316):
    // u += A^{-1} (rhs - A u) until the correction is at the rounding of u. It makes the solve backward stable where
    // the factorisation's pivots are not (an ill-conditioned saddle point whose LU depends on the rounding of the BLAS
    // kernel), and its forward error that of the rounding of the solution rather than the condition number times
    // the working precision. Each step costs one back substitution. The rows `fixed` keep their values.
    Vector<double> r(u.size()), correction(u.size());
    double         previous = std::numeric_limits<double>::infinity();
    for (unsigned int step = 0; step < max_refinement_steps; ++step)
      {
        residual(u, r);
        for (const auto i : fixed)
          r[i] = 0;
        correction = r;
        direct.solve(correction);
        for (const auto i : fixed)
          correction[i] = 0;
        const double size = correction.linfty_norm();
        if (!(size < previous))
          return; // diverging or stalled: keep u
        u += correction;
        if (size <= refinement_target * u.linfty_norm() || size > 0.5 * previous)
          return;
        previous = size;
      }
  }



  Vector<double> DirectSystem::solve(const bool prescribe, const std::vector<double> &g, const Vector<double> &b,
                                     Vector<double> &reaction, double &factorize_seconds)
  {
    const Factorization &direct = factorization(prescribe, factorize_seconds);
    const unsigned int   n      = stiffness.m();

    // With a translation (header) the unknown is v = u - c t, c the prescribed value of the stiffest prescribed row,
    // under the load b - c A t (A t: non-zero only in the rows that do not annihilate t).
    double c = 0;
    if (prescribe && !anchor.empty() && !prescribed.empty())
      {
        unsigned int stiffest = 0;
        for (unsigned int i = 1; i < prescribed.size(); ++i)
          if (std::abs(stiffness.diag_element(prescribed[i])) > std::abs(stiffness.diag_element(prescribed[stiffest])))
            stiffest = i;
        c = g[stiffest];
      }
    Vector<double> load(b);
    if (c != 0)
      load.add(-c, grounded);

    // rhs = load - A g_ext off P, A_ii g_i on P (g - c).
    Vector<double> v(n), rhs(load);
    if (prescribe)
      {
        Vector<double> g_ext(n);
        for (unsigned int i = 0; i < prescribed.size(); ++i)
          g_ext[prescribed[i]] = g[i] - c;
        accurate_residual(stiffness, g_ext, load, rhs);
        for (unsigned int i = 0; i < prescribed.size(); ++i)
          rhs[prescribed[i]] = eliminated.diag_element(prescribed[i]) * (g[i] - c);
      }
    v = rhs;
    direct.solve(v);
    if (anchor.empty())
      {
        const SparseMatrix<double> &A = prescribe ? eliminated : stiffness;
        refine(direct, [&](const Vector<double> &x, Vector<double> &r) { accurate_residual(A, x, rhs, r); }, {}, v);
      }
    else
      {
        // Against A with the anchored rows (header), in the full unknowns: the rows of P keep v_P = g - c.
        if (prescribe)
          for (unsigned int i = 0; i < prescribed.size(); ++i)
            v[prescribed[i]] = g[i] - c;
        const auto residual = [&](const Vector<double> &x, Vector<double> &r) {
          anchored_residual(stiffness, translation, anchor, x, load, r);
        };
        refine(direct, residual, prescribe ? prescribed : std::vector<types::global_dof_index>(), v);
      }
    constraints->distribute(v);

    // R = A u - b = A v - load, accurately: on a stiff surface its rows cancel large terms (header).
    reaction.reinit(n);
    anchored_residual(stiffness, translation, anchor, v, load, reaction);
    reaction *= -1;
    if (c == 0)
      return v;
    Vector<double> u(v);
    u.add(c, translation);
    constraints->distribute(u);
    return u;
  }



  void DirectSystem::set_translation(const Vector<double> &t)
  {
    if (t.size() != stiffness.m())
      throw std::invalid_argument("DirectSystem::set_translation: " + std::to_string(t.size()) +
                                  " entries, the system has " + std::to_string(stiffness.m()) + " DoFs");
    translation = t;
    // The unconstrained DoFs only (distribute() sets the others). A row's anchor: its largest entry over t, where
    // the row annihilates t within rounding (elsewhere the far field or a clamped neighbour grounds it).
    constraints->set_zero(translation);
    anchor.assign(stiffness.m(), numbers::invalid_dof_index);
    for (unsigned int i = 0; i < stiffness.m(); ++i)
      {
        double                  sum = 0, magnitude = 0, largest = 0;
        types::global_dof_index best = numbers::invalid_dof_index;
        for (auto entry = stiffness.begin(i); entry != stiffness.end(i); ++entry)
          if (translation[entry->column()] != 0.0)
            {
              sum += entry->value();
              magnitude += std::abs(entry->value());
              if (std::abs(entry->value()) > largest)
                largest = std::abs(entry->value()), best = entry->column();
            }
        if (magnitude > 0 && std::abs(sum) <= translation_free_rows * magnitude)
          anchor[i] = best;
      }
    // A t in the other rows, summed accurately.
    grounded.reinit(stiffness.m());
    const Vector<double> none(stiffness.m());
    accurate_residual(stiffness, translation, none, grounded);
    grounded *= -1;
    for (unsigned int i = 0; i < stiffness.m(); ++i)
      if (anchor[i] != numbers::invalid_dof_index)
        grounded[i] = 0;
  }



  double DirectSystem::energy(const Vector<double> &u) const
  {
    Vector<double> u_free(u), Au(u.size());
    constraints->set_zero(u_free);
    stiffness.vmult(Au, u_free);
    return u_free * Au;
  }



  double DirectSystem::energy_magnitude(const Vector<double> &u) const
  {
    Vector<double> u_free(u);
    constraints->set_zero(u_free);
    double sum = 0;
    for (unsigned int i = 0; i < u_free.size(); ++i)
      if (u_free[i] != 0)
        for (auto entry = stiffness.begin(i); entry != stiffness.end(i); ++entry)
          sum += std::abs(u_free[i] * entry->value() * u_free[entry->column()]);
    return sum;
  }
} // namespace gradcontact::fem
