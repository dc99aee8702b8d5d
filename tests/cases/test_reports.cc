// Reports are written under temporary names and renamed when complete (cases/report/report.h); what a killed run
// left behind is removed by the next run, what a running process writes is not.
#include "scene_files.h"

#include <cases/report/report.h>
#include <cases/app/runner.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

namespace
{
  /// The pid of a process that has exited (and been reaped): a run that was killed.
  long finished_process()
  {
    const pid_t child = ::fork();
    if (child == 0)
      ::_exit(0);
    REQUIRE(child > 0);
    ::waitpid(child, nullptr, 0);
    return child;
  }

  void make_folder_with_file(const fs::path &folder)
  {
    fs::create_directories(folder);
    std::ofstream(folder / "errors.csv") << "half a report\n";
  }
} // namespace

TEST_CASE("The temporaries of finished processes shall be removed, those of running ones kept", "[cases][quick]")
{
  const TemporaryFolder reports("gradcontact-reports");
  const fs::path killed = temporary_sibling(reports.path() / "scene_a", finished_process());
  const fs::path running = temporary_sibling(reports.path() / "scene_b");
  const fs::path earlier_version = reports.path() / ".scene_c.tmp";
  const fs::path summary = temporary_sibling(reports.path() / "summary.md", finished_process());
  const fs::path report = reports.path() / "scene_d";
  const fs::path hidden = reports.path() / ".notes";
  for (const fs::path &p : {killed, running, earlier_version, report, hidden})
    make_folder_with_file(p);
  std::ofstream(summary) << "half a summary\n";
  CAPTURE(killed, running, summary);
  REQUIRE(killed.filename().string().front() == '.');

  const std::vector<fs::path> removed = remove_stale_temporaries(reports.path());
  CHECK(removed.size() == 3);
  CHECK_FALSE(fs::exists(killed));
  CHECK_FALSE(fs::exists(earlier_version));
  CHECK_FALSE(fs::exists(summary));
  CHECK(fs::exists(running / "errors.csv"));
  CHECK(fs::exists(report / "errors.csv"));
  CHECK(fs::exists(hidden / "errors.csv"));
}

TEST_CASE("A temporary of another host shall be kept (a shared reports folder)", "[cases][quick]")
{
  const TemporaryFolder reports("gradcontact-reports");
  const fs::path here = temporary_sibling(reports.path() / "scene", finished_process());
  std::string name = here.filename().string();
  name.replace(name.find(".tmp-") + 5, 0, "elsewhere.");
  const fs::path other_host = reports.path() / name;
  make_folder_with_file(other_host);
  CAPTURE(other_host);
  CHECK(remove_stale_temporaries(reports.path()).empty());
  CHECK(fs::exists(other_host));
}

