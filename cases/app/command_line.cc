#include "app/command_line.h"

#ifndef GRADCONTACT_WITH_FEM
#  define GRADCONTACT_WITH_FEM 1 // the FE build; cases/CMakeLists.txt sets 0 for -DGRADCONTACT_WITH_FEM=OFF
#endif

// GRADCONTACT_WITH_FEM = 0 (configured with -DGRADCONTACT_WITH_FEM=OFF): the command line is `eval` alone, answered by
// the analytic library; the other commands and "method": "fe" need the FE module.
#if GRADCONTACT_WITH_FEM
#  include "app/runner.h"
#  include "tools/bench.h"
#  include "tools/fe_oracle.h"
#  include "tools/figures.h"
#  include "tools/stress.h"
#endif

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace
  {
    struct Command
    {
      std::string name;
      std::string synopsis; ///< the arguments
      std::string text;     ///< what it does, lines indented by the caller
      int (*run)(const std::vector<std::string> &args);
    };

#if GRADCONTACT_WITH_FEM
    int eval(const std::vector<std::string> &args_in)
    {
      // --batch: read the whole input first (cases/tools/fe_oracle.h, EvalReading); else each line answered at once.
      std::vector<std::string> args;
      EvalReading              reading = EvalReading::per_line;
      bool                     use_cache = true;
      for (const std::string &a : args_in)
        if (a == "--batch")
          reading = EvalReading::whole_input;
        else if (a == "--no-cache")
          use_cache = false;
        else
          args.push_back(a);
      // FE answers kept between processes (per line only): in GRADCONTACT_EVAL_CACHE (set but empty: none), else in
      // the user's cache folder
      std::optional<ResultCache> cache;
      if (use_cache && reading == EvalReading::per_line)
        {
          const char *own = std::getenv("GRADCONTACT_EVAL_CACHE"), *xdg = std::getenv("XDG_CACHE_HOME"),
                     *home = std::getenv("HOME");
          const std::filesystem::path folder =
            own ? std::filesystem::path(own) // empty: no cache
            : xdg && *xdg ? std::filesystem::path(xdg) / "gradcontact" / "eval"
            : home && *home ? std::filesystem::path(home) / ".cache" / "gradcontact" / "eval"
                            : std::filesystem::path();
          if (!folder.empty())
            cache.emplace(folder);
        }
      const ResultCache *kept = cache ? &*cache : nullptr;
      if (args.size() > 1)
        throw std::invalid_argument("eval: takes at most one file (got " + std::to_string(args.size()) + ")");
      FeOracle oracle; // "method": "fe" (cases/tools/fe_oracle.h)
      if (args.empty() || args[0] == "-")
        {
          evaluate_stream(std::cin, std::cout, oracle, reading, kept);
          return 0;
        }
      std::ifstream in(args[0]);
      if (!in)
        throw std::invalid_argument("eval: cannot open file '" + args[0] + "'");
      evaluate_stream(in, std::cout, oracle, reading, kept);
      return 0;
    }

#else
    /// One answer line per request line, written as soon as the line is read (batch::evaluate); a request with
    /// "method": "fe" is an error that names the build option.
    int eval_stream(std::istream &in, std::ostream &out)
    {
      int errors = 0;
      for (std::string line; std::getline(in, line);)
        {
          if (line.find_first_not_of(" \t\r") == std::string::npos)
            continue;
          batch::Answer answer = batch::evaluate(line);
          const nlohmann::json request = nlohmann::json::parse(line, nullptr, false);
          if (!answer.ok && request.is_object() && request.value("method", nlohmann::json()) == "fe")
            answer.error = "method = 'fe': this gradcontact was built without the FE module "
                           "(-DGRADCONTACT_WITH_FEM=OFF); 'closed_form' and 'numerical_mdr' are answered";
          errors += answer.ok ? 0 : 1;
          out << batch::to_json(answer) << std::endl;
        }
      return errors;
    }

    int eval(const std::vector<std::string> &args_in)
    {
      std::vector<std::string> args; // --batch and --no-cache concern the FE's answers: nothing to do here
      for (const std::string &a : args_in)
        if (a != "--batch" && a != "--no-cache")
          args.push_back(a);
      if (args.size() > 1)
        throw std::invalid_argument("eval: takes at most one file (got " + std::to_string(args.size()) + ")");
      if (args.empty() || args[0] == "-")
        {
          eval_stream(std::cin, std::cout);
          return 0;
        }
      std::ifstream in(args[0]);
      if (!in)
        throw std::invalid_argument("eval: cannot open file '" + args[0] + "'");
      eval_stream(in, std::cout);
      return 0;
    }
#endif

    const std::vector<Command> &commands()
    {
      static const std::vector<Command> list = {
        {"eval", "[--batch] [--no-cache] [file]",
         "evaluate JSON Lines requests from file (or stdin), one answer\n"
         "line per request, each written as soon as its line is read (vocabulary:\n"
         "analytic/README.md; \"method\": \"fe\" answers by the FE model with an error\n"
         "estimate, cases/tools/fe_oracle.h); --batch reads the whole input first, so that\n"
         "the FE samples all pressures and displacements of one state together;\n"
         "read per line, FE answers are kept between runs in GRADCONTACT_EVAL_CACHE\n"
         "(default ~/.cache/gradcontact/eval) unless --no-cache",
         eval},
#if GRADCONTACT_WITH_FEM
        {"run", "<scene|folder> ... [--set Section/key=value] [--reports DIR] [--quiet]\n"
                "    [--verbose] [--force] [--shard i/N] [--map-shard i/N] [--help-scene] [--help-functions]",
         "run scenes (.prm, .json, .jsonl) and write reports/<scene>/ and\n"
         "reports/summary.md; --help-scene lists every scene entry, --help-functions\n"
         "the functions of candidate expressions; --force solves a refinement level\n"
         "that the memory forecast would refuse; --shard i/N runs\n"
         "only the scenes at positions j with j % N == i, 0-based; --map-shard i/N\n"
         "solves only those (k, lambda) points of a Tabor-parameter map into its point\n"
         "cache (a run without it then writes the report)",
         run},
        {"sweep", "<scene.prm> --over Section/key=v1,v2,... [run options]",
         "run a scene once per value (same options as run; --shard i/N splits\n"
         "the values)",
         sweep},
        {"figures", "<file.json|folder> [--reports DIR] [--no-cache]",
         "draw the chapter's figures (cases/figures), check their FE points -> reports/figures/", figures},
        {"bench", "[--part analytic|fe|peer|oracle|accuracy|stresses|all] [--quick] [--reports DIR] [--repeat N]\n"
                  "    [--fe-repeat N] [--references FILE] [--peer-scripts DIR]\n"
                  "    [--scene flat_punch,paraboloid,jkr_paraboloid,tangential_punch]",
         "work-precision benchmarks -> reports/benchmarks/ (analytic closed\n"
         "forms; FE degrees 1-4 against wall time and DoFs; the FreeFem++ peer when\n"
         "FreeFem++ is installed; batches of FE eval requests; the accuracy\n"
         "contract over k, nu, profiles and asked tolerances; the stresses below a\n"
         "sphere, closed form against FE)",
         bench},
        {"stress", "[--reports DIR] [--references FILE] [--mdr-stride N]",
         "numerical-stability tables of the analytic module by region and\n"
         "absolute scale -> reports/benchmarks/stability.md",
         stress},
#endif
      };
      return list;
    }

    const Command *find(const std::string &name)
    {
      for (const Command &c : commands())
        if (c.name == name)
          return &c;
      return nullptr;
    }

    std::string indented(const std::string &text, const std::string &indent)
    {
      std::string out = indent;
      for (const char c : text)
        out += c == '\n' ? "\n" + indent : std::string(1, c);
      return out + "\n";
    }

    bool asks_for_help(const std::string &a) { return a == "--help" || a == "-h" || a == "help"; }
  } // namespace

  std::vector<std::string> command_names()
  {
    std::vector<std::string> names;
    for (const Command &c : commands())
      names.push_back(c.name);
    return names;
  }

  std::string usage(const std::string &command)
  {
    if (command.empty())
      {
        std::string out = "usage: gradcontact <command> [args]\n       gradcontact <command> --help\n\ncommands:\n";
        for (const Command &c : commands())
          out += "  " + c.name + " " + c.synopsis + "\n" + indented(c.text, "      ");
        return out + "  --help   this text\n";
      }
    const Command *c = find(command);
    if (!c)
      {
        std::string names;
        for (const Command &k : commands())
          names += (names.empty() ? "" : ", ") + k.name;
        throw std::invalid_argument("unknown command '" + command + "' (commands: " + names + ")");
      }
    return "usage: gradcontact " + c->name + " " + c->synopsis + "\n\n" + indented(c->text, "  ");
  }

  int command_line(const std::vector<std::string> &args, std::ostream &out)
  {
    if (args.empty())
      {
        out << usage();
        return 2;
      }
    if (asks_for_help(args[0]))
      {
        out << usage();
        return 0;
      }
    const Command *c = find(args[0]);
    if (!c)
      throw std::invalid_argument(usage(args[0])); // names the command and lists the valid ones
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (std::any_of(rest.begin(), rest.end(), [](const std::string &a) { return a == "--help" || a == "-h"; }))
      {
        out << usage(c->name);
        return 0;
      }
    return c->run(rest);
  }
} // namespace gradcontact::cases
