// Applicability maps (cases/runners/fe_map.h): the threshold read from a map, and a small map run end to end.
#include "scene_files.h"

#include <cases/runners/fe_cohesive.h>
#include <cases/runners/fe_map.h>
#include <cases/report/map_pipeline.h>
#include <cases/report/thresholds.h>
#include <cases/model/map_published.h>
#include <cases/app/runner.h>

#include <analytic/maugis_dugdale.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

TEST_CASE("The threshold of a map shall be where a power-law decay of the deviation crosses it", "[cases][quick]")
{
  // |deviation| = 0.3 (ratio)^-0.5 crosses 1e-2 at ratio (0.3/1e-2)^2 = 900, between 100 and 1000: the
  // log-log interpolation is exact for a power law.
  const std::vector<double> ratios{1, 10, 100, 1000, 1e4};
  std::vector<double> deviations;
  for (const double r : ratios)
    deviations.push_back(-0.3 / std::sqrt(r));
  const auto crossing = threshold_ratio(ratios, deviations, 1e-2);
  REQUIRE(crossing.has_value());
  CHECK(*crossing == Approx(900).epsilon(1e-12));
  CHECK(threshold_cell(ratios, deviations, 1e-2, true) == ">= 900");
  // Within at every ratio, and never within.
  const auto every = threshold_ratio(ratios, deviations, 1.);
  REQUIRE(every.has_value());
  CHECK(*every == 1.);
  CHECK(threshold_cell(ratios, deviations, 1., true) == "at every ratio (from 1)");
  CHECK_FALSE(threshold_ratio(ratios, deviations, 1e-3).has_value());
  CHECK(threshold_cell(ratios, deviations, 1e-3, true) == "not within it up to 10000");
  // A deviation that comes back above the threshold at a larger ratio moves the answer past it.
  deviations[3] = 0.5;
  const auto past = threshold_ratio(ratios, deviations, 0.1);
  REQUIRE(past.has_value());
  CHECK(*past > 1000.);
  CHECK_THROWS_WITH(threshold_ratio({1, 2}, {0.1}, 0.01), Catch::Contains("2 ratios and 1 deviations"));
}

TEST_CASE("A coating map shall read its threshold toward a/H -> 0", "[cases][quick]")
{
  // |deviation| = 0.3 (a/H)^0.5 (a coating is the power law as a/H -> 0): within 1e-2 when
  // a/H <= (1e-2 / 0.3)^2 = 1/900.
  const std::vector<double> ratios{1e-4, 1e-3, 1e-2, 0.1, 1};
  std::vector<double> deviations;
  for (const double r : ratios)
    deviations.push_back(0.3 * std::sqrt(r));
  const std::string at = threshold_cell(ratios, deviations, 1e-2, false);
  REQUIRE(at.rfind("<= ", 0) == 0);
  CHECK(std::stod(at.substr(3)) == Approx(1. / 900).epsilon(1e-5)); // format() keeps 6 digits
  CHECK(threshold_cell(ratios, deviations, 1., false) == "at every ratio (up to 1)");
  CHECK(threshold_cell(ratios, deviations, 1e-4, false) == "not within it down to 0.0001");
}

TEST_CASE("A map scene shall check the power law itself and write the map, its thresholds and plots", "[cases]")
{
  const TemporaryFolder folder("gradcontact-map");
  const fs::path scene = folder.path() / "small_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0.5\nend\n"
                          "subsection Load\n  set type = flat punch\n  set a = 1e-4\n  set depth = 1e-6\nend\n"
                          "subsection Discretization\n  set degree = 1\n  set force tolerance = 1e-3\nend\n"
                          "subsection Tolerances\n  set force = 1e-2\n  set pressure = 1e-1\nend\n"
                          "subsection Map\n  set parameter = coating thickness\n  set values = 0.01, 1\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "small_map";
  for (const char *file : {"errors.csv", "map.csv", "map.md"})
    CHECK(fs::exists(out / file));
  const std::string md = testing::read_text(out / "map.md");
  CHECK(md.find("| 0.01 |") != std::string::npos);
  CHECK(md.find("within 1 % when a/H |") != std::string::npos);
  // A coating 100 a thick is the power law within a few per cent at most; one a / 1 thick is far from it.
  // map.csv: k, a/H, the force deviation, ...; rows in ascending a/H (thick coating first).
  const auto csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[0][0] == "k");
  CHECK(csv[0][1] == "a_over_H");
  CHECK(csv[0][2] == "force_deviation");
  const auto force_deviation = [](const std::vector<std::string> &row) { return std::stod(row.at(2)); };
  const auto &thick = csv[1], &thin = csv[2];
  CHECK(std::abs(force_deviation(thick)) < std::abs(force_deviation(thin)));
}