TEST_CASE("gradcontact run shall remove a killed run's temporary report folder", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-run");
  const fs::path reports = folder.path() / "reports";
  const fs::path stale = temporary_sibling(reports / "other_scene", finished_process());
  make_folder_with_file(stale);
  const fs::path scene = folder.path() / "one_check.jsonl";
  std::ofstream(scene) << R"({"case":"flat_punch","quantity":"force","material":{"E0":1e9,"c0":1e-3,"k":0.5,"nu":0.3},"a":1e-4,"d":1e-6})"
                       << "\n";
  CHECK(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  CHECK(fs::exists(reports / "one_check" / "errors.csv"));
  CHECK_FALSE(fs::exists(stale));
  for (const auto &entry : fs::directory_iterator(reports))
    CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("A failed writer shall leave neither a report nor a temporary", "[cases][quick]")
{
  const TemporaryFolder reports("gradcontact-reports");
  const fs::path target = reports.path() / "scene";
  REQUIRE_THROWS_AS(atomic_folder(target,
                                  [](const fs::path &tmp) {
                                    std::ofstream(tmp / "errors.csv") << "half\n";
                                    throw std::runtime_error("the writer fails");
                                  }),
                    std::runtime_error);
  CHECK(fs::is_empty(reports.path()));
}

TEST_CASE("Runs that write the same report at once shall each succeed and leave one whole report", "[cases][quick]")
{
  const TemporaryFolder reports("gradcontact-concurrent");
  const fs::path target = reports.path() / "scene";
  // Eight processes each replace the report 25 times; a report is whole when its two files carry the same
  // writer mark. Before the exchange, a run that found the other's folder in place failed with "cannot
  // rename: Directory not empty" and could leave no report at all.
  constexpr int writers = 8, rounds = 25;
  std::vector<pid_t> children;
  for (int w = 0; w < writers; ++w)
    {
      const pid_t child = ::fork();
      REQUIRE(child >= 0);
      if (child == 0)
        {
          int status = 0;
          try
            {
              for (int i = 0; i < rounds; ++i)
                atomic_folder(target, [&](const fs::path &tmp) {
                  const std::string mark = std::to_string(w) + "-" + std::to_string(i) + "\n";
                  std::ofstream(tmp / "errors.csv") << mark;
                  std::ofstream(tmp / "summary.md") << mark;
                });
            }
          catch (...)
            {
              status = 1;
            }
          ::_exit(status);
        }
      children.push_back(child);
    }
  int failed = 0;
  for (const pid_t child : children)
    {
      int status = 0;
      ::waitpid(child, &status, 0);
      failed += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
  CHECK(failed == 0);
  const auto read = [](const fs::path &p) {
    std::ifstream in(p);
    std::string s;
    std::getline(in, s);
    return s;
  };
  REQUIRE(fs::exists(target / "errors.csv"));
  CHECK(read(target / "errors.csv") == read(target / "summary.md"));
  CHECK(read(target / "errors.csv").find("-" + std::to_string(rounds - 1)) != std::string::npos);
  for (const auto &entry : fs::directory_iterator(reports.path()))
    CHECK(entry.path().filename() == "scene");
}

TEST_CASE("Two gradcontact runs of the same scene into one reports folder at once shall both pass", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-two-runs");
  const fs::path reports = folder.path() / "reports";
  const fs::path scene = folder.path() / "one_check.jsonl";
  std::ofstream(scene) << R"({"case":"flat_punch","quantity":"force","material":{"E0":1e9,"c0":1e-3,"k":0.5,"nu":0.3},"a":1e-4,"d":1e-6})"
                       << "\n";
  std::vector<pid_t> children;
  for (int i = 0; i < 2; ++i)
    {
      const pid_t child = ::fork();
      REQUIRE(child >= 0);
      if (child == 0)
        {
          int status = 1;
          try
            {
              for (int round = 0; round < 20; ++round)
                if (run({scene.string(), "--reports", reports.string(), "--quiet"}) != 0)
                  ::_exit(1);
              status = 0;
            }
          catch (...)
            {
            }
          ::_exit(status);
        }
      children.push_back(child);
    }
  for (const pid_t child : children)
    {
      int status = 0;
      ::waitpid(child, &status, 0);
      CHECK((WIFEXITED(status) && WEXITSTATUS(status) == 0));
    }
  CHECK(fs::exists(reports / "one_check" / "errors.csv"));
  for (const auto &entry : fs::directory_iterator(reports))
    CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
}

TEST_CASE("A convergence scene's report shall hold its rows against the reference and the observed order",
          "[cases]")
{
  // A homogeneous flat punch (k = 0): the reference is Sneddon's F = 2 E0 a d / (1 - nu^2), written out here,
  // independent of the analytic library and of the FE. Degree 1, uniform refinements 0-2 of a coarse mesh
  // (cheap): the force is an energy functional, its error falls as h^2 = h^{2p}.
  const TemporaryFolder folder("gradcontact-report-contents");
  const fs::path scene = folder.path() / "punch_h.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0\n  set E0 = 2e9\n  set c0 = 3e-4\n  set nu = 0.3\nend\n"
                          "subsection Load\n  set type = flat punch\n  set a = 1e-4\n  set depth = 1e-6\nend\n"
                          "subsection Discretization\n  set degree = 1\n  set refinements = 0, 1, 2\n"
                          "  set force tolerance = 1e-3\nend\n"
                          "subsection Tolerances\n  set force = 1e-2\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);

  const auto rows = testing::read_csv(reports / "punch_h" / "errors.csv");
  const std::vector<std::string> columns{"quantity", "metric", "method", "reference", "reference_value", "value",
                                         "abs_error", "rel_error", "tolerance", "pass", "dofs", "seconds", "error",
                                         "fe_asked", "fe_estimate", "fe_contract"};
  REQUIRE(rows.size() == 4);
  CHECK(rows[0] == columns);
  const double sneddon = 2 * 2e9 * 1e-4 * 1e-6 / (1 - 0.3 * 0.3);
  std::vector<double> errors;
  for (std::size_t i = 1; i < rows.size(); ++i)
    {
      const auto &r = rows[i];
      REQUIRE(r.size() == columns.size());
      CAPTURE(i, r[0], r[2], r[4], r[5], r[7]);
      CHECK(r[0] == "force");
      CHECK(r[2] == "FE (" + std::to_string(i - 1) + " ref.)");
      CHECK(std::stod(r[4]) == Approx(sneddon).epsilon(1e-14));
      const double value = std::stod(r[5]);
      CHECK(std::stod(r[7]) == Approx(std::abs(value / sneddon - 1)).epsilon(1e-10));
      CHECK(r[9] == "pass");
      errors.push_back(std::abs(value / sneddon - 1));
    }
  // Each refinement divides the error by about 4 (h^2).
  CHECK(errors[0] / errors[1] == Approx(4).epsilon(0.15));
  CHECK(errors[1] / errors[2] == Approx(4).epsilon(0.15));
  CHECK(errors[2] < 1e-3);

  const std::string md = testing::read_text(reports / "punch_h" / "convergence.md");
  for (const char *level : {"| 0 |", "| 1 |", "| 2 |"})
    CHECK(md.find(level) != std::string::npos);
  const std::string marker = "Observed order over the last three levels: ";
  const auto at = md.find(marker);
  REQUIRE(at != std::string::npos);
  const double order = std::stod(md.substr(at + marker.size()));
  CHECK(order > 1.8);
  CHECK(order < 2.3);
}
