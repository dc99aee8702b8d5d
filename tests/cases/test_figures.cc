// `gradcontact figures` on the one figure that takes a fraction of a second (Fig. 9.14, the stretch factor of
// 9.29): it draws the plot and writes data a reader can check. The reference of the k = 0 curve is the
// classical stretch factor of a power-law profile f = A r^n in the MDR, kappa(n) = sqrt(pi) Gamma(n/2 + 1) /
// Gamma(n/2 + 1/2) (Popov and Hess, Method of Dimensionality Reduction, 2015, ch. 3), written out here.
#include "scene_files.h"

#include <cases/tools/figures.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

TEST_CASE("gradcontact figures shall draw Fig. 9.14 and its k = 0 curve shall be the classical stretch factor",
          "[cases][quick]")
{
  const TemporaryFolder reports("gradcontact-figure");
  REQUIRE(figures({"cases/figures/fig_9_14_stretch_factor.json", "--reports", reports.path().string()}) == 0);
  const fs::path stem = reports.path() / "figures" / "fig_9_14_stretch_factor";
  for (const char *ext : {".dat", ".gp", ".svg", ".png"})
    {
      CAPTURE(ext);
      REQUIRE(fs::exists(stem.string() + ext));
      CHECK(fs::file_size(stem.string() + ext) > 0);
    }

  // The data: one block per curve, "# <title>" then "x y" lines.
  std::ifstream in(stem.string() + ".dat");
  std::string   block;
  int           curves = 0, checked = 0;
  double        worst  = 0;
  for (std::string line; std::getline(in, line);)
    {
      if (line.rfind("# ", 0) == 0)
        {
          block = line.substr(2);
          ++curves;
          continue;
        }
      if (block != "k = 0.0" || line.empty())
        continue;
      std::istringstream s(line);
      double n = 0, kappa = 0;
      REQUIRE(static_cast<bool>(s >> n >> kappa));
      const double exact = std::sqrt(M_PI) * std::tgamma(n / 2 + 1) / std::tgamma(n / 2 + 0.5);
      worst = std::max(worst, std::abs(kappa / exact - 1));
      ++checked;
    }
  CHECK(curves == 5);
  CHECK(checked == 120);
  CAPTURE(worst);
  CHECK(worst < 1e-10); // the data keep 12 significant digits
}

// The check of a figure's points, on a figure small enough to run in a test: the Boussinesq flat punch (k = 0
// of 9.14), p / p_mean = 1 / (2 sqrt(1 - r^2/a^2)), drawn by the closed form, and points tabulated here from
// that formula written out (independent of the code under test). Three cases: exact points pass; one wrong
// point fails; a curve drawn over a shorter range than the points fails the points it no longer covers.
namespace
{
  double boussinesq_over_mean(const double r) { return 0.5 / std::sqrt(1 - r * r); }

  // A figure with the k = 0 flat-punch pressure swept over [0, r_max] and the points (r, y) checked against it.
  std::string punch_figure(const double r_max, const std::vector<double> &r, const std::vector<double> &y,
                           const double tolerance = 1e-6)
  {
    std::ostringstream s;
    s.precision(17);
    const std::string material = R"({"E0": 1, "c0": 1, "k": 0, "nu": 0.3})";
    s << R"({"name": "punch", "figure": "test", "title": "punch", "curves": [)"
      << R"({"title": "k = 0", "sweep": {"key": "r", "from": 0, "to": )" << r_max << R"(, "points": 50},)"
      << R"("x": {"sweep": true}, "y": {"request": {"case": "flat_punch", "quantity": "pressure", "material": )"
      << material << R"(, "a": 1, "d": 1}, "scale": 3.141592653589793, "divide_by": {"case": "flat_punch", )"
      << R"("quantity": "force", "material": )" << material << R"(, "a": 1, "d": 1}}},)"
      << R"({"title": "points", "points": {"x": [)";
    for (std::size_t i = 0; i < r.size(); ++i)
      s << (i ? ", " : "") << r[i];
    s << R"(], "y": [)";
    for (std::size_t i = 0; i < y.size(); ++i)
      s << (i ? ", " : "") << y[i];
    s << R"(]}, "check": {"curves": ["k = 0"], "tolerance": )" << tolerance << R"(, "why": "test"}}]})";
    return s.str();
  }