namespace
{
  /// A map of 2 panels of 3 points whose point (panel p, point j) solves to 10 p + j: it logs the driver's calls and
  /// checks every value it has in a row.
  class CountingMap final : public MapStrategy
  {
  public:
    explicit CountingMap(const bool keyed)
      : keyed(keyed)
    {}
    std::size_t panels() const override { return 2; }
    std::size_t points(std::size_t) const override { return 3; }
    void open_panel(const std::size_t panel, SceneResult &, bool) override { log.push_back("open " + std::to_string(panel)); }
    std::optional<MapPointKey> point_key(const std::size_t panel, const std::size_t point) const override
    {
      if (!keyed)
        return std::nullopt;
      return MapPointKey{"counting map point", std::to_string(panel) + ", " + std::to_string(point)};
    }
    void solve(const std::size_t panel, const std::size_t point, SceneResult &, bool) override
    {
      log.push_back("solve " + std::to_string(panel) + " " + std::to_string(point));
      values[{panel, point}] = 10. * panel + point;
    }
    nlohmann::json stored(const std::size_t panel, const std::size_t point) const override
    {
      return values.at({panel, point});
    }
    void restore(const std::size_t panel, const std::size_t point, const nlohmann::json &value) override
    {
      log.push_back("read " + std::to_string(panel) + " " + std::to_string(point));
      values[{panel, point}] = value.get<double>();
    }
    void close_panel(const std::size_t panel, const fs::path &, SceneResult &result, bool) override
    {
      log.push_back("close " + std::to_string(panel));
      for (const auto &[at, value] : values)
        if (at.first == panel)
          result.rows.push_back(compare("value", std::to_string(at.second), "solve", "exact", 10. * panel + at.second,
                                        value, 1., 1e-12, 0, 0.));
    }
    MapReport report(const fs::path &, bool) override
    {
      Table table({Column::both("value", "value")});
      for (const auto &[at, value] : values)
        table.add({value});
      return {table, "# counting map\n\n" + table.md()};
    }
    void plot(const fs::path &) override { log.push_back("plot"); }

    std::vector<std::string> log;
    std::map<std::pair<std::size_t, std::size_t>, double> values;

  private:
    bool keyed;
  };
} // namespace

TEST_CASE("The map pipeline shall run a map's panels and points in order, cache its keyed points and share them "
          "among shards", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-map-pipeline");
  const fs::path report = folder.path() / "reports" / "counting";
  fs::create_directories(report);
  const MapRun run{report, "the resolved parameters", true, false};

  // Points without a key: each solved, panel by panel, then the report and the plots.
  CountingMap plain(false);
  SceneResult solved;
  run_map(plain, run, solved);
  CHECK(plain.log == std::vector<std::string>{"open 0", "solve 0 0", "solve 0 1", "solve 0 2", "close 0", "open 1",
                                              "solve 1 0", "solve 1 1", "solve 1 2", "close 1", "plot"});
  CHECK(solved.rows.size() == 6);
  CHECK(testing::read_csv(report / "map.csv").size() == 7);
  CHECK(testing::read_text(report / "map.md").find("# counting map") == 0);
  MapShard halves{0, 2};
  CHECK_THROWS_WITH(run_map(plain, run, halves, solved), Catch::Contains("not cached"));
  fs::remove(report / "map.csv");

  // Keyed points: shard 0 of 2 solves the points j % 2 == 0 and writes no report; shard 1 reads those and solves
  // its own; a run without shards reads all six and writes the report.
  CountingMap first(true), second(true), whole(true);
  MapShard    first_half{0, 2}, second_half{1, 2}, all;
  SceneResult r0, r1, r;
  run_map(first, run, first_half, r0);
  CHECK(first_half.computed == 3);
  CHECK(first_half.skipped == 3);
  CHECK(first_half.cached == 0);
  CHECK(r0.rows.size() == 3);
  CHECK_FALSE(fs::exists(report / "map.csv"));
  CHECK(std::find(first.log.begin(), first.log.end(), "plot") == first.log.end());
  run_map(second, run, second_half, r1);
  CHECK(second_half.computed == 3);
  CHECK(second_half.cached == 3);
  CHECK(second_half.skipped == 0);
  run_map(whole, run, all, r);
  CHECK(all.cached == 6);
  CHECK(all.computed == 0);
  REQUIRE(r.rows.size() == 6);
  for (const Row &row : r.rows)
    CHECK(row.pass);
  CHECK(testing::read_csv(report / "map.csv").size() == 7);
  MapShard beyond{2, 2};
  CHECK_THROWS_WITH(run_map(whole, run, beyond, r), Catch::Contains("shard 2/2"));
}

