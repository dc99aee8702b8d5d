// The vocabulary every FE model of gradcontact shares: how the graded half-space is discretised
// (element degree, quadrature, formulation), a mesh and a discretisation chosen together, the timings
// a result reports, and the checks of a solved state with their tolerances.
//
// Nothing here belongs to one solver: the axisymmetric (Fourier mode 0), the Fourier mode-1 and the
// distributed solvers, and the validation models built on them, include this header, not each other.
#ifndef GRADCONTACT_FEM_DISCRETIZATION_H
#define GRADCONTACT_FEM_DISCRETIZATION_H

#include <fem/grid/mesh.h>
#include <fem/modulus/modulus.h>
#include <fem/modulus/surface_map.h>

#include <deal.II/base/types.h>

#include <chrono>
#include <functional>
#include <string>

namespace gradcontact::fem
{
  /// Which unknowns a solver uses. The mixed one (Taylor-Hood: displacement in FE_Q(p), the pressure
  /// q = lambda div u in FE_Q(p - 1)) does not lock as nu -> 1/2 (fem/elasticity/graded_elasticity.h).
  enum class Formulation
  {
    displacement, ///< displacement only; -1 < nu < 1/2; locks as nu -> 1/2
    mixed,        ///< displacement and q = lambda div u; 0 < nu <= 1/2, degree >= 2
    automatic     ///< mixed for nu >= automatic_mixed_threshold, else displacement
  };

  /// `automatic` switches to the mixed formulation from this nu on: at nu = 0.45 (k = 0, degree 3) the
  /// two formulations are about equally accurate (the mixed one better in the flat-punch force, the
  /// displacement one in the paraboloid's p(r)); closer to 1/2 the displacement formulation locks and the
  /// mixed one is better in both (`fem_study formulation=mixed` against `formulation=displacement`).
  inline constexpr double automatic_mixed_threshold = 0.45;

  /// How the meridian model ends at the truncation boundary max(r, z) = L.
  enum class FarField
  {
    clamped,  ///< u = 0 there: the truncation error falls like (a/L)^{1+s}
    condensed ///< the infinitely many rings beyond L condensed onto it (fem/elasticity/far_field.h), serial meridian model
  };

  struct DiscretizationParameters
  {
    unsigned int degree = 3;                     ///< FE_Q degree, 1..4 (of the displacement; 2..4 when mixed)
    unsigned int extra_quadrature_points = 2;    ///< points per direction: degree + this
    unsigned int discontinuity_subdivisions = 8; ///< QIterated copies in cells crossing a jump of E
    Formulation  formulation = Formulation::displacement;
    /// The singular depth map of the surface (fem/modulus/surface_map.h), off by default; with it a modulus
    /// E ~ z^s, 0 < s < 1, needs no z-halvings of the surface cells.
    SurfaceMapParameters surface_map;
    /// `condensed` needs a modulus that is a power law of depth at the size of the last rings, the displacement
    /// formulation and two rings at least; the axisymmetric (mode 0) and mode-1 solvers only.
    FarField far_field = FarField::clamped;

    /// Throws std::invalid_argument naming the entry, its value and the valid range.
    void validate() const;
  };

  /// The formulation used for Poisson ratio nu: displacement or mixed (never automatic). Throws
  /// std::invalid_argument when the result is mixed and the degree is 1 (FE_Q(0) does not exist).
  Formulation resolve_formulation(const DiscretizationParameters &discretization, double nu);

  /// For the solvers without the mixed formulation (distributed, Fourier mode 1): throws
  /// std::invalid_argument "<where>: not supported with the mixed formulation" when
  /// resolve_formulation gives mixed.
  void require_displacement_formulation(const DiscretizationParameters &discretization, double nu,
                                        const std::string &where);

  /// A mesh and a discretisation chosen together.
  struct Settings
  {
    MeshParameters           mesh;
    DiscretizationParameters discretization;
  };

