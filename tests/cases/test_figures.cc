// `gradcontact figures` on the one figure that takes a fraction of a second (Fig. 9.14, the stretch factor of
// 9.29): it draws the plot and writes data a reader can check. The reference of the k = 0 curve is the
// classical stretch factor of a power-law profile f = A r^n in the MDR, kappa(n) = sqrt(pi) Gamma(n/2 + 1) /
// Gamma(n/2 + 1/2) (Popov and Hess, Method of Dimensionality Reduction, 2015, ch. 3), written out here.
#include "scene_files.h"

#include <cases/figures.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace gradcontact::cases;
namespace fs = std::filesystem;
using testing::TemporaryFolder;

TEST_CASE("gradcontact figures shall draw Fig. 9.14 and its k = 0 curve shall be the classical stretch factor",
          "[cases]")
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
