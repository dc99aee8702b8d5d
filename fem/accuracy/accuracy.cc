#include <fem/accuracy/accuracy.h>
#include <fem/base/errors.h>
#include <fem/modulus/modulus.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    constexpr double min_tolerance = 1e-9, max_tolerance = 0.1;
    /// L / a of the condensed far field: its rings are cheap, and near k = -1 the condensation close to the contact
    /// (L = 100 a) leaves an error that does not fall with h, which the ladder would not see.
    constexpr double contract_far_field_size = 1e4;

    std::string format(const double x)
    {
      std::ostringstream s;
      s.precision(2);
      s << x;
      return s.str();
    }

    /// The truncation error of a clamped far field at L / a: (a / L)^(1 + s), s the exponent deep below
    /// (recommended_mesh_parameters picks L by it).
    double truncation_error(const Settings &settings, const Material &material)
    {
      if (settings.discretization.far_field == FarField::condensed)
        return 0;
      return std::pow(settings.mesh.far_field_size, -(1 + material.modulus->deep_exponent()));
    }

    /// The quantities the contract covers for `load`, as the values of one level's result.
    std::vector<LadderValue> quantities(const LoadCase &load, const Result &r, const double contact_radius,
                                        const std::vector<StressPoint> &points)
    {
      std::vector<LadderValue> q;
      if (load.type != LoadType::constant_pressure)
        q.push_back({"force", r.force, std::abs(r.force), false, 1, true});
      if (load.type == LoadType::indenter || load.type == LoadType::indenter_force ||
          load.type == LoadType::constant_pressure)
        q.push_back({"depth", r.depth, std::abs(r.depth), false});
      if (load.type == LoadType::indenter_depth || load.type == LoadType::indenter_force)
        q.push_back({"contact radius", r.contact_radius, std::abs(r.contact_radius), false});
      double p_max = 0;
      for (const Sample &s : r.pressure)
        p_max = std::max(p_max, std::abs(s.value));
      // A pressure sample: its recovery from the reactions (the L2 projection on the surface trace) spreads the edge
      // singularity's error into the contact, where two levels can agree far below it; its estimate needs three.
      for (const Sample &s : r.pressure)
        q.push_back({"p(" + format(s.r) + ")", s.value, p_max, true, 1, true});
      for (const Sample &s : r.displacement)
        q.push_back({"w(" + format(s.r) + ")", s.value, std::abs(s.value), false, s.r / contact_radius});
      // A stress sample: relative to the largest stress component sampled (a component that crosses zero would
      // otherwise ask for an error far below the field's size), and, recovered like the pressure, on three levels.
      double s_max = 0;
      for (const StressValue &s : r.stress)
        s_max = std::max({s_max, std::abs(s.rr), std::abs(s.zz), std::abs(s.tt), std::abs(s.rz)});
      for (std::size_t i = 0; i < r.stress.size(); ++i)
        {
          const StressValue &s     = r.stress[i];
          const std::string  where = "(" + format(points[i].r) + ", " + format(points[i].z) + ")";
          for (const auto &[name, value] : {std::pair{"sigma_rr", s.rr}, std::pair{"sigma_zz", s.zz},
                                            std::pair{"sigma_tt", s.tt}, std::pair{"sigma_rz", s.rz}})
            q.push_back({name + where, value, s_max, true, 1, true});
        }
      return q;
    }
  } // namespace



  void AccuracyBudget::validate() const
  {
    if (max_dofs < 1000)
      fail("AccuracyBudget", "max_dofs", max_dofs, "[1000, inf)");
    if (max_levels < 2 || max_levels > 6)
      fail("AccuracyBudget", "max_levels", max_levels, "[2, 6] (an estimate needs two levels)");
    if (!(max_factor_bytes >= 1e6))
      fail("AccuracyBudget", "max_factor_bytes", max_factor_bytes, "[1e6, inf)");
  }



  Ladder contract_ladder(const Material &material)
  {
    if (!material.modulus)
      throw std::invalid_argument("contract_ladder: the material has no modulus field");
    return material.modulus->discontinuities().empty() ? Ladder::hp : Ladder::uniform;
  }



  bool probes_rounding(const Material &material)
  {
    if (!material.modulus)
      throw std::invalid_argument("probes_rounding: the material has no modulus field");
    return material.modulus->surface_exponent() < 0;
  }



  Settings ladder_settings(const Settings &base, const Ladder ladder, const unsigned int level)
  {
    Settings s = base;
    if (ladder == Ladder::uniform)
      {
        s.mesh.global_refinements += level;
        return s;
      }
    s.discretization.degree += level;
    if (s.discretization.degree > max_contract_degree)
      fail("ladder_settings (hp)", "level", level,
           "[0, " + std::to_string(max_contract_degree - base.discretization.degree) + "] (degree at most " +
             std::to_string(max_contract_degree) + ")");
    s.mesh.edge_refinements += hp_edge_step * level;
    if (s.mesh.axis_refinements > 0)
      s.mesh.axis_refinements += hp_axis_step * level;
    // The map resolves lengths down to its floor: the floor follows the edge cell, else the ladder would converge
    // to the answer of a fixed floor.
    if (s.discretization.surface_map.enabled)
      s.discretization.surface_map.floor = s.mesh.h_edge * std::pow(0.5, s.mesh.edge_refinements);
    return s;
  }



  double ContractResult::worst_relative() const
  {
    double worst = 0;
    for (const Estimated *e : {&force, &depth, &contact_radius})
      if (e->scale > 0)
        worst = std::max(worst, e->relative());
    for (const auto *samples : {&pressure, &displacement})
      for (const Estimated &e : *samples)
        worst = std::max(worst, e.relative());
    for (const auto &point : stress)
      for (const Estimated &e : point)
        worst = std::max(worst, e.relative());
    return worst;
  }



  unsigned int contract_degree(const double tolerance, const double surface_exponent)
  {
    // Degree 2 converges the force, the depth and w(r) with a steady ratio per uniform refinement over the whole
    // range of k (the surface map for k > 0, the condensed far field for k <= 0); degrees 3 and 4 reach further on
    // fewer levels. Below a stiff surface (s < 0) the recovered pressure of degree 2 changes sign from level to level
    // near the contact edge, so that its ladder reads oscillation and never shows convergence; from degree 3 its
    // changes keep their sign and fall (ladder_study k=-0.5 load=punch pr=0.9 p=2, then p=3). Closer to k = -1
    // (below stiff_degree_limit) the thin stiff surface cells limit both degrees alike, and degree 3 only costs
    // more: the force's levels at k = -0.95 stop converging at degree 3 where degree 2's do.
    const unsigned int degree = tolerance >= 1e-4 ? 2 : tolerance >= 1e-7 ? 3 : 4;
    return surface_exponent < 0 && surface_exponent >= stiff_degree_limit ? std::max(degree, 3u) : degree;
  }



  double assumed_ratio(const unsigned int degree, const double surface_exponent)
  {
    // Conservative: a quarter for degree 2, a half above (where the flat punch's edge limits degree 3, its ratio
    // approaches a half; where the solution is smooth it is far smaller). A stiff surface (s < 0) makes the contact
    // edge's field less regular, p ~ (a - r)^((1 + s)/2) under an indenter: the edge cells' share of the error then
    // falls like h^(1 + s), a ratio 2^-(1 + s) per refinement, which two levels cannot tell from a faster one.
    const double base = degree <= 2 ? 0.25 : 0.5;
    return surface_exponent < 0 ? std::clamp(std::pow(2.0, -(1 + surface_exponent)), base, ratio_limit) : base;
  }



  double hp_assumed_ratio(const double surface_exponent)
  {
    return surface_exponent >= 0.9 ? 0.5 : 1. / 3;
  }



  Estimated estimate(const std::vector<double> &values, const double assumed, const double scale, const double accident)
  {
    Estimated e;
    e.scale  = scale;
    e.levels = values;
    if (values.empty())
      return e;
    e.value = values.back();
    const std::size_t n = values.size() - 1;
    if (n == 0)
      return e;
    const double d_n = std::abs(values[n] - values[n - 1]);
    double       tail = d_n;
    e.ratio          = assumed;
    if (n >= 2)
      {
        const double d_prev   = std::abs(values[n - 1] - values[n - 2]);
        const double observed = d_prev > 0 ? d_n / d_prev : (d_n > 0 ? ratio_limit : 0.0);
        e.ratio               = std::clamp(observed, assumed, ratio_limit);
        // Changes of opposite sign: the levels oscillate about the limit, and the geometric tail is no bound.
        if ((values[n] - values[n - 1]) * (values[n - 1] - values[n - 2]) < 0)
          e.ratio = std::max(e.ratio, oscillation_ratio);
        // A change far below any rate of the ladder (less than assumed^2 of the one before) is an accident of two
        // levels on opposite sides of the limit, not convergence.
        tail = std::max(d_n, (accident < 0 ? assumed * assumed : accident) * d_prev);
      }
    e.error = tail * e.ratio / (1 - e.ratio);
    return e;
  }



  Settings contract_settings(const double contact_radius, const Material &material, const double tolerance,
                             const double largest_displacement_radius)
  {
    if (!material.modulus)
      throw std::invalid_argument("contract_settings: the material has no modulus field");
    if (!(tolerance >= min_tolerance && tolerance <= max_tolerance))
      fail("contract_settings", "tolerance", tolerance, "[1e-9, 0.1]");
    Settings settings = recommended_settings(contact_radius, *material.modulus, std::min(tolerance, 1e-2));
    const bool hp     = contract_ladder(material) == Ladder::hp;
    settings.discretization.degree =
      hp ? hp_first_degree : contract_degree(tolerance, material.modulus->surface_exponent());
    settings.discretization.formulation = Formulation::automatic;
    if (hp)
      settings.mesh.edge_refinements = std::max(settings.mesh.edge_refinements, hp_edge_refinements);
    // A clamped far field (the surface map's, a modulus that is no power law of depth) far enough for its truncation error
    // (a / L)^(1 + s) to stay below tol / 64 (the run refuses above tol / 4), and below that relative to w(r) at
    // the largest displacement radius r, whose share of the truncation is larger; the ladder cannot see this error.
    // The rings grow geometrically, so L costs little.
    const double reach = std::max(1.0, largest_displacement_radius / contact_radius);
    settings.mesh.far_field_size =
      std::clamp(reach * std::pow(64 / tolerance, 1 / (1 + material.modulus->deep_exponent())),
                 settings.mesh.far_field_size, std::max(settings.mesh.far_field_size, 1e16));
    // The mixed formulation (Taylor-Hood) at degree 2 gives garbage from the first uniform refinement on (flagged by
    // the energy check), degree 3 does not: its ladder starts at 3.
    if (resolve_formulation(settings.discretization, material.nu) == Formulation::mixed)
      settings.discretization.degree = std::max(settings.discretization.degree, 3u);
    if (!use_surface_map(settings, *material.modulus))
      use_condensed_far_field(settings, material,
                              std::max(contract_far_field_size, 1.5 * largest_displacement_radius / contact_radius));
    return hp ? ladder_settings(settings, Ladder::hp, 0) : settings; // the floor of level 0
  }



  void grade_axis(Settings &settings, const LoadCase &load)
  {
    const bool indenter = load.type == LoadType::indenter || load.type == LoadType::indenter_depth ||
                          load.type == LoadType::indenter_force;
    if (indenter && load.profile.exponent() < 2)
      settings.mesh.axis_refinements = std::max(settings.mesh.axis_refinements, axis_refinement_cycles);
  }



  LadderRecord::LadderRecord(const Material &material, const Settings &base, const double tolerance,
                             const AccuracyBudget &budget)
    : ladder(contract_ladder(material))
    , first_degree(base.discretization.degree)
    , surface_exponent(material.modulus->surface_exponent())
    , asked(tolerance)
    , truncation(truncation_error(base, material))
    , deep_exponent(material.modulus->deep_exponent())
    , budget(budget)
  {
    if (!(tolerance >= min_tolerance && tolerance <= max_tolerance))
      fem::fail("LadderRecord", "tolerance", tolerance, "[1e-9, 0.1]");
    budget.validate();
    if (truncation > asked / 4)
      stop = "far field: the clamped boundary at L / a = " + format(base.mesh.far_field_size) +
             " leaves a truncation error of about " + format(truncation) + " (E grows like z^" +
             format(material.modulus->deep_exponent()) +
             " deep below; the condensed far field needs a power law of depth)";
  }



  unsigned int LadderRecord::degree() const
  {
    const unsigned int solved = levels() > 0 ? levels() - 1 : 0;
    return first_degree + (ladder == Ladder::hp ? solved : 0);
  }



  Estimated LadderRecord::estimate(const std::vector<double> &values, const double scale, const bool local) const
  {
    if (ladder == Ladder::hp)
      {
        const double floor = hp_assumed_ratio(surface_exponent);
        return fem::estimate(values, local ? std::max(floor, hp_local_floor) : floor, scale, hp_accident);
      }
    return fem::estimate(values, assumed_ratio(first_degree, surface_exponent), scale);
  }



  Estimated LadderRecord::estimate(const std::size_t i) const
  {
    Estimated e = estimate(history.at(i), last.at(i).scale, last.at(i).local);
    // Two levels of the uniform ladder show one change and no ratio: the tail rests on the assumed ratio alone. A
    // safety factor covers a slower approach (Roache's grid convergence index takes 3 for two grids, 1.25 for
    // three; the assumed ratio here is already the stiff surface's slowest edge rate, 2^-(1 + s)).
    if (ladder == Ladder::uniform && history[i].size() == 2)
      e.error *= two_level_safety;
    e.error += truncation * std::pow(std::max(1.0, last[i].reach), 1 + deep_exponent) * e.scale;
    if (!rounding.empty())
      {
        e.rounding = rounding[i];
        e.error += rounding_safety * rounding[i];
      }
    return e;
  }



  bool LadderRecord::next_level_allowed()
  {
    if (is_met || !stop.empty())
      return false;
    const unsigned int l = levels();
    if (ladder == Ladder::hp ? first_degree + l > max_contract_degree : l >= budget.max_levels)
      {
        stop = "levels: " + std::to_string(l) + " solved (" +
               (ladder == Ladder::hp ? "the hp ladder ends at degree " + std::to_string(max_contract_degree) :
                                       std::string("AccuracyBudget::max_levels")) +
               ")";
        return false;
      }
    if (l >= 2)
      {
        const double growth = double(dofs[l - 1]) / double(dofs[l - 2]), next = double(dofs[l - 1]) * growth;
        if (next > budget.max_dofs)
          {
            stop = "DoF budget: level " + std::to_string(l) + " would have about " + format(next) +
                   " DoFs, above AccuracyBudget::max_dofs = " + std::to_string(budget.max_dofs);
            return false;
          }
      }
    return true;
  }



  void LadderRecord::fail(const std::string &why)
  {
    is_met = false; // a failed rounding probe unmakes a met ladder
    stop   = why;
  }



  bool LadderRecord::stalled_before(const std::size_t i) const
  {
    // The hp ladder's changes can pause for one level before its degree takes over again (the soft layer of k near
    // 1 shows it outside the contact): a verdict of no convergence there waits for a second change that does not
    // fall. Its levels are few, and the DoF budget still stops it.
    if (ladder == Ladder::uniform)
      return true;
    const std::vector<double> &h = history[i];
    if (h.size() < 4)
      return false;
    const std::vector<double> before(h.begin(), h.end() - 1);
    return estimate(before, last[i].scale, last[i].local).ratio >= ratio_limit;
  }



  bool LadderRecord::add(const std::vector<LadderValue> &values, const dealii::types::global_dof_index level_dofs)
  {
    if (!history.empty() && values.size() != history.size())
      throw std::logic_error("LadderRecord::add: level " + std::to_string(levels()) + " has " +
                             std::to_string(values.size()) + " quantities, the levels before " +
                             std::to_string(history.size()));
    if (history.empty())
      history.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
      history[i].push_back(values[i].value);
    last = values;
    dofs.push_back(level_dofs);
    if (levels() < 2)
      return false;

    // The verdict: every estimate within `asked` (met), or else whether more levels can help. They cannot when a
    // quantity's changes do not fall (observed ratio at ratio_limit or above: "no convergence"), or, on the uniform
    // ladder, when the levels its observed ratio needs would exceed the DoF budget (predicted from the growth of the
    // DoFs over the last level; the ladder then stops before its largest solves). The hp ladder's ratios fall from
    // level to level and its levels are cheap: a prediction from the clamped ratio would stop it too early.
    is_met               = true;
    double levels_needed = 0;
    for (std::size_t i = 0; i < last.size(); ++i)
      {
        const Estimated e     = estimate(i);
        const bool      three = history[i].size() >= 3;
        if ((last[i].local || ladder == Ladder::hp) && !three)
          is_met = false; // a pressure's estimate needs three levels, and every estimate of the hp ladder
        if (e.relative() <= asked)
          continue;
        is_met = false;
        // A recovered sample's first change can be an accident of two levels close to each other on the way to the
        // limit, so its verdict of no convergence waits for a fourth level (the budget check below still applies).
        const bool judged = last[i].local ? history[i].size() >= 4 : three;
        if (judged && e.ratio >= ratio_limit && e.relative() * e.ratio > asked && stalled_before(i))
          {
            stop = "no convergence";
            return true;
          }
        if (three && ladder == Ladder::uniform)
          levels_needed = std::max(levels_needed, std::ceil(std::log(asked / e.relative()) / std::log(e.ratio)));
      }
    if (is_met)
      return true;
    const double growth = double(dofs.back()) / double(dofs[dofs.size() - 2]);
    const double predicted = double(dofs.back()) * std::pow(growth, levels_needed);
    if (levels_needed > 0 && predicted > budget.max_dofs)
      {
        stop = "DoF budget: about " + std::to_string(static_cast<int>(levels_needed)) +
               " more level(s) needed at the observed ratios, about " + format(predicted) +
               " DoFs, above AccuracyBudget::max_dofs = " + std::to_string(budget.max_dofs);
        return true;
      }
    return false;
  }



  void LadderRecord::add_rounding(const std::vector<LadderValue> &probe, const double factor)
  {
    if (probe.size() != last.size())
      throw std::logic_error("LadderRecord::add_rounding: the probe has " + std::to_string(probe.size()) +
                             " quantities, the last level " + std::to_string(last.size()));
    rounding.assign(last.size(), 0.);
    for (std::size_t i = 0; i < last.size(); ++i)
      rounding[i] = std::abs(probe[i].value / (last[i].scales ? factor : 1.) - last[i].value);
    if (!is_met)
      return;
    for (std::size_t i = 0; i < last.size(); ++i)
      if (estimate(i).relative() > asked)
        {
          is_met = false;
          stop   = "rounding: the matrix's rounding moves " + last[i].name + " by about " +
                 format(rounding[i] / std::max(last[i].scale, std::numeric_limits<double>::min())) +
                 " (the stiff surface's entries, rounded anew with every modulus times " + format(factor) + ")";
          return;
        }
  }



  std::string LadderRecord::limit() const
  {
    if (is_met)
      return "";
    std::string text = stop.empty() ? "levels: " + std::to_string(levels()) + " solved" : stop;
    if (last.empty() || history.front().size() < 2)
      return text;
    // The quantity furthest from the tolerance, with its changes' ratio and, when they do not fall, what at the
    // surface keeps them from falling.
    std::size_t worst = 0;
    for (std::size_t j = 1; j < last.size(); ++j)
      if (estimate(j).relative() > estimate(worst).relative())
        worst = j;
    const Estimated e = estimate(worst);
    text += "; " + last[worst].name + " still estimated " + format(e.relative()) + " off";
    if (history[worst].size() >= 3 && e.ratio >= ratio_limit)
      text += " and not converging (change ratio " + format(e.ratio) + " per level" +
              (surface_exponent < 0 ? ": the stiff surface of k < 0, whose entries' rounding grows with every level)" :
               surface_exponent > 0 ? ": the soft surface layer of k > 0)" :
                                      ")");
    return text;
  }



  ContractSolver::ContractSolver(const Material &material, const Settings &base, const double tolerance,
                                 const AccuracyBudget &budget)
    : material(material)
    , base(base)
    , ladder(contract_ladder(material))
    , asked(tolerance)
    , budget(budget)
  {
    if (!(tolerance >= min_tolerance && tolerance <= max_tolerance))
      fail("ContractSolver", "tolerance", tolerance, "[1e-9, 0.1]");
    budget.validate();
    base.discretization.validate();
  }

  ContractSolver::~ContractSolver() = default;



  double ContractSolver::held_bytes()
  {
    double held = probe ? double(probe->factor_bytes()) : 0.;
    for (std::size_t i = 0; i < solvers.size(); ++i)
      if (solvers[i])
        {
          const double bytes = double(solvers[i]->factor_bytes());
          if (bytes > 0)
            level_bytes[i] = bytes;
          held += bytes;
        }
    return held;
  }



  bool ContractSolver::make_room(const double bytes, const unsigned int keep)
  {
    if (held_bytes() + bytes <= budget.max_factor_bytes)
      return true;
    // The other levels' factorisations only save later loads their set-up: they give way, and are made again when a
    // later load's ladder needs them.
    probe.reset();
    for (std::size_t i = 0; i < solvers.size(); ++i)
      if (i != keep)
        solvers[i].reset();
    return held_bytes() + bytes <= budget.max_factor_bytes;
  }



  AxisymmetricSolver *ContractSolver::level(const unsigned int l, std::string &limit)
  {
    if (l < solvers.size() && solvers[l])
      return solvers[l].get();
    held_bytes(); // records the sizes of the levels held
    if (l >= solvers.size())
      solvers.resize(l + 1), level_bytes.resize(l + 1, 0.);
    // The level's factorisation: known when it was made before, else predicted from the growth over the last level.
    const double last = l >= 1 ? level_bytes[l - 1] : 0, before = l >= 2 ? level_bytes[l - 2] : 0;
    const double next = level_bytes[l] > 0 ? level_bytes[l] : before > 0 ? last * last / before : 0;
    if (!make_room(next, l))
      {
        limit = "memory budget: level " + std::to_string(l) + "'s factorisation and matrices would hold about " +
                format(next) + " bytes, above AccuracyBudget::max_factor_bytes = " + format(budget.max_factor_bytes);
        return nullptr;
      }
    const Settings s = ladder_settings(base, ladder, l);
    auto solver = std::make_unique<AxisymmetricSolver>(material, s.mesh, s.discretization);
    if (solver->n_dofs() > budget.max_dofs)
      {
        limit = "DoF budget: level " + std::to_string(l) + " has " + std::to_string(solver->n_dofs()) +
                " DoFs, above AccuracyBudget::max_dofs = " + std::to_string(budget.max_dofs);
        return nullptr;
      }
    solvers[l] = std::move(solver);
    return solvers[l].get();
  }



  void ContractSolver::probe_rounding(const LoadCase &load, const OutputRequest &outputs, LadderRecord &record)
  {
    const unsigned int l = record.levels() - 1;
    // A probe that cannot run leaves a refusal's estimates without the rounding and its limit as it was; a met ladder
    // cannot be confirmed without it.
    const auto give_up = [&record](const std::string &why) {
      if (record.met())
        record.fail(why);
    };
    if (l >= solvers.size() || !solvers[l])
      return; // dropped for a level above it, which was refused: the ladder is not met
    if (!probe || probe_level != l)
      {
        probe.reset(); // before the next is made: the memory of one probe at a time
        const double bytes = double(solvers[l]->factor_bytes());
        if (!make_room(bytes, l))
          {
            give_up("memory budget: the rounding probe of level " + std::to_string(l) + " would hold about " +
                    format(bytes) + " bytes next to the level's own, above AccuracyBudget::max_factor_bytes = " +
                    format(budget.max_factor_bytes));
            return;
          }
        Material scaled = material;
        scaled.modulus  = std::make_shared<ScaledModulus>(material.modulus, rounding_probe_factor);
        const Settings s = ladder_settings(base, ladder, l);
        probe            = std::make_unique<AxisymmetricSolver>(scaled, s.mesh, s.discretization);
        probe_level      = l;
      }
    // The loads that are forces or stresses scale with the modulus; depths and profiles do not.
    LoadCase scaled_load = load;
    scaled_load.force *= rounding_probe_factor;
    scaled_load.pressure *= rounding_probe_factor;
    scaled_load.cohesion.stress *= rounding_probe_factor;
    Result r;
    try
      {
        r = probe->run(scaled_load, outputs);
      }
    catch (const std::runtime_error &e)
      {
        give_up("failed solve of the rounding probe on level " + std::to_string(l) + ": " + e.what());
        return;
      }
    if (!r.reliable)
      {
        give_up("unreliable solve of the rounding probe on level " + std::to_string(l) + ": " + r.message);
        return;
      }
    record.add_rounding(quantities(scaled_load, r, base.mesh.contact_radius, outputs.stress_points),
                        rounding_probe_factor);
  }



  ContractResult ContractSolver::run(const LoadCase &load, const OutputRequest &outputs)
  {
    const auto     start = std::chrono::steady_clock::now();
    ContractResult out;
    out.tolerance = asked;
    LadderRecord record(material, base, asked, budget);
    while (record.next_level_allowed())
      {
        std::string         limit;
        Result              r;
        try
          {
            AxisymmetricSolver *solver = level(record.levels(), limit);
            if (!solver)
              {
                record.fail(limit);
                break;
              }
            r = solver->run(load, outputs);
          }
        catch (const std::runtime_error &e)
          {
            // A factorisation that fails (a numerically singular matrix) limits the ladder like an unreliable solve;
            // bad input (std::invalid_argument) is not caught.
            record.fail("failed solve on level " + std::to_string(record.levels()) + ": " + e.what());
            break;
          }
        if (!r.reliable)
          {
            record.fail("unreliable solve on level " + std::to_string(record.levels()) + " (" +
                        std::to_string(r.n_dofs) + " DoFs): " + r.message);
            out.result = std::move(r);
            break;
          }
        const bool stop = record.add(quantities(load, r, base.mesh.contact_radius, outputs.stress_points), r.n_dofs);
        out.result      = std::move(r);
        if (stop)
          break;
      }

    // A refused ladder is probed too, so that the estimates it prints include the rounding.
    if (record.levels() >= 2 && probes_rounding(material))
      probe_rounding(load, outputs, record);

    // The estimates of the finest level solved.
    out.met        = record.met();
    out.limit      = record.limit();
    out.degree     = record.degree();
    out.level_dofs = record.level_dofs();
    std::size_t i = 0;
    if (record.levels() > 0)
      {
        if (load.type != LoadType::constant_pressure)
          out.force = record.estimate(i++);
        if (load.type == LoadType::indenter || load.type == LoadType::indenter_force ||
            load.type == LoadType::constant_pressure)
          out.depth = record.estimate(i++);
        if (load.type == LoadType::indenter_depth || load.type == LoadType::indenter_force)
          out.contact_radius = record.estimate(i++);
        for (std::size_t j = 0; j < out.result.pressure.size(); ++j)
          out.pressure.push_back(record.estimate(i++));
        for (std::size_t j = 0; j < out.result.displacement.size(); ++j)
          out.displacement.push_back(record.estimate(i++));
        for (std::size_t j = 0; j < out.result.stress.size(); ++j)
          {
            std::array<Estimated, 4> components;
            for (Estimated &c : components)
              c = record.estimate(i++);
            out.stress.push_back(components);
          }
      }
    out.seconds = seconds_since(start);
    return out;
  }
} // namespace gradcontact::fem
