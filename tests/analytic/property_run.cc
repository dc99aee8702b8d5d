// property_run: the randomized property run of the analytic module at any size.
//
//   property_run [--points N] [--seed S] [--mdr-stride M] [--timeout T] [--report FILE]
//                [--inject crash:I|hang:I|refuse:I]   (self-test of the detector: point I crashes or hangs, or
//                                                      points I, I+1, ... answer with an explicit refusal)
//
// Requirement: over N random valid requests (tests/analytic/random_requests.h, every case and quantity
// of the vocabulary, E0 1e6..1e12 Pa, c0 1e-6..1 m, k in [-0.95, 0.95], nu in [0, 0.4999]) the closed
// forms shall return no NaN or inf, no unexplained error, shall not hang (no answer within T seconds)
// and shall not crash, and shall refuse at most max_refused_fraction (10%) of the points explicitly (the
// cap of the fast test, random_requests.h); every M-th point is also evaluated by the numerical MDR (the
// independent path) and shall agree within 1e-9, or 1e-12 of the scale where the value crosses zero, and
// within 1e-12 at the points drawn in a region where a formula can cancel (RandomRequests: p(0) with
// n + k -> 1, r or c within 1e-5 of a, small x of 1 - (1 - x)^p, small amplitudes; the tolerances of
// test_closed_vs_mdr.cc). The numerical MDR's explicit refusal of p(0) with n + k - 1 < (1 + k)/10
// (random_requests.h: centre_out_of_reach) is not a disagreement there (the closed form answers alone;
// counted); anywhere else it is. Point i is the first request of RandomRequests(S + i): any point is
// replayed from its number alone (printed for every failure).
//
// Hangs and crashes cannot be caught in-process, so the points run in a child process that reports each
// point over a pipe; the parent records a crash (the child died on a signal) or a hang (no report within
// T s: the child is killed) at the point after the last reported one and restarts a child after it.
// Exit code 0 when every count of a failure is zero and the refusals are within the cap (printed last:
// "property_run: exit code N"). --report writes a markdown summary (through a temporary file renamed at the
// end: a failed run leaves no half-written report).
#include <analytic/batch.h>

#include "random_requests.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace gradcontact;
using nlohmann::json;

namespace
{
  using testing::max_refused_fraction;
  using testing::relative_floor;
  using testing::tol_closed_vs_mdr;
  using testing::tol_targeted;

  struct Options
  {
    long          points     = 1000000;
    unsigned long seed       = 20261123;
    long          mdr_stride = 100; ///< numerical MDR on every M-th point (0: never)
    double        timeout    = 60.; ///< seconds without an answer that count as a hang
    std::string   report;
    std::string   inject;       ///< "crash" or "hang" at point inject_point, "refuse" from it on (self-test only)
    long          inject_point = -1;
  };

  long parse_integer(const std::string &name, const std::string &text, const long lo, const long hi)
  {
    std::size_t used = 0;
    long        v    = 0;
    try
      {
        v = std::stol(text, &used);
      }
    catch (const std::logic_error &)
      {
        used = 0;
      }
    if (used == 0 || used != text.size() || v < lo || v > hi)
      throw std::invalid_argument("property_run: " + name + " = '" + text + "' is not an integer in [" +
                                  std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }

  Options parse(int argc, char **argv)
  {
    Options o;
    for (int i = 1; i < argc; ++i)
      {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
          if (i + 1 == argc)
            throw std::invalid_argument("property_run: " + a + " needs a value");
          return argv[++i];
        };
        if (a == "--points")
          o.points = parse_integer(a, value(), 1, 1000000000);
        else if (a == "--seed")
          o.seed = static_cast<unsigned long>(parse_integer(a, value(), 0, 1L << 62));
        else if (a == "--mdr-stride")
          o.mdr_stride = parse_integer(a, value(), 0, 1000000000);
        else if (a == "--timeout")
          o.timeout = static_cast<double>(parse_integer(a, value(), 1, 86400));
        else if (a == "--report")
          o.report = value();
        else if (a == "--inject")
          {
            const std::string v = value();
            const auto        colon = v.find(':');
            o.inject = v.substr(0, colon);
            if (colon == std::string::npos || (o.inject != "crash" && o.inject != "hang" && o.inject != "refuse"))
              throw std::invalid_argument("property_run: --inject = '" + v + "' is not crash:I, hang:I or refuse:I");
            o.inject_point = parse_integer("--inject point", v.substr(colon + 1), 0, 1000000000);
          }
        else
          throw std::invalid_argument("property_run: unknown argument '" + a +
                                      "' (--points N --seed S --mdr-stride M --timeout T --report FILE)");
      }
    return o;
  }