TEST_CASE("A map scene with a load it cannot map shall be an error naming the entries", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-map-bad");
  const fs::path scene = folder.path() / "bad_map.prm";
  std::ofstream(scene) << "subsection Load\n  set type = constant pressure\nend\n"
                          "subsection Map\n  set parameter = surface depth\n  set values = 1\nend\n";
  CHECK_THROWS_WITH(read_scene(scene.string(), {}), Catch::Contains("bad_map.prm") && Catch::Contains("Map/parameter") &&
                                                  Catch::Contains("constant pressure"));
}

TEST_CASE("An error-function scene shall name its entries, values and ranges when they are bad", "[cases][quick]")
{
  using testing::scene_with;
  const std::vector<std::string> erf{"Material/modulus=error function", "Material/k=0", "Material/erf width=1e-5"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), erf.begin(), erf.end());
    return scene_with(extra);
  };
  CHECK(with({}).material.modulus == MaterialParameters::Modulus::error_function);
  CHECK_THROWS_WITH(with({"Material/erf width=0"}), Catch::Contains("Material/erf width = 0") &&
                                                      Catch::Contains("(0, inf)") && Catch::Contains("error function"));
  CHECK_THROWS_WITH(with({"Material/k=0.5"}), Catch::Contains("Material/k = 0.5 must be 0"));
  CHECK_THROWS_WITH(with({"Material/surface modulus ratio=0"}),
                    Catch::Contains("Material/surface modulus ratio = 0") && Catch::Contains("(0, inf)"));
  // A map over a/w needs k = 0, from Material/k or every Map/k value.
  CHECK_THROWS_WITH(scene_with({"Map/parameter=erf width", "Map/values=1"}),
                    Catch::Contains("Map/parameter = erf width with k = 0.5 (Material/k)"));
  CHECK_THROWS_WITH(scene_with({"Map/parameter=erf width", "Map/values=1", "Map/k values=0, 0.25"}),
                    Catch::Contains("k = 0.25 (Map/k values)"));
  CHECK(scene_with({"Map/parameter=erf width", "Map/values=1", "Material/k=0"}).kind == SceneKind::map);
}

TEST_CASE("The load-displacement exponent of a map shall be exact for power-law deviations", "[cases][quick]")
{
  // With 1 + dF = (a/w)^beta and 1 + da = (a/w)^gamma, ln d = n (1 - gamma) ln(a/w) + const and
  // ln F = (n + 1)/n ln d + beta ln(a/w): N = (n + 1)/n + beta / (n (1 - gamma)) on every interval.
  const double n = GENERATE(2.0, 1.0, 1.5), beta = -0.3, gamma = 0.1;
  const std::vector<double> ratios{0.01, 0.1, 1, 10, 1e3};
  std::vector<double> force, radius;
  for (const double r : ratios)
    {
      force.push_back(std::pow(r, beta) - 1);
      radius.push_back(std::pow(r, gamma) - 1);
    }
  const auto exponents = load_exponents(n, ratios, force, radius);
  REQUIRE(exponents.size() == ratios.size() - 1);
  for (const LoadExponent &e : exponents)
    {
      CAPTURE(n, e.ratio_low, e.exponent);
      CHECK_THAT(e.exponent, Catch::Matchers::WithinRel((n + 1) / n + beta / (n * (1 - gamma)), 1e-12));
    }
  CHECK_THAT(load_exponents(n, {1, 10}, {0, 0}, {0, 0}).front().exponent, Catch::Matchers::WithinRel((n + 1) / n, 1e-15));
  CHECK_THROWS_WITH(load_exponents(n, {1, 10}, {0}, {0, 0}), Catch::Contains("2 ratios, 1 force"));
  CHECK_THROWS_WITH(load_exponents(0, {1, 10}, {0, 0}, {0, 0}), Catch::Contains("n = 0"));
}

