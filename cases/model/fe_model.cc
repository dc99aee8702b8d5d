#include "model/fe_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
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
        case MaterialParameters::Modulus::error_function:
          material.modulus =
            std::make_shared<fem::ErrorFunctionModulus>(m.E0, m.surface_modulus_ratio * m.E0, m.erf_width);
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

  std::optional<fem::Material> fe_indenter_body(const Scene &s)
  {
    const IndenterParameters &i = s.indenter;
    if (i.elasticity == IndenterParameters::Elasticity::rigid)
      return std::nullopt;
    const double k = i.elasticity == IndenterParameters::Elasticity::graded ? s.material.k : 0.;
    return fem::Material{std::make_shared<fem::PowerLawModulus>(i.E, s.material.c0, k), i.nu};
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

  std::optional<fem::Profile> fe_indenter_profile(const LoadParameters &l)
  {
    switch (l.type)
      {
        case Type::paraboloid:
          return fem::Profile::paraboloid(l.R);
        case Type::cone:
          return fem::Profile::cone(l.tan_theta);
        case Type::power_law:
          return fem::Profile::power_law(l.n, l.A);
        case Type::concave_punch:
          return fem::Profile::concave_paraboloid(l.h0);
        case Type::flat_punch:
        case Type::constant_pressure:
          break;
      }
    return std::nullopt;
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
          lc.profile = *fe_indenter_profile(l);
          return lc;
        case Type::constant_pressure:
          lc.type = fem::LoadType::constant_pressure;
          lc.pressure = l.p0;
          return lc;
        case Type::paraboloid:
        case Type::cone:
        case Type::power_law:
          lc.profile = *fe_indenter_profile(l);
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
    fem::Settings settings = fem::recommended_settings(contact_radius, *material.modulus, tolerance);
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
    model.indenter_body = fe_indenter_body(s);
    model.load = fe_load(s);
    model.settings = fe_settings(s, model.material, s.load.a, refinement);
    return model;
  }

  bool condense_far_field(const Scene &s, const fem::Material &material, fem::Settings &settings)
  {
    if (!s.discretization.condensed_far_field)
      return false;
    double L = s.discretization.far_field;
    if (!(L > 0.))
      {
        L = fem::condensed_far_field_size;
        for (const double r : s.outputs.displacement_radii)
          L = std::max(L, 1.5 * r);
      }
    return fem::use_condensed_far_field(settings, material, L);
  }

  fem::Profile candidate_indenter(const mdr::Profile &profile)
  {
    return fem::Profile::custom(profile.f, 2.);
  }

  FeModel candidate_fe_model(const Scene &s, const fem::Profile &profile)
  {
    FeModel model = fe_model(s, finest_refinement(s));
    model.load = fem::LoadCase();
    model.load.type = fem::LoadType::indenter;
    model.load.profile = profile;
    return model;
  }

  fem::Result solve_candidate(const Scene &s, const mdr::Profile &profile)
  {
    FeModel model = candidate_fe_model(s, candidate_indenter(profile));
    condense_far_field(s, model.material, model.settings);
    fem::AxisymmetricSolver solver(model.material, model.settings.mesh, model.settings.discretization);
    return solver.run(model.load, output_request(s));
  }

  double largest_magnitude(const std::vector<fem::Sample> &samples)
  {
    double largest = 0.;
    for (const fem::Sample &x : samples)
      largest = std::max(largest, std::abs(x.value));
    return largest;
  }

  /// Outputs/pressure radii and displacement radii (in units of Load/a) as FE sample radii.
  fem::OutputRequest output_request(const Scene &s)
  {
    fem::OutputRequest out;
    for (const double x : s.outputs.pressure_radii)
      out.pressure_radii.push_back(x * s.load.a);
    for (const double x : s.outputs.displacement_radii)
      out.displacement_radii.push_back(x * s.load.a);
    return out;
  }

  /// The unilateral solve of a scene with `indenter`: Load/control force or depth (Load/force, Load/depth), the
  /// scene's elastic indenter, meshes graded from Load/a toward the edge found.
  fem::UnilateralResult solve_unilateral(const Scene &s, const FeModel &model, fem::Indenter indenter,
                                         const bool by_force, const fem::OutputRequest &out)
  {
    fem::UnilateralLoad load;
    load.indenter = std::move(indenter);
    load.control  = by_force ? fem::ContactControl::force : fem::ContactControl::depth;
    load.depth    = s.load.depth;
    load.force    = s.load.force;
    load.friction.coefficient = s.friction.coefficient;
    load.friction.load_steps  = s.friction.load_steps;
    fem::Remeshing remeshing;
    remeshing.indenter_body = model.indenter_body;
    return fem::solve_remeshed(model.material, model.settings, load, s.load.a, out, remeshing);
  }

  fem::Indenter candidate_unilateral_indenter(const Scene &s, const std::function<double(double)> &profile)
  {
    const CandidateParameters &c = s.candidate;
    fem::Indenter              indenter;
    if (!c.profile_table.empty())
      {
        // A relative path is taken from the scene's folder.
        std::filesystem::path table(c.profile_table);
        if (table.is_relative() && !s.file.empty())
          table = std::filesystem::path(s.file).parent_path() / table;
        indenter = fem::Indenter::from_csv(table.string());
      }
    else
      indenter = fem::Indenter{profile, std::numeric_limits<double>::infinity(), "candidate profile"};
    if (c.indenter_radius > 0.)
      indenter.extent = std::min(indenter.extent, c.indenter_radius);
    return indenter;
  }
} // namespace gradcontact::cases
