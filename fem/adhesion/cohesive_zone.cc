#include <fem/adhesion/cohesive_zone.h>
#include <fem/base/errors.h>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    /// Slack of the gap checks, relative to h_0 (round-off of the root and of the back-substitutions).
    constexpr double gap_slack = 1e-6;

    /// Points on each side of c in the mean of the gap over its window (CohesiveParameters::gap_window).
    constexpr unsigned int gap_samples = 32;

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

    /// A wide zone (small Tabor parameter): the near field widened to `wanted` (units of a) when it is smaller;
    /// the surface cells away from a and c grow with it (the refinement toward c and the grading toward a keep
    /// both ends resolved).
    void widen_near_field(MeshParameters &mesh, const double wanted)
    {
      const double base = mesh.near_field_size;
      if (wanted > base)
        {
          mesh.h_far *= wanted / base;
          mesh.h_surface_outer = std::clamp(wanted / 20, mesh.h_surface, mesh.h_far);
          mesh.near_field_size = wanted;
          // The truncation boundary stays beyond the widened near field, two rings at least (a condensed far field,
          // fem/elasticity/far_field.h, needs them; a clamped one lies far beyond anyway).
          mesh.far_field_size = std::max(mesh.far_field_size, 4 * wanted);
        }
    }

    /// The surface refinement of a mesh refined toward c_hint (none when not `refined`): toward c (the traction
    /// jump), and its gap window resolved by zone_cells cells.
    SurfaceRefinement zone_refinement(const CohesiveParameters &parameters, const double a, const double c_hint,
                                      const bool refined)
    {
      SurfaceRefinement refinement;
      if (refined)
        {
          const double delta = parameters.gap_window * (c_hint - a);
          refinement.radii   = {c_hint};
          refinement.levels  = parameters.zone_refinements;
          refinement.intervals.push_back({c_hint - delta, c_hint + delta, parameters.zone_cells});
        }
      return refinement;
    }

    /// The samples of the gap window of zone end c: 2 gap_samples + 1 points evenly over [c - delta, c + delta],
    /// delta = gap_window (c - a), in order (mean_gap reads them so).
    OutputRequest gap_window(const CohesiveParameters &parameters, const double a, const double c)
    {
      OutputRequest out;
      const double  delta = parameters.gap_window * (c - a);
      for (unsigned int i = 0; i <= 2 * gap_samples; ++i)
        out.displacement_radii.push_back(c - delta + i * delta / gap_samples);
      return out;
    }

    /// The samples of the state of zone end c: the gap window, then the gap inside the zone and beyond it (up to
    /// `reach`), which finish_state checks.
    OutputRequest state_samples(const CohesiveParameters &parameters, const double a, const double c,
                                const double reach)
    {
      const std::vector<double> inside{0.25, 0.5, 0.75}, beyond{1.05, 1.3, 1.6};
      OutputRequest             out = gap_window(parameters, a, c);
      for (const double t : inside)
        out.displacement_radii.push_back(a + t * (c - a));
      for (const double t : beyond)
        if (t * c < reach)
          out.displacement_radii.push_back(t * c);
      return out;
    }

    /// The gap at c, h(c) = f(c) - d + w(c), as its mean over [c - delta, c + delta] (trapezoidal rule on the
    /// 2 gap_samples + 1 samples of gap_window, the first ones of r): near the traction jump at c the gap opens like
    /// sign(r - c) |r - c|^{1-k} (k = 0: (r - c) ln|r - c|), whose FE value at c itself converges only like (cell
    /// width)^{1-k}, a few 1e-3 h_0 on the soft surface of k = 0.5 even with cells of 1e-10 c - a; the mean cancels
    /// the odd term, and what remains is the even part, O((delta / (c - a))^2), so the mean moves far less with the
    /// window than the point value does between meshes (`build/cases/tools/studies/cohesive_study` varies the window with
    /// gap_window=).
    double mean_gap(const Profile &profile, const double a, const Result &r)
    {
      const auto h = [&](const unsigned int i) {
        return profile(r.displacement[i].r, a) - r.depth + r.displacement[i].value;
      };
      double sum = 0.5 * (h(0) + h(2 * gap_samples));
      for (unsigned int i = 1; i < 2 * gap_samples; ++i)
        sum += h(i);
      return sum / (2 * gap_samples);
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
    if (!(gap_window > 0 && gap_window <= 0.1))
      fail("CohesiveParameters", "gap_window", gap_window, "(0, 0.1]");
    if (zone_cells < 1 || zone_cells > 1024)
      fail("CohesiveParameters", "zone_cells", zone_cells, "[1, 1024]");
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
    // c / a from the two solved radii nearest in ln a: ln(c / a - 1) linear in ln a through them (the zone's width
    // changes smoothly along the path, by a factor 17 between a = 0.12 and 1.25 a_JKR at k = 0.5, lambda = 0.1);
    // the nearest one's c / a when only one is solved; NaN when none.
    const double         s = std::log(a);
    const CohesiveState *first = nullptr, *second = nullptr; // the nearest and the next nearest in ln a
    double               d1 = std::numeric_limits<double>::max(), d2 = d1;
    for (const auto &[r, st] : solved)
      {
        const double distance = std::abs(std::log(r) - s);
        if (distance < d1)
          second = first, d2 = d1, first = &st, d1 = distance;
        else if (distance < d2)
          second = &st, d2 = distance;
      }
    if (!first)
      return std::numeric_limits<double>::quiet_NaN();
    const double ratio1 = first->zone_radius / first->radius;
    if (!second || !(ratio1 > 1) || !(second->zone_radius > second->radius))
      return ratio1;
    const auto   width = [](const CohesiveState *st) { return std::log(st->zone_radius / st->radius - 1); };
    const double s1 = std::log(first->radius), s2 = std::log(second->radius);
    // Two states closer than the search's resolution (a vertex next to Brent's point) give a slope of their noise.
    if (std::abs(s1 - s2) < parameters.radius_tolerance)
      return ratio1;
    const double w     = width(first) + (width(first) - width(second)) * (s - s1) / (s1 - s2);
    const double ratio = 1 + std::exp(w);
    // Trusted as far as the zone's width is: within a factor 4 of the nearest state's, and never beyond the ratio
    // at which the contact counts as vanished (the near field grows with it).
    if (!std::isfinite(ratio))
      return ratio1;
    return std::min(std::clamp(ratio, 1 + (ratio1 - 1) / 4, 1 + 4 * (ratio1 - 1)),
                    std::max(ratio1, parameters.max_zone_ratio));
  }



  CohesiveState CohesiveContact::solve_on_mesh(const double a, const double c_hint, const bool refined,
                                               const std::function<bool(double)> &root_wanted, double &c_found,
                                               double &g_hint)
  {
    const auto start = std::chrono::steady_clock::now();
    Settings   s     = settings(a);
    s.mesh.contact_radius = a;
    widen_near_field(s.mesh, near_field_step(parameters.near_field_margin * c_hint / a));
    const double            reach = 0.9 * s.mesh.near_field_size * a; // the zone must end inside the near field
    const SurfaceRefinement refinement = zone_refinement(parameters, a, c_hint, refined);
    AxisymmetricSolver      solver(material, s.mesh, s.discretization, refinement);

    const double h0 = law.range();
    LoadCase     load;
    load.type            = LoadType::indenter;
    load.profile         = profile;
    load.cohesion.stress = law.strength;
    CohesiveState state;
    state.radius = a;
    state.meshes = 1;
    state.n_dofs = solver.n_dofs();
    // g(c) = h(c) - h_0 of zone end c, h(c) the mean gap over its window (mean_gap).
    Result     last;
    const auto g = [&](const double c) {
      load.cohesion.radius = c;
      last                 = solver.run(load, gap_window(parameters, a, c));
      ++state.zone_solves;
      return mean_gap(profile, a, last) - h0;
    };
    // The state of zone end c with its samples (the window, then the gap inside the zone and beyond it): its g.
    Result     at_state;
    const auto solve_state = [&](const double c) {
      load.cohesion.radius = c;
      at_state             = solver.run(load, state_samples(parameters, a, c, reach));
      ++state.zone_solves;
      state.zone_radius = c;
      state.depth       = at_state.depth;
      state.force       = at_state.force;
      return mean_gap(profile, a, at_state) - h0;
    };

    // On a refined mesh the state is the one at c_hint (the point it is refined toward, where h(c) is accurate),
    // and the mesh's own root is searched only when asked (a first refined mesh: the next point; later ones are
    // placed by secants through G). Bracket: g(a) = -h_0, and g(c_hint) or g stepped up from the hint until > 0.
    g_hint     = std::numeric_limits<double>::quiet_NaN();
    c_found    = std::numeric_limits<double>::quiet_NaN();
    double lo = a, g_lo = -h0, hi = std::max(c_hint, a * 1.01), g_hi = 0;
    if (refined)
      {
        hi = c_hint;
        g_hi = solve_state(c_hint);
        g_hint = g_hi / h0;
        if (!root_wanted(g_hint))
          return finish_state(state, at_state, a, start);
        // The next point from the tangent of g at c_hint (one more solve, a difference over the gap window's half
        // width): g is smooth in c on one mesh (the tension is integrated on the faces split at c) and most accurate
        // at the point the mesh is refined toward. Taken when it stays within half the zone of the point; else the
        // root.
        const double step  = parameters.gap_window * (c_hint - a);
        const double slope = (g(c_hint + step) - g_hi) / step;
        const double next  = c_hint - g_hi / slope;
        if (slope > 0 && std::isfinite(next) && std::abs(next - c_hint) <= 0.5 * (c_hint - a) && next < reach)
          {
            c_found = next;
            return finish_state(state, at_state, a, start);
          }
        if (g_hi < 0)
          lo = c_hint, g_lo = g_hi, hi = std::min(a + 1.5 * (c_hint - a), reach), g_hi = g(hi);
      }
    else
      g_hi = g(hi);
    while (g_hi < 0)
      {
        if (hi >= reach)
          {
            c_found = std::numeric_limits<double>::infinity(); // beyond this near field
            if (refined)
              return finish_state(state, at_state, a, start);
            state.seconds = seconds_since(start);
            return state;
          }
        lo = hi, g_lo = g_hi;
        hi   = std::min(a + 1.5 * (hi - a), reach);
        g_hi = g(hi);
      }
    std::uintmax_t iterations = 60;
    const auto     root       = boost::math::tools::toms748_solve(g, lo, hi, g_lo, g_hi,
                                                                  boost::math::tools::eps_tolerance<double>(40), iterations);
    c_found = 0.5 * (root.first + root.second);
    if (!refined)
      solve_state(c_found);
    return finish_state(state, at_state, a, start);
  }



  CohesiveState CohesiveContact::finish_state(CohesiveState &state, const Result &last, const double a,
                                              const std::chrono::steady_clock::time_point start) const
  {
    // The checks of the samples beyond the window: 0 <= h <= h_0 inside the zone, h >= h_0 beyond it.
    const double h0 = law.range(), c = state.zone_radius;
    std::ostringstream msg;
    msg << last.message;
    for (const Sample &w : last.displacement)
      if (std::abs(w.r - c) > parameters.gap_window * (c - a) * (1 + 1e-9)) // the window's gap is the mean
      {
        const double h = profile(w.r, a) - last.depth + w.value;
        if (w.r < c && (h < -gap_slack * h0 || h > h0 * (1 + gap_slack)))
          msg << "gap " << h / h0 << " h_0 inside the cohesive zone at r = " << w.r << "; ";
        if (w.r > c && h < h0 * (1 - gap_slack))
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

    const double  ratio   = predicted_zone_ratio(a);
    double        hint    = std::isnan(ratio) ? 2 * a : ratio * a;
    bool          refined = !std::isnan(ratio); // a first pass without refinement finds c
    CohesiveState total;
    double        c = 0, g = 0;
    // The root of G(p) = g_{mesh(p)}(p) (header): the first step is the tangent step of g on the first refined mesh
    // (or its root of g), then secants through the last two points (the mesh's own root is off by its resolution away
    // from p).
    double p_previous = std::numeric_limits<double>::quiet_NaN(), g_previous = 0;
    CohesiveState previous; // the state at p_previous
    double        root_offset = 0; // |c - p| of the last mesh whose root was searched
    // The secant step through the last two points (NaN when there is none, or it leaves the distance of the last
    // two points and of the last mesh root from its point).
    const auto secant_step = [&](const double g_now) {
      if (std::isnan(p_previous) || g_now == g_previous)
        return std::numeric_limits<double>::quiet_NaN();
      const double secant = hint - g_now * (hint - p_previous) / (g_now - g_previous);
      const double span   = 2 * std::max(std::abs(hint - p_previous), root_offset);
      return (std::isfinite(secant) && secant > a && std::abs(secant - hint) <= span) ?
               secant :
               std::numeric_limits<double>::quiet_NaN();
    };
    // Accepted: |G| within the tolerance, a first refined mesh alone only within 1 % of it.
    const auto accepted = [&](const double g_now) {
      return std::abs(g_now) <= parameters.zone_tolerance &&
             (!std::isnan(p_previous) || std::abs(g_now) <= 1e-2 * parameters.zone_tolerance);
    };
    // A refined mesh searches its own root (or tangent step) when it is the first one, or when its G is neither
    // accepted nor followed by a secant step; otherwise it only evaluates G at its point.
    const auto root_wanted = [&](const double g_now) {
      return std::isnan(p_previous) || (!accepted(g_now) && std::isnan(secant_step(g_now)));
    };
    for (unsigned int pass = 0; pass < 16; ++pass)
      {
        CohesiveState s = solve_on_mesh(a, hint, refined, root_wanted, c, g);
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
        if (parameters.zone_refinements == 0)
          return solved.emplace(a, total).first->second;
        // The root between the last two points: d, F and c interpolated linearly in G (their FE states are on two
        // meshes), so that F(a) is smooth where its minimum is flat (taking the state at p itself moves a_c there by
        // more than radius_tolerance); a first refined mesh stands alone only within 1 % of the tolerance.
        if (refined && accepted(g))
          {
            const double t = std::isnan(p_previous) ? 0 : g / (g - g_previous);
            if (std::isfinite(t) && std::abs(t) <= 1)
              {
                total.zone_radius += t * (previous.zone_radius - total.zone_radius);
                total.depth += t * (previous.depth - total.depth);
                total.force += t * (previous.force - total.force);
              }
            return solved.emplace(a, total).first->second;
          }
        if (!std::isnan(c))
          root_offset = std::abs(c - hint);
        double next = c;
        if (refined)
          {
            const double secant = secant_step(g);
            if (!std::isnan(secant))
              next = secant;
          }
        if (refined)
          p_previous = hint, g_previous = g, previous = s;
        refined = true;
        hint    = next;
      }
    std::ostringstream msg;
    msg << "CohesiveContact: the end of the cohesive zone did not settle at a = " << a << " after " << total.meshes
        << " meshes (last c = " << c << ", h(c) / h_0 - 1 = " << g << ")";
    throw std::runtime_error(msg.str());
  }



  CohesiveState CohesiveContact::parabolic_vertex(const AdhesionControl control, const CohesiveState &best)
  {
    // The solved states next to `best` on each side in s = ln a (Brent's last bracket, or states solved before).
    const auto at = solved.find(best.radius);
    if (at == solved.end() || at == solved.begin() || std::next(at) == solved.end())
      return best;
    const auto objective = [control](const CohesiveState &st) {
      return control == AdhesionControl::force ? st.force : st.depth;
    };
    const auto  &left = std::prev(at)->second, &right = std::next(at)->second;
    const double s0 = std::log(left.radius), s1 = std::log(best.radius), s2 = std::log(right.radius);
    const double v0 = objective(left), v1 = objective(best), v2 = objective(right);
    // The vertex of the parabola through the three (successive parabolic interpolation; Press, Teukolsky, Vetterling
    // and Flannery, Numerical Recipes, 3rd ed. (2007), eq. 10.3.1).
    const double p = (s1 - s0) * (v1 - v2), q = (s1 - s2) * (v1 - v0);
    const double denominator = 2 * (p - q);
    if (!(v1 <= v0 && v1 <= v2) || !(std::abs(denominator) > 0))
      return best;
    const double vertex = s1 - ((s1 - s0) * p - (s1 - s2) * q) / denominator;
    // Only inside the bracket and not within the search's resolution of `best` (critical_state's radius rule).
    if (!(vertex > s0 && vertex < s2) || std::abs(vertex - s1) <= 0.1 * parameters.radius_tolerance)
      return best;
    try
      {
        const CohesiveState &candidate = state(std::exp(vertex));
        // Brent's result stands where the vertex's state is no lower or fails its checks.
        return objective(candidate) <= v1 && (candidate.consistent || !best.consistent) ? candidate : best;
      }
    catch (const std::runtime_error &)
      {
        return best; // no zone end found at the vertex: Brent's result stands
      }
  }



  CohesiveCriticalState CohesiveContact::critical_state(const AdhesionControl control, const double a0)
  {
    if (!(a0 > 0) || !std::isfinite(a0))
      fail("CohesiveContact::critical_state", "a0", a0, "(0, inf)");
    const auto         start  = std::chrono::steady_clock::now();
    const std::size_t  before = solved.size();
    CohesiveCriticalState result;
    // The radius of s = ln a: the nearest solved one when it lies within a tenth of the search's resolution (Brent
    // begins at the bracket's right end, already solved, and after a walk to the left its first golden-section
    // step falls on the walk's middle, solved too): moving s by less than radius_tolerance / 10 changes the value
    // by less than what the search resolves near its minimum.
    const auto radius = [&](const double s) {
      const double a = std::exp(s);
      double       nearest = a, distance = 0.1 * parameters.radius_tolerance;
      const auto   above   = solved.lower_bound(a);
      const auto   consider = [&](const double r) {
        if (std::abs(std::log(r) - s) <= distance)
          nearest = r, distance = std::abs(std::log(r) - s);
      };
      if (above != solved.end())
        consider(above->first);
      if (above != solved.begin())
        consider(std::prev(above)->first);
      return nearest;
    };
    const auto value = [&](const double s) {
      if (solved.size() - before >= parameters.max_states)
        {
          std::ostringstream msg;
          msg << "CohesiveContact::critical_state: no minimum after " << parameters.max_states << " states";
          throw std::runtime_error(msg.str());
        }
      const CohesiveState &st = state(radius(s));
      return control == AdhesionControl::force ? st.force : st.depth;
    };
    const auto vanished = [&](const double s) {
      try
        {
          const CohesiveState &st = state(radius(s));
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
    // The right end only when the walk does not go left at once (the pull-off radius is mostly below the JKR start).
    double       v_mid = value(mid), v_left = value(left);
    double       v_right = v_left < v_mid ? std::numeric_limits<double>::infinity() : value(right);
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
                result.state                = state(radius(mid));
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
        // Brent's tolerance is relative to |x|: in x = ln a + shift, |x| is about 1 over the bracket, so that the
        // tolerance is radius_tolerance in ln a whatever the unit of length (in x = ln a it was |ln a| times
        // larger, about 12 times for a ~ 5e-6 m, and F_c lost accuracy against the MDR's).
        const double   shift      = 1 - 0.5 * (left + right);
        const int      bits       = static_cast<int>(std::ceil(-std::log2(parameters.radius_tolerance))) + 1;
        std::uintmax_t iterations = parameters.max_states;
        const auto     minimum    = boost::math::tools::brent_find_minima(
          [&](const double x) { return value(x - shift); }, left + shift, right + shift, bits, iterations);
        result.state = state(radius(minimum.first - shift));
        result.state = parabolic_vertex(control, result.state);
      }
    result.states_solved = solved.size() - before;
    for (const auto &[r, st] : solved)
      result.max_dofs = std::max(result.max_dofs, st.n_dofs);
    result.seconds = seconds_since(start);
    return result;
  }
} // namespace gradcontact::fem
