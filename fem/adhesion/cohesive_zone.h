// Adhesion with a finite range: the Dugdale cohesive zone on the graded half-space, without the JKR
// assumption of the chapter (9.45-9.74). Nothing here comes from the MDR or a closed form.
//
// The law (Dugdale; Maugis, J. Colloid Interface Sci. 150 (1992) 243-269). Between the rigid axisymmetric
// indenter z = d - f(r) and the surface z = w(r), the gap is h(r) = f(r) - d + w(r). Where 0 < h < h_0 the
// surfaces attract with the constant tension sigma_0, beyond h_0 not at all; the work of adhesion is
// dgamma = sigma_0 h_0. Where h = 0 they touch (r <= a). For a profile that opens monotonically the state
// is a disc of contact r <= a and an annular cohesive zone a < r < c.
//
// The FE state of contact radius a (the mesh's contact radius, a node). With the tension sigma_0 on the
// whole disc r <= c (on the contact it only lowers the contact pressure, which becomes p + sigma_0), the
// radius-controlled state of AxisymmetricSolver (LoadType::indenter with LoadCase::cohesion) has the depth
// at which the contact pressure p + sigma_0 vanishes at the edge node: the total traction is continuous at
// a, the Maugis condition that the stress is finite there. The zone's end c is the root of
//   g(c) = h(c) - h_0 = f(c) - d(c) + w(c; c) - h_0,
// g(a) = -h_0 < 0; c is not a node: the tension is integrated exactly on the faces split at c
// (fem/elasticity/surface_trace.h). Each evaluation of g is one back-substitution with the factorisation of the mesh (the
// solver keeps the indenter's unit-depth and profile solutions; the tension's is the only new one). The force is that
// of the contact pressure minus pi c^2 sigma_0.
//
// The zone end. At the traction jump the gap opens like sign(r - c) |r - c|^{1-k} (k = 0: (r - c) ln|r - c|):
// on the soft surface of k > 0 the FE gap at the point c converges only like (cell width)^{1-k}, and a zone
// much thinner than the cells at the contact edge (k = 0.5, lambda = 10: c - a = 2e-5 a against cells of
// 1e-5 a) turns that into errors in F far above the zone tolerance. So h(c) is the mean gap over the window
// c +- `gap_window` (c - a), where the odd term cancels, and each refined mesh is refined toward one point p
// (SurfaceRefinement: `zone_cells` cells across its window, then `zone_refinements` levels toward p) and g is
// taken at p, where it is accurate: the zone end is the root of G(p) = g_{mesh(p)}(p), found from a first mesh
// without refinement (its root of g) or the zone ratio predicted from the two nearest solved states, then one
// tangent step of g on the first refined mesh (g at p and at p + gap_window (p - a); the mesh's root of g when
// that step leaves p +- (p - a) / 2), then secants through G, until |G(p)| <= `zone_tolerance` h_0 (each later
// mesh costs one solve of g). The force then does not depend on the window width or the cells across it to
// within the test's bound, while one mesh per p without the mean moves F by far more (test_cohesive.cc, "a
// cohesive zone thinner than the edge cells ..."; `cohesive_study` varies both with gap_window= and
// zone_cells=).
//
// The path. The states are parametrised by a (Maugis' path following: F(a) and d(a) are single-valued along
// it, through the force- and displacement-controlled instabilities, where F(d) is not). Pull-off under force
// control is the minimum of F(a), under displacement control the minimum of d(a): a Brent search in ln a on a
// bracket found by stepping from a0 (each point its own meshes), then one state at the vertex of the parabola
// through Brent's best state and its solved neighbours (the state's other quantities, a_c and d_c or F_c, are first
// order in the radius). A walk that reaches a = a_min (the contact
// vanishing, c / a > `max_zone_ratio`) stops: under force control the minimum is then at the vanishing contact
// (DMT-like, small Tabor parameter), under displacement control there is no interior minimum (the contact
// shrinks to nothing without a jump); the state says so (`at_vanishing_contact`).
//
// Checks of every state (`consistent`, `message`): the contact pressure is compressive (AxisymmetricSolver's
// check), 0 <= h <= h_0 inside the zone and h >= h_0 beyond it at sample radii.
#ifndef GRADCONTACT_FEM_COHESIVE_ZONE_H
#define GRADCONTACT_FEM_COHESIVE_ZONE_H

#include <fem/adhesion/adhesion.h>
#include <fem/bodies/axisymmetric_solver.h>