  /// The cheapest settings found for a modulus E ~ z^s at the surface (s = surface_exponent: k for
  /// the power law, 0 for a layered or finite-surface modulus) and a wanted relative force error; their
  /// error and cost per degree are the work-precision table of `./vv bench`
  /// (reports/benchmarks/fe_work_precision.md), one setting at a time `build/cases/tools/studies/fem_study`.
  /// force_tolerance >= 2e-4 and -0.9 <= s <= 0.5: degree 2 on the mesh of degree 3 (checked for the power
  /// law only, at nu = 0.3). force_tolerance >= 1e-6: degree 3, h_edge = 1e-5 a, rings g = 1.15. Below:
  /// degree 4, h_edge = 1e-6 a, h_far = 4 a, g = 1.3 (for k > 0 the error is limited by the u_z ~ z^{1-k}
  /// surface layer unless use_surface_map), and z-halvings only under r <= a.
  Settings recommended_settings(double contact_radius, double surface_exponent, double force_tolerance);

  /// The same for a modulus field: the surface settings of its surface exponent, the far field of its deep
  /// exponent (the truncation error falls like (a/L)^(1 + s) with s the exponent far below the surface), and
  /// for a finite surface modulus E0 ((z + z0)/c0)^k the power law's mesh with surface cells of z0/4, for the
  /// error-function grading the homogeneous mesh with surface cells of w/4.
  Settings recommended_settings(double contact_radius, const ModulusField &modulus, double force_tolerance);

  /// Switches `settings` from z-halvings to the surface map (fem/modulus/surface_map.h) when `modulus` vanishes at the
  /// surface like z^s, 0 < s <= 0.95, and has no jumps, and widens L by SurfaceMap::far_field_contraction of the
  /// automatic (or already set) scale; returns whether it did. It pays for a contact edge at the mesh's
  /// contact radius: the map resolves the u_z ~ z^{1-k} layer with the cells the halvings would spend there,
  /// so the same error takes fewer DoFs, and near k = 1 the halvings lose the force where the map keeps it
  /// (`build/cases/tools/studies/fem_study load=punch k=0.5 map=auto` against `map=0`; test_surface_map.cc at k = 0.9).
  /// Where other surface features need cells finer than the distance to that edge (a cohesive zone's end,
  /// a stick radius, an edge found by a unilateral solve) the map squeezes them and the halvings are more
  /// accurate, and at degree 2 a mesh keeps more accuracy with the halvings.
  bool use_surface_map(Settings &settings, const ModulusField &modulus);
  /// Whether use_surface_map would switch a setting for `modulus`.
  bool surface_map_applies(const ModulusField &modulus);

  /// The mesh and discretisation at contact radius a (physical units): the searches over a (adhesion,
  /// cohesive zones, distributed depth/force control) solve on a mesh graded at each trial radius.
  using SettingsAtRadius = std::function<Settings(double contact_radius)>;

  /// L / a that use_condensed_far_field gives the mesh: the near field and rings out to where the
  /// surface displacement is sampled (w(r) is known for r <= L only).
  inline constexpr double condensed_far_field_size = 100.0;

  /// Whether E(10 z) = 10^s E(z) at every depth z = 1e-12 .. 1e6 (physical units) to 1e-12, s the surface
  /// exponent, without jumps: the far-field rings are then scaled copies of each other (fem/elasticity/far_field.h).
  bool power_law_of_depth(const ModulusField &modulus);

  /// Switches `settings` to the condensed far field (fem/elasticity/far_field.h, the exterior of max(r, z) = L condensed
  /// onto it, no truncation error) with L / a = `far_field_size`, when `material` has a power-law modulus
  /// (power_law_of_depth) and no surface map is on (the map is homogeneous only for L >> a); returns whether
  /// it did. Either formulation: the mixed one's pressure DoFs are scaled ring by ring (fem/elasticity/far_field.h). For
  /// the axisymmetric and mode-1 solvers on the meshes of fem/grid/mesh.h (the unilateral, distributed and 3D ones
  /// refuse it). Where k < 0 a clamped boundary's truncation (a / L)^(1 + k) needs L far beyond 1e16 a for
  /// tight tolerances; the condensed one has none.
  bool use_condensed_far_field(Settings &settings, const Material &material,
                               double far_field_size = condensed_far_field_size);