  json raw_request(const Options &o, const long i) { return testing::RandomRequests(o.seed + i).next(); }
  json request(const Options &o, const long i) { return testing::resolve(raw_request(o, i)); }

  batch::Answer evaluate(json q, const char *method)
  {
    q["method"] = method;
    return batch::evaluate(q.dump());
  }

  /// Outcome of one point, one line over the pipe: "<i> <code> <seconds> <mdr difference>\n".
  enum Code : int
  {
    ok = 0,          ///< finite value
    refused = 1,     ///< an explicit error message (a valid refusal, e.g. no critical state)
    nonfinite = 2,   ///< NaN or inf (batch names the request: "non-finite result")
    unexplained = 3, ///< any other internal or empty error
    disagrees = 4,   ///< closed form and numerical MDR differ beyond the tolerance, or one refuses alone
    centre_alone = 5, ///< the numerical MDR refuses p(0) out of its reach (centre_out_of_reach): closed form only
  };

  /// The child: evaluates points [first, n) and reports each.
  [[noreturn]] void child(const Options &o, const long first, const int fd)
  {
    for (long i = first; i < o.points; ++i)
      {
        if (o.inject == "refuse" && i >= o.inject_point)
          {
            // an explicit refusal in place of the evaluation (self-test of the refusal cap)
            char      line[128];
            const int len = std::snprintf(line, sizeof line, "%ld %d %.6e %.6e\n", i, int{refused}, 0., -1.);
            if (write(fd, line, len) != len)
              _exit(3);
            continue;
          }
        if (i == o.inject_point)
          {
            if (o.inject == "crash")
              std::raise(SIGSEGV);
            for (;;)
              pause(); // hang until the parent kills us
          }
        const auto   start  = std::chrono::steady_clock::now();
        const json   raw    = raw_request(o, i);
        const bool   target = !testing::region_of(raw).empty();
        const json   q      = testing::resolve(raw);
        const auto   closed = evaluate(q, "closed_form");
        int          code   = ok;
        double       diff   = -1; // no comparison
        if (!closed.ok)
          code = closed.error.find("non-finite") != std::string::npos ? nonfinite :
                 (closed.error.empty() || closed.error.find("internal error") != std::string::npos) ? unexplained :
                                                                                                    refused;
        else if (!std::isfinite(closed.value))
          code = nonfinite;
        if (code <= refused && o.mdr_stride > 0 && i % o.mdr_stride == 0)
          {
            const auto numeric = evaluate(q, "numerical_mdr");
            if (closed.ok && !numeric.ok && testing::excused_centre_refusal(q, numeric.error))
              code = centre_alone; // an explained limit of the numerical MDR: the closed form answers alone
            else if (numeric.ok != closed.ok)
              code = disagrees;
            else if (closed.ok)
              {
                const double scale = std::max(std::abs(numeric.value), std::abs(closed.value));
                const double d     = std::abs(closed.value - numeric.value);
                diff               = d / std::max(scale, 1e-300);
                if (!(diff <= (target ? tol_targeted : tol_closed_vs_mdr) || d <= relative_floor * scale))
                  code = disagrees;
              }
          }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        char         line[128];
        const int    len = std::snprintf(line, sizeof line, "%ld %d %.6e %.6e\n", i, code, seconds, diff);
        if (write(fd, line, len) != len)
          _exit(3);
      }
    _exit(0);
  }