TEST_CASE("An erf-width map shall write the published comparison with the trend of its own points", "[cases]")
{
  // A stiff skin (m = 10) under a paraboloid, coarse: the exponent dips below Hertz's 1.5 between the limits.
  const TemporaryFolder folder("gradcontact-map-erf");
  const fs::path scene = folder.path() / "erf_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0\n  set surface modulus ratio = 10\nend\n"
                          "subsection Load\n  set type = paraboloid\n  set a = 1e-4\n  set R = 5e-3\nend\n"
                          "subsection Discretization\n  set degree = 1\n  set force tolerance = 1e-3\nend\n"
                          "subsection Tolerances\n  set force = 1e-2\n  set contact radius = 1e-2\n"
                          "  set pressure = 1e-1\nend\n"
                          "subsection Map\n  set parameter = erf width\n  set values = 0.1, 1, 10\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const std::string md = testing::read_text(reports / "erf_map" / "map.md");
  CHECK(md.find("within 1 % when a/w |") != std::string::npos);
  CHECK(md.find("### Published comparison") != std::string::npos);
  CHECK(md.find("Int. J. Eng. Sci. 47 (2009) 1274-1283") != std::string::npos);
  CHECK(md.find("| 0.1 - 1 |") != std::string::npos);
  CHECK(md.find("closer to linear than the homogeneous half-space, as published") != std::string::npos);
  const auto csv = testing::read_csv(reports / "erf_map" / "map.csv");
  REQUIRE(csv.size() == 4);
  CHECK(csv[0][1] == "a_over_w");
}

TEST_CASE("An indenter-modulus map at k = 0 shall be Hertz's two elastic bodies", "[cases]")
{
  // A homogeneous indenter E1 = ratio E0 (nu1 = nu = 0.3) on a homogeneous half-space: at a given depth Hertz's
  // force scales with E* = (1/E*_0 + 1/E*_1)^-1, so F / F_rigid - 1 = -x / (1 + x), x = E0 / E1 (equal nu), and
  // the contact radius a = sqrt(R d) does not change. The 1 % threshold is where x / (1 + x) = 0.01: E1/E0 = 99.
  const TemporaryFolder folder("gradcontact-indenter-map");
  const fs::path scene = folder.path() / "hertz_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0\n  set nu = 0.3\nend\n"
                          "subsection Load\n  set type = paraboloid\n  set a = 1e-4\n  set R = 5e-3\nend\n"
                          "subsection Indenter\n  set nu = 0.3\nend\n"
                          "subsection Discretization\n  set degree = 2\nend\n"
                          "subsection Tolerances\n  set force = 1e-4\n  set contact radius = 1e-4\n"
                          "  set pressure = 1e-3\nend\n"
                          "subsection Map\n  set parameter = indenter modulus\n  set values = 1, 10, 100, 1000\n"
                          "  set thresholds = 0.01\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "hertz_map";
  const auto csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 5);
  CHECK(csv[0][1] == "E1_over_E0");
  for (std::size_t i = 1; i < csv.size(); ++i)
    {
      const double ratio = std::stod(csv[i][1]), x = 1 / ratio;
      CAPTURE(ratio, csv[i][2], csv[i][3]);
      CHECK(std::stod(csv[i][2]) == Approx(-x / (1 + x)).margin(1e-4));
      CHECK(std::abs(std::stod(csv[i][3])) < 1e-4);
    }
  // The threshold cell of the force: log-log interpolation between 10 and 100 of -x/(1+x) (not a power law:
  // within 0.2 % of 99).
  const std::string md = testing::read_text(out / "map.md");
  const std::string row = "| 0 | force | >= ";
  const auto at = md.find(row);
  REQUIRE(at != std::string::npos);
  CHECK(std::stod(md.substr(at + row.size())) == Approx(99.).epsilon(2e-3));
  // The sharp checks (the rigid limit and two graded bodies by 9.4) are rows of errors.csv, and pass.
  const auto errors = testing::read_csv(out / "errors.csv");
  REQUIRE(errors.size() >= 7);
  for (std::size_t i = 1; i < errors.size(); ++i)
    CHECK(errors[i][9] == "pass");
}