  struct Checked
  {
    int exit_code = -1;
    std::vector<std::vector<std::string>> rows; // punch.csv without its header
  };

  /// Draws `figure` (named `name`) from <folder>/<name>.json into `reports`.
  Checked draw_figure(const TemporaryFolder &folder, const fs::path &reports, const std::string &name,
                      const std::string &figure)
  {
    const fs::path file = folder.path() / (name + ".json");
    std::ofstream(file) << figure;
    Checked c;
    c.exit_code = figures({file.string(), "--reports", reports.string()});
    c.rows = testing::read_csv(reports / "figures" / (name + ".csv"));
    c.rows.erase(c.rows.begin());
    return c;
  }

  Checked draw_punch(const TemporaryFolder &folder, const std::string &figure)
  {
    return draw_figure(folder, folder.path(), "punch", figure);
  }

  const std::vector<double> radii = {0.1, 0.5, 0.8};
  std::vector<double> exact_values()
  {
    std::vector<double> y;
    for (const double r : radii)
      y.push_back(boussinesq_over_mean(r));
    return y;
  }
} // namespace

TEST_CASE("gradcontact figures shall pass points that lie on their closed form and tabulate each one", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-check");
  const Checked c = draw_punch(folder, punch_figure(0.9, radii, exact_values()));
  CHECK(c.exit_code == 0);
  REQUIRE(c.rows.size() == radii.size());
  for (const auto &row : c.rows)
    {
      CAPTURE(row);
      CHECK(row[7] == "true");
      CHECK(std::stod(row[5]) < 1e-9); // the closed form at the same abscissa, not an interpolation
    }
  const std::string md = testing::read_text(folder.path() / "figures" / "punch.md");
  CHECK(md.find("| points | 0.5 |") != std::string::npos);
  const std::string index = testing::read_text(folder.path() / "figures" / "index.md");
  CHECK(index.find("[punch.md](punch.md)") != std::string::npos);
}

TEST_CASE("gradcontact figures shall fail on a point beyond its tolerance", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-wrong");
  std::vector<double> y = exact_values();
  y[1] *= 1.01; // 1 % off at r = a/2: above the 1e-6 tolerance
  const Checked c = draw_punch(folder, punch_figure(0.9, radii, y));
  CHECK(c.exit_code != 0);
  REQUIRE(c.rows.size() == radii.size());
  CHECK(c.rows[0][7] == "true");
  CHECK(c.rows[1][7] == "false");
  CHECK(c.rows[1][8] == "error above tolerance");
  CHECK(c.rows[2][7] == "true");
}

TEST_CASE("gradcontact figures shall fail on a point outside the drawn range of its curve", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-truncated");
  // the curve drawn to r = 0.6 a only: the exact point at r = 0.8 a has no curve under it
  const Checked c = draw_punch(folder, punch_figure(0.6, radii, exact_values()));
  CHECK(c.exit_code != 0);
  REQUIRE(c.rows.size() == radii.size());
  CHECK(c.rows[0][7] == "true");
  CHECK(c.rows[1][7] == "true");
  CHECK(c.rows[2][7] == "false");
  CHECK(c.rows[2][8].find("outside the drawn range") != std::string::npos);
}

TEST_CASE("gradcontact figures shall refuse a check tolerance outside (0, 1), naming it", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-tolerance");
  const fs::path file = folder.path() / "punch.json";
  std::ofstream(file) << punch_figure(0.9, radii, exact_values(), 2.);
  try
    {
      figures({file.string(), "--reports", folder.path().string()});
      FAIL("no error");
    }
  catch (const std::invalid_argument &e)
    {
      const std::string what = e.what();
      CAPTURE(what);
      CHECK(what.find("tolerance = 2") != std::string::npos);
      CHECK(what.find("(0, 1)") != std::string::npos);
    }
  CHECK_FALSE(fs::exists(folder.path() / "figures" / "punch.csv")); // no half-written table
}

