// gradcontact/cases: FE work-precision benchmarks and the FreeFem++ peer (`gradcontact bench --part
// fe|peer`).
//
// Scenes (both models, both references from analytic/normal.h, an independent path):
//   flat punch, depth d = 1e-3 a:        relative error of F against (9.16);
//   paraboloid R = 50 a, contact radius a: relative errors of F(a) and d(a) against the Hertz-type closed
//                                          forms; the scene's error is the larger of the two;
//   JKR paraboloid, dgamma = 0.05 J/m^2:  pull-off force (force control) against (9.56), analytic/adhesion.h;
//   tangential flat punch, delta = 1e-3 a: F_x of the Fourier-mode-1 model against the MDR K_T delta (9.78).
// E0 = 2 GPa, c0 = 3 a, a = 0.1 mm, nu = 0.3, k in {-0.5, 0, 0.5}.
//
// deal.II model: FE degrees 1..4 on a ladder of meshes (`fe_mesh_level`), L/a and the surface layer
// from recommended_mesh_parameters(a, k). FreeFem++ peer (cases/peers/freefem/*.edp): P2 on its own
// ladder of meshes (its `-level`), the same L/a. Every run is repeated; a row keeps the minimum and the
// median of the wall time, the minimum of every phase, the process CPU time, and the wall time of the
// first repetition (cold: gmsh runs then, its .msh is cached in the report's temporary folder after).
#ifndef GRADCONTACT_CASES_FE_BENCH_H
#define GRADCONTACT_CASES_FE_BENCH_H

#include <fem/grid/mesh.h>

#include <filesystem>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  struct FeBenchOptions
  {
    bool                quick   = false; ///< k = 0, degrees 1-2, levels 0-1, peer levels 0-1
    int                 repeat  = 3;     ///< repetitions of every run
    bool                with_fe = true, with_peer = false;
    std::filesystem::path peer_scripts; ///< folder of flat_punch.edp and paraboloid.edp
    std::string         freefem = "FreeFem++";
    /// Scenes to run (flat_punch, paraboloid, jkr_paraboloid, tangential_punch); empty: all.
    std::vector<std::string> scenes;
  };

  /// One run of one model on one mesh, timed over the repetitions (a comparison is a value).
  struct WorkPrecisionRow
  {
    std::string  load;  ///< "flat_punch" | "paraboloid"
    double       k = 0;
    std::string  model; ///< "deal.II" | "FreeFem++"
    unsigned int degree = 0, level = 0;
    double       h_edge = 0, ring_growth = 0, far_field = 0; ///< h_edge / a; g (deal.II); L / a
    unsigned int dofs = 0;
    double       force_error = 0, depth_error = 0, error = 0; ///< relative; error = max |.|
    double       wall_min = 0, wall_median = 0, wall_cold = 0, cpu_min = 0; ///< seconds
    /// Phases (minimum over the repetitions, seconds). deal.II: Result::time; FreeFem++: mesh,
    /// assemble (+ factorisation: FreeFem factorises on assembly of a matrix with a solver), solve,
    /// postprocess = reactions.
    double mesh = 0, setup = 0, assemble = 0, factorize = 0, solve = 0, postprocess = 0;
    std::string note; ///< what went wrong, if anything (the row then has error = inf)
  };

  /// The mesh of refinement level 0..4 of the deal.II ladder for contact radius a and surface exponent k:
  /// h_edge = 1e-2 .. 1e-6 a, ring growth 1.6 .. 1.15, recommended L/a and surface layer.
  fem::MeshParameters fe_mesh_level(double contact_radius, double k, unsigned int level);

  /// Runs the selected parts and writes fe_work_precision.{csv,md}, the plots and (with the peer) peer.md
  /// into `folder` (a temporary folder the caller renames). `machine` is recorded in the markdown.
  /// Returns the rows (for tests and the caller's summary).
  std::vector<WorkPrecisionRow> run_fe_bench(const FeBenchOptions &options, const std::filesystem::path &folder,
                                             const std::string &machine);

  /// Error of curve B relative to curve A at equal time and time ratio at equal error: the lower
  /// envelopes (best error reached in at most that time) interpolated log-log, over the overlap.
  struct PeerRatio
  {
    double at = 0;    ///< the time (s) or the error at which the ratio is taken
    double ratio = 0; ///< peer / deal.II
  };
  /// x: times, y: errors of one model's runs. Returns peer/ours error ratios at the peer's run times
  /// (within the range of ours).
  std::vector<PeerRatio> error_ratio_at_equal_time(const std::vector<double> &ours_t, const std::vector<double> &ours_e,
                                                   const std::vector<double> &peer_t, const std::vector<double> &peer_e);
  /// Peer/ours time ratios at the peer's errors (within the range of ours).
  std::vector<PeerRatio> time_ratio_at_equal_error(const std::vector<double> &ours_t, const std::vector<double> &ours_e,
                                                   const std::vector<double> &peer_t, const std::vector<double> &peer_e);
} // namespace gradcontact::cases

#endif