  struct Tally
  {
    long   evaluated = 0, counts[6] = {0, 0, 0, 0, 0, 0}, hangs = 0, crashes = 0, compared = 0;
    double slowest = 0;
    long   slowest_point = -1;
    std::map<std::string, double> worst; ///< case/quantity -> worst closed vs numerical difference
    std::vector<std::string> failures;   ///< "point i: what" (replay: RandomRequests(seed + i))
  };

  const char *code_name(const int c)
  {
    static const char *names[] = {"ok",
                                  "refused",
                                  "NaN or inf",
                                  "unexplained error",
                                  "closed form vs numerical MDR",
                                  "closed form alone (p(0) out of the numerical MDR's reach)"};
    return names[c];
  }

  /// Runs every point in children; returns the tally.
  Tally run(const Options &o)
  {
    Tally t;
    long  next = 0;
    while (next < o.points)
      {
        int fds[2];
        if (pipe(fds) != 0)
          throw std::runtime_error(std::string("property_run: pipe failed: ") + std::strerror(errno));
        const pid_t pid = fork();
        if (pid < 0)
          throw std::runtime_error(std::string("property_run: fork failed: ") + std::strerror(errno));
        if (pid == 0)
          {
            close(fds[0]);
            child(o, next, fds[1]);
          }
        close(fds[1]);
        std::string buffer;
        bool        hung = false;
        for (;;)
          {
            pollfd p{fds[0], POLLIN, 0};
            const int ready = poll(&p, 1, static_cast<int>(o.timeout * 1000));
            if (ready < 0 && errno == EINTR)
              continue;
            if (ready == 0)
              {
                hung = true;
                kill(pid, SIGKILL); // our own child, by its id
                break;
              }
            char      chunk[1 << 16];
            const auto n = read(fds[0], chunk, sizeof chunk);
            if (n <= 0)
              break; // the child closed the pipe: finished or died
            buffer.append(chunk, n);
            std::size_t start = 0, end;
            while ((end = buffer.find('\n', start)) != std::string::npos)
              {
                long   i;
                int    code;
                double seconds, diff;
                if (std::sscanf(buffer.c_str() + start, "%ld %d %le %le", &i, &code, &seconds, &diff) == 4)
                  {
                    ++t.evaluated;
                    ++t.counts[code];
                    if (seconds > t.slowest)
                      {
                        t.slowest       = seconds;
                        t.slowest_point = i;
                      }
                    if (diff >= 0)
                      {
                        ++t.compared;
                        const json raw = raw_request(o, i);
                        const std::string region = testing::region_of(raw);
                        const json q = testing::resolve(raw);
                        const std::string key = q["case"].get<std::string>() + "/" + q["quantity"].get<std::string>() +
                                                (region.empty() ? "" : " (" + region + ")");
                        t.worst[key] = std::max(t.worst[key], diff);
                      }
                    if (code >= nonfinite && code <= disagrees)
                      t.failures.push_back("point " + std::to_string(i) + ": " + code_name(code) + ": " +
                                           request(o, i).dump());
                    next = i + 1;
                    if (next % 100000 == 0)
                      std::cerr << "property_run: " << next << " points\n";
                  }
                start = end + 1;
              }
            buffer.erase(0, start);
          }
        close(fds[0]);
        int status = 0;
        waitpid(pid, &status, 0);
        const bool clean = !hung && WIFEXITED(status) && WEXITSTATUS(status) == 0;
        if (!clean && next < o.points)
          {
            // the point after the last reported one hung or crashed: record it and skip it
            (hung ? t.hangs : t.crashes) += 1;
            t.failures.push_back("point " + std::to_string(next) + ": " +
                                 (hung ? "hang (no answer within " + std::to_string(static_cast<long>(o.timeout)) + " s)" :
                                         WIFSIGNALED(status) ? std::string("crash (signal ") +
                                                                 strsignal(WTERMSIG(status)) + ")" :
                                                               "crash (exit " + std::to_string(WEXITSTATUS(status)) + ")") +
                                 ": " + request(o, next).dump());
            ++next;
          }
      }
    return t;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const Options o = parse(argc, argv);
      std::cout << "property_run: " << o.points << " points, seed " << o.seed << ", numerical MDR on every "
                << o.mdr_stride << "th, hang after " << o.timeout << " s\n";
      const auto   start   = std::chrono::steady_clock::now();
      const Tally  t       = run(o);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const long   failed  = t.counts[nonfinite] + t.counts[unexplained] + t.counts[disagrees] + t.hangs + t.crashes;
      const long   refusal_cap = static_cast<long>(max_refused_fraction * static_cast<double>(t.evaluated));
      const bool   too_many_refused = t.counts[refused] > refusal_cap;
      const int    exit_code = (failed == 0 && !too_many_refused) ? 0 : 1;

      std::ostringstream md;
      md << "# Randomized property run of the analytic module (`property_run`)\n\n"
         << "Points: " << o.points << " (seed " << o.seed << ", point i = first request of RandomRequests(seed + i)); "
         << "numerical MDR on every " << o.mdr_stride << "th point; hang = no answer within " << o.timeout
         << " s. Wall time: " << seconds << " s (" << 1e6 * seconds / std::max(1L, o.points) << " us per point).\n\n"
         << "| outcome | points |\n|---|---|\n"
         << "| evaluated | " << t.evaluated << " |\n"
         << "| finite value | " << t.counts[ok] + t.counts[centre_alone] << " |\n"
         << "| explicit refusal (at most " << refusal_cap << ") | " << t.counts[refused] << " |\n"
         << "| NaN or inf | " << t.counts[nonfinite] << " |\n"
         << "| unexplained error | " << t.counts[unexplained] << " |\n"
         << "| hang | " << t.hangs << " |\n"
         << "| crash | " << t.crashes << " |\n"
         << "| compared with the numerical MDR | " << t.compared << " |\n"
         << "| p(0) out of the numerical MDR's reach (closed form alone) | " << t.counts[centre_alone] << " |\n"
         << "| disagreement beyond 1e-9 (1e-12 in the targeted regions) | " << t.counts[disagrees] << " |\n\n";
      if (too_many_refused)
        md << "**Refusals over the cap:** " << t.counts[refused] << " of " << t.evaluated << " evaluated points ("
           << 100. * static_cast<double>(t.counts[refused]) / static_cast<double>(std::max(1L, t.evaluated))
           << "%) were refused; at most " << 100. * max_refused_fraction
           << "% may be (max_refused_fraction, tests/analytic/random_requests.h).\n\n";
      md
         << "Slowest point: " << t.slowest << " s (point " << t.slowest_point << ").\n\n"
         << "Worst closed-form vs numerical-MDR difference per case/quantity:\n\n";
      for (const auto &w : t.worst)
        md << "- " << w.first << ": " << w.second << "\n";
      if (!t.failures.empty())
        {
          md << "\n## Failures (first 50)\n\n";
          for (std::size_t i = 0; i < t.failures.size() && i < 50; ++i)
            md << "- " << t.failures[i] << "\n";
        }
      std::cout << md.str();
      if (!o.report.empty())
        {
          const std::filesystem::path file = o.report, tmp = file.string() + ".tmp";
          if (file.has_parent_path())
            std::filesystem::create_directories(file.parent_path());
          {
            std::ofstream out(tmp);
            out << md.str();
            if (!out)
              throw std::runtime_error("property_run: cannot write " + tmp.string());
          }
          std::filesystem::rename(tmp, file);
        }
      std::cout << "property_run: exit code " << exit_code << "\n";
      return exit_code;
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << '\n';
      return 2;
    }
}