// The same checks on real FE points: the flat punch of cases/default/fe_flat_punch.prm at k = 0.5 (one FE
// solve; the second figure takes its points from the cache of the first, keyed by the scene's resolved
// parameters). Made wrong by 1 % (scale_y), or drawn against a curve cut at r = 0.5 a, the figure shall fail.
namespace
{
  std::string fe_punch_figure(const double r_max, const double scale_y)
  {
    std::ostringstream s;
    s.precision(17);
    const std::string material = R"({"E0": 1, "c0": 1, "k": 0.5, "nu": 0.3})";
    s << R"({"name": "fe_punch", "title": "fe punch", "curves": [)"
      << R"({"title": "k = 0.5", "sweep": {"key": "r", "from": 0, "to": )" << r_max << R"(, "points": 60},)"
      << R"("x": {"sweep": true}, "y": {"request": {"case": "flat_punch", "quantity": "pressure", "material": )"
      << material << R"(, "a": 1, "d": 1}, "scale": 3.141592653589793, "divide_by": {"case": "flat_punch", )"
      << R"("quantity": "force", "material": )" << material << R"(, "a": 1, "d": 1}}},)"
      << R"({"title": "FE", "fe": {"scene": "cases/default/fe_flat_punch.prm", "set": ["Material/k=0.5"], )"
      << R"("quantity": "pressure", "radii": [0, 0.4, 0.8], "normaliser": "force", "per_area": true}, )"
      << R"("scale_y": )" << scale_y << R"(, "check": {"curves": ["k = 0.5"], "tolerance": 1e-4, "why": "test"}}]})";
    return s.str();
  }
} // namespace

TEST_CASE("gradcontact figures shall fail on a wrong FE point and on an FE point beyond a truncated curve",
          "[cases]")
{
  const TemporaryFolder folder("gradcontact-figure-fe");
  const fs::path file = folder.path() / "fe_punch.json";
  const auto run = [&](const double r_max, const double scale_y) {
    std::ofstream(file) << fe_punch_figure(r_max, scale_y);
    const int code = figures({file.string(), "--reports", folder.path().string()});
    auto rows = testing::read_csv(folder.path() / "figures" / "fe_punch.csv");
    rows.erase(rows.begin());
    return std::make_pair(code, rows);
  };
  {
    const auto [code, rows] = run(0.9, 1.0); // the FE as it is: within 1e-4 of 9.14
    CHECK(code == 0);
    REQUIRE(rows.size() == 3);
    for (const auto &row : rows)
      {
        CAPTURE(row);
        CHECK(row[7] == "true");
      }
  }
  {
    const auto [code, rows] = run(0.9, 1.01); // every FE point 1 % high
    CHECK(code != 0);
    REQUIRE(rows.size() == 3);
    for (const auto &row : rows)
      {
        CAPTURE(row);
        CHECK(row[7] == "false");
      }
  }
  {
    const auto [code, rows] = run(0.5, 1.0); // the curve stops before the FE point at r = 0.8 a
    CHECK(code != 0);
    REQUIRE(rows.size() == 3);
    CHECK(rows[0][7] == "true");
    CHECK(rows[1][7] == "true");
    CHECK(rows[2][7] == "false");
    CHECK(rows[2][8].find("outside the drawn range") != std::string::npos);
  }
}

