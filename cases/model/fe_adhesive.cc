#include "model/fe_adhesive.h"
#include "report/report.h"

#include <fem/accuracy/accuracy.h>
#include <fem/bodies/axisymmetric_solver.h>

#include <algorithm>
#include <cmath>

namespace gradcontact::cases
{
  using Type = LoadParameters::Type;

  namespace
  {
    fem::SettingsAtRadius scene_settings(const Scene &s, const fem::Material &material, const unsigned int level)
    {
      return [&s, material, level](const double a) {
        fem::Settings st = fe_settings(s, material, a, level);
        condense_far_field(s, material, st);
        return st;
      };
    }

    fem::SettingsAtRadius contract_settings(const Scene &s, const fem::Material &material, const unsigned int level)
    {
      const double                      tolerance = s.discretization.force_tolerance;
      const std::optional<fem::Profile> profile   = fe_indenter_profile(s.load);
      return [material, level, tolerance, profile](const double a) {
        fem::Settings base = fem::contract_settings(a, material, tolerance);
        if (profile)
          {
            fem::LoadCase load;
            load.type    = fem::LoadType::indenter;
            load.profile = *profile;
            fem::grade_axis(base, load);
          }
        return fem::ladder_settings(base, fem::contract_ladder(material), level);
      };
    }

    /// The search's parameters (AdhesiveModel's header on the contract's tolerance).
    fem::AdhesionParameters search_parameters(const AdhesionParameters &ad, const double contract_tolerance)
    {
      fem::AdhesionParameters parameters;
      parameters.stencil_ratio = ad.stencil_ratio;
      parameters.local_stencil = ad.local_stencil;
      if (contract_tolerance > 0)
        parameters.radius_tolerance = std::clamp(contract_tolerance / 1000, 1e-12, parameters.radius_tolerance);
      return parameters;
    }

    AdhesivePoint point(const fem::AdhesiveState &st)
    {
      return AdhesivePoint{st.radius, st.depth, st.force, st.delta, st.scaling_exponent};
    }

    AdhesiveCriticalPoint critical_point(const fem::AdhesiveCriticalState &c)
    {
      return AdhesiveCriticalPoint{point(c.state), c.max_dofs, c.radii_solved, c.fe_seconds};
    }

    AdhesiveSurface surface_of(const fem::AdhesiveContact::Profiles &p)
    {
      return AdhesiveSurface{point(p.state), p.pressure, p.displacement};
    }
  } // namespace

  fem::SettingsAtRadius adhesive_settings(const Scene &s, const fem::Material &material, const unsigned int level,
                                          const bool on_contract_ladder)
  {
    return on_contract_ladder ? contract_settings(s, material, level) : scene_settings(s, material, level);
  }

  fem::AdhesionControl fe_control(const Control control)
  {
    return control == Control::force ? fem::AdhesionControl::force : fem::AdhesionControl::displacement;
  }

  AdhesiveModel::AdhesiveModel(const Scene &s, const unsigned int level, const bool on_contract_ladder)
    : dgamma(s.adhesion.work_of_adhesion)
    , tensile_strength(s.adhesion.tensile_strength)
  {
    const fem::Material material = fe_material(s);
    contact                      = std::make_unique<fem::AdhesiveContact>(
      material, fe_indenter_profile(s.load), adhesive_settings(s, material, level, on_contract_ladder),
      search_parameters(s.adhesion, on_contract_ladder ? s.discretization.force_tolerance : 0));
  }

  AdhesiveModel::AdhesiveModel(const Scene &s, const fem::Profile &indenter)
    : dgamma(s.adhesion.work_of_adhesion)
    , tensile_strength(s.adhesion.tensile_strength)
  {
    const fem::Material material = fe_material(s);
    contact = std::make_unique<fem::AdhesiveContact>(material, indenter,
                                                     scene_settings(s, material, finest_refinement(s)));
  }

  AdhesiveModel::~AdhesiveModel() = default;

  AdhesivePoint AdhesiveModel::state(const double a)
  {
    return point(contact->adhesive_state(a, dgamma));
  }

  AdhesiveCriticalPoint AdhesiveModel::critical_state(const Control control, const double a0)
  {
    return critical_point(contact->critical_state(dgamma, fe_control(control), a0));
  }

  AdhesiveCriticalPoint AdhesiveModel::periphery_state(const double a)
  {
    return critical_point(contact->periphery_state(a, dgamma));
  }

  AdhesiveCriticalPoint AdhesiveModel::centre_state(const double a)
  {
    return critical_point(contact->centre_state(a, dgamma, tensile_strength));
  }

  double AdhesiveModel::transition_h0(const double a)
  {
    return contact->transition_h0(a, dgamma, tensile_strength);
  }

