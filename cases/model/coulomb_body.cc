#include "model/coulomb_body.h"

#include "model/fe_model.h"

#include <fem/base/errors.h>
#include <fem/bodies/half_space_3d.h>
#include <fem/modulus/modulus.h>

#include <deal.II/base/mpi.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace gradcontact::cases
{
  void CoulombSphereCase::validate() const
  {
    const std::string where = "CoulombSphereCase";
    if (!(R > 0) || !std::isfinite(R))
      fem::fail(where, "R", R, "(0, inf)");
    if (!(candidates > 1) || !std::isfinite(candidates))
      fem::fail(where, "candidates", candidates, "(1, inf) (the contact must lie inside the candidate nodes)");
    if (!(depth > 0) || !std::isfinite(depth))
      fem::fail(where, "depth", depth, "(0, inf)");
    if (!(mu_normal >= 0))
      fem::fail(where, "mu_normal", mu_normal, "[0, inf]");
    if (!(mu >= 0) || (delta > 0 && !(mu > 0)))
      fem::fail(where, "mu", mu, delta > 0 ? "(0, inf] (delta > 0)" : "[0, inf]");
    if (!(delta >= 0) || !std::isfinite(delta))
      fem::fail(where, "delta", delta, "[0, inf)");
    if (normal_steps < 1)
      fem::fail(where, "normal_steps", normal_steps, "[1, inf)");
    if (delta > 0 && tangential_steps < 1)
      fem::fail(where, "tangential_steps", tangential_steps, "[1, inf) (delta > 0)");
    if (cycle && !(delta > 0))
      fem::fail(where, "delta", delta, "(0, inf) (cycle = true)");
    if (idealised_reference && !decoupled_reference)
      throw std::invalid_argument(where + ": idealised_reference = true needs decoupled_reference = true (the slip "
                                  "direction's effect is measured against the decoupled path)");
  }

  CoulombSphereSurface prepare_coulomb_sphere(const MPI_Comm communicator, const CoulombSphereCase &c)
  {
    c.validate();
    const auto           start = std::chrono::steady_clock::now();
    CoulombSphereSurface out;
    const fem::Material  material{std::make_shared<fem::PowerLawModulus>(c.E0, c.c0, c.k), c.nu};
    fem::HalfSpace3DSolver solver(communicator, material, c.mesh, c.discretization, c.solver);
    out.compliance = solver.surface_compliance(c.candidates * c.mesh.contact_radius);
    out.seconds    = dealii::Utilities::MPI::max(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), communicator);
    out.dofs       = solver.n_dofs();
    out.k = c.k;
    out.nu = c.nu;
    return out;
  }

  /// The far field of the mesh / a: Discretization/far field, else 1e5 (k < 0) or 1e3.
  double coulomb_far_field(const Scene &s, const double k)
  {
    return s.discretization.far_field > 0 ? s.discretization.far_field : (k < 0 ? 1e5 : 1e3);
  }

  CoulombSphereCase coulomb_case(const Scene &s, const double k, const double nu)
  {
    CoulombSphereCase c;
    c.E0 = s.material.E0;
    c.c0 = s.material.c0;
    c.k  = k;
    c.nu = nu;
    c.R  = s.load.R;
    c.mesh.contact_radius          = s.load.a;
    c.mesh.sectors                 = 4;
    c.mesh.h_edge                  = 1e-2;
    c.mesh.far_field_size          = coulomb_far_field(s, k);
    c.mesh.surface_layer_thickness = k > 0 ? 1e-4 : 0.;
    c.mesh.inner_ring_width        = 0.025; // the stick-slip boundary resolved anywhere in the contact
    c.candidates                   = 1.15;
    c.discretization.degree        = s.discretization.degree;
    // nu = 1/2 (Holl's ratio at k = 0) has only the mixed formulation; the others keep the scene's.
    c.discretization.formulation = nu >= 0.5 ? fem::Formulation::mixed : fe_formulation(s);
    c.normal_steps = c.tangential_steps = s.tangential.load_steps;
    c.cycle               = true;
    c.decoupled_reference = true;
    c.idealised_reference = true;
    return c;
  }

  void add_friction_work(const fem::CoulombState3D &step, double &into)
  {
    for (std::size_t i = 0; i < step.status.size(); ++i)
      if (step.status[i] == fem::NodeStatus::slip)
        into += 2 * std::hypot(step.nodal_force[i][0], step.nodal_force[i][1]) *
                std::hypot(step.slip[i][0], step.slip[i][1]);
  }
} // namespace gradcontact::cases
