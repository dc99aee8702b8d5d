#include "model/normal_model.h"
#include "report/report.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

namespace gradcontact::cases
{
  FeModel normal_fe_model(const Scene &s, const unsigned int refinement)
  {
    FeModel model = fe_model(s, refinement);
    fem::grade_axis(model.settings, model.load);
    if (s.discretization.surface_map && s.load.contact != LoadParameters::Contact::unilateral &&
        fem::resolve_formulation(model.settings.discretization, model.material.nu) != fem::Formulation::mixed)
      fem::use_surface_map(model.settings, *model.material.modulus);
    if (s.load.contact != LoadParameters::Contact::unilateral)
      condense_far_field(s, model.material, model.settings);
    return model;
  }

  DiscSolve solve_disc(const FeModel &model, const fem::OutputRequest &out)
  {
    fem::AxisymmetricSolver solver(model.material, model.settings.mesh, model.settings.discretization);
    const fem::Result       r = solver.run(model.load, out);
    return {r, double(solver.factor_bytes())};
  }

  fem::UnilateralResult solve_normal_unilateral(const Scene &s, const FeModel &model, const fem::OutputRequest &out)
  {
    const bool by_force =
      s.load.type != LoadParameters::Type::concave_punch && s.load.control == LoadParameters::Control::force;
    return solve_unilateral(s, model, fem::Indenter::of(model.load.profile, s.load.a), by_force, out);
  }

  namespace
  {
    /// The friction path's summary in the message of a unilateral result.
    std::string friction_message(const Scene &s, const fem::UnilateralResult &u)
    {
      return " Coulomb friction mu = " + format(s.friction.coefficient) + " during loading (" +
             std::to_string(u.path.size()) + " load steps, " + std::to_string(u.iterations) + " active-set solves): " +
             (std::isnan(u.stick_radius)
                ? std::string("no stick zone at the axis")
                : "stick radius " + format(u.stick_radius / u.outer_edge) + " of the contact") +
             ", " + std::to_string(u.stick_nodes) + " vertices stick, " + std::to_string(u.slip_inward_nodes) +
             " slip inward, " + std::to_string(u.slip_outward_nodes) + " outward;";
    }
  } // namespace

  fem::Result as_disc_result(const Scene &s, const FeModel &model, const fem::UnilateralResult &u)
  {
    fem::Result r;
    static_cast<fem::RunReport &>(r) = u;
    r.force            = u.force;
    r.depth            = u.depth;
    r.contact_radius   = u.outer_edge;
    r.edge_node_radius = u.edge_bracket.first;
    r.active_set_size  = u.active_nodes;
    r.iterations       = u.iterations;
    r.pressure         = u.pressure;
    r.displacement     = u.displacement;
    if (model.indenter_body)
      {
        // The chapter's w of two bodies (9.4) is the approach of both surfaces: w + w'.
        for (std::size_t i = 0; i < r.displacement.size(); ++i)
          r.displacement[i].value += u.indenter_displacement.at(i).value;
        r.message += " elastic indenter: w(r) is the sum of both surfaces' displacements;";
      }
    if (frictional_loading(s))
      r.message += friction_message(s, u);
    r.consistent_contact = u.zones.size() == 1;
    if (u.zones.size() != 1)
      {
        r.message += " unilateral contact in " + std::to_string(u.zones.size()) + " zones (r/a):";
        for (const fem::ContactZone &z : u.zones)
          r.message += " [" + format(z.r_in / s.load.a) + ", " + format(z.r_out / s.load.a) + "]";
        r.message += ";";
      }
    if (!u.zones.empty() && u.zones.front().r_in > 0)
      r.message += " the contact is an annulus from r = " + format(u.zones.front().r_in) + ";";
    return r;
  }

  UnilateralPanel unilateral_panel(const Scene &s, const double k, const double nu)
  {
    UnilateralPanel p;
    p.scene = s;
    p.scene.material.k = k;
    p.scene.material.nu = nu;
    p.scene.map.parameter = MapParameters::Parameter::none;
    p.scene.load.control = LoadParameters::Control::contact_radius;
    p.scene.indenter.elasticity = IndenterParameters::Elasticity::rigid;
    if (nu >= 0.5)
      p.scene.discretization.formulation = DiscretizationParameters::Formulation::mixed;
    p.model = fe_model(p.scene, finest_refinement(p.scene));
    p.reference = std::make_unique<AnalyticReference>(p.scene, batch::Method::closed_form,
                                                      AnalyticReference::Problem::normal);
    p.load.indenter = fem::Indenter::of(p.model.load.profile, s.load.a);
    p.load.depth = p.reference->get("depth");
    return p;
  }

  FrictionSolver friction_solver(const Scene &s, const UnilateralPanel &panel,
                                 const std::vector<double> &pressure_radii)
  {
    FrictionSolver f;
    f.load = panel.load;
    f.load.friction.load_steps = s.friction.load_steps;
    for (const double x : pressure_radii)
      f.request.pressure_radii.push_back(x * s.load.a);
    const auto start = std::chrono::steady_clock::now();
    f.solver = std::make_unique<fem::UnilateralContactSolver>(panel.model.material, panel.model.settings.mesh,
                                                              panel.model.settings.discretization, 1.6 * s.load.a);
    f.setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return f;
  }

  std::unique_ptr<fem::UnilateralContactSolver> elastic_indenter_solver(const Scene &s, const UnilateralPanel &panel,
                                                                        const double near_field)
  {
    const Scene &g = panel.scene;
    return std::make_unique<fem::UnilateralContactSolver>(
      panel.model.material, panel.model.settings.mesh, panel.model.settings.discretization, near_field,
      fem::SurfaceRefinement{},
      fem::Material{std::make_shared<fem::PowerLawModulus>(g.material.E0, g.material.c0, 0.), s.indenter.nu});
  }

  fem::ContractResult solve_normal_contract(const Scene &s, const FeModel &model)
  {
    double w_max = 0;
    for (const double x : s.outputs.displacement_radii)
      w_max = std::max(w_max, x * s.load.a);
    fem::Settings settings = fem::contract_settings(s.load.a, model.material, s.discretization.force_tolerance, w_max);
    fem::grade_axis(settings, model.load); // the tip's pressure at the axis (as normal_fe_model)
    fem::ContractSolver solver(model.material, settings, s.discretization.force_tolerance);
    return solver.run(model.load, output_request(s));
  }
} // namespace gradcontact::cases
