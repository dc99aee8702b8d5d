// gradcontact/cases: the command line of the suite, as a library function (the executable's main only
// catches and prints). Commands:
//   eval     JSON Lines requests -> one answer a line (analytic/README.md)
//   run      run scenes (.prm, .json, .jsonl) -> reports/<scene>/, reports/summary.md
//   sweep    run one scene once per value of one entry
//   figures  the chapter's figures (cases/figures) -> reports/figures/
//   bench    work-precision benchmarks -> reports/benchmarks/
//   stress   numerical-stability tables -> reports/benchmarks/stability.md
// `gradcontact <command> --help` prints that command's usage and exits with 0.
#ifndef GRADCONTACT_CASES_COMMAND_LINE_H
#define GRADCONTACT_CASES_COMMAND_LINE_H

#include <iosfwd>
#include <string>
#include <vector>

namespace gradcontact::cases
{
  /// The commands, in the order of the usage text.
  std::vector<std::string> command_names();

  /// The usage of one command; an empty name gives the usage of the whole command line. An unknown name is
  /// an error that lists the commands.
  std::string usage(const std::string &command = "");

  /// Runs `args` (without the program name): usage and --help to `out`, exit code returned; bad input throws
  /// std::invalid_argument (the caller prints what() and exits non-zero).
  int command_line(const std::vector<std::string> &args, std::ostream &out);
} // namespace gradcontact::cases

#endif
