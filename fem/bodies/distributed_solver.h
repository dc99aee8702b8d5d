// The axisymmetric graded half-space on a distributed triangulation (p4est) with Trilinos linear algebra:
// the variant of fem/bodies/axisymmetric_solver.h for runs that outgrow one process.
//
// Same model, same discrete operator: the coarse mesh comes from make_coarse_mesh and is refined by
// refine_mesh (fem/grid/mesh.h), the cell matrices and loads from fem/elasticity/graded_elasticity.h, the material
// from fem/modulus/modulus.h. On meshes without z-only halvings the mesh, hence the discrete problem, is the
// one of the serial solver, and the answers agree to the accuracy of the linear solvers.
//
// Loads. LoadType::flat_punch (u_z = d on r <= a, no shear), LoadType::constant_pressure (p0 on
// r <= a) and LoadType::indenter (any Profile in frictionless contact on r <= a, the mesh's contact
// radius: contact-radius control as in the serial solver, u = d u1 + u2 with u2 the state u_z = -f(r)
// on the contact and d from a vanishing nodal force at the edge node r = a; both share the one
// factorisation or preconditioner of the contact-constrained matrix); the other load types throw
// std::invalid_argument. The flat punch is solved as d times the
// unit punch u1 (u_z = 1 on the contact z-DoFs, an inhomogeneous AffineConstraints), so one matrix and
// one preconditioner or factorisation serve every depth. Force from the reaction,
//   F = 2 pi sum_{i in contact} (A u)_i = 2 pi a(u, phi),   phi = sum of the contact z-basis functions,
// with A assembled with the homogeneous constraints only (axis, far field, hanging nodes); the constant
// pressure gives F = pi p0 a^2 and the depth w_c = u_z(0, 0).
//
// Linear solvers: fem/linear_algebra/distributed_linear_solver.h (MUMPS by default, or CG + ML AMG).
//
// Reliability as in the serial solver: |u.Au - work| / u.Au above 1e-6 marks the result unreliable.
//
// MPI. The caller initialises MPI (Utilities::MPI::MPI_InitFinalize); every process of `communicator`
// must construct the solver and call run() with the same arguments. The results are the same on every
// process.
#ifndef GRADCONTACT_FEM_DISTRIBUTED_SOLVER_H
#define GRADCONTACT_FEM_DISTRIBUTED_SOLVER_H

