#include <fem/cohesive_zone.h>
#include <fem/errors.h>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    /// Slack of the gap checks, relative to h_0 (round-off of the root and of the back-substitutions).
    constexpr double gap_slack = 1e-6;

    /// The zone does not end within max_zone_ratio a: the contact has all but vanished (critical_state reads it so).
    struct ZoneBeyondReach : std::runtime_error
    {
      using std::runtime_error::runtime_error;
    };

    /// The near-field sizes the meshes use: 4 * 1.25^j, so that neighbouring states share gmsh's cached mesh.
    double near_field_step(const double wanted)
    {
      double r = 4;
      while (r < wanted)
        r *= 1.25;
      return r;
    }
  } // namespace



  void DugdaleLaw::validate() const
  {
    if (!(strength > 0) || !std::isfinite(strength))
      fail("DugdaleLaw", "strength (sigma_0)", strength, "(0, inf)");
    if (!(work > 0) || !std::isfinite(work))
      fail("DugdaleLaw", "work of adhesion", work, "(0, inf)");
  }

  void CohesiveParameters::validate() const
  {
    if (zone_refinements > 30)
      fail("CohesiveParameters", "zone_refinements", zone_refinements, "[0, 30]");
    if (!(zone_tolerance > 0 && zone_tolerance < 1))
      fail("CohesiveParameters", "zone_tolerance", zone_tolerance, "(0, 1)");
    if (!(near_field_margin >= 1.2 && near_field_margin <= 100))
      fail("CohesiveParameters", "near_field_margin", near_field_margin, "[1.2, 100]");
    if (!(radius_tolerance >= 1e-10 && radius_tolerance <= 0.1))
      fail("CohesiveParameters", "radius_tolerance", radius_tolerance, "[1e-10, 0.1]");
    if (!(stencil_ratio > 1 && stencil_ratio <= 4))
      fail("CohesiveParameters", "stencil_ratio", stencil_ratio, "(1, 4]");
    if (!(max_zone_ratio > 1.5 && std::isfinite(max_zone_ratio)))
      fail("CohesiveParameters", "max_zone_ratio", max_zone_ratio, "(1.5, inf)");
    if (max_states < 5 || max_states > 1000)
      fail("CohesiveParameters", "max_states", max_states, "[5, 1000]");
  }



  CohesiveContact::CohesiveContact(const Material &material_, const Profile &profile_, const DugdaleLaw &law_,
                                   SettingsFunction settings_, const CohesiveParameters &parameters_)
    : material(material_)
    , profile(profile_)
    , law((law_.validate(), law_))
    , settings(std::move(settings_))
    , parameters((parameters_.validate(), parameters_))
  {
    profile.validate();
    if (profile.shape == Profile::Shape::concave_paraboloid)
      throw std::invalid_argument("CohesiveContact: the profile must open monotonically (not the concave punch)");
    if (!settings)
      throw std::invalid_argument("CohesiveContact: the settings function is empty");
  }



  double CohesiveContact::predicted_zone_ratio(const double a) const
  {
    // c / a of the nearest solved radius (in ln a); NaN when none.
    double best = std::numeric_limits<double>::quiet_NaN(), distance = std::numeric_limits<double>::max();
    for (const auto &[r, s] : solved)
      if (std::abs(std::log(r / a)) < distance)
        {
          distance = std::abs(std::log(r / a));
          best     = s.zone_radius / r;
        }
    return best;
  }



  CohesiveState CohesiveContact::solve_on_mesh(const double a, const double c_hint, const std::vector<double> &refine_at,
                                               double &c_found)
  {
    const auto start = std::chrono::steady_clock::now();
    Settings   s     = settings(a);
    s.mesh.contact_radius = a;
    const double base     = s.mesh.near_field_size;
    const double wanted   = near_field_step(parameters.near_field_margin * c_hint / a);
    if (wanted > base)
      {
        // A wide zone (small Tabor parameter): the surface cells away from a and c grow with the near field
        // (the refinement toward c and the grading toward a keep both ends resolved).
        s.mesh.h_far *= wanted / base;
        s.mesh.h_surface_outer = std::clamp(wanted / 20, s.mesh.h_surface, s.mesh.h_far);
        s.mesh.near_field_size = wanted;
      }
    const double       reach = 0.9 * s.mesh.near_field_size * a; // the zone must end inside the near field
    SurfaceRefinement  refinement;
    if (!refine_at.empty() && parameters.zone_refinements > 0)
      refinement = {refine_at, parameters.zone_refinements};
    AxisymmetricSolver solver(material, s.mesh, s.discretization, refinement);

    const double h0 = law.range();
    LoadCase     load;
    load.type            = LoadType::indenter;
    load.profile         = profile;
    load.cohesion.stress = law.strength;
    CohesiveState state;
    state.radius = a;
    state.meshes = 1;
    state.n_dofs = solver.n_dofs();
    Result last;
    const auto g = [&](const double c) {
      load.cohesion.radius = c;
      OutputRequest out;
      out.displacement_radii = {c};
      last                   = solver.run(load, out);
      ++state.zone_solves;
      return profile(c, a) - last.depth + last.displacement.front().value - h0;
    };

    // Bracket: g(a) = -h_0; step c - a up from the hint until g > 0.
    double hi = std::max(c_hint, a * 1.01), g_hi = g(hi);
    while (g_hi < 0)
      {
        if (hi >= reach)
          {
            c_found = std::numeric_limits<double>::infinity(); // beyond this near field
            return state;
          }
        hi   = std::min(a + 1.5 * (hi - a), reach);
        g_hi = g(hi);
      }
    double lo = a, g_lo = -h0;
    if (hi > c_hint * 1.0000001 && c_hint > a * (1 + 1e-9))
      {
        // The hint was too small: it is the better lower end.
        const double g_hint = g(c_hint);
        if (g_hint < 0)
          lo = c_hint, g_lo = g_hint;
      }
    std::uintmax_t iterations = 60;
    const auto     root       = boost::math::tools::toms748_solve(g, lo, hi, g_lo, g_hi,
                                                                  boost::math::tools::eps_tolerance<double>(40), iterations);
    c_found = 0.5 * (root.first + root.second);

    // The state at c with its samples: the gap inside the zone and beyond it.
    load.cohesion.radius = c_found;
    OutputRequest out;
    const std::vector<double> inside{0.25, 0.5, 0.75}, beyond{1.05, 1.3, 1.6};
    for (const double t : inside)
      out.displacement_radii.push_back(a + t * (c_found - a));
    for (const double t : beyond)
      if (t * c_found < reach)
        out.displacement_radii.push_back(t * c_found);
    out.displacement_radii.push_back(c_found);
    last = solver.run(load, out);
    ++state.zone_solves;
    state.zone_radius = c_found;
    state.depth       = last.depth;
    state.force       = last.force;
    std::ostringstream msg;
    msg << last.message;
    for (const Sample &w : last.displacement)
      {
        const double h = profile(w.r, a) - last.depth + w.value;
        if (w.r < c_found && (h < -gap_slack * h0 || h > h0 * (1 + gap_slack)))
          msg << "gap " << h / h0 << " h_0 inside the cohesive zone at r = " << w.r << "; ";
        if (w.r > c_found && h < h0 * (1 - gap_slack))
          msg << "gap " << h / h0 << " h_0 < h_0 beyond the cohesive zone at r = " << w.r << "; ";
      }
    state.message    = msg.str();
    state.consistent = last.consistent_contact && last.reliable && state.message.empty();
    state.seconds    = seconds_since(start);
    return state;
  }



  const CohesiveState &CohesiveContact::state(const double a)
  {
    if (!(a > 0) || !std::isfinite(a))
      fail("CohesiveContact::state", "contact radius a", a, "(0, inf)");
    for (const auto &[r, s] : solved)
      if (std::abs(r - a) <= 1e-12 * a)
        return s;

    double ratio = predicted_zone_ratio(a);
    double hint  = std::isnan(ratio) ? 2 * a : ratio * a;
    CohesiveState total;
    double        c = 0;
    bool          refined = std::isnan(ratio) ? false : true; // a first pass without refinement finds c
    std::vector<double> found; // the zone ends of the meshes so far
    for (unsigned int pass = 0; pass < 12; ++pass)
      {
        // Refined toward the hint and the zone ends of the last two meshes: a c that alternates between two places
        // finds both resolved.
        std::vector<double> refine_at;
        if (refined)
          {
            refine_at.push_back(hint);
            for (std::size_t j = found.size() >= 2 ? found.size() - 2 : 0; j < found.size(); ++j)
              refine_at.push_back(found[j]);
          }
        CohesiveState s = solve_on_mesh(a, hint, refine_at, c);
        if (std::isfinite(c))
          found.push_back(c);
        s.meshes += total.meshes;
        s.zone_solves += total.zone_solves;
        s.seconds += total.seconds;
        total = s;
        if (std::isinf(c))
          {
            hint *= 2;
            if (hint > parameters.max_zone_ratio * a)
              {
                std::ostringstream msg;
                msg << "CohesiveContact: no end of the cohesive zone within c <= " << parameters.max_zone_ratio
                    << " a at a = " << a;
                throw ZoneBeyondReach(msg.str());
              }
            continue;
          }
        // A zone thinner than the mesh's own resolution of its width (c - a below about 1e-3 c) is settled when c
        // moves by less than 1e-6 c.
        const bool settled =
          refined && std::abs(c - hint) <= std::max(parameters.zone_tolerance * (c - a), 1e-6 * c);
        if (settled || parameters.zone_refinements == 0)
          return solved.emplace(a, total).first->second;
        refined = true;
        hint    = c;
      }
    std::ostringstream msg;
    msg << "CohesiveContact: the end of the cohesive zone did not settle at a = " << a << " after " << total.meshes
        << " meshes (last c = " << c << ")";
    throw std::runtime_error(msg.str());
  }



  CohesiveCriticalState CohesiveContact::critical_state(const AdhesionControl control, const double a0)
  {
    if (!(a0 > 0) || !std::isfinite(a0))
      fail("CohesiveContact::critical_state", "a0", a0, "(0, inf)");
    const auto         start  = std::chrono::steady_clock::now();
    const std::size_t  before = solved.size();
    CohesiveCriticalState result;
    const auto value = [&](const double s) {
      if (solved.size() - before >= parameters.max_states)
        {
          std::ostringstream msg;
          msg << "CohesiveContact::critical_state: no minimum after " << parameters.max_states << " states";
          throw std::runtime_error(msg.str());
        }
      const CohesiveState &st = state(std::exp(s));
      return control == AdhesionControl::force ? st.force : st.depth;
    };
    const auto vanished = [&](const double s) {
      try
        {
          const CohesiveState &st = state(std::exp(s));
          return st.zone_radius / st.radius > parameters.max_zone_ratio / 1.5;
        }
      catch (const ZoneBeyondReach &)
        {
          return true;
        }
    };
    // Bracket by an expanding walk (steps growing by the golden ratio), then Brent inside it.
    constexpr double growth = 1.618;
    const double     q      = std::log(parameters.stencil_ratio);
    double left = std::log(a0) - q, mid = std::log(a0), right = std::log(a0) + q;
    double s_vanished = -std::numeric_limits<double>::infinity();
    double v_left = value(left), v_mid = value(mid), v_right = value(right);
    while (!(v_mid <= v_left && v_mid <= v_right))
      {
        if (v_left < v_mid)
          {
            double next = left - growth * (mid - left);
            right = mid, v_right = v_mid;
            mid = left, v_mid = v_left;
            // Never beyond a radius where the contact is known to have vanished: halve toward it instead, until
            // the step is a quarter of the first one (then the minimum is the vanishing contact itself).
            if (next <= s_vanished)
              next = 0.5 * (mid + s_vanished);
            bool gone = false;
            while (vanished(next))
              {
                s_vanished = next;
                if (mid - s_vanished < q / 4)
                  {
                    gone = true;
                    break;
                  }
                next = 0.5 * (mid + s_vanished);
              }
            if (gone)
              {
                // The last state on the path before the contact vanishes.
                result.at_vanishing_contact = true;
                result.state                = state(std::exp(mid));
                break;
              }
            left   = next;
            v_left = value(left);
          }
        else
          {
            const double next = right + growth * (right - mid);
            left = mid, v_left = v_mid;
            mid = right, v_mid = v_right;
            right = next;
            v_right = value(right);
          }
      }
    if (!result.at_vanishing_contact)
      {
        const int      bits       = static_cast<int>(std::ceil(-std::log2(parameters.radius_tolerance))) + 1;
        std::uintmax_t iterations = parameters.max_states;
        const auto     minimum    = boost::math::tools::brent_find_minima(value, left, right, bits, iterations);
        result.state              = state(std::exp(minimum.first));
      }
    result.states_solved = solved.size() - before;
    for (const auto &[r, st] : solved)
      result.max_dofs = std::max(result.max_dofs, st.n_dofs);
    result.seconds = seconds_since(start);
    return result;
  }
} // namespace gradcontact::fem
