#include <fem/adhesion/adhesion.h>
#include <fem/base/errors.h>

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// Two radii closer than this in s = ln a are the same radius (a node is never solved twice).
    constexpr double same_radius = 1e-12;

    /// The polynomial through (t_i, y_i) in Newton form, with its first two derivatives at t.
    struct Interpolant
    {
      std::vector<double> t, c;

      Interpolant(const std::vector<double> &t_, const std::vector<double> &y) : t(t_), c(y)
      {
        // Divided differences in place: c_j = y[t_0, ..., t_j].
        for (std::size_t j = 1; j < t.size(); ++j)
          for (std::size_t i = t.size() - 1; i >= j; --i)
            c[i] = (c[i] - c[i - 1]) / (t[i] - t[i - j]);
      }

      /// value, first and second derivative (Horner's scheme for the Newton form and its derivatives)
      std::array<double, 3> operator()(const double x) const
      {
        const std::size_t n = c.size();
        double p = c[n - 1], dp = 0, d2p = 0;
        for (std::size_t i = n - 1; i-- > 0;)
          {
            d2p = d2p * (x - t[i]) + 2 * dp;
            dp  = dp * (x - t[i]) + p;
            p   = p * (x - t[i]) + c[i];
          }
        return {{p, dp, d2p}};
      }
    };

    bool is_curved(const std::optional<Profile> &p)
    {
      return p && p->shape != Profile::Shape::concave_paraboloid;
    }
  } // namespace



  void AdhesionParameters::validate() const
  {
    if (!(stencil_ratio > 1 + 1e-6 && stencil_ratio <= 2))
      fail("AdhesionParameters", "stencil_ratio", stencil_ratio, "(1 + 1e-6, 2]");
    if (fit_points < 2 || fit_points > 5)
      fail("AdhesionParameters", "fit_points", fit_points, "[2, 5]");
    if (!(radius_tolerance >= 1e-12 && radius_tolerance <= 1e-2))
      fail("AdhesionParameters", "radius_tolerance", radius_tolerance, "[1e-12, 1e-2]");
    if (max_iterations < 1 || max_iterations > 200)
      fail("AdhesionParameters", "max_iterations", max_iterations, "[1, 200]");
  }



  AdhesiveContact::AdhesiveContact(const Material &material_, const std::optional<Profile> &profile_,
                                   SettingsFunction settings_, const AdhesionParameters &parameters_)
    // nu = 0.5 is allowed here: each radius's settings choose the formulation, and its solver refuses
    // nu = 0.5 with the displacement formulation.
    : material((material_.validate(true), material_))
    , profile(profile_)
    , settings(std::move(settings_))
    , parameters((parameters_.validate(), parameters_))
  {
    if (profile)
      profile->validate();
    if (!settings)
      throw std::invalid_argument("AdhesiveContact: no settings function for the meshes of the radii");
  }



  const RadiusState &AdhesiveContact::state(const double a)
  {
    if (!std::isfinite(a) || !(a > 0))
      fail("AdhesiveContact::state", "contact radius a", a, "(0, inf)");
    const double s  = std::log(a);
    const auto   it = nodes.lower_bound(s - same_radius);
    if (it != nodes.end() && std::abs(it->first - s) <= same_radius)
      return it->second;

    const auto start = std::chrono::steady_clock::now();
    Settings   st    = settings(a);
    st.mesh.contact_radius = a; // every length of the mesh is relative to a
    AxisymmetricSolver solver(material, st.mesh, st.discretization);

    RadiusState  state;
    state.a = a;
    // p(0) for the centre mechanism of the concave punch: from degree 3 on the recovered pressure (M p = R) is
    // as accurate at the axis as elsewhere, while at degree 2 the axis node, which the r-weighted recovery
    // barely constrains, lags by orders of magnitude (test_fem.cc, the recovered pressure of the flat punch),
    // so the centre needs degree >= 3.
    OutputRequest centre;
    centre.pressure_radii = {0.};

    // K(a) and p_1(0): the flat punch of unit depth (a reaction force, fem/bodies/axisymmetric_solver.h).
    LoadCase punch;
    punch.type  = LoadType::flat_punch;
    punch.depth = 1.;
    const Result flat = solver.run(punch, centre);
    if (!flat.reliable)
      throw std::runtime_error("AdhesiveContact: flat punch of radius " + std::to_string(a) +
                               " is unreliable: " + flat.message);
    state.stiffness             = flat.force;
    state.punch_centre_pressure = flat.pressure.at(0).value;

    if (profile)
      {
        // The non-adhesive state of contact radius a: the depth at which the edge carries no force.
        LoadCase indenter;
        indenter.type    = LoadType::indenter;
        indenter.profile = *profile;
        const Result n   = solver.run(indenter, centre);
        if (!n.reliable)
          throw std::runtime_error("AdhesiveContact: profile state of radius " + std::to_string(a) +
                                   " is unreliable: " + n.message);
        state.depth                   = n.depth;
        state.force                   = n.force;
        state.profile_centre_pressure = n.pressure.at(0).value;
        // Zero where the profile is flat on r <= a (a rounded punch inside its flat): no non-adhesive load.
        if (is_curved(profile) && !(state.depth >= 0 && state.force >= 0))
          {
            std::ostringstream msg;
            msg << "AdhesiveContact: the non-adhesive state of radius " << a << " has depth " << state.depth
                << " and force " << state.force << " (neither may be negative for a convex profile)";
            throw std::runtime_error(msg.str());
          }
      }
    state.n_dofs  = flat.n_dofs;
    state.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return nodes.emplace(s, state).first->second;
  }



  AdhesiveContact::Local AdhesiveContact::interpolate(const double s) const
  {
    if (nodes.size() < 2)
      throw std::logic_error("AdhesiveContact::interpolate: fewer than two solved radii");
    // The fit_points solved radii nearest s.
    std::vector<std::pair<double, const RadiusState *>> near;
    for (const auto &[sn, st] : nodes)
      near.emplace_back(sn, &st);
    std::sort(near.begin(), near.end(), [s](const auto &x, const auto &y) {
      return std::abs(x.first - s) < std::abs(y.first - s);
    });
    // Radii much closer together than the stencil would turn the FE discretisation error into a large
    // derivative error (a 1e-8 difference over 1e-6 in s is 1e-2): keep nodes at least h/2 apart.
    const double spacing = 0.5 * std::log(parameters.stencil_ratio);
    std::vector<double> t, lnK, depths, forces;
    for (const auto &[sn, st] : near)
      {
        if (t.size() == parameters.fit_points)
          break;
        if (std::any_of(t.begin(), t.end(), [&](const double u) { return std::abs(u - sn) < spacing; }))
          continue;
        t.push_back(sn);
        lnK.push_back(std::log(st->stiffness));
        depths.push_back(st->depth);
        forces.push_back(st->force);
      }
    Local      l;
    const auto k = Interpolant(t, lnK)(s);
    l.lnK = k[0], l.dlnK = k[1], l.d2lnK = k[2];
    if (is_curved(profile))
      {
        // In the logarithm, where d_n and F_n are powers of a (the power law); the values themselves where one
        // is not positive (a profile flat around the axis, f = 0 on r <= a: no non-adhesive load there).
        const auto interpolated = [&](std::vector<double> values) {
          if (std::any_of(values.begin(), values.end(), [](const double v) { return !(v > 0); }))
            return Interpolant(t, values)(s)[0];
          for (double &v : values)
            v = std::log(v);
          return std::exp(Interpolant(t, values)(s)[0]);
        };
        l.depth = interpolated(depths);
        l.force = interpolated(forces);
      }
    return l;
  }



  AdhesiveState AdhesiveContact::evaluate(const double s, const double dgamma) const
  {
    const Local   l = interpolate(s);
    AdhesiveState st;
    st.radius           = std::exp(s);
    st.stiffness        = std::exp(l.lnK);
    st.scaling_exponent = l.dlnK;
    st.stiffness_slope  = st.stiffness * l.dlnK / st.radius;
    if (!(st.stiffness_slope > 0) || !std::isfinite(st.stiffness_slope))
      {
        std::ostringstream msg;
        msg << "AdhesiveContact: the FE flat-punch stiffness does not grow with the contact radius at a = "
            << st.radius << " (a K'/K = " << l.dlnK << "): no energy release rate";
        throw std::runtime_error(msg.str());
      }
    st.delta = std::sqrt(4 * pi * st.radius * dgamma / st.stiffness_slope);
    st.depth = l.depth - st.delta;
    st.force = l.force - st.stiffness * st.delta;
    return st;
  }



  void AdhesiveContact::ensure_stencil(const double s)
  {
    const double h = std::log(parameters.stencil_ratio);
    for (const double t : {s - h, s, s + h})
      state(std::exp(t));
  }



  AdhesiveState AdhesiveContact::adhesive_state(const double a, const double dgamma)
  {
    if (!std::isfinite(dgamma) || !(dgamma > 0))
      fail("AdhesiveContact", "work of adhesion dgamma", dgamma, "(0, inf)");
    const RadiusState &n = state(a);
    if (nodes.size() < parameters.fit_points)
      ensure_stencil(std::log(a));
    AdhesiveState st = evaluate(std::log(a), dgamma);
    // At a solved radius the non-adhesive state is the node's own (no interpolation).
    st.depth = n.depth - st.delta + concave_offset();
    st.force = n.force - st.stiffness * st.delta;
    return st;
  }



  double AdhesiveContact::energy_release_rate(const double a, const double delta)
  {
    state(a);
    if (nodes.size() < parameters.fit_points)
      ensure_stencil(std::log(a));
    const AdhesiveState st = evaluate(std::log(a), 1.);
    return delta * delta * st.stiffness_slope / (4 * pi * a);
  }



  double AdhesiveContact::concave_offset() const
  {
    return profile && profile->shape == Profile::Shape::concave_paraboloid ? profile->h0 : 0.;
  }



  AdhesiveCriticalState AdhesiveContact::summary(const AdhesiveState &st, const unsigned int iterations) const
  {
    AdhesiveCriticalState c;
    c.state        = st;
    c.radii_solved = nodes.size();
    c.iterations   = iterations;
    for (const auto &node : nodes)
      {
        c.max_dofs = std::max(c.max_dofs, node.second.n_dofs);
        c.fe_seconds += node.second.seconds;
      }
    return c;
  }



  AdhesiveCriticalState AdhesiveContact::critical_state(const double dgamma, const AdhesionControl control,
                                                        const double a0)
  {
    if (!is_curved(profile))
      throw std::invalid_argument("AdhesiveContact::critical_state: needs a curved profile (paraboloid, "
                                  "cone, power law); use periphery_state for the flat and concave punches");
    if (!std::isfinite(dgamma) || !(dgamma > 0))
      fail("AdhesiveContact::critical_state", "work of adhesion dgamma", dgamma, "(0, inf)");
    if (!std::isfinite(a0) || !(a0 > 0))
      fail("AdhesiveContact::critical_state", "initial radius a0", a0, "(0, inf)");

    // The curve to minimise: F(a) under force control, d(a) under displacement control; +inf where the
    // local model is not defined (an extrapolation with K' <= 0), so the minimiser avoids it.
    const auto objective = [&](const double s) {
      try
        {
          const AdhesiveState st = evaluate(s, dgamma);
          const double        v  = control == AdhesionControl::force ? st.force : st.depth;
          return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
        }
      catch (const std::runtime_error &)
        {
          return std::numeric_limits<double>::infinity();
        }
    };
    // One step may move a by at most this factor: the fit is trusted only near its radii.
    const double max_step = std::log(4.);
    const double tol      = parameters.radius_tolerance;
    const double s0       = std::log(a0);
    const double s_lo     = s0 - std::log(1e6), s_hi = s0 + std::log(1e6);
    const auto   minimise = [&](const double centre) {
      return boost::math::tools::brent_find_minima(objective, centre - max_step, centre + max_step, 50).first;
    };

    if (nodes.size() < parameters.fit_points)
      ensure_stencil(s0);
    // Each step minimises the local model and solves the FE model at the minimiser; the search ends when
    // the minimiser falls inside the solved stencil (within h/2 of a solved radius), where the local fit
    // is as good as the stencil makes it.
    const double h  = std::log(parameters.stencil_ratio);
    double       s  = s0;
    unsigned int it = 0;
    for (;; ++it)
      {
        if (it >= parameters.max_iterations)
          {
            std::ostringstream msg;
            msg << "AdhesiveContact: no critical state under "
                << (control == AdhesionControl::force ? "force" : "displacement")
                << " control: the search did not settle after " << it << " FE radii (last a = " << std::exp(s)
                << ")";
            throw std::runtime_error(msg.str());
          }
        const double s_new = minimise(s);
        if (s_new < s_lo || s_new > s_hi)
          {
            std::ostringstream msg;
            msg << "AdhesiveContact: no critical state under "
                << (control == AdhesionControl::force ? "force" : "displacement")
                << " control: the curve keeps falling toward a = " << std::exp(s_new) << " (started at a0 = " << a0
                << "; no minimum within a factor 1e6)";
            throw std::runtime_error(msg.str());
          }
        double nearest = std::numeric_limits<double>::infinity();
        for (const auto &node : nodes)
          nearest = std::min(nearest, std::abs(node.first - s_new));
        const bool settled = nearest <= std::max(0.5 * h, tol) || std::abs(s_new - s) <= tol;
        s                  = s_new;
        if (settled)
          break;
        state(std::exp(s));
      }

    double shift = 0;
    if (parameters.local_stencil)
      {
        ensure_stencil(s);
        const double s_final = minimise(s);
        shift                = std::abs(std::expm1(s_final - s));
        s                    = s_final;
      }
    AdhesiveCriticalState c = summary(evaluate(s, dgamma), it + 1);
    c.search_shift          = shift;
    return c;
  }



  AdhesiveCriticalState AdhesiveContact::periphery_state(const double a, const double dgamma)
  {
    if (is_curved(profile))
      throw std::invalid_argument("AdhesiveContact::periphery_state: for the flat and concave punches; a "
                                  "curved profile's critical state comes from critical_state");
    const AdhesiveState st = adhesive_state(a, dgamma);
    return summary(st, 0);
  }



  AdhesiveCriticalState AdhesiveContact::centre_state(const double a, const double dgamma, const double sigma_th)
  {
    if (!profile || profile->shape != Profile::Shape::concave_paraboloid)
      throw std::invalid_argument("AdhesiveContact::centre_state: only the concave punch separates at the centre");
    if (!std::isfinite(sigma_th) || !(sigma_th > 0))
      fail("AdhesiveContact::centre_state", "tensile strength sigma_th", sigma_th, "(0, inf)");
    AdhesiveState      st = adhesive_state(a, dgamma); // solves a and its stencil
    const RadiusState &n  = state(a);
    // p(0) = p_n(0) - delta p_1(0) = -sigma_th.
    const double delta = (n.profile_centre_pressure + sigma_th) / n.punch_centre_pressure;
    // delta < 0 is a legitimate state: the centre reaches sigma_th while the rim is still pressed deeper
    // than the edge-force-free state (edge in compression); unloading meets it before the periphery.
    st.delta = delta;
    st.depth = n.depth - delta + concave_offset();
    st.force = n.force - n.stiffness * delta;
    return summary(st, 0);
  }



  double AdhesiveContact::transition_h0(const double a, const double dgamma, const double sigma_th)
  {
    if (!profile || profile->shape != Profile::Shape::concave_paraboloid || !(profile->h0 > 0))
      throw std::invalid_argument("AdhesiveContact::transition_h0: needs the concave punch with h0 > 0");
    const AdhesiveState periphery = adhesive_state(a, dgamma);
    const RadiusState  &n         = state(a);
    // delta_centre(h0) = (h0 p^_n(0) + sigma_th) / p_1(0), p^_n = p_n / h0 (linear in h0); equal to the
    // periphery's delta (independent of h0) at h0*.
    const double pn_per_h0 = n.profile_centre_pressure / profile->h0;
    const double h0        = (periphery.delta * n.punch_centre_pressure - sigma_th) / pn_per_h0;
    if (!(h0 > 0))
      {
        std::ostringstream msg;
        msg << "AdhesiveContact::transition_h0: sigma_th = " << sigma_th
            << " is too small: the centre separates first for every h0 >= 0 (no transition)";
        throw std::runtime_error(msg.str());
      }
    return h0;
  }


  AdhesiveContact::Profiles AdhesiveContact::profiles(const double a, const double dgamma,
                                                      const std::vector<double> &pressure_radii,
                                                      const std::vector<double> &displacement_radii)
  {
    const AdhesiveState st = adhesive_state(a, dgamma);
    Profiles out = profiles_at_delta(a, st.delta, pressure_radii, displacement_radii);
    out.state = st;
    return out;
  }



  AdhesiveContact::Profiles AdhesiveContact::profiles_at_delta(const double a, const double delta,
                                                               const std::vector<double> &pressure_radii,
                                                               const std::vector<double> &displacement_radii)
  {
    if (!std::isfinite(delta))
      fail("AdhesiveContact::profiles_at_delta", "delta", delta, "finite");
    Profiles out;
    out.state.radius = a;
    out.state.delta  = delta;
    Settings st = settings(a);
    st.mesh.contact_radius = a;
    AxisymmetricSolver solver(material, st.mesh, st.discretization);
    OutputRequest request;
    request.pressure_radii     = pressure_radii;
    request.displacement_radii = displacement_radii;
    LoadCase punch;
    punch.type  = LoadType::flat_punch;
    punch.depth = 1.;
    const Result unit = solver.run(punch, request);
    Result       profile_state; // zero for the flat punch
    if (profile)
      {
        LoadCase indenter;
        indenter.type    = LoadType::indenter;
        indenter.profile = *profile;
        profile_state    = solver.run(indenter, request);
      }
    for (std::size_t i = 0; i < unit.pressure.size(); ++i)
      out.pressure.push_back({unit.pressure[i].r, (profile ? profile_state.pressure[i].value : 0.) -
                                                    delta * unit.pressure[i].value});
    for (std::size_t i = 0; i < unit.displacement.size(); ++i)
      out.displacement.push_back({unit.displacement[i].r, (profile ? profile_state.displacement[i].value : 0.) -
                                                            delta * unit.displacement[i].value});
    return out;
  }
} // namespace gradcontact::fem