  AdhesiveSurface AdhesiveModel::surface(const double a, const std::vector<double> &pressure_radii,
                                         const std::vector<double> &displacement_radii)
  {
    return surface_of(contact->profiles(a, dgamma, pressure_radii, displacement_radii));
  }

  AdhesiveSurface AdhesiveModel::surface_at_delta(const double a, const double delta,
                                                  const std::vector<double> &pressure_radii,
                                                  const std::vector<double> &displacement_radii)
  {
    return surface_of(contact->profiles_at_delta(a, delta, pressure_radii, displacement_radii));
  }

  namespace
  {
    /// The scene's indenter (Load/type); an error naming the scene when it is no curved profile, which `model` needs.
    fem::Profile curved_indenter(const Scene &s, const std::string &model)
    {
      const std::optional<fem::Profile> profile = fe_indenter_profile(s.load);
      if (!profile)
        throw std::invalid_argument("scene " + s.file + ": " + model + " needs a curved indenter (Load/type)");
      return *profile;
    }
  } // namespace

  DugdaleModel::DugdaleModel(const Scene &s, const double sigma0, const unsigned int level,
                             const bool on_contract_ladder)
  {
    const fem::Material material = fe_material(s);
    contact = std::make_unique<fem::CohesiveContact>(material, curved_indenter(s, "a cohesive zone"),
                                                     fem::DugdaleLaw{sigma0, s.adhesion.work_of_adhesion},
                                                     adhesive_settings(s, material, level, on_contract_ladder));
  }

  DugdaleModel::DugdaleModel(const Scene &s, const fem::Profile &indenter)
  {
    const fem::Material material = fe_material(s);
    contact = std::make_unique<fem::CohesiveContact>(
      material, indenter, fem::DugdaleLaw{s.adhesion.cohesive_strength, s.adhesion.work_of_adhesion},
      scene_settings(s, material, finest_refinement(s)));
  }

  DugdaleModel::DugdaleModel(std::unique_ptr<fem::CohesiveContact> contact)
    : contact(std::move(contact))
  {}

  DugdaleModel DugdaleModel::on_plain_meshes(const Scene &s, const double sigma0, const unsigned int level)
  {
    const fem::Material material = fe_material(s);
    return DugdaleModel(std::make_unique<fem::CohesiveContact>(
      material, curved_indenter(s, "a cohesive zone"), fem::DugdaleLaw{sigma0, s.adhesion.work_of_adhesion},
      [s, material, level](const double a) { return fe_settings(s, material, a, level); }));
  }

  DugdaleModel::DugdaleModel(DugdaleModel &&) noexcept = default;
  DugdaleModel::~DugdaleModel() = default;

  namespace
  {
    CohesivePoint cohesive_point(const fem::CohesiveState &st)
    {
      return CohesivePoint{st.radius, st.zone_radius, st.depth,      st.force,
                           st.n_dofs, st.seconds,     st.consistent, st.message};
    }
  } // namespace

  CohesivePoint DugdaleModel::state(const double a)
  {
    return cohesive_point(contact->state(a));
  }

  CohesiveCriticalPoint DugdaleModel::critical_state(const Control control, const double a0)
  {
    const fem::CohesiveCriticalState c = contact->critical_state(fe_control(control), a0);
    return CohesiveCriticalPoint{cohesive_point(c.state), c.at_vanishing_contact, c.states_solved, c.max_dofs,
                                 c.seconds};
  }

  std::vector<std::pair<double, CohesivePoint>> DugdaleModel::states() const
  {
    std::vector<std::pair<double, CohesivePoint>> out;
    for (const auto &[a, st] : contact->states())
      out.emplace_back(a, cohesive_point(st));
    return out;
  }

  LennardJonesTrace trace_lennard_jones(const Scene &s, const fem::Profile &indenter, const double critical_radius,
                                        const double stop_force)
  {
    const fem::Material        material = fe_material(s);
    const fem::LennardJonesLaw law =
      fem::LennardJonesLaw::with_max_stress(s.adhesion.cohesive_strength, s.adhesion.work_of_adhesion);
    fem::SmoothCohesionParameters parameters;
    parameters.follow_edge = true;
    parameters.max_steps   = 20000;
    parameters.stop_force  = stop_force;
    LennardJonesTrace trace;
    trace.separation = law.separation;
    for (double edge_refinement = 1; edge_refinement <= fem::max_edge_refinement; edge_refinement *= 2)
      {
        fem::SmoothCohesionParameters refined = parameters;
        refined.edge_band = parameters.edge_band / std::sqrt(edge_refinement);
        try
          {
            fem::SmoothCohesiveContact model(material, indenter,
                                             fem::smooth_cohesion_settings(material, critical_radius,
                                                                           std::pow(2.0, finest_refinement(s)),
                                                                           edge_refinement),
                                             refined);
            trace.path    = model.trace(law);
            trace.failure = trace.path.converged ? "" : trace.path.message;
          }
        catch (const std::exception &e)
          {
            trace.failure = concise(e);
          }
        if (trace.failure.empty())
          break;
        trace.failure += " (edge refinement " + format(edge_refinement) + ")";
      }
    return trace;
  }