TEST_CASE("A friction map shall read its threshold toward mu -> 0 and read full stick on its own", "[cases][quick]")
{
  // |deviation| = 0.02 mu (the linear regime of full slip) crosses 1e-3 at mu = 0.05; full stick is read apart.
  const std::vector<double> mus{0.01, 0.1, 0.3, 1};
  std::vector<double> deviations;
  for (const double mu : mus)
    deviations.push_back(0.02 * mu);
  const std::string at = friction_threshold_cell(mus, deviations, 0.03, 1e-3);
  REQUIRE(at.rfind("<= ", 0) == 0);
  CHECK(std::stod(at.substr(3)) == Approx(0.05).epsilon(1e-5));
  CHECK(friction_threshold_cell(mus, deviations, 0.03, 0.1) == "at every mu (full stick included)");
  CHECK(friction_threshold_cell(mus, deviations, 0.3, 0.1) == "at every mu up to 1, not at full stick");
  CHECK(friction_threshold_cell(mus, deviations, std::nullopt, 0.1) == "at every mu up to 1");
  CHECK(friction_threshold_cell({}, {}, 0.05, 0.1) == "at full stick");
}

// Label slow (./vv test --all): the default tier keeps friction's sharp check at Holl's ratio (tests/fem) and the
// other map kinds' pipeline.
TEST_CASE("A friction map shall check the frictionless FE and Holl's ratio, and write the map of (k, nu, mu)",
          "[slow]")
{
  // k = 0.5, nu = 0.2 and Holl's ratio 0.4: at 0.4 friction changes nothing (exact: the sharp-check rows pass); at
  // 0.2 full stick raises the force at the depth.
  const TemporaryFolder folder("gradcontact-friction-map");
  const fs::path scene = folder.path() / "friction_map.prm";
  std::ofstream(scene) << "subsection Material\n  set nu = 0.2\nend\n"
                          "subsection Load\n  set type = paraboloid\n  set a = 1e-4\n  set R = 5e-3\nend\n"
                          "subsection Friction\n  set load steps = 6\nend\n"
                          "subsection Discretization\n  set degree = 2\n  set force tolerance = 1e-2\nend\n"
                          "subsection Tolerances\n  set force = 1e-2\n  set contact radius = 1e-2\n"
                          "  set pressure = 5e-2\nend\n"
                          "subsection Map\n  set parameter = friction coefficient\n  set values = 1\n"
                          "  set k values = 0.5\n  set thresholds = 0.01\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "friction_map";
  for (const char *file : {"errors.csv", "map.csv", "map.md"})
    CHECK(fs::exists(out / file));
  // map.csv: k, nu, mu, the deviations, c/a, ...; nu = 0.2 (mu = 1, inf), then Holl's 0.4 (mu = 1, inf).
  const auto csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 5);
  CHECK(csv[0][1] == "nu");
  CHECK(csv[0][2] == "mu");
  CHECK(csv[0][6] == "stick_radius_over_a");
  CHECK(csv[4][2] == "inf");
  for (std::size_t i = 1; i < csv.size(); ++i)
    {
      const double nu = std::stod(csv[i][1]), force = std::stod(csv[i][3]), stick = std::stod(csv[i][6]);
      CAPTURE(nu, csv[i][2], force, stick);
      CHECK(csv[i][9].empty());
      CHECK(stick > 0);
      CHECK(stick <= 1);
      if (nu < 0.3)
        CHECK(force > 1e-3);
      else
        CHECK(std::abs(force) < 1e-6);
    }
  // The sharp checks (the frictionless FE against the closed forms; at Holl's ratio friction against none) pass.
  const auto errors = testing::read_csv(out / "errors.csv");
  REQUIRE(errors.size() == 11);
  for (std::size_t i = 1; i < errors.size(); ++i)
    CHECK(errors[i][9] == "pass");
  const std::string md = testing::read_text(out / "map.md");
  CHECK(md.find("## k = 0.5, nu = 1/(2 + k) = 0.4") != std::string::npos);
  CHECK(md.find("within 1 % when mu |") != std::string::npos);
  CHECK(md.find("## The largest effect of friction") != std::string::npos);
}