// The pressure profile of an fe_adhesion point set (Fig. 9.24: p(r) of the adhesive state, 9.53) is asked at
// r / a in [0, 1): p(r) is singular at the contact edge r = a and zero beyond it, so a radius there is bad input,
// refused with its name, value and valid range before any FE solve (the critical search alone costs several).
// The quantities r and pressure belong to the profile and need "pressure_radii"; mixed with a state quantity
// (radius, depth, force, k), or with radii but no profile quantity, the point set is refused too.
namespace
{
  std::string adhesive_pressure_figure(const std::string &pressure_radii, const std::string &x_quantity,
                                       const std::string &y_quantity)
  {
    std::ostringstream s;
    // a cheap analytic curve (9.53 at k = 0, 10 samples) for the point set to be checked against
    s << R"({"name": "jkr", "title": "jkr", "curves": [)"
      << R"({"title": "k = 0", "sweep": {"key": "r", "from": 0, "to": 0.25, "points": 10}, "x": {"sweep": true},)"
      << R"("y": {"request": {"case": "jkr_paraboloid", "quantity": "pressure", "material": {"E0": 1, "c0": 1,)"
      << R"("k": 0, "nu": 0.3}, "geometry": {"R": 1}, "dgamma": 0.01, "a": 0.3}}},)"
      << R"({"title": "FE", "fe_adhesion": {"scene": "cases/default/fe_jkr_paraboloid.prm", "set": ["Material/k=0"],)"
      << R"("a_over_ac": [1.0], )" << pressure_radii << R"("x": {"quantity": ")" << x_quantity
      << R"("}, "y": {"quantity": ")" << y_quantity
      << R"("}}, "check": {"curves": ["k = 0"], "tolerance": 1e-3, "why": "test"}}]})";
    return s.str();
  }

  /// The what() of the invalid_argument `figures` throws on `figure` ("" when it throws none).
  std::string refusal(const TemporaryFolder &folder, const std::string &figure)
  {
    const fs::path file = folder.path() / "jkr.json";
    std::ofstream(file) << figure;
    try
      {
        figures({file.string(), "--reports", folder.path().string()});
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

// (No brackets in a test name: ctest's discovery reads them as a CMake bracket argument and merges the names.)
TEST_CASE("gradcontact figures shall refuse an fe_adhesion pressure radius r/a outside 0 <= r/a < 1, naming the "
          "parameter, its value and the valid range",
          "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-adhesive-pressure");
  // (the bad radius as written, its position in the list)
  const auto bad_radius = GENERATE(std::make_pair(std::string("1"), 1), std::make_pair(std::string("1.5"), 1),
                                   std::make_pair(std::string("-0.1"), 0));
  const std::string bad = bad_radius.first;
  const int index = bad_radius.second;
  const std::string radii = index == 0 ? "[" + bad + ", 0.5]" : "[0.5, " + bad + "]";
  const std::string what = refusal(folder, adhesive_pressure_figure(R"("pressure_radii": )" + radii + ", ", "r", "pressure"));
  CAPTURE(bad, what);
  CHECK(what.find("pressure_radii[" + std::to_string(index) + "] = " + bad) != std::string::npos);
  CHECK(what.find("[0, 1)") != std::string::npos);
  CHECK(what.find("contact edge") != std::string::npos);
  CHECK_FALSE(fs::exists(folder.path() / "figures" / "jkr.csv")); // no table of a refused figure
  CHECK_FALSE(fs::exists(folder.path() / "figures" / "cache")); // refused before the FE: nothing cached
}

TEST_CASE("gradcontact figures shall refuse an fe_adhesion pressure profile that is asked inconsistently",
          "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-figure-adhesive-profile");
  SECTION("r and pressure without pressure_radii")
  {
    const std::string what = refusal(folder, adhesive_pressure_figure("", "r", "pressure"));
    CAPTURE(what);
    CHECK(what.find("need \"pressure_radii\"") != std::string::npos);
  }
  SECTION("pressure against a state quantity")
  {
    const std::string what = refusal(folder, adhesive_pressure_figure(R"("pressure_radii": [0.5], )", "k", "pressure"));
    CAPTURE(what);
    CHECK(what.find("x quantity 'k' and y quantity 'pressure'") != std::string::npos);
  }
  SECTION("pressure_radii without r or pressure")
  {
    const std::string what = refusal(folder, adhesive_pressure_figure(R"("pressure_radii": [0.5], )", "depth", "force"));
    CAPTURE(what);
    CHECK(what.find("\"pressure_radii\" given but neither x nor y is r or pressure") != std::string::npos);
  }
  SECTION("an unknown quantity")
  {
    const std::string what = refusal(folder, adhesive_pressure_figure("", "radius", "stress"));
    CAPTURE(what);
    CHECK(what.find("quantity 'stress' is not radius, depth, force, k, r or pressure") != std::string::npos);
  }
}

