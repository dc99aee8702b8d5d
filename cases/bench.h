// gradcontact/cases: work-precision benchmarks (`gradcontact bench`, `./vv bench`).
//
// Analytic part: nanoseconds per evaluation of every closed-form family and milliseconds per
// numerical MDR quantity, each with its worst relative error against the 34-digit references of
// tests/data/references.jsonl (an independent mpmath evaluation of the MDR integrals). Several
// repetitions; minimum and median are reported with the machine and the build.
#pragma once

#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// `gradcontact bench [--reports DIR] [--references FILE] [--repeat N]`; returns the exit code.
  int bench(const std::vector<std::string> &args);
} // namespace gradcontact::cases