TEST_CASE("The Tabor parameter of a graded medium shall be Maugis' at k = 0", "[cases][quick]")
{
  // Maugis: lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^{1/3}, from a path that knows nothing of the chapter's
  // Delta_l or its critical radius.
  const double E0 = 1e9, nu = 0.3, R = 5e-3, dgamma = 0.05;
  const gradcontact::Medium m = gradcontact::medium(gradcontact::GradedHalfSpace{E0, 1e-3, 0, nu});
  for (const double lambda : {0.05, 1.0, 10.0})
    {
      const double sigma0 = cohesive_strength(lambda, m, gradcontact::Paraboloid{R}, dgamma);
      CHECK(gradcontact::maugis_dugdale::tabor_parameter(sigma0, dgamma, R, E0 / (1 - nu * nu)) ==
            Approx(lambda).epsilon(1e-12));
    }
  CHECK_THROWS_WITH(cohesive_strength(-1, m, gradcontact::Paraboloid{R}, dgamma), Catch::Contains("lambda = -1"));
}

TEST_CASE("The graded Maugis-Dugdale threshold shall be where Maugis' closed form leaves JKR at k = 0", "[cases][quick]")
{
  // Reference: bisection in lambda on Maugis' dimensionless pull-off (analytic/maugis_dugdale.h, k = 0 closed form)
  // against JKR's -3/2 (force) and -5/6 (displacement; "no jump" counts as 100 %), written here.
  const double E0 = 1e9, nu = 0.3, R = 5e-3, dgamma = 0.05;
  const gradcontact::Medium m = gradcontact::medium(gradcontact::GradedHalfSpace{E0, 1e-3, 0, nu});
  for (const bool force_control : {true, false})
    for (const double t : {0.1, 0.01})
      {
        const auto deviation = [&](const double lambda) {
          const auto p = gradcontact::maugis_dugdale::pull_off(lambda, force_control ? gradcontact::Control::force
                                                                                     : gradcontact::Control::displacement);
          return p.exists ? std::abs(p.state.P / (force_control ? -1.5 : -5.0 / 6) - 1) : 1.0;
        };
        double lo = 0.05, hi = 100; // deviation(lo) > t > deviation(hi), one crossing between
        REQUIRE(deviation(lo) > t);
        REQUIRE(deviation(hi) < t);
        for (int i = 0; i < 60; ++i)
          (deviation(std::sqrt(lo * hi)) > t ? lo : hi) = std::sqrt(lo * hi);
        const auto at = graded_maugis_dugdale_threshold(m, gradcontact::Paraboloid{R}, dgamma, force_control, t);
        REQUIRE(at);
        // (Under displacement control the force sits at the flat minimum of d(a), known to ~1e-8 by either search:
        // the crossing moves by ~1e-6.)
        CHECK(*at == Approx(hi).epsilon(1e-5));
      }
  // Not within it up to lambda = 1000 (JKR's deviation there is about 1e-5); refusals.
  CHECK_FALSE(graded_maugis_dugdale_threshold(m, gradcontact::Paraboloid{R}, dgamma, true, 1e-8));
  CHECK_THROWS_WITH(graded_maugis_dugdale_threshold(m, gradcontact::Paraboloid{R}, dgamma, true, 0),
                    Catch::Contains("threshold = 0"));
}

TEST_CASE("A graded Maugis-Dugdale row shall read a jump that one side alone finds by its depth", "[cases][quick]")
{
  // Where d(a) is flat as the contact vanishes (small lambda), the FE can find a minimum of d that the reference
  // does not (the power-law tip n = 4 at k = 0, lambda = 0.3, just short of the vanishing depth): the row
  // then compares depths. The reference's own states (analytic/maugis_dugdale.h) give the depths here.
  namespace md = gradcontact::maugis_dugdale;
  const gradcontact::Medium   m = gradcontact::medium(gradcontact::GradedHalfSpace{2e9, 3e-4, 0, 0.3});
  const gradcontact::PowerLaw tip{4, 2e9};
  const double                dgamma = 0.05, sigma0 = md::strength(m, tip, dgamma, 0.3);
  REQUIRE_FALSE(md::pull_off(m, tip, md::Dugdale{sigma0, dgamma}, gradcontact::Control::displacement).exists);
  const double end = md::vanishing_contact(m, tip, md::Dugdale{sigma0, dgamma}).depth;
  const auto   row = [&](const double depth) {
    return graded_maugis_dugdale_row(m, tip, sigma0, dgamma, false, true, -0.01, depth, "test", "FE", 1e-3, 1e-3, 0, 0);
  };
  REQUIRE(row(end * (1 + 5.5e-5)));
  CHECK(row(end * (1 + 5.5e-5))->pass);
  CHECK(row(end * (1 + 5.5e-5))->metric.find("Maugis-Dugdale none") != std::string::npos);
  CHECK_FALSE(row(end * 0.99)->pass); // a jump 1 % from the vanishing depth is a real disagreement
  // Neither side has a jump: nothing to compare.
  CHECK_FALSE(graded_maugis_dugdale_row(m, tip, sigma0, dgamma, false, false, -0.01, end, "test", "FE", 1e-3, 1e-3, 0, 0));
}

