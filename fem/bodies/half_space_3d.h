// Linear elasticity of the graded half-space in 3D, on a distributed triangulation (p4est) with Trilinos
// linear algebra: the model for loads that are not axisymmetric and for contact problems that do not
// separate into Fourier modes (Coulomb stick-slip with a free slip direction).
//
// Geometry (fem/grid/mesh_3d.h): the half cylinder x^2 + y^2 <= L^2, y >= 0, 0 <= z <= L, z into the material,
// the revolution of the meridian domain of fem/grid/mesh.h. The plane y = 0 is a symmetry plane (u_y = 0, no
// shear traction on it), exact for every load that is symmetric under y -> -y: normal loads and tangential
// loads in x. Forces and energies of the whole body are twice those of the half modelled.
//
// Unknowns and weak form: u = (u_x, u_y, u_z) in FE_Q(p)^3 on MappingQ(p) (the cylindrical faces curved),
//   a(u, v) = \int [lambda div u div v + 2 mu eps(u) : eps(v)] dV,  lambda, mu from E(z) and nu,
// with the cell integrals of fem/elasticity/graded_elasticity.h (CartesianStrain: Gauss in the bulk, Gauss-Jacobi
// across the cells on z = 0 where E ~ z^s). u = 0 on the far field (r = L and z = L).
// With DiscretizationParameters::formulation = mixed (or automatic at nu >= 0.45) the element is Taylor-Hood,
// (u, q) in FE_Q(p)^3 x FE_Q(p - 1), q = lambda div u, the same mixed blocks as the axisymmetric model
// (fem/elasticity/graded_elasticity.h): the only formulation that has nu = 1/2 (the incompressible, decoupled pairing of a
// homogeneous body, k = 0). The saddle point needs the direct solver; the pressure is free on every boundary and
// is eliminated with the interior in the surface compliance.
//
// Loads (FlatPunch3D): a rigid flat punch on the contact disc r <= a. Each displacement component is
// either prescribed (u_c = value on the disc) or free (no traction in c on the disc), e.g.
//   normal frictionless punch   u_z = d,            u_x, u_y free        (Boussinesq; F_z)
//   tangential punch            u_x = delta, u_y = 0, u_z free          (Mindlin's problem; F_x, the
//                               mode-1 FlatPunch of fem/tangential/fourier_mode1_solver.h)
//   bonded punch                u = (delta, 0, d)                        (full stick)
// One matrix and one factorisation per set of prescribed components, reused by every value while the
// set does not change (only the last one is kept: a 3D sparse LU takes gigabytes). Forces are the
// reactions F_c = 2 sum_{i in contact, c} (A u)_i (A with the constraints condensed, i.e. the partition of
// unity on the disc; 2 for the half not modelled); F_y = 0 by symmetry.
//
// Check: |u.Au - work of the prescribed displacements| / u.Au above 1e-6 marks the result unreliable.
//
// MPI: as fem/bodies/distributed_solver.h (the caller initialises MPI; every process constructs and runs with the
// same arguments; results are the same on every process).
#ifndef GRADCONTACT_FEM_HALF_SPACE_3D_H
#define GRADCONTACT_FEM_HALF_SPACE_3D_H

#include <fem/bodies/surface_compliance_3d.h>
#include <fem/grid/discretization.h>
#include <fem/linear_algebra/distributed_linear_solver.h>
#include <fem/grid/mesh_3d.h>
#include <fem/modulus/modulus.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// A rigid flat punch on r <= a (header).
  struct FlatPunch3D
  {
    std::array<bool, 3>   prescribed   = {{false, false, true}};
    std::array<double, 3> displacement = {{0, 0, 0}}; ///< of the prescribed components (physical units)

    /// Throws std::invalid_argument for a non-finite value or nothing prescribed.
    void validate() const;
  };

  struct HalfSpace3DResult
  {
    std::array<double, 3> force = {{0, 0, 0}}; ///< F_x, F_y (= 0), F_z of the whole body, compressive F_z > 0
    std::string           message;              ///< what failed, if anything
    double                energy_mismatch = 0;  ///< |u.Au - work| / u.Au
    bool                  reliable        = true;

    dealii::types::global_dof_index n_dofs      = 0;
    unsigned int                    n_cells     = 0;
    unsigned int                    n_processes = 0;
    HalfSpaceMesh3DInfo             mesh;
    LinearSolveReport               linear;
    Timings                         time; ///< mesh, setup, assemble once per solver; factorize, solve this run
    double memory_mb = 0; ///< peak resident memory of the largest process (VmHWM), MiB
  };

  class HalfSpace3DSolver
  {
  public:
    /// Builds the distributed mesh, DoFs, the free constraints and the stiffness (collective). Throws
    /// std::invalid_argument on bad input (nu = 1/2 with the displacement formulation, amg_cg with the mixed one)
    /// and std::runtime_error when MPI is not initialised.
    HalfSpace3DSolver(MPI_Comm communicator, const Material &material, const HalfSpaceMesh3DParameters &mesh,
                      const DiscretizationParameters &discretization,
                      const DistributedSolverParameters &solver = {});
    ~HalfSpace3DSolver();

    /// One flat-punch load (collective).
    HalfSpace3DResult run(const FlatPunch3D &punch);

    /// The compliance of the surface nodes with r <= radius (collective; fem/tangential/coulomb_contact_3d.h): one solve
    /// per nodal force component with the factorisation of the free body. Throws std::runtime_error when a
    /// surface DoF there is constrained other than by the symmetry plane (a hanging node: use a mesh without
    /// refinement cycles), std::invalid_argument for radius outside (0, L).
    SurfaceCompliance3D surface_compliance(double radius);

    dealii::types::global_dof_index n_dofs() const { return dof_handler.n_dofs(); }

  private:
    using Vector = dealii::TrilinosWrappers::MPI::Vector;
    using Matrix = dealii::TrilinosWrappers::SparseMatrix;

    /// The matrix, constraints and solver of one set of prescribed components.
    struct Constrained
    {
      dealii::AffineConstraints<double>              constraints; ///< free ones + the prescribed lines
      Matrix                                         own_matrix; ///< assembled when something is prescribed
      const Matrix                                  *matrix = nullptr; ///< own_matrix, or the free stiffness
      std::unique_ptr<DistributedLinearSolver<3>>    solver;
    };

    void assemble(const dealii::AffineConstraints<double> &constraints, Matrix &matrix);
    Constrained &constrained(const std::array<bool, 3> &prescribed);

    MPI_Comm                          communicator;
    const Material                    material;
    const HalfSpaceMesh3DParameters   mesh_parameters;
    const Formulation                 formulation; ///< displacement or mixed (resolved)
    const DiscretizationParameters    discretization;
    const DistributedSolverParameters solver_parameters;

    dealii::parallel::distributed::Triangulation<3> triangulation;
    HalfSpaceMesh3DInfo                             mesh_info;
    const dealii::FESystem<3>                       fe;
    dealii::DoFHandler<3>                           dof_handler;
    const dealii::MappingQ<3>                       mapping;

    dealii::IndexSet                  owned, relevant;
    dealii::AffineConstraints<double> constraints; ///< hanging nodes, far field, symmetry plane
    Matrix                            stiffness;   ///< A with `constraints`: reactions and energy
    /// The contact DoFs of each component that `constraints` leaves free (locally relevant).
    std::array<std::vector<dealii::types::global_dof_index>, 3> contact_dofs;
    std::map<unsigned int, std::unique_ptr<Constrained>>        by_mask; ///< the last set only
    Timings                                                     setup_time;
  };
} // namespace gradcontact::fem

#endif
