#include "tools/fe_oracle.h"
#include "model/fe_stress.h"

#include <analytic/batch.h>
#include <analytic/errors.h>
#include <analytic/material.h>
#include <analytic/subsurface.h>
#include <fem/accuracy/accuracy.h>
#include <fem/modulus/modulus.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <cstdio>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace gradcontact::cases
{
  using json = nlohmann::json;

  namespace
  {
    constexpr double default_tolerance = 1e-6;
    constexpr double min_tolerance = 1e-8, max_tolerance = 1e-2;

    std::string exact(const double x)
    {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.17g", x);
      return buffer;
    }

    std::string brief(const double x)
    {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.2g", x);
      return buffer;
    }

    [[noreturn]] void refuse(const std::string &what) { throw std::invalid_argument("fe: " + what); }

    double positive(const std::optional<double> &value, const std::string &name, const std::string &why)
    {
      if (!value)
        refuse(name + ": missing (" + why + ")");
      if (!(std::isfinite(*value) && *value > 0))
        refuse(name + " = " + check::format(*value) + "; valid: (0, inf)");
      return *value;
    }
  } // namespace


  struct FeOracle::UnitState
  {
    fem::LoadCase load;
    std::unique_ptr<fem::ContractSolver> solver;
    fem::ContractResult scalars;  ///< force and depth, on the levels the contract needed for them
    double far_field = 0;         ///< L / a of the meshes
    bool   rigid_contact = false; ///< an indenter: its contact must be consistent
    /// (pressure?, r/a) -> the estimated sample
    std::map<std::pair<bool, double>, fem::Estimated> samples;
    /// radii announced by FeOracle::plan, solved together with the first one asked
    std::map<bool, std::set<double>> planned;
    /// (r/a, z/a) -> the estimated stress components, and the points announced
    std::map<std::pair<double, double>, std::array<fem::Estimated, 4>> stresses;
    std::set<std::pair<double, double>>                              planned_stress;
    /// measure -> its largest value below the contact (largest())
    std::map<std::string, FeStressMaximum> maxima;

    /// Refuses an answer that the contract did not deliver, naming what limits it and what the finest level gives. A
    /// quantity whose own estimate is within the tolerance is delivered though another one of the same run is not
    /// (a pressure's estimate counts from three levels on, fem/accuracy/accuracy.h).
    void check(const fem::ContractResult &r, const fem::Estimated &e, const char *what) const
    {
      const bool local = std::string(what) == "pressure" || std::string(what) == "stress";
      const bool own = e.relative() <= r.tolerance && (!local || e.levels.size() >= 3);
      if (!r.met && !own)
        throw std::runtime_error(std::string("fe: the ") + what + " does not reach tolerance " +
                                 check::format(r.tolerance) + ": " + r.limit + " (the finest level, " +
                                 std::to_string(r.level_dofs.empty() ? 0 : r.level_dofs.back()) +
                                 " DoFs, gives an estimated relative error of " + brief(e.relative()) + ")");
      if (rigid_contact && !r.result.consistent_contact)
        throw std::runtime_error(std::string("fe: the FE contact state is inconsistent (a tensile contact node or a "
                                             "negative gap): ") +
                                 r.result.message);
    }

    fem::Estimated sample(const bool pressure, const double r)
    {
      const auto key = std::make_pair(pressure, r);
      const auto found = samples.find(key);
      if (found != samples.end())
        return found->second;
      // One ladder run samples r and every planned radius of the quantity not solved yet; each sample has its
      // own estimate, and the contract covers them all.
      std::set<double> radii = planned[pressure];
      radii.insert(r);
      std::vector<double> wanted;
      for (const double x : radii)
        if (!samples.count({pressure, x}))
          wanted.push_back(x);
      fem::OutputRequest outputs;
      (pressure ? outputs.pressure_radii : outputs.displacement_radii) = wanted;
      const fem::ContractResult result = solver->run(load, outputs);
      const auto &estimates = pressure ? result.pressure : result.displacement;
      if (estimates.size() != wanted.size())
        throw std::runtime_error("fe: " + std::to_string(estimates.size()) + " FE samples for " +
                                 std::to_string(wanted.size()) + " radii (" + result.limit + result.result.message + ")");
      for (std::size_t i = 0; i < wanted.size(); ++i)
        {
          // the pressure's scale: the largest |p| sampled on the finest level, which the contract divides by
          check(result, estimates[i], pressure ? "pressure" : "displacement");
          samples[{pressure, wanted[i]}] = estimates[i];
        }
      planned[pressure].clear();
      return samples.at(key);
    }

    /// The stress components at (r/a, z/a), with every planned point not solved yet in the same ladder run.
    const std::array<fem::Estimated, 4> &stress(const double r, const double z)
    {
      const auto key = std::make_pair(r, z);
      if (const auto found = stresses.find(key); found != stresses.end())
        return found->second;
      std::set<std::pair<double, double>> points = planned_stress;
      points.insert(key);
      fem::OutputRequest outputs;
      for (const auto &[x, y] : points)
        if (!stresses.count({x, y}))
          outputs.stress_points.push_back({x, y});
      const fem::ContractResult result = solver->run(load, outputs);
      if (result.stress.size() != outputs.stress_points.size())
        throw std::runtime_error("fe: " + std::to_string(result.stress.size()) + " FE stress samples for " +
                                 std::to_string(outputs.stress_points.size()) + " points (" + result.limit +
                                 result.result.message + ")");
      for (std::size_t i = 0; i < result.stress.size(); ++i)
        {
          for (const fem::Estimated &e : result.stress[i])
            check(result, e, "stress");
          stresses[{outputs.stress_points[i].r, outputs.stress_points[i].z}] = result.stress[i];
        }
      planned_stress.clear();
      return stresses.at(key);
    }

    /// The largest measure `name` below the contact (model/fe_stress.h), delivered when its estimate holds.
    const FeStressMaximum &largest(const std::string &name)
    {
      if (const auto found = maxima.find(name); found != maxima.end())
        return found->second;
      FeStressMaximum m = largest_fe_stress(*solver, load, name);
      check(m.run, m.at_point, "stress");
      return maxima[name] = std::move(m);
    }
  };


  FeOracle::FeOracle() = default;
  FeOracle::~FeOracle() = default;

  FeOracle::UnitState &FeOracle::unit_state(const std::string &key, const double k, const double nu,
                                           const double tolerance, const fem::LoadCase &load,
                                           const unsigned int min_degree)
  {
    auto &slot = states[key];
    if (slot)
      return *slot;
    auto state = std::make_unique<UnitState>();
    state->load = load;
    state->rigid_contact = load.type != fem::LoadType::flat_punch;
    fem::Material material;
    material.modulus = std::make_shared<fem::PowerLawModulus>(1.0, 1.0, k);
    material.nu = nu;
    // L / a = 1e4 keeps the displacement requests up to r = 1e4 a (the condensed far field's rings are cheap).
    fem::Settings settings = fem::contract_settings(1.0, material, tolerance, 1e4 / 1.5);
    fem::grade_axis(settings, load);
    settings.discretization.degree = std::max(settings.discretization.degree, min_degree);
    state->far_field = settings.mesh.far_field_size;
    state->solver = std::make_unique<fem::ContractSolver>(material, settings, tolerance);
    state->scalars = state->solver->run(load);
    ++solved;
    slot = std::move(state);
    return *slot;
  }

  /// A request as the FE sees it: its unit state and how to scale that state's values.
  struct FeOracle::Parsed
  {
    std::string key;           ///< of the unit state
    double k = 0, nu = 0, tolerance = default_tolerance;
    fem::LoadCase load;
    std::string quantity;
    double E_a = 0, a = 0, amplitude = 0;
    double r = 0;               ///< r / a (pressure, displacement, stress)
    double z = 0;               ///< z / a (stress)
    std::string component;      ///< of a stress
    bool   outside = false;     ///< a pressure outside the contact: exactly 0
    unsigned int min_degree = 0; ///< of its state's ladder (unit_state)
  };

  void FeOracle::parse_stress(const batch::Request &q, const double k, const std::string &c, Parsed &p)
  {
    if (p.quantity != "stress")
      {
        // max_stress, max_stress_radius, max_stress_depth
        if (!q.component || (*q.component != "von_mises" && *q.component != "max_shear"))
          refuse("component: " + (q.component ? "= '" + *q.component + "'" : std::string("missing")) +
                 "; valid: von_mises, max_shear (the measure of a largest stress)");
        if (k < 0)
          refuse("k = " + check::format(k) + ": on a stiff surface the radial and hoop stresses grow without "
                 "bound toward the surface, so a largest stress does not exist; valid: k >= 0");
        if (c == "flat_punch")
          refuse("case = 'flat_punch': its edge makes every stress measure unbounded; valid: paraboloid, cone, "
                 "power_law");
        p.component = *q.component;
        return;
      }
    if (!q.r || !q.z)
      refuse(std::string(q.r ? "z" : "r") + ": missing (the point of the stress)");
    p.r = *q.r / p.a;
    p.z = *q.z / p.a;
    if (!(std::isfinite(p.r) && p.r >= 0))
      refuse("r = " + check::format(*q.r) + "; valid: [0, inf)");
    if (!(std::isfinite(p.z) && p.z > 0))
      refuse("z = " + check::format(*q.z) + "; valid: (0, inf) (below the surface)");
    if (!q.component)
      refuse("component: missing (rr, zz, tt, rz, principal_max, principal_min, von_mises, max_shear)");
    p.component = *q.component;
    stress_component(AxisymmetricStress{}, p.component); // names the valid components when it is none
  }

  FeOracle::Parsed FeOracle::parse(const json &request) const
  {
    if (!request.is_object())
      refuse("a request is a JSON object, not " + request.dump());
    Parsed p;
    json j = request;
    if (j.contains("tolerance"))
      {
        if (!j.at("tolerance").is_number())
          refuse("tolerance = " + j.at("tolerance").dump() + "; valid: a number in [1e-8, 1e-2]");
        p.tolerance = j.at("tolerance").get<double>();
        if (!(p.tolerance >= min_tolerance && p.tolerance <= max_tolerance))
          refuse("tolerance = " + check::format(p.tolerance) + "; valid: [1e-8, 1e-2] (the relative force error asked)");
      }
    for (const char *key : {"tolerance", "method", "id"})
      j.erase(key);
    const batch::Request q = batch::parse(j);
    if (!q.material)
      refuse("material: missing (an object {E0, c0, k, nu})");
    if (q.material2)
      refuse("material2: the FE oracle answers a rigid indenter on one graded body only");
    const GradedHalfSpace body = *q.material;
    validate("fe", body);
    p.k = body.k;
    p.nu = body.nu;

    const std::string &c = q.case_name;
    double n = 0;
    p.a = positive(q.a, "a", "the contact radius (flat punch: the punch radius)");
    if (c == "flat_punch")
      {
        if (!q.d || !std::isfinite(*q.d) || *q.d == 0)
          refuse("d: " + (q.d ? "= " + check::format(*q.d) + "; valid: finite and non-zero" : std::string("missing")) +
                 " (the depth of the flat punch)");
        p.load.type = fem::LoadType::flat_punch;
        p.load.depth = 1;
        p.amplitude = *q.d / p.a;
      }
    else if (c == "paraboloid" || c == "cone" || c == "power_law")
      {
        p.load.type = fem::LoadType::indenter;
        if (c == "paraboloid")
          {
            p.load.profile = fem::Profile::paraboloid(1);
            p.amplitude = p.a / positive(q.geometry.R, "geometry.R", "the radius of the paraboloid");
          }
        else if (c == "cone")
          {
            p.load.profile = fem::Profile::cone(1);
            p.amplitude = positive(q.geometry.tan_theta, "geometry.tan_theta", "the slope of the cone");
          }
        else
          {
            n = positive(q.geometry.n, "geometry.n", "the exponent of f = A r^n");
            p.load.profile = fem::Profile::power_law(n, 1);
            p.amplitude = positive(q.geometry.A, "geometry.A", "the factor of f = A r^n") * std::pow(p.a, n - 1);
          }
      }
    else
      refuse("case = '" + c + "' has no FE answer (valid: flat_punch, paraboloid, cone, power_law)");

    p.quantity = q.quantity;
    const bool maximum = p.quantity == "max_stress" || p.quantity == "max_stress_radius" ||
                         p.quantity == "max_stress_depth";
    if (p.quantity != "force" && p.quantity != "depth" && p.quantity != "pressure" && p.quantity != "displacement" &&
        p.quantity != "stress" && !maximum)
      refuse("quantity = '" + p.quantity + "' has no FE answer (valid: force, depth, pressure, displacement, stress, "
             "max_stress, max_stress_radius, max_stress_depth)");
    if (maximum || p.quantity == "stress")
      parse_stress(q, body.k, c, p);
    if (p.quantity == "depth" && c == "flat_punch")
      refuse("quantity = 'depth' of the flat punch is its input d");
    if (p.quantity == "pressure" || p.quantity == "displacement")
      {
        if (!q.r)
          refuse("r: missing (the radius of the " + p.quantity + ")");
        p.r = *q.r / p.a;
        if (!(std::isfinite(p.r) && p.r >= 0))
          refuse("r = " + check::format(*q.r) + "; valid: [0, inf)");
        // The tip f ~ r^n makes p(0) infinite unless n + k > 1 (9.30): the cone (n = 1) on k <= 0.
        const double tip = c == "cone" ? 1. : c == "power_law" ? n : 2.;
        if (p.quantity == "pressure" && p.r == 0 && c != "flat_punch" && !(tip - 1 + body.k > 0))
          refuse("r = 0: the pressure of a tip f ~ r^n with n + k = " + check::format(tip + body.k) +
                 " <= 1 is infinite at the axis; valid: r > 0");
        if (p.quantity == "pressure" && p.r >= 1)
          {
            if (c == "flat_punch" && p.r == 1)
              refuse("r = a: the pressure of the flat punch is singular at its edge; valid: r != a");
            p.outside = true;
          }
      }
    p.key = exact(p.k) + " " + exact(p.nu) + " " + exact(p.tolerance) + " " + c + " " + exact(n);
    if (p.quantity == "stress" && p.k < 0)
      {
        // Below a stiff surface the stresses, gradients of the displacement, converge irregularly from level to level
        // at degree 2, the uniform ladder's degree for coarse tolerances, and steadily from degree 3 on: a stress
        // state of its own.
        p.min_degree = 3;
        p.key += " stress";
      }
    p.E_a = body.E0 * std::pow(p.a / body.c0, body.k);
    return p;
  }

  void FeOracle::plan(const json &request)
  {
    Parsed p;
    try
      {
        p = parse(request);
      }
    catch (const std::exception &)
      {
        return; // evaluate() reports it
      }
    const auto found = states.find(p.key);
    if (p.quantity == "stress")
      {
        (found != states.end() ? found->second->planned_stress : stress_plans[p.key]).insert({p.r, p.z});
        return;
      }
    if (p.quantity != "pressure" && p.quantity != "displacement")
      return;
    if (p.outside)
      return;
    auto &radii = found != states.end() ? found->second->planned : plans[p.key];
    radii[p.quantity == "pressure"].insert(p.r);
  }

  FeOracle::Answer FeOracle::evaluate(const json &request)
  {
    const Parsed p = parse(request);
    const bool existed = states.count(p.key) > 0;
    UnitState &state = unit_state(p.key, p.k, p.nu, p.tolerance, p.load, p.min_degree);
    if (!existed)
      {
        state.planned = std::move(plans[p.key]);
        plans.erase(p.key);
        state.planned_stress = std::move(stress_plans[p.key]);
        stress_plans.erase(p.key);
      }
    Answer answer;
    answer.dofs = state.scalars.level_dofs.empty() ? 0 : state.scalars.level_dofs.back();
    answer.formulation = state.scalars.result.formulation == fem::Formulation::mixed ? "mixed" : "displacement";
    ++answered;
    if (p.outside)
      return answer; // no pressure outside the contact: exactly 0
    fem::Estimated v; // the unit problem's value and its estimate
    double scale = 0;
    if (p.quantity == "force")
      {
        v = state.scalars.force;
        state.check(state.scalars, v, "force");
        scale = p.E_a * p.a * p.a * p.amplitude;
      }
    else if (p.quantity == "depth")
      {
        v = state.scalars.depth;
        state.check(state.scalars, v, "depth");
        scale = p.a * p.amplitude;
      }
    else if (p.quantity == "stress")
      {
        v     = stress_measure(state.stress(p.r, p.z), p.component);
        scale = p.E_a * p.amplitude;
      }
    else if (p.quantity == "max_stress")
      {
        v     = state.largest(p.component).value;
        scale = p.E_a * p.amplitude;
      }
    else if (p.quantity == "max_stress_radius" || p.quantity == "max_stress_depth")
      {
        const FeStressMaximum &m = state.largest(p.component);
        v                = p.quantity == "max_stress_radius" ? m.r : m.z;
        scale            = p.a;
      }
    else
      {
        const bool pressure = p.quantity == "pressure";
        if (!pressure && p.r > state.far_field)
          refuse("r / a = " + check::format(p.r) + " lies beyond the FE far field; valid: r / a <= " +
                 check::format(state.far_field));
        v = state.sample(pressure, p.r);
        scale = pressure ? p.E_a * p.amplitude : p.a * p.amplitude;
      }
    answer.value = scale * v.value;
    answer.error_estimate = std::abs(scale) * v.error;
    answer.relative_error_estimate = v.relative();
    return answer;
  }

  namespace
  {
    bool blank(const std::string &line)
    {
      return line.find_first_not_of(" \t\r") == std::string::npos;
    }

    /// The request of `line` when it asks the FE ("method": "fe"), else null (a closed-form or numerical-MDR
    /// request, or invalid JSON, which batch::evaluate reports).
    std::optional<json> fe_request(const std::string &line)
    {
      try
        {
          json j = json::parse(line);
          if (j.is_object() && j.contains("method") && j.at("method").is_string() && j.at("method") == "fe")
            return j;
        }
      catch (const json::exception &)
        {
        }
      return std::nullopt;
    }

    /// The FE's answer to `request`, from `cache` when it holds it (and stored there when it did not).
    FeOracle::Answer cached_answer(const json &request, FeOracle &oracle, const ResultCache *cache)
    {
      if (!cache)
        return oracle.evaluate(request);
      json key = request;
      key.erase("id");
      const std::string text = "eval fe\n" + key.dump();
      if (const std::optional<json> hit = cache->get(text))
        {
          FeOracle::Answer a;
          a.value                   = hit->at("value").get<double>();
          a.error_estimate          = hit->at("error_estimate").get<double>();
          a.relative_error_estimate = hit->at("relative_error_estimate").get<double>();
          a.dofs                    = hit->at("dofs").get<unsigned int>();
          a.formulation             = hit->at("formulation").get<std::string>();
          return a;
        }
      const FeOracle::Answer a = oracle.evaluate(request);
      cache->put(text, json{{"value", a.value},
                            {"error_estimate", a.error_estimate},
                            {"relative_error_estimate", a.relative_error_estimate},
                            {"dofs", a.dofs},
                            {"formulation", a.formulation}});
      return a;
    }

    /// Writes the answer line of one request; returns 1 for an error, else 0.
    int answer_line(const std::string &line, std::ostream &out, FeOracle &oracle, const ResultCache *cache = nullptr)
    {
      const std::optional<json> fe = fe_request(line);
      if (!fe)
        {
          const batch::Answer answer = batch::evaluate(line);
          out << batch::to_json(answer) << '\n';
          return answer.ok ? 0 : 1;
        }
      const std::string id = fe->contains("id") ? fe->at("id").dump() : "null";
      try
        {
          const FeOracle::Answer a = cached_answer(*fe, oracle, cache);
          out << "{\"id\":" << id << ",\"value\":" << exact(a.value) << ",\"error_estimate\":" << exact(a.error_estimate)
              << ",\"relative_error_estimate\":" << exact(a.relative_error_estimate) << ",\"dofs\":" << a.dofs
              << ",\"formulation\":\"" << a.formulation << "\"}\n";
          return 0;
        }
      catch (const std::exception &e)
        {
          out << "{\"id\":" << id << ",\"error\":" << json(std::string(e.what())).dump() << "}\n";
          return 1;
        }
    }
  } // namespace

  int evaluate_stream(std::istream &in, std::ostream &out, FeOracle &oracle, const EvalReading reading,
                      const ResultCache *cache)
  {
    int errors = 0;
    if (reading == EvalReading::per_line)
      {
        for (std::string line; std::getline(in, line);)
          if (!blank(line))
            {
              if (const std::optional<json> fe = fe_request(line))
                oracle.plan(*fe);
              errors += answer_line(line, out, oracle, cache);
              out.flush();
            }
        return errors;
      }
    // All lines first: the FE's pressures and displacements of one unit state are sampled together.
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      if (!blank(line))
        lines.push_back(line);
    for (const std::string &line : lines)
      if (const std::optional<json> fe = fe_request(line))
        oracle.plan(*fe);
    for (const std::string &line : lines)
      errors += answer_line(line, out, oracle);
    out.flush();
    return errors;
  }
} // namespace gradcontact::cases
