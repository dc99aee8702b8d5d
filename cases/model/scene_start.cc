#include "model/scene_start.h"

#include "report/table.h"

#include <fem/base/table_file.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  namespace
  {
    /// Material/modulus = table: the power law E0 (z/c0)^k closest to the table where the contact feels it, by least
    /// squares of ln E over ln z on the rows 0 < z <= 3 Load/a (all rows with z > 0 when fewer than 3 lie there), so
    /// that a user sees which power law the measured grading is near, and can rerun against it.
    std::string table_fit_note(const Scene &s)
    {
      fs::path table(s.material.table_file);
      if (table.is_relative() && !s.file.empty())
        table = fs::path(s.file).parent_path() / table;
      const fem::TableFile rows = fem::read_table_file(table.string(), "Material/table file", "z", "E");
      const auto fit = [&](const double z_max) {
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (std::size_t i = 0; i < rows.x.size(); ++i)
          if (rows.x[i] > 0 && rows.x[i] <= z_max && rows.y[i] > 0)
            {
              const double x = std::log(rows.x[i] / s.material.c0), y = std::log(rows.y[i]);
              n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
            }
        const double k = n >= 2 && n * sxx - sx * sx > 0 ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : std::nan("");
        return std::make_tuple(n, std::exp((sy - k * sx) / n), k);
      };
      double z_max = 3 * s.load.a;
      auto [n, E0, k] = fit(z_max);
      if (n < 3)
        {
          z_max = std::numeric_limits<double>::infinity();
          std::tie(n, E0, k) = fit(z_max);
        }
      if (!std::isfinite(k))
        return "";
      return "the table's least-squares power law over its " + format(n) + " rows with 0 < z <= " +
             (std::isfinite(z_max) ? format(z_max) + " m (3 Load/a)" : std::string("its last")) + ": E0 = " +
             format(E0) + " Pa, k = " + format(k) + " at c0 = " + format(s.material.c0) + " m" +
             (k > -1 && k < 1 ? " (--set Material/E0=" + format(E0) + " --set Material/k=" + format(k) +
                                  " checks the table against it)" :
                                " (outside -1 < k < 1, where the chapter's forms hold)");
    }
  } // namespace

  SceneResult started(const Scene &s, const fs::path &folder)
  {
    SceneResult result;
    result.name = s.info.name;
    result.description = s.info.description;
    if (s.material.modulus == MaterialParameters::Modulus::table)
      if (const std::string note = table_fit_note(s); !note.empty())
        result.description += (result.description.empty() ? "" : " ") + std::string("(") + note + ")";
    result.kind = to_string(s.kind);
    write_text(folder / "parameters.prm", s.resolved);
    return result;
  }
} // namespace gradcontact::cases