// Label slow (./vv test --all): the default tier keeps the cohesive zone's Maugis-Dugdale checks (tests/fem) and the
// Dugdale example scenes.
TEST_CASE("A Tabor-parameter map shall check Maugis-Dugdale at k = 0 and write the map", "[slow]")
{
  const TemporaryFolder folder("gradcontact-cohesive-map");
  const fs::path scene = folder.path() / "cohesive_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0\nend\n"
                          "subsection Load\n  set type = paraboloid\n  set R = 5e-3\nend\n"
                          "subsection Adhesion\n  set work of adhesion = 0.05\n  set control = force\nend\n"
                          "subsection Discretization\n  set degree = 2\nend\n"
                          "subsection Tolerances\n  set force = 1e-4\nend\n"
                          "subsection Map\n  set parameter = Tabor parameter\n  set values = 1, 3\n"
                          "  set thresholds = 0.1\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "cohesive_map";
  for (const char *file : {"errors.csv", "map.csv", "map.md"})
    CHECK(fs::exists(out / file));
  const auto csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 3);
  CHECK(csv[0][7] == "force_deviation");
  // Maugis-Dugdale: F_c / F_c,JKR = 1.0672 at lambda = 1 and 1.0112 at 3 (Johnson & Greenwood.s
  // equations, tests/analytic/test_maugis_dugdale.cc checks their limits): the deviation falls toward JKR.
  CHECK(std::stod(csv[1][7]) == Approx(0.0672).margin(2e-3));
  CHECK(std::stod(csv[2][7]) < std::stod(csv[1][7]));
  const auto errors = testing::read_csv(out / "errors.csv");
  REQUIRE(errors.size() == 5); // header, Maugis-Dugdale at 1 and 3, the JKR and DMT trends
  for (std::size_t i = 1; i < errors.size(); ++i)
    CHECK(errors[i][9] == "pass");
  const std::string md = testing::read_text(out / "map.md");
  CHECK(md.find("within 10 % when lambda |") != std::string::npos);

  // Two --map-shard jobs fill the point cache of a fresh folder (one lambda each), no report; the run without it
  // writes the same map from their points, solving nothing.
  const fs::path sharded = folder.path() / "sharded";
  for (const char *shard : {"0/2", "1/2"})
    REQUIRE(run({scene.string(), "--reports", sharded.string(), "--quiet", "--map-shard", shard}) == 0);
  CHECK_FALSE(fs::exists(sharded / "cohesive_map"));
  CHECK(std::distance(fs::directory_iterator(sharded / ".map-points"), fs::directory_iterator{}) == 2);
  REQUIRE(run({scene.string(), "--reports", sharded.string(), "--quiet"}) == 0);
  // every column equal to the unsharded run's, except the solve times: those are the shards' (read, not solved again)
  const auto assembled = testing::read_csv(sharded / "cohesive_map" / "map.csv");
  REQUIRE(assembled.size() == csv.size());
  const auto seconds = std::find(csv[0].begin(), csv[0].end(), "seconds") - csv[0].begin();
  for (std::size_t i = 0; i < csv.size(); ++i)
    for (std::size_t j = 0; j < csv[i].size(); ++j)
      if (static_cast<long>(j) != seconds || i == 0)
        CHECK(assembled[i][j] == csv[i][j]);
  // a rerun of the unsharded folder reads its own points: the same table, times included
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  CHECK(testing::read_csv(out / "map.csv") == csv);
  CHECK_THROWS_WITH(run({scene.string(), "--reports", sharded.string(), "--map-shard", "2/2"}),
                    Catch::Contains("--map-shard '2/2'"));
}

