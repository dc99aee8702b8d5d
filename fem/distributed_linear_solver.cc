#include <fem/distributed_linear_solver.h>
#include <fem/errors.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>

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

  template class DistributedLinearSolver<2>;
  template class DistributedLinearSolver<3>;
} // namespace gradcontact::fem