#include <fem/grid/discretization.h>
#include <fem/linear_algebra/distributed_linear_solver.h>
#include <fem/bodies/loads.h>
#include <fem/grid/mesh.h>
#include <fem/modulus/modulus.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace gradcontact::fem
{
  struct DistributedResult : RunReport
  {
    double force = 0; ///< F_N, compressive positive
    double depth = 0; ///< d (flat punch, indenter) or w_c = u_z(0, 0) (constant pressure)
    double contact_radius = 0; ///< a (the mesh's contact radius)
    /// indenter: fem/base/contact_check.h's min_relative_contact_force (>= -1e-3 for a consistent state)
    double min_relative_contact_force = 0;
    bool   consistent_contact = true; ///< indenter: no tensile nodal contact force beyond the tolerance

    unsigned int n_processes = 0;
    unsigned int control_trials = 0; ///< depth/force control (solve_controlled): radius-controlled states solved
    std::string  solver;          ///< "Amesos_Mumps" or "CG + ML AMG"
    unsigned int iterations = 0;  ///< CG iterations of this run (0: direct)
    double       residual   = 0;  ///< ||b - A u|| / ||b|| of the linear solve
  };

  class DistributedSolver
  {
  public:
    /// Builds the distributed mesh, DoFs, constraints and both matrices (collective). Throws
    /// std::invalid_argument on bad input (also a surface_layer_thickness that needs z-only halvings,
    /// which p4est cannot do) and std::runtime_error when MPI is not initialised.
    DistributedSolver(MPI_Comm communicator, const Material &material, const MeshParameters &mesh,
                      const DiscretizationParameters &discretization,
                      const DistributedSolverParameters &solver = {});
    ~DistributedSolver();

    /// Solves one load case (collective), reusing everything load independent.
    DistributedResult run(const LoadCase &load);

    dealii::types::global_dof_index n_dofs() const { return dof_handler.n_dofs(); }

  private:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;
    using Matrix = dealii::TrilinosWrappers::SparseMatrix;

    void make_grid();
    void setup_system();
    void assemble_system();
    /// u = A^{-1} b for the contact-constrained matrix (true) or the free one; iterations and the
    /// factorisation time into `result`.
    void solve(bool contact_constrained, const Vector &b, Vector &u, DistributedResult &result);
    /// The three load cases; each returns the work of its loads per 2 pi and fills force and depth.
    double solve_flat_punch(const LoadCase &load, Vector &u, DistributedResult &result);
    double solve_indenter(const LoadCase &load, Vector &u, DistributedResult &result);
    double solve_pressure(const LoadCase &load, Vector &u, DistributedResult &result);
    double elapsed_max(const std::chrono::steady_clock::time_point &start) const;

    MPI_Comm                          communicator;
    const Material                    material;
    const MeshParameters              mesh_parameters;
    const DiscretizationParameters    discretization;
    const DistributedSolverParameters solver_parameters;

    dealii::parallel::distributed::Triangulation<2> triangulation;
    MeshInfo                                        mesh_info;
    const dealii::FESystem<2>                       fe;
    dealii::DoFHandler<2>                           dof_handler;
    const dealii::MappingQ1<2>                      mapping;

    dealii::IndexSet owned, relevant;
    /// Homogeneous: hanging nodes, u_r = 0 on the axis, u = 0 on the far field.
    dealii::AffineConstraints<double> constraints;
    /// The same plus u_z = 1 on the contact z-DoFs (the unit punch).
    dealii::AffineConstraints<double> punch_constraints;
    Matrix stiffness;       ///< A with `constraints`: the reaction A u and the energy u.Au
    Matrix punch_matrix;    ///< A with `punch_constraints`
    Vector unit_punch_rhs;  ///< the right-hand side of the unit punch
    std::vector<dealii::types::global_dof_index> owned_contact_dofs; ///< locally owned contact z-DoFs
    std::vector<double> owned_contact_r; ///< their radii
    dealii::types::global_dof_index edge_dof; ///< the contact z-DoF at r = a (owner only; else invalid)
    dealii::types::global_dof_index centre_dof; ///< the z-DoF at (0, 0)
    DistributedLinearSolver<2> punch_solver, free_solver;
    Timings      setup_time;
  };
  /// Depth or force control of a rigid indenter on the distributed solver (`load.type` indenter_depth or
  /// indenter_force, collective). p4est cannot take the serial solver's search over contact sets of one mesh
  /// (fem/bodies/axisymmetric_solver.h), so the contact radius a is searched over radius-controlled states, each on
  /// its own mesh graded at a (`settings(a)`, a new DistributedSolver): the secant method on (log a,
  /// log(value(a) / target)), value = d(a) or F(a), from a0 and a0 times or over 1.05 (toward the target), steps
  /// limited to a factor 2. On a power-law modulus the problem is scale free (every mesh a scaled copy), d and F
  /// are powers of a and the third state is the answer. Stops when |value / target - 1| <= tolerance, or when a moves by less than 1e-9
  /// relative (the value's round-off is above the tolerance: said in `message`); throws std::runtime_error with
  /// the trials, the last a and value after `max_trials`, or when value(a) does not grow with a. The result is
  /// the last state, with control_trials set.
  DistributedResult solve_controlled(MPI_Comm communicator, const Material &material, const LoadCase &load,
                                     const SettingsAtRadius &settings, double a0, double tolerance = 1e-10,
                                     unsigned int max_trials = 20, const DistributedSolverParameters &solver = {});
} // namespace gradcontact::fem

#endif
