// gradcontact/cases: numerical-stability stress tables of the analytic module (`gradcontact stress`).
//
// Every row of the high-precision references (tests/data/references.jsonl: 34-digit values of the MDR
// integrals from mpmath, generated over the stress grid: k to +-0.99, k to 0 from both sides, nu = 0 and
// nu -> 0.5, c0/a over many decades, r -> a from both sides, r -> 0, r -> infinity) is evaluated by the
// closed form and the numerical MDR and sorted into the regions of parameter space it belongs to. The
// absolute scales are stressed by exact similarity: every length of a request times 2^m and every modulus
// times 2^j (E0 from 1e-3 to 1e12 Pa, lengths from 1e-9 to 1e3 m) changes each quantity by the exact power
// of two its dimension gives (force ~ E L^2, pressure ~ E, depth ~ L, energy ~ E L^3), so the reference
// stays exact. Each row is held to its own allowance, the conditioning of its inputs (the `conditioning` column of
// the references: the relative change under half-ulp input perturbations) plus the method's floor, so that a loss
// of digits beyond what the inputs justify fails. The regions include those where a formula can cancel:
// p(0) at tiny |k| and with n + k -> 1, r and c within 1e-5 of a, small x of 1 - (1 - x)^p on the loading branch,
// small oscillation amplitudes. Per region and method: rows, worst relative error, worst error/allowance and its
// row, NaN or inf results (none allowed) and explicit refusals (clear errors that explain a limit).
#ifndef GRADCONTACT_CASES_STRESS_H
#define GRADCONTACT_CASES_STRESS_H

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact stress [--reports DIR] [--references FILE] [--mdr-stride N]`; returns the exit code
  /// (non-zero when a NaN or inf is returned or a row's error exceeds its allowance).
  int stress(const std::vector<std::string> &args);
} // namespace gradcontact::cases

#endif