// The FE pressure points of an adhesive state end to end, at k = 0 where the critical radius under force control
// is Johnson-Kendall-Roberts' (1971), a_c = (9 pi dgamma R^2 / (8 E*))^(1/3), E* = E0 / (1 - nu^2), written out
// here: the curve is 9.53 at k = 0 (JKR's p(r)) at that a_c, the points the FE model's own critical state (one
// critical search, nu = 0.3, degree 2) at r = x a_c,FE. As they are, every point lies on the curve; made 1 % high
// (scale_y, the points taken from the cache of the first run) every point fails; and each abscissa is
// x a_c,FE, within the FE's error in a_c of x a_c.
namespace
{
  constexpr double jkr_E0 = 1, jkr_nu = 0.3, jkr_R = 1, jkr_dgamma = 0.01;

  double jkr_critical_radius()
  {
    const double E_star = jkr_E0 / (1 - jkr_nu * jkr_nu);
    return std::cbrt(9 * M_PI * jkr_dgamma * jkr_R * jkr_R / (8 * E_star));
  }

  const std::vector<double> jkr_pressure_radii = {0, 0.75, 0.9};
  // p(r) of the FE state is well within 1e-3 of max |y| (worst on the axis); 1 % of |p| at these radii is above
  // 1e-3 of max |y|, so 1e-3 passes the FE as it is and fails it 1 % off.
  constexpr double fe_jkr_tolerance = 1e-3;
  // The FE critical radius is far closer to JKR's than 1e-4: the abscissae r = x a_c,FE within 1e-4 a_c.
  constexpr double fe_jkr_radius_tolerance = 1e-4;

  std::string fe_jkr_pressure_figure(const double scale_y)
  {
    std::ostringstream s;
    s.precision(17);
    const double ac = jkr_critical_radius();
    const std::string material = R"({"E0": 1, "c0": 1, "k": 0, "nu": 0.3})";
    s << R"({"name": "fe_jkr", "title": "fe jkr", "curves": [)"
      << R"({"title": "k = 0", "sweep": {"key": "r", "from": 0, "to": )" << 0.95 * ac << R"(, "points": 40},)"
      << R"("x": {"sweep": true}, "y": {"request": {"case": "jkr_paraboloid", "quantity": "pressure", "material": )"
      << material << R"(, "geometry": {"R": 1}, "dgamma": 0.01, "a": )" << ac << R"(}}},)"
      << R"({"title": "FE", "fe_adhesion": {"scene": "cases/default/fe_jkr_paraboloid.prm", "set": ["Material/E0=1", )"
      << R"("Material/c0=1", "Material/k=0", "Material/nu=0.3", "Discretization/degree=2", "Load/R=1", "Load/a=0.3", )"
      << R"("Adhesion/work of adhesion=0.01", "Adhesion/control=force", "Adhesion/curve points=", )"
      << R"("Outputs/pressure radii=", "Outputs/displacement radii="], "control": "force", "a_over_ac": [1.0], )"
      << R"("pressure_radii": [0, 0.75, 0.9], "x": {"quantity": "r"}, "y": {"quantity": "pressure"}}, )"
      << R"("scale_y": )" << scale_y << R"(, "check": {"curves": ["k = 0"], "tolerance": )" << fe_jkr_tolerance
      << R"(, "why": "test"}}]})";
    return s.str();
  }
} // namespace

