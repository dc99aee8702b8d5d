// The accuracy contract of the axisymmetric model: an FE answer at an asked relative tolerance, with an error
// estimate that does not need the exact solution, or a refusal that names what stops it.
//
// The ladder: a sequence of discretisations whose answers converge to the exact one, solved from the cheapest up.
// Two kinds (contract_ladder picks one by the modulus):
// - hp, where the modulus has no jumps (E ~ z^s at the surface, any s): level l raises the degree by one (2, 3, ...,
//   max_contract_degree) and adds hp_edge_step geometric refinements at the contact edge (hp_axis_step at the axis
//   where a cone's tip is graded), and the surface map's floor follows the edge cell. Every length the solution is
//   singular over shrinks with the degree, the geometric mesh of hp-FEM (Babuska & Guo, SIAM J. Numer. Anal. 25
//   (1988) 837; Schwab, p- and hp-Finite Element Methods, 1998, ch. 4): the error falls exponentially, by a ratio
//   of a tenth or less per level, where uniform refinement at a fixed degree stalls at the edge singularity's
//   algebraic rate (the flat punch's force error ~ h^(1+k)). On a stiff surface (s < 0) the highest levels carry
//   the rounding of the stiff cells' entries, which the levels cannot show: the rounding probe below measures it.
// - uniform, on moduli with jumps (whose interfaces the geometric mesh does not follow): level l is the mesh of
//   contract_settings refined uniformly l times (every cell halved), at one degree.
// Either way the change of a quantity from level to level, d_l = q_l - q_{l-1}, falls like rho^l once the levels
// resolve the solution. Then the error of q_n is the geometric tail (Richardson extrapolation with the observed
// ratio; Richardson, Phil. Trans. R. Soc. A 226 (1927) 299; Roache, Verification and Validation in Computational
// Science and Engineering, 1998, ch. 5):
//   |q_n - q_inf| = |d_n| rho / (1 - rho).
// With two levels rho is the assumed ratio (of the ladder and the degree, and 2^-(1 + s) on a stiff surface
// E ~ z^s, s < 0), and the uniform ladder's estimate is doubled (two_level_safety); from three on it is observed,
// |d_n| / |d_{n-1}|, kept within [assumed, ratio_limit], at least oscillation_ratio when the two changes have
// opposite signs, and applied to max(|d_n|, assumed^2 |d_{n-1}|): an accidental near-zero d_n (two levels on
// opposite sides of the limit) does not pass for convergence. The hp ladder's estimates always take three levels
// (its first two are cheap). The ladder stops at the first level whose estimates are
// all within the tolerance, or refuses when the next level would exceed the DoF budget, or when the quantities stop
// converging (observed ratio at ratio_limit or above; on the hp ladder on two levels in a row), or when the levels the observed ratios still need would exceed
// the budget (so that a refusal does not cost the largest solves), or when a level's solve is unreliable. On a
// stiff surface the last level is probed for rounding (rounding_probe_factor): its change joins every estimate, and a
// met ladder is judged once more and refused ("rounding") when it no longer holds.
//
// What is estimated: the force, the depth (under contact-radius control) or the contact radius (under depth or
// force control), p(r) at the asked radii relative to the largest |p| sampled (on three levels at least), w(r)
// relative to |w(r)|, and the recovered stress components at the asked points (fem/elasticity/stress_recovery.h)
// relative to the largest component sampled (on three levels at least).
#ifndef GRADCONTACT_FEM_ACCURACY_H
#define GRADCONTACT_FEM_ACCURACY_H

#include <fem/bodies/axisymmetric_solver.h>

#include <deal.II/base/types.h>