  /// For the solvers without the condensed far field: throws std::invalid_argument "<where>: ... far_field =
  /// condensed ..." when `discretization` asks for it (their L would truncate the half-space).
  void require_clamped_far_field(const DiscretizationParameters &discretization, const std::string &where);

  /// Wall-clock seconds of the phases of a solve.
  struct Timings
  {
    double mesh = 0, setup = 0, assemble = 0; ///< once per solver (copied into every result)
    double factorize = 0;                     ///< this run (0 if the factorisation was reused)
    double solve = 0, postprocess = 0;        ///< this run
  };

  /// Seconds since `start` (steady clock).
  inline double seconds_since(const std::chrono::steady_clock::time_point &start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// Relative tolerance of "this support point sits at r = a": support points are exact up to
  /// round-off.
  inline constexpr double node_tolerance = 1e-10;

  /// The energy check of a linear solve. At the discrete solution u.Au equals the work of the
  /// prescribed displacements and loads; a relative mismatch above this (or above the rounding of the two sums,
  /// check_energy) means the solver returned garbage (an ill-conditioned system).
  inline constexpr double energy_mismatch_tolerance = 1e-6;

  /// A contact state is inconsistent when a nodal contact force (relative to the largest) or a gap
  /// (relative to the depth) falls below -this. Not round-off: the nodal forces of Lagrange elements
  /// of degree >= 2 are not sign-definite where p vanishes like (a - r)^{(1+k)/2}, so consistent states
  /// dip slightly below zero, while a violated complete contact of the concave punch is O(1); the
  /// threshold lies between the two.
  inline constexpr double consistency_tolerance = 1e-3;

  /// The outcome of the energy check.
  struct EnergyCheck
  {
    double      mismatch = 0; ///< |energy - work| / |energy|
    bool        reliable = true;
    std::string message;      ///< empty when reliable
  };

  /// |energy - work| / |energy| against energy_mismatch_tolerance, or against the rounding of the two sums when that
  /// is larger: `magnitude` = |u|.|A||u| (DirectSystem::energy_magnitude; 0: not known). Both sums add products of
  /// A's entries with u's, so each is exact to about eps |u|.|A||u|; where thin stiff surface cells (k < 0) carry an
  /// almost rigid motion that is many orders above u.Au, and a correct solve shows a mismatch far above 1e-6. The
  /// message names the thinnest surface cell (the usual cause) and `details` (e.g. the linear residual of an
  /// iterative solve).
  EnergyCheck check_energy(double energy, double work, double min_surface_cell, const std::string &details = "",
                           double magnitude = 0);

  /// What every solver's run reports besides its physics (the base of Result, TangentialResult and
  /// DistributedResult): size, mesh, times and the energy check.
  struct RunReport
  {
    std::string message; ///< what failed, if anything
    /// |u.Au - work of the loads| / u.Au (times 2 pi or pi, as the solver's energy): a solver-garbage
    /// detector (ill-conditioning).
    double energy_mismatch = 0;
    bool   reliable        = true; ///< energy_mismatch small enough (else `message` says why)
    dealii::types::global_dof_index n_dofs  = 0; ///< all DoFs (displacement and, when mixed, pressure)
    unsigned int                    n_cells = 0; ///< active cells of the whole mesh
    MeshInfo                        mesh;
    /// The condensed far field (fem/elasticity/far_field.h): the measured stiffness ratio of consecutive rings, the last two
    /// rings' relative deviation from scaled copies, and the doublings; zeros when clamped.
    double       far_field_ring_scale      = 0;
    double       far_field_self_similarity = 0;
    unsigned int far_field_doublings       = 0;
    /// mesh, setup, assemble once per solver; factorize this run's (0 when reused), solve and postprocess
    /// this run's (the slowest process in parallel).
    Timings time;

    /// The solver's size, mesh and setup times at the start of a run.
    void start(const Timings &setup, dealii::types::global_dof_index dofs, unsigned int cells, const MeshInfo &info);
    /// Takes the outcome of the energy check (its message appended to `message`).
    void record(const EnergyCheck &check);
  };
} // namespace gradcontact::fem

#endif
