// gradcontact/cases: the 3D body of a Coulomb contact (model part): a rigid indenter on the power-law graded
// half-space in 3D (fem/bodies/half_space_3d.h), its mesh, discretisation and loading path, and its surface compliance,
// which every path on that body shares (fem/tangential/coulomb_contact_3d.h).
#ifndef GRADCONTACT_CASES_COULOMB_BODY_H
#define GRADCONTACT_CASES_COULOMB_BODY_H

#include "scene/scene.h"

#include <fem/tangential/coulomb_contact_3d.h>
#include <fem/grid/discretization.h>
#include <fem/linear_algebra/distributed_linear_solver.h>
#include <fem/grid/mesh_3d.h>

#include <mpi.h>

namespace gradcontact::cases
{
  struct CoulombSphereCase
  {
    double E0 = 2e9, c0 = 3e-4, k = 0, nu = 0.3; ///< E(z) = E0 (z/c0)^k, Pa and m
    double R  = 5e-3;                           ///< the sphere's radius, m
    fem::HalfSpaceMesh3DParameters   mesh;      ///< mesh.contact_radius: the radius the rings are graded toward
    fem::DiscretizationParameters    discretization;
    fem::DistributedSolverParameters solver;
    double       candidates       = 1.3;  ///< the candidate surface nodes lie within candidates * mesh.contact_radius
    double       depth            = 0;    ///< d of the normal loading, m, > 0
    double       mu_normal        = 0.3;  ///< friction during the normal loading, [0, inf]
    double       mu               = 0.3;  ///< friction during the tangential loading, (0, inf] (inf: full stick); unused when delta = 0
    double       delta            = 0;    ///< the tangential amplitude delta_A, m, > 0 (0: no tangential loading)
    unsigned int normal_steps     = 10;   ///< >= 1
    unsigned int tangential_steps = 10;   ///< of the loading to delta_A, >= 1 when delta > 0; each branch of the cycle takes twice
    bool         cycle            = false; ///< unloading to -delta_A and reloading to delta_A
    /// Also run the path without the normal-tangential coupling (fem::without_coupling) and compare.
    bool         decoupled_reference = false;
    /// Also run the path of the chapter's idealisation on the same discrete body: decoupled and with every
    /// tangential force along x (fem::without_coupling of fem::along_load, Cattaneo-Mindlin's assumption), and compare.
    bool         idealised_reference = false;

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  /// The surface compliance of a case's body (k, nu, mesh, candidates): what the paths of every friction
  /// coefficient, amplitude and step count on that body share.
  struct CoulombSphereSurface
  {
    fem::SurfaceCompliance3D compliance;
    unsigned long long       dofs    = 0;
    double                   seconds = 0; ///< mesh, assembly and compliance
    double                   k = 0, nu = 0; ///< of the body, checked against the case that uses it
  };

  /// Builds the 3D model of the case's body and its surface compliance (collective).
  CoulombSphereSurface prepare_coulomb_sphere(MPI_Comm communicator, const CoulombSphereCase &c);

  /// Adds the work of friction in one step of a path to `into`: mu P |s| of every slipping node (P constant and the
  /// slip one-way within a step: exact for the step's slip), twice for the whole body (the model is the half body).
  void add_friction_work(const fem::CoulombState3D &step, double &into);

  /// The far field of a scene's 3D mesh / a: Discretization/far field, else 1e5 (k < 0) or 1e3.
  double coulomb_far_field(const Scene &s, double k);

  /// The 3D body of a scene's material at (k, nu): the mesh graded toward Load/a (4 sectors, h_edge = a/100, rings of
  /// at most a/40 inside the contact, candidate nodes within 1.15 a, L = Discretization/far field or 1000 a for
  /// k >= 0 and 1e5 a for k < 0), the scene's degree and formulation (mixed at nu = 1/2), Tangential/load steps
  /// each way, one cycle, with the decoupled and idealised references; the sphere of Load/R. Its friction, depth
  /// and delta are the caller's to set.
  CoulombSphereCase coulomb_case(const Scene &s, double k, double nu);
} // namespace gradcontact::cases

#endif