  AdhesivePoint LennardJonesTrace::state(const double a) const
  {
    const std::vector<fem::SmoothCohesionState> &st = path.states;
    for (std::size_t i = st.size(); i-- > 1;)
      {
        const double r0 = st[i - 1].peak_radius, r1 = st[i].peak_radius;
        if (r0 > 0. && r1 > r0 && r0 <= a && a <= r1)
          {
            const double t = (a - r0) / (r1 - r0);
            return AdhesivePoint{a, (1 - t) * st[i - 1].depth + t * st[i].depth + separation,
                                 (1 - t) * st[i - 1].force + t * st[i].force};
          }
      }
    double largest = 0.;
    for (const fem::SmoothCohesionState &x : st)
      largest = std::max(largest, x.peak_radius);
    throw std::runtime_error("the Lennard-Jones path does not reach the contact radius a = " + format(a) +
                             " on its contact branch (its largest peak radius is " + format(largest) + ")");
  }

  bool LennardJonesTrace::has_pull_off(const Control control) const
  {
    return control == Control::force ? path.has_force_minimum : path.has_depth_jump;
  }

  std::vector<AdhesivePoint> LennardJonesTrace::states() const
  {
    std::vector<AdhesivePoint> points;
    for (const fem::SmoothCohesionState &st : path.states)
      points.push_back(AdhesivePoint{st.peak_radius, st.depth + separation, st.force});
    return points;
  }

  LennardJonesModel::LennardJonesModel(const Scene &s, const double critical_radius, const unsigned int level,
                                       const double edge_refinement)
  {
    const fem::Material material = fe_material(s);
    fem::SmoothCohesionParameters parameters;
    parameters.follow_edge = true;
    parameters.edge_band   = parameters.edge_band / std::sqrt(edge_refinement);
    parameters.max_steps   = 20000; // the path's length grows with lambda: thousands of steps at 10
    contact                = std::make_unique<fem::SmoothCohesiveContact>(
      material, curved_indenter(s, "a Lennard-Jones path"),
      fem::smooth_cohesion_settings(material, critical_radius, std::pow(2.0, level), edge_refinement), parameters);
  }

  LennardJonesModel::~LennardJonesModel() = default;

  double rigid_lennard_jones_pull_off(const Scene &s, const double strength)
  {
    return fem::rigid_pull_off(fem::LennardJonesLaw::with_max_stress(strength, s.adhesion.work_of_adhesion),
                               curved_indenter(s, "a rigid pull-off"))
      .force;
  }

  LennardJonesTrace LennardJonesModel::trace(const double strength, const double dgamma)
  {
    const fem::LennardJonesLaw law = fem::LennardJonesLaw::with_max_stress(strength, dgamma);
    LennardJonesTrace          trace;
    trace.separation = law.separation;
    try
      {
        trace.path = contact->trace(law);
      }
    catch (const std::exception &e)
      {
        trace.path.converged = false;
        trace.path.message   = concise(e);
      }
    return trace;
  }

  AdhesivePoint LennardJonesTrace::pull_off(const Control control) const
  {
    const bool force_control = control == Control::force;
    if (!has_pull_off(control))
      throw std::runtime_error(force_control ? "the Lennard-Jones path has no minimum of F before the contact" :
                                               "the Lennard-Jones path has no jump under displacement control "
                                               "(d grows monotonically: a small Tabor parameter)");
    const fem::SmoothCohesionState &c = force_control ? path.force_pull_off : path.depth_pull_off;
    return AdhesivePoint{c.peak_radius, c.depth + separation, c.force};
  }

  TensionSurface optimal_profile_surface(const Scene &s, const unsigned int level, const bool on_contract_ladder)
  {
    const fem::Material material = fe_material(s);
    const fem::Settings st       = adhesive_settings(s, material, level, on_contract_ladder)(s.load.a);
    fem::AxisymmetricSolver solver(material, st.mesh, st.discretization);
    fem::LoadCase tension;
    tension.type     = fem::LoadType::constant_pressure;
    tension.pressure = -s.adhesion.tensile_strength;
    fem::OutputRequest out;
    for (const double x : s.outputs.displacement_radii)
      out.displacement_radii.push_back(x * s.load.a);
    const fem::Result r = solver.run(tension, out);
    return TensionSurface{r.n_dofs, r.reliable, r.message, r.depth, r.displacement};
  }
} // namespace gradcontact::cases
