// gradcontact: the command line of the suite.
//
//   gradcontact eval [file]          JSON Lines requests (stdin without file) -> one answer a line
//   gradcontact run <scene|folder>   run scenes, write reports/<scene>/ and reports/summary.md
//   gradcontact bench                 work-precision benchmarks, write reports/benchmarks/
//   gradcontact stress                numerical-stability tables, write reports/benchmarks/stability.md
//   gradcontact --help
//
// Sample runs:
//   echo '{"id":1,"case":"paraboloid","quantity":"force","material":{"E0":1e9,"c0":1e-3,"k":0.5,
//          "nu":0.3},"geometry":{"R":0.01},"a":1e-4}' | gradcontact eval
//   gradcontact run cases/default
//
// Errors are reported here, at the boundary: what() on stderr and a non-zero exit code.
#include <analytic/batch.hpp>

#include "bench.h"
#include "figures.h"
#include "runner.h"
#include "stress.h"

#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  void usage(std::ostream &out)
  {
    out << "usage: gradcontact <command> [args]\n\n"
           "commands:\n"
           "  eval [file]              evaluate JSON Lines requests from file (or stdin), one answer\n"
           "                           line per request (vocabulary: analytic/README.md)\n"
           "  run <scene|folder> ...   run scenes (.prm, .jsonl) and write reports/ (options:\n"
           "                           --set Section/key=value, --reports DIR, --quiet, --verbose,\n"
           "                           --help-scene lists every scene entry, --shard i/N runs\n"
           "                           only the scenes at positions j with j % N == i, 0-based)\n"
           "  sweep <scene.prm> --over Section/key=v1,v2,...\n"
           "                           run a scene once per value (same options as run; --shard\n"
           "                           i/N splits the values)\n"
           "  figures <file.json|folder> [--reports DIR]\n"
           "                           draw the chapter's figures (cases/figures) -> reports/figures/\n"
           "  bench [--part analytic|fe|peer|all] [--quick] [--reports DIR] [--repeat N]\n"
           "        [--fe-repeat N] [--peer-scripts DIR] [--scene flat_punch,paraboloid,\n"
           "        jkr_paraboloid,tangential_punch]\n"
           "                           work-precision benchmarks -> reports/benchmarks/ (analytic\n"
           "                           closed forms; FE degrees 1-4 against wall time and DoFs; the\n"
           "                           FreeFem++ peer when FreeFem++ is installed)\n"
           "  stress [--reports DIR] [--mdr-stride N]\n"
           "                           numerical-stability tables of the analytic module by region and\n"
           "                           absolute scale -> reports/benchmarks/stability.md\n"
           "  --help                   this text\n";
  }

  int eval(const std::vector<std::string> &args)
  {
    if (args.size() > 1)
      throw std::invalid_argument("eval: takes at most one file (got " + std::to_string(args.size()) + ")");
    if (args.empty() || args[0] == "-")
      {
        gradcontact::batch::evaluate_stream(std::cin, std::cout);
        return 0;
      }
    std::ifstream in(args[0]);
    if (!in)
      throw std::invalid_argument("eval: cannot open file '" + args[0] + "'");
    gradcontact::batch::evaluate_stream(in, std::cout);
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") ||
          !std::strcmp(argv[1], "help"))
        {
          usage(std::cout);
          return argc < 2 ? 2 : 0;
        }
      const std::string command = argv[1];
      const std::vector<std::string> args(argv + 2, argv + argc);
      if (command == "eval")
        return eval(args);
      if (command == "run")
        return gradcontact::cases::run(args);
      if (command == "sweep")
        return gradcontact::cases::sweep(args);
      if (command == "figures")
        return gradcontact::cases::figures(args);
      if (command == "bench")
        return gradcontact::cases::bench(args);
      if (command == "stress")
        return gradcontact::cases::stress(args);
      std::cerr << "gradcontact: unknown command '" << command << "'\n";
      usage(std::cerr);
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gradcontact: " << e.what() << '\n';
      return 1;
    }
}