TEST_CASE("gradcontact figures shall draw the FE pressure of the adhesive critical state on JKR's p(r) (9.53 at "
          "k = 0) and fail it when it is 1 % off",
          "[cases]")
{
  const TemporaryFolder folder("gradcontact-figure-fe-jkr");
  const fs::path file = folder.path() / "fe_jkr.json";
  const auto run = [&](const double scale_y) {
    std::ofstream(file) << fe_jkr_pressure_figure(scale_y);
    const int code = figures({file.string(), "--reports", folder.path().string()});
    auto rows = testing::read_csv(folder.path() / "figures" / "fe_jkr.csv");
    rows.erase(rows.begin());
    return std::make_pair(code, rows);
  };
  {
    const auto [code, rows] = run(1.0);
    CHECK(code == 0);
    REQUIRE(rows.size() == jkr_pressure_radii.size());
    for (std::size_t j = 0; j < rows.size(); ++j)
      {
        const double x = std::stod(rows[j][1]), expected = jkr_pressure_radii[j] * jkr_critical_radius();
        CAPTURE(rows[j], expected);
        CHECK(rows[j][7] == "true");
        CHECK(std::abs(x - expected) <= fe_jkr_radius_tolerance * jkr_critical_radius());
      }
  }
  {
    const auto [code, rows] = run(1.01);
    CHECK(code != 0);
    REQUIRE(rows.size() == jkr_pressure_radii.size());
    for (const auto &row : rows)
      {
        CAPTURE(row);
        CHECK(row[7] == "false");
      }
  }
}

namespace
{
  // A small coating map (as in test_map.cc) and a figure of its force over the power law's against a/H.
  void write_small_map(const fs::path &scene)
  {
    std::ofstream(scene) << "subsection Material\n  set k = 0.5\nend\n"
                            "subsection Load\n  set type = flat punch\n  set a = 1e-4\n  set depth = 1e-6\nend\n"
                            "subsection Discretization\n  set degree = 1\n  set force tolerance = 1e-3\nend\n"
                            "subsection Tolerances\n  set force = 1e-2\n  set pressure = 1e-1\nend\n"
                            "subsection Map\n  set parameter = coating thickness\n  set values = 0.01, 1\nend\n";
  }

  std::string map_figure(const fs::path &scene, const std::string &check)
  {
    return R"({"name": "coating", "figure": "V.test", "caption": "test", "title": "coating", "logx": true, "curves": [)"
           R"({"title": "power law", "sweep": {"key": "a_over_H", "from": 1e-3, "to": 10, "points": 2, "log": true},)"
           R"("x": {"sweep": true}, "y": {"value": 1}},)"
           R"({"title": "FE", "fe_map": {"scene": ")" +
           scene.string() + R"(", "where": {"k": 0.5}, "x": "a_over_H", "y": "force_deviation"}, "offset_y": 1, )"
           R"("check": )" + check + "}]}";
  }

  const std::string measured = R"({"curves": ["power law"], "measured": true, "why": "test"})";

  Checked draw_map_figure(const TemporaryFolder &folder, const std::string &figure)
  {
    return draw_figure(folder, folder.path() / "reports", "coating", figure);
  }
} // namespace

