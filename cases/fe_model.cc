#include "fe_model.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

namespace gradcontact::cases
{
  using Type = LoadParameters::Type;
  using Control = LoadParameters::Control;

  fem::Material fe_material(const Scene &s)
  {
    const MaterialParameters &m = s.material;
    const auto power = std::make_shared<fem::PowerLawModulus>(m.E0, m.c0, m.k);
    fem::Material material;
    material.nu = m.nu;
    switch (m.modulus)
      {
        case MaterialParameters::Modulus::power_law:
          material.modulus = power;
          break;
        case MaterialParameters::Modulus::layered:
          material.modulus = fem::LayeredModulus::uniform(power, m.layers, m.layered_depth * s.load.a);
          break;
        case MaterialParameters::Modulus::expression:
          material.modulus = std::make_shared<fem::ExpressionModulus>(
            m.expression, std::map<std::string, double>{{"E0", m.E0}, {"c0", m.c0}, {"k", m.k}}, m.k);
          break;
        case MaterialParameters::Modulus::shifted_power_law:
          material.modulus = std::make_shared<fem::ShiftedPowerLawModulus>(m.E0, m.c0, m.k, m.surface_depth);
          break;
        case MaterialParameters::Modulus::coating:
          material.modulus = std::make_shared<fem::CoatingModulus>(m.E0, m.c0, m.k, m.coating_thickness);
          break;
        case MaterialParameters::Modulus::table:
          {
            // A relative path is taken from the scene's folder.
            std::filesystem::path table(m.table_file);
            if (table.is_relative() && !s.file.empty())
              table = std::filesystem::path(s.file).parent_path() / table;
            material.modulus = fem::TabulatedModulus::from_csv(table.string());
            break;
          }
      }
    return material;
  }

  fem::Formulation fe_formulation(const Scene &s)
  {
    switch (s.discretization.formulation)
      {
        case DiscretizationParameters::Formulation::mixed:
          return fem::Formulation::mixed;
        case DiscretizationParameters::Formulation::automatic:
          return fem::Formulation::automatic;
        case DiscretizationParameters::Formulation::displacement:
          break;
      }
    return fem::Formulation::displacement;
  }

  fem::LoadCase fe_load(const Scene &s)
  {
    const LoadParameters &l = s.load;
    fem::LoadCase lc;
    switch (l.type)
      {
        case Type::flat_punch:
          lc.type = fem::LoadType::flat_punch;
          lc.depth = l.depth;
          return lc;
        case Type::concave_punch:
          lc.type = fem::LoadType::concave_punch;
          lc.depth = l.depth;
          lc.profile = fem::Profile::concave_paraboloid(l.h0);
          return lc;
        case Type::constant_pressure:
          lc.type = fem::LoadType::constant_pressure;
          lc.pressure = l.p0;
          return lc;
        case Type::paraboloid:
          lc.profile = fem::Profile::paraboloid(l.R);
          break;
        case Type::cone:
          lc.profile = fem::Profile::cone(l.tan_theta);
          break;
        case Type::power_law:
          lc.profile = fem::Profile::power_law(l.n, l.A);
          break;
      }
    lc.type = l.control == Control::contact_radius ? fem::LoadType::indenter
              : l.control == Control::depth        ? fem::LoadType::indenter_depth
                                                   : fem::LoadType::indenter_force;
    lc.depth = l.depth;
    lc.force = l.force;
    return lc;
  }

  fem::Settings fe_settings(const Scene &s, const fem::Material &material, const double contact_radius,
                            const unsigned int refinement)
  {
    if (!material.modulus)
      throw std::invalid_argument("fe_settings: the material has no modulus field");
    const double tolerance = s.discretization.force_tolerance;
    fem::Settings settings =
      fem::recommended_settings(contact_radius, material.modulus->surface_exponent(), tolerance);
    // The truncation error falls like (a/L)^(1 + s) with s the exponent of the field far below the surface:
    // for layers over a power law that is the power law's. Measured (flat punch, 16 layers over 10 a, k = -0.5):
    // L/a of s = 0 (1.1e8) lost 1.2e-4 of the force against L/a = 1e16.
    const double deep = material.modulus->deep_exponent();
    if (deep != material.modulus->surface_exponent())
      settings.mesh.far_field_size = fem::recommended_settings(contact_radius, deep, tolerance).mesh.far_field_size;
    // A finite surface modulus E0 ((z + z0)/c0)^k: the power law's mesh with surface cells of z0/4, so that E
    // varies by a bounded factor in each (plain Gauss: E is regular at z = 0), but not thinner than 1e-10 a
    // (k > 0) or 2e-6 a (k < 0, where thinner cells with the stiff surface are flagged ill-conditioned:
    // halvings to 5e-7 a gave an energy mismatch of 2.8e-6 at k = -0.5).
    if (const auto *shifted = dynamic_cast<const fem::ShiftedPowerLawModulus *>(material.modulus.get()))
      {
        settings.mesh = fem::recommended_settings(contact_radius, shifted->k, tolerance).mesh;
        settings.mesh.surface_layer_thickness =
          std::clamp(shifted->z0 / (4 * contact_radius), shifted->k < 0 ? 2e-6 : 1e-10, 1.);
      }
    settings.discretization.degree = s.discretization.degree;
    settings.discretization.formulation = fe_formulation(s);
    settings.mesh.global_refinements = refinement;
    if (s.discretization.far_field > 0.)
      settings.mesh.far_field_size = s.discretization.far_field;
    return settings;
  }

  unsigned int finest_refinement(const Scene &s)
  {
    if (s.discretization.refinements.empty())
      throw std::invalid_argument("scene " + s.file + ": Discretization/refinements is empty (give at least one level)");
    return s.discretization.refinements.back();
  }

  FeModel fe_model(const Scene &s, const unsigned int refinement)
  {
    FeModel model;
    model.material = fe_material(s);
    model.load = fe_load(s);
    model.settings = fe_settings(s, model.material, s.load.a, refinement);
    return model;
  }

  FeModel candidate_fe_model(const Scene &s, const fem::Profile &profile)
  {
    FeModel model = fe_model(s, finest_refinement(s));
    model.load = fem::LoadCase();
    model.load.type = fem::LoadType::indenter;
    model.load.profile = profile;
    return model;
  }
} // namespace gradcontact::cases