#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// What a ladder may spend.
  struct AccuracyBudget
  {
    /// The largest mesh a ladder solves (the axisymmetric solver's direct factorisation: memory grows a little faster
    /// than the DoFs).
    dealii::types::global_dof_index max_dofs = 1'200'000;
    /// Levels 0 .. max_levels - 1 at most (>= 2) of the uniform ladder; the hp ladder ends at max_contract_degree.
    unsigned int max_levels = 4;
    /// The memory the factorisations and matrices of the levels a ContractSolver keeps may hold together (bytes). A
    /// level's is predicted from the growth over the level before (high degrees fill the factor faster than the DoFs
    /// grow); the levels below give way to it (they only save later loads their set-up), so that only a level that
    /// does not fit alone is refused.
    double max_factor_bytes = 8e9;

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  /// A value and the estimate of its error.
  struct Estimated
  {
    double value = 0;
    double error = std::numeric_limits<double>::infinity(); ///< estimated |value - exact| (absolute)
    double scale = 0;    ///< what the relative error divides by: |value|, or max |p| for a pressure
    double ratio = 0;    ///< the convergence ratio used (assumed or observed)
    double rounding = 0; ///< the rounding probe's change, whose rounding_safety multiple `error` includes (absolute)
    std::vector<double> levels; ///< the value on every level solved (the last is `value`)

    double relative() const { return scale > 0 ? error / scale : error; }
  };

  struct ContractResult
  {
    Result result;    ///< the finest level's run: its values are the answer
    Estimated force, depth, contact_radius;
    std::vector<Estimated> pressure, displacement; ///< at the OutputRequest's radii, in its order
    /// (sigma_rr, sigma_zz, sigma_tt, sigma_rz) at the OutputRequest's stress points, in its order
    std::vector<std::array<Estimated, 4>> stress;
    double tolerance = 0;                          ///< the relative tolerance asked
    bool   met       = false;                      ///< every estimate within the tolerance
    /// Empty when met; else what stopped the ladder: "DoF budget: ...", "no convergence: ...", "unreliable solve: ...".
    std::string  limit;
    unsigned int degree = 0;                                ///< of the finest level solved (of every level on the uniform ladder)
    std::vector<dealii::types::global_dof_index> level_dofs; ///< DoFs of every level solved
    double seconds = 0; ///< wall time of this run (with the set-up of the levels it made)

    /// The largest relative estimate of the quantities the contract covers.
    double worst_relative() const;
  };

  /// The two ladders of the header.
  enum class Ladder
  {
    uniform,
    hp
  };

  /// hp where the modulus has no jumps, else uniform.
  Ladder contract_ladder(const Material &material);

  /// The hp ladder: its first degree (at least 3 in the mixed formulation), its last, and what every level adds.
  inline constexpr unsigned int hp_first_degree = 2, max_contract_degree = 8;
  inline constexpr unsigned int hp_edge_refinements = 2; ///< at (a, 0) on level 0
  inline constexpr unsigned int hp_edge_step = 2, hp_axis_step = 2;

  /// The settings of level `level` of `ladder` above level 0 `base` (the header).
  Settings ladder_settings(const Settings &base, Ladder ladder, unsigned int level);

  /// The settings of level 0 for a relative tolerance: the recommended mesh (recommended_settings) with the degree of
  /// the ladder (hp: hp_first_degree and hp_edge_refinements; uniform: contract_degree; at least 3 in the mixed
  /// formulation), the surface map where the modulus vanishes at the surface
  /// (use_surface_map; the k > 0 layer u_z ~ z^(1-k) then needs no halvings that would keep the ratio at 2^-(1-k)),
  /// else the condensed far field for a power law of depth (no truncation error; L / a = far_field_size, at least
  /// 1.5 times the largest displacement radius) in the displacement formulation, and the formulation `automatic`
  /// (mixed from nu = 0.45 on).
  Settings contract_settings(double contact_radius, const Material &material, double tolerance,
                             double largest_displacement_radius = 0);

  /// The degree of the uniform ladder for a relative tolerance (see contract_settings), on a modulus with surface
  /// exponent s (E ~ z^s): at least 3 on a stiff surface (stiff_degree_limit <= s < 0), where degree 2 does not
  /// converge a pressure sample.
  unsigned int contract_degree(double tolerance, double surface_exponent = 0);
  /// Below this surface exponent the uniform ladder keeps the tolerance's degree (contract_degree).
  inline constexpr double stiff_degree_limit = -0.8;

  /// The estimate of the error of values.back(), values[l] the quantity on level l (the file's header).
  /// `assumed_ratio`: the ratio with two levels and the floor of the observed one; scale: see Estimated.
  /// `accident`: a change below accident |d_(n-1)| counts as accident |d_(n-1)| (default, below 0: assumed^2).
  Estimated estimate(const std::vector<double> &values, double assumed_ratio, double scale, double accident = -1);

  /// The ratio a degree's uniform ladder is assumed to converge with (per refinement) before it is observed, on a
  /// modulus with surface exponent s (E ~ z^s; slower on a stiff surface, s < 0).
  double assumed_ratio(unsigned int degree, double surface_exponent = 0);

  /// The same for the hp ladder (per level), the floor of its observed ratios, on a modulus with surface exponent s.
  /// Its convergence is exponential with ratios that grow from level to level (a few hundredths on its first levels,
  /// a third and more on its last ones), so a ratio observed on two changes underestimates the next: the floor is
  /// a third, and a half on the thin soft layer of s >= 0.9, whose levels approach their limit the least regularly.
  double hp_assumed_ratio(double surface_exponent);
  /// The hp ladder's accident factor (estimate), smaller than its floor squared: a twentyfold fall from one level to
  /// the next is real there.
  inline constexpr double hp_accident = 0.04;
  /// The hp ladder's floor for a recovered pressure sample (LadderValue::local): the L2 recovery spreads the edge
  /// singularity's error into the contact, and a sample's changes fall less regularly than an integral's.
  inline constexpr double hp_local_floor = 0.5;

  /// The rounding probe. The stored matrix is rounded entry by entry, and on a stiff surface (s < 0) the small stiff
  /// cells at the contact edge have entries of order E(h) p^4, so that the rounding of the entries reaches an
  /// indenter's force and depth, and the pressures, far above the machine epsilon (DirectSystem::set_translation
  /// keeps the rounding of the row sums out, not that of the entries). The ladder cannot see it: from level to level it stays about the same,
  /// and the levels then look converged. So a ladder on a stiff surface solves its last level once more with
  /// every modulus times this factor and the loads with it (ScaledModulus): in exact arithmetic the displacements
  /// are the same and forces, pressures and stresses scale by the factor, while every entry is rounded anew. The
  /// change that remains, with the factor divided out, is a sample of the rounding's effect (the difference of two
  /// roundings); rounding_safety times it joins every estimate, of a refused ladder too (unless the probe's
  /// factorisation would exceed AccuracyBudget::max_factor_bytes: then a met ladder is refused, a refused one keeps
  /// its estimates without it).
  inline constexpr double rounding_probe_factor = 1.3;
  inline constexpr double rounding_safety = 2;
  /// Whether ContractSolver probes the rounding of the last level for this modulus (a stiff surface, s < 0).
  bool probes_rounding(const Material &material);

  /// The factor on an estimate of the uniform ladder from two levels (ratio assumed, not observed; Roache, Verification
  /// and Validation in Computational Science and Engineering, 1998, ch. 5: the grid convergence index's safety factor).
  inline constexpr double two_level_safety = 2;

  /// Observed ratios above this are no convergence: the estimate would be 4 |d_n| or more.
  inline constexpr double ratio_limit = 0.8;

  /// The ratio used at least when the last two changes have opposite signs (the levels oscillate about the limit).
  inline constexpr double oscillation_ratio = 0.5;

  /// Refinement cycles toward the axis for a tip f ~ r^n, n < 2 (the cone's p ~ arccosh(a/r), a cusp of the power
  /// law): MeshParameters::axis_refinements.
  inline constexpr unsigned int axis_refinement_cycles = 12;

  /// Grades `settings` toward the axis when `load` is an indenter whose tip exponent is below 2 (no change else).
  void grade_axis(Settings &settings, const LoadCase &load);

  /// One quantity of one level, as the contract judges it.
  struct LadderValue
  {
    std::string name;
    double      value = 0;
    double      scale = 0;     ///< what its relative error divides by (Estimated::scale)
    bool        local = false; ///< a recovered pressure sample: its estimate takes three levels on either ladder
    double      reach = 1;     ///< r / a of a displacement sample (its share of a clamped far field's truncation)
    bool        scales = false; ///< a force, pressure or stress: times the factor of the rounding probe
  };

  /// The contract's record of quantities solved level by level on a ladder (ladder_settings of a level-0 `base`):
  /// their histories, estimates, and the verdict after every level. ContractSolver keeps one per load; any FE
  /// procedure that can be run on the ladder's settings (an adhesive critical search, for example) can keep its own.
  class LadderRecord
  {
  public:
    /// Throws std::invalid_argument on a bad tolerance or budget (naming it).
    LadderRecord(const Material &material, const Settings &base, double tolerance, const AccuracyBudget &budget = {});

    /// Records level levels(): the same quantities in the same order as on the levels before, and the level's
    /// largest DoF count. Returns true when the ladder stops here (met(), or limit() names why not).
    bool add(const std::vector<LadderValue> &values, dealii::types::global_dof_index dofs);
    /// Records the rounding probe of the last level: the same quantities solved with every modulus and load times
    /// `factor` (rounding_probe_factor). A quantity's rounding is its change with the factor divided out (where it
    /// scales), and its estimate adds rounding_safety times that; a met() ladder is judged again, and when it no
    /// longer holds, limit() names the rounding.
    void add_rounding(const std::vector<LadderValue> &probe, double factor);
    /// Records that level levels() could not be solved (an unreliable solve, a failed search): the ladder stops.
    void fail(const std::string &why);
    /// Before solving level levels(): whether it may be solved (the ladder's last level, AccuracyBudget::max_levels,
    /// the DoFs predicted from the growth of the last level). When not, limit() names why and the ladder stops.
    bool next_level_allowed();

    bool        met() const { return is_met; }
    std::string limit() const; ///< empty when met; else the limit and the quantity furthest from the tolerance
    unsigned int levels() const { return static_cast<unsigned>(dofs.size()); }
    unsigned int degree() const; ///< of the last level recorded (of every level on the uniform ladder)
    const std::vector<dealii::types::global_dof_index> &level_dofs() const { return dofs; }
    double       tolerance() const { return asked; }
    Ladder       kind() const { return ladder; }
    /// The estimate of quantity i (in the order of add) on the last level recorded: the ladder's tail, plus the
    /// truncation of a clamped far field, which no level reduces: (a / L)^(1 + s) relative, (r / L)^(1 + s) for w(r),
    /// s the exponent deep below.
    Estimated estimate(std::size_t i) const;
    /// The estimate of values `values` of one quantity on this ladder (`local`: a recovered pressure sample).
    Estimated estimate(const std::vector<double> &values, double scale, bool local = false) const;

  private:
    Ladder                           ladder;
    unsigned int                     first_degree;
    double                           surface_exponent, asked;
    double                           truncation, deep_exponent; ///< of a clamped far field (0 when condensed)
    AccuracyBudget                   budget;
    std::vector<std::vector<double>> history; ///< history[i][l]: quantity i on level l
    std::vector<LadderValue>         last;
    std::vector<double>              rounding; ///< per quantity, of the last level, when probed (absolute)

    /// Whether quantity i's change stopped falling on the level before the last too (always true on the uniform
    /// ladder, whose one stalled change is its verdict).
    bool stalled_before(std::size_t i) const;
    std::vector<dealii::types::global_dof_index> dofs;
    bool                             is_met = false;
    std::string                      stop;
  };

  /// Solves `load` on the ladder until the contract holds or a limit is reached. The solvers of the levels are kept,
  /// so that further loads (other radii, other depths) reuse their factorisations.
  class ContractSolver
  {
  public:
    /// `base`: level 0 (contract_settings, or the caller's); its global_refinements is the first level.
    ContractSolver(const Material &material, const Settings &base, double tolerance, const AccuracyBudget &budget = {});
    ~ContractSolver();

    /// Throws std::invalid_argument on a bad tolerance or budget (naming it); a failed solve is a refusal in the
    /// result, not an exception.
    ContractResult run(const LoadCase &load, const OutputRequest &outputs = {});

    double tolerance() const { return asked; }

  private:
    /// The solver of level l, made on first use (again after make_room dropped it); null when its size exceeds the
    /// budget (`limit` says so).
    AxisymmetricSolver *level(unsigned int l, std::string &limit);
    /// The bytes the solvers and the probe hold (DirectSystem::factor_bytes); records every level's in level_bytes.
    double held_bytes();
    /// Whether `bytes` more fit into AccuracyBudget::max_factor_bytes, after dropping the probe and every level's
    /// solver but level `keep`'s when they do not fit beside them.
    bool make_room(double bytes, unsigned int keep);
    /// The rounding probe of the record's last level (the header of rounding_probe_factor): solves `load` on the
    /// level's mesh with the modulus and the load scaled, and gives the record its quantities.
    void probe_rounding(const LoadCase &load, const OutputRequest &outputs, LadderRecord &record);

    Material                                         material;
    Settings                                         base;
    Ladder                                           ladder;
    double                                           asked;
    AccuracyBudget                                   budget;
    std::vector<std::unique_ptr<AxisymmetricSolver>> solvers; ///< per level; null where dropped (make_room)
    std::vector<double>                              level_bytes; ///< per level, once known (held_bytes)
    std::unique_ptr<AxisymmetricSolver>              probe; ///< the rounding probe's solver, of level probe_level
    unsigned int                                     probe_level = 0;
  };
} // namespace gradcontact::fem

#endif