#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// The Dugdale law: the tension `strength` (sigma_0) up to the separation work / strength (h_0).
  struct DugdaleLaw
  {
    double strength = 0; ///< sigma_0 > 0
    double work     = 0; ///< dgamma > 0
    double range() const { return work / strength; }
    void   validate() const;
  };

  struct CohesiveParameters
  {
    unsigned int zone_refinements = 8;    ///< SurfaceRefinement levels toward c
    double       gap_window       = 1e-3; ///< h(c) is the mean gap over c +- gap_window (c - a)
    unsigned int zone_cells       = 32;   ///< surface cells across that window (at least)
    double       zone_tolerance   = 1e-4; ///< accepted |h(c) / h_0 - 1| on the mesh refined toward c
    double       near_field_margin = 2.0; ///< the near field reaches at least this times c
    /// Brent's resolution of the critical radius in ln a; the state at the parabola's vertex through its best
    /// state and that state's solved neighbours follows (parabolic_vertex). a_c itself is no better than the FE's
    /// flat minimum allows: near the minimum F and d change to second order in a, so a_c is resolved only to
    /// the square root of their error. With the vertex, 1e-2 gives F_c, d_c and a_c as close to the MDR as 1e-3
    /// does, with fewer states.
    double       radius_tolerance = 1e-2;
    double       stencil_ratio    = 1.25; ///< first step of the bracketing walk (then growing by the golden ratio)
    double       max_zone_ratio   = 200;  ///< c / a beyond which the contact counts as vanished
    unsigned int max_states       = 80;   ///< FE states per critical search
    void         validate() const;
  };

  struct CohesiveState
  {
    double       radius = 0, zone_radius = 0, depth = 0, force = 0; ///< a, c, d, F (tensile negative)
    unsigned int meshes = 0;        ///< meshes built for this state (the zone refinement passes)
    unsigned int zone_solves = 0;   ///< evaluations of g(c), all meshes
    unsigned int n_dofs = 0;        ///< of the last mesh
    double       seconds = 0;
    bool         consistent = true; ///< the checks of the header
    std::string  message;
  };

  struct CohesiveCriticalState
  {
    CohesiveState state;
    /// The walk reached a_min (header); `state` is the smallest-radius state solved before it.
    bool          at_vanishing_contact = false;
    unsigned int  states_solved = 0; ///< FE states of this search
    unsigned int  max_dofs = 0;
    double        seconds = 0;
  };

  class CohesiveContact
  {
  public:
    using SettingsFunction = AdhesiveContact::SettingsFunction;

    /// `settings(a)`: the mesh and discretisation of contact radius a (its near field is widened to reach c).
    CohesiveContact(const Material &material, const Profile &profile, const DugdaleLaw &law, SettingsFunction settings,
                    const CohesiveParameters &parameters = {});

    /// The state of contact radius a > 0 (solved on first use, cached). std::runtime_error when no zone end is
    /// found inside a near field of max_zone_ratio a.
    const CohesiveState &state(double a);

    /// Pull-off: the minimum of F(a) (force) or d(a) (displacement), searched from a0.
    CohesiveCriticalState critical_state(AdhesionControl control, double a0);

    /// The states solved so far, by a.
    const std::map<double, CohesiveState> &states() const { return solved; }

  private:
    /// One mesh, refined toward c_hint when `refined`: c_found, the root of g (searched from c_hint) on unrefined
    /// meshes, on refined ones when root_wanted(g(c_hint) / h_0) the tangent step from c_hint (the root where that
    /// step fails), else NaN; g(c_hint) / h_0 (NaN when not evaluated); the state at c_hint (refined) or at c_found
    /// (not refined).
    CohesiveState solve_on_mesh(double a, double c_hint, bool refined, const std::function<bool(double)> &root_wanted,
                                double &c_found, double &g_hint);
    /// The gap checks of the header on the samples of `last` (the state's own solve), its time since `start`.
    CohesiveState finish_state(CohesiveState &state, const Result &last, double a,
                               std::chrono::steady_clock::time_point start) const;
    double        predicted_zone_ratio(double a) const;
    /// The state at the vertex of the parabola in ln a through `best` (the smallest objective solved) and its
    /// solved neighbours, when that vertex lies between them and its objective is not larger; else `best`.
    /// Brent stops within radius_tolerance of the minimiser: F_c and d_c (displacement control) are then good to
    /// its square, but the other quantities of the state (a_c, and d_c under force control) only to its first
    /// power; at the vertex they are good to its square as well.
    CohesiveState parabolic_vertex(AdhesionControl control, const CohesiveState &best);

    const Material                   material;
    const Profile                    profile;
    const DugdaleLaw                 law;
    const SettingsFunction           settings;
    const CohesiveParameters         parameters;
    std::map<double, CohesiveState>  solved;
  };
} // namespace gradcontact::fem

#endif
