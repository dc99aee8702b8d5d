// gradcontact/cases: the stresses below a sphere, closed form against FE (`gradcontact bench --part stresses`).
//
// For the paraboloid on E0 (z/c0)^k, nu = 0.3 and nu = 0.45, at k = -0.5, 0 and 0.5, one contact radius:
//   - the largest shear stress below the contact, its depth and radius (max_stress with component max_shear): the
//     closed-form search of analytic/subsurface.h against the FE oracle's search on its recovered field
//     (cases/tools/fe_oracle.h). On k < 0 neither side has a largest stress (the skin's stresses grow without bound
//     toward the surface), so the FE is asked the stress at the point where the largest shear below z = 0.05 a lies
//     on the closed-form side (a grid of that region), and the table says so;
//   - the largest radial (ring-crack) stress just below the surface outside the contact, sigma_rr at z = 1e-3 a
//     (a grid of r in [a, 2a] on the closed-form side), with the FE asked at that point.
// Values over p_m = F / (pi a^2); each FE value with the contract's estimate at the asked tolerance and its time,
// each difference relative to p_m. Writes stresses.md and stresses.csv; returns the number of FE answers further
// from the closed form than their own estimate allows (more than 3x the estimate), or refused without a limit.
#ifndef GRADCONTACT_CASES_STRESS_BENCH_H
#define GRADCONTACT_CASES_STRESS_BENCH_H

#include <filesystem>
#include <string>

namespace gradcontact::cases
{
  struct StressBenchOptions
  {
    bool   quick     = false; ///< nu = 0.3 and k = 0 only
    double tolerance = 1e-5;  ///< asked of the FE
  };

  /// Runs the table and writes stresses.{md,csv} into `folder`; returns the number of broken promises (header).
  int run_stress_bench(const StressBenchOptions &options, const std::filesystem::path &folder,
                       const std::string &machine);
} // namespace gradcontact::cases

#endif