TEST_CASE("gradcontact figures shall draw a map's points, measured, from the map report of the same parameters",
          "[cases]")
{
  const TemporaryFolder folder("gradcontact-figure-map");
  const fs::path scene = folder.path() / "small_map.prm";
  write_small_map(scene);
  // No report yet: the figure runs the map into reports/figures/maps/.
  const Checked first = draw_map_figure(folder, map_figure(scene, measured));
  CHECK(first.exit_code == 0);
  REQUIRE(first.rows.size() == 2);
  fs::path own;
  for (const auto &e : fs::directory_iterator(folder.path() / "reports" / "figures" / "maps"))
    own = e.path();
  REQUIRE(fs::exists(own / "map.csv"));
  const auto map = testing::read_csv(own / "map.csv");
  REQUIRE(map.size() == 3);
  for (std::size_t i = 0; i < 2; ++i)
    {
      CAPTURE(first.rows[i]);
      CHECK(first.rows[i][7] == "measured");
      CHECK(first.rows[i][6] == "nan"); // no tolerance
      CHECK(std::stod(first.rows[i][1]) == std::stod(map[i + 1][1]));
      CHECK(std::stod(first.rows[i][2]) == Approx(1 + std::stod(map[i + 1][2])).epsilon(1e-10)); // 12 digits
    }
  // A report of `gradcontact run` with the same resolved parameters is read instead: planted values show it.
  const fs::path run_report = folder.path() / "reports" / "small_map";
  fs::create_directories(run_report);
  fs::copy_file(own / "parameters.prm", run_report / "parameters.prm");
  std::ofstream(run_report / "map.csv") << "k,a_over_H,force_deviation,contact_radius_deviation,pressure_deviation,"
                                           "dofs,seconds,error\n0.5,0.01,0.5,nan,0,1,1,\n0.5,1,0.25,nan,0,1,1,\n"
                                           "0.25,1,7,nan,0,1,1,\n";
  const Checked planted = draw_map_figure(folder, map_figure(scene, measured));
  CHECK(planted.exit_code == 0);
  REQUIRE(planted.rows.size() == 2); // the k = 0.25 row is not selected
  CHECK(std::stod(planted.rows[0][2]) == 1.5);
  CHECK(std::stod(planted.rows[1][2]) == 1.25);
  CHECK(std::stod(planted.rows[0][5]) == Approx(0.5).epsilon(1e-12)); // |1.5 - 1| / max |y| = 1
  // The same points under a tolerance fail; a point beyond the drawn curve fails even when measured.
  CHECK(draw_map_figure(folder, map_figure(scene, R"({"curves": ["power law"], "tolerance": 0.3, "why": "t"})"))
          .exit_code != 0);
  std::ofstream(run_report / "map.csv", std::ios::app) << "0.5,100,0,nan,0,1,1,\n";
  const Checked beyond = draw_map_figure(folder, map_figure(scene, measured));
  CHECK(beyond.exit_code != 0);
  REQUIRE(beyond.rows.size() == 3);
  CHECK(beyond.rows[2][7] == "false");
  CHECK(beyond.rows[2][8].find("outside the drawn range") != std::string::npos);
  // The index lists it among the validation figures.
  const std::string index = testing::read_text(folder.path() / "reports" / "figures" / "index.md");
  CHECK(index.find("## Validation figures") != std::string::npos);
  CHECK(index.find("[coating.md](coating.md)") != std::string::npos);
}

TEST_CASE("gradcontact figures shall refuse a map point set that is asked wrongly, naming what", "[cases]")
{
  const TemporaryFolder folder("gradcontact-figure-map-bad");
  const fs::path scene = folder.path() / "small_map.prm";
  write_small_map(scene);
  const fs::path file = folder.path() / "coating.json";
  const auto refused = [&](const std::string &figure) {
    std::ofstream(file) << figure;
    try
      {
        figures({file.string(), "--reports", (folder.path() / "reports").string()});
      }
    catch (const std::exception &e)
      {
        return std::string(e.what());
      }
    return std::string("not refused");
  };
  CHECK_THAT(refused(map_figure(scene, R"({"curves": ["power law"], "measured": true, "tolerance": 0.1})")),
             Catch::Contains("\"measured\" check has no \"tolerance\""));
  const fs::path normal = folder.path() / "normal.prm";
  std::ofstream(normal) << "subsection Load\n  set type = flat punch\n  set a = 1e-4\n  set depth = 1e-6\nend\n";
  CHECK_THAT(refused(map_figure(normal, measured)), Catch::Contains("normal.prm") && Catch::Contains("no Map section"));
}
