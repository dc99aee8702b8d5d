#include <fem/direct_system.h>
#include <fem/discretization.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <chrono>

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



  void DirectSystem::solve_free(Vector<double> &b_and_u, double &factorize_seconds)
  {
    factorization(false, factorize_seconds).solve(b_and_u);
    constraints->distribute(b_and_u);
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