TEST_CASE("A Coulomb 3D map shall read the shipped scene and name the entries it cannot take", "[cases][quick]")
{
  const Scene shipped = read_scene("cases/validation/map_coulomb_3d_sphere.prm", {});
  CHECK(shipped.kind == SceneKind::map);
  CHECK(shipped.map.parameter == MapParameters::Parameter::coulomb_3d);
  CHECK(shipped.tangential.study == TangentialParameters::Study::oscillation);

  using testing::scene_with;
  const std::vector<std::string> base{"Map/parameter=Coulomb 3D", "Tangential/study=oscillation", "Load/type=paraboloid",
                                      "Load/R=5e-3", "Friction/coefficient=0.3"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), base.begin(), base.end());
    return scene_with(extra);
  };
  CHECK(with({}).kind == SceneKind::map);
  CHECK_THROWS_WITH(scene_with({"Map/parameter=Coulomb 3D", "Load/type=paraboloid"}),
                    Catch::Contains("Tangential/study = oscillation"));
  CHECK(with({"Map/values=0.1, 0.3"}).map.values.size() == 2); // the friction coefficients
  CHECK_THROWS_WITH(with({"Map/values=0"}), Catch::Contains("Map/values: 0 must be in (0, inf)"));
  CHECK_THROWS_WITH(with({"Load/type=flat punch"}), Catch::Contains("Load/type = paraboloid"));
  CHECK(with({"Map/nu values=0.3, 0.5"}).map.poisson_ratios.size() == 2); // nu = 1/2 runs the mixed 3D element
  CHECK_THROWS_WITH(with({"Tangential/Holl ratio=true"}), Catch::Contains("use Map/Holl ratio"));
  CHECK_THROWS_WITH(with({"Load/R=1e-5"}), Catch::Contains("Load/a < Load/R"));
}

TEST_CASE("A Lennard-Jones Tabor map shall follow the path from DMT toward JKR and refuse the law elsewhere", "[cases]")
{
  const TemporaryFolder folder("gradcontact-lennard-jones-map");
  const fs::path scene = folder.path() / "lj_map.prm";
  std::ofstream(scene) << "subsection Material\n  set k = 0\nend\n"
                          "subsection Load\n  set type = paraboloid\n  set R = 5e-3\nend\n"
                          "subsection Adhesion\n  set work of adhesion = 0.05\n  set control = both\n"
                          "  set law = Lennard-Jones\nend\n"
                          "subsection Map\n  set parameter = Tabor parameter\n  set values = 0.3, 1\n"
                          "  set thresholds = 0.1\nend\n";
  const fs::path reports = folder.path() / "reports";
  REQUIRE(run({scene.string(), "--reports", reports.string(), "--quiet"}) == 0);
  const fs::path out = reports / "lj_map";
  const auto     csv = testing::read_csv(out / "map.csv");
  REQUIRE(csv.size() == 5); // header, (0.3, 1) x (force, displacement)
  REQUIRE(csv[0][7] == "force_deviation");
  REQUIRE(csv[0][16] == "vanishing_contact");
  // Force control: between DMT (F_c / F_c,JKR = 4/3 at k = 0) and JKR, falling toward JKR.
  for (const std::size_t row : {1, 3})
    {
      CHECK(csv[row][2] == "force");
      CHECK(std::stod(csv[row][7]) > 0);
      CHECK(std::stod(csv[row][7]) < 1.0 / 3.0);
    }
  CHECK(std::stod(csv[3][7]) < std::stod(csv[1][7]));
  // Displacement control: no jump at lambda = 0.3 (the contact shrinks to nothing), a jump at 1 (Greenwood 1997).
  CHECK(csv[2][16] == "1");
  CHECK(csv[4][16] == "0");
  const auto errors = testing::read_csv(out / "errors.csv");
  REQUIRE(errors.size() == 4); // header, the JKR trends of both controls, the DMT trend
  for (std::size_t i = 1; i < errors.size(); ++i)
    CHECK(errors[i][9] == "pass");
  const std::string md = testing::read_text(out / "map.md");
  CHECK(md.find("Lennard-Jones law") != std::string::npos);

  using testing::scene_with;
  CHECK_THROWS_WITH(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones"}),
                    Catch::Contains("Lennard-Jones runs in Tabor-parameter maps and adhesive candidates only"));
  CHECK_THROWS_WITH(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones",
                                "Map/parameter=Tabor parameter", "Map/values=1", "Adhesion/Tabor parameter=2"}),
                    Catch::Contains("Map/values gives the lambdas"));
  CHECK_THROWS_WITH(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones",
                                "Map/parameter=Tabor parameter", "Map/values=1, 50"}),
                    Catch::Contains("Map/values: lambda = 50"));
}
