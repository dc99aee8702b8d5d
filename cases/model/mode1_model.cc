#include "model/mode1_model.h"
#include "model/fe_model.h"

#include <fem/accuracy/accuracy.h>

namespace gradcontact::cases
{
  fem::Settings mode1_contract_settings(const Scene &s, const fem::Material &material, const unsigned int level)
  {
    fem::Settings base = fem::contract_settings(s.load.a, material, s.discretization.force_tolerance);
    base.discretization.formulation = fem::Formulation::displacement;
    return fem::ladder_settings(base, fem::contract_ladder(material), level);
  }

  Mode1Model::Mode1Model(const Scene &s, const std::vector<double> &refined_radii,
                         const std::optional<unsigned int> contract_level)
  {
    material = fe_material(s);
    if (contract_level)
      settings = mode1_contract_settings(s, material, *contract_level);
    else
      {
        settings = fe_settings(s, material, s.load.a, finest_refinement(s)); // the mode-1 solver refuses mixed
        condense_far_field(s, material, settings);
      }
    fem::SurfaceRefinement refinement;
    refinement.radii  = refined_radii;
    refinement.levels = refined_radii.empty() ? 0 : s.tangential.stick_levels;
    solver = std::make_unique<fem::FourierMode1Solver>(material, settings.mesh, settings.discretization, refinement);
  }

  Mode1Model::~Mode1Model() = default;

  fem::TangentialResult Mode1Model::flat_punch(const double delta)
  {
    return solver->run(fem::TangentialLoad::flat_punch(delta));
  }

  fem::TangentialResult Mode1Model::traction(const std::function<double(double)> &tau, const double a,
                                             const double stick_radius, const std::vector<double> &kinks,
                                             const std::vector<double> &displacement_radii)
  {
    fem::TangentialOutputRequest out;
    out.displacement_radii = displacement_radii;
    return solver->run(fem::TangentialLoad::profile(tau, a, stick_radius, kinks), out);
  }

  fem::TangentialResult Mode1Model::partial_slip(const std::function<double(double, double)> &pressure,
                                                 const double mu, const double a, const double c,
                                                 const std::vector<double> &displacement_radii)
  {
    fem::TangentialOutputRequest out;
    out.displacement_radii = displacement_radii;
    return solver->run(fem::TangentialLoad::partial_slip(pressure, mu, a, c), out);
  }

  unsigned int Mode1Model::n_dofs() const
  {
    return solver->n_dofs();
  }

  fem::Result Mode1Model::normal_flat_punch(const double depth) const
  {
    fem::AxisymmetricSolver normal(material, settings.mesh, settings.discretization);
    fem::LoadCase punch;
    punch.type  = fem::LoadType::flat_punch;
    punch.depth = depth;
    return normal.run(punch);
  }
} // namespace gradcontact::cases
