#include "runners/stress_map.h"
#include "report/map_pipeline.h"
#include "model/fe_stress.h"
#include "model/scene_start.h"
#include "report/table.h"

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/subsurface.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

namespace gradcontact::cases
{
  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// The real grading's length over a: z0 of a finite surface modulus, H of a coating (0 for the power law).
    double grading_length(const Scene &s)
    {
      if (s.material.modulus == MaterialParameters::Modulus::shifted_power_law)
        return s.material.surface_depth / s.load.a;
      if (s.material.modulus == MaterialParameters::Modulus::coating)
        return s.material.coating_thickness / s.load.a;
      return 0;
    }

    std::string grading_text(const Scene &s)
    {
      std::ostringstream t;
      if (s.material.modulus == MaterialParameters::Modulus::shifted_power_law)
        t << "the finite surface modulus E0 ((z + z0)/c0)^k, z0 = " << grading_length(s) << " a";
      else if (s.material.modulus == MaterialParameters::Modulus::coating)
        t << "a coating E0 (z/c0)^k of thickness H = " << grading_length(s) << " a on its substrate";
      else
        t << "E0 (z/c0)^k";
      return t.str();
    }

    /// One measure of one (k, nu): closed form and FE, the stress over p_m, the place over a.
    struct MapRow
    {
      double         k = 0, nu = 0;
      std::string    measure;
      StressMaximum  closed_form{nan, nan, nan}; ///< of the power law (none on k < 0)
      FeStressMaximum fe;
      std::string    refused; ///< the FE's limit when it could not vouch for the tolerance
      double         seconds = 0;
      bool           checked = true; ///< the closed form is exact here (else the FE's deviation from it is reported)
    };

    /// The rows of both measures of one (k, nu) on `sphere` (of the scene's grading): the FE searches share their
    /// first grid. The closed form is the power law's (none on k < 0, where it has no largest stress); it checks the
    /// FE where it is exact: on the power law, and on a real grading at k = 0 (a homogeneous body).
    std::vector<MapRow> rows_of(const double k, const double nu, const bool power_law, UnitSphere &sphere)
    {
      const std::vector<std::string> measures = {"max_shear", "von_mises"};
      const auto                     start    = std::chrono::steady_clock::now();
      std::vector<FeStressMaximum>   fe       = largest_fe_stresses(sphere, measures);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const Medium               medium = gradcontact::medium(GradedHalfSpace{1.0, 1.0, k, nu});
      const AxisymmetricPressure load   = contact_pressure(medium, Paraboloid{1.0}, 1.0);
      const double               p_m    = force(medium, Paraboloid{1.0}, 1.0) / M_PI;
      const double               tolerance = sphere.solver().tolerance();
      std::vector<MapRow>        rows;
      for (std::size_t m = 0; m < measures.size(); ++m)
        {
          MapRow row;
          row.k       = k;
          row.nu      = nu;
          row.measure = measures[m];
          row.checked = power_law || k == 0;
          if (k >= 0)
            {
              row.closed_form = largest_stress(PointLoadField(k, nu), load,
                                               m == 1 ? StressMeasure::von_mises : StressMeasure::max_shear);
              row.closed_form.value /= p_m;
            }
          row.fe      = std::move(fe[m]);
          row.seconds = seconds / measures.size();
          if (!row.fe.run.met && !(row.fe.at_point.relative() <= tolerance && row.fe.at_point.levels.size() >= 3))
            row.refused = row.fe.run.limit;
          // Over the closed form's p_m on the power law, over the FE's own on a real grading.
          const double scale = power_law ? p_m : row.fe.run.result.force / M_PI;
          row.fe.value.value /= scale;
          row.fe.value.error /= scale;
          rows.push_back(std::move(row));
        }
      return rows;
    }

    Table table_of(const std::vector<MapRow> &rows)
    {
      const auto fe = [](const MapRow &r, const fem::Estimated &e) { return r.refused.empty() ? Cell(e.value) : Cell(); };
      const auto est = [](const MapRow &r, const fem::Estimated &e) { return r.refused.empty() ? Cell(e.error) : Cell(); };
      const auto closed = [](const double x) { return std::isfinite(x) ? Cell(x) : Cell(); };
      std::vector<Field<MapRow>> fields = {
        {Column::both("k", "k"), [](const MapRow &r) { return Cell(r.k); }},
        {Column::both("nu", "nu"), [](const MapRow &r) { return Cell(r.nu); }},
        {Column::both("measure", "measure"), [](const MapRow &r) { return Cell(r.measure); }},
        {Column::both("closed_form", "closed form / p_m").md_as({'g', 8}),
         [&](const MapRow &r) { return closed(r.closed_form.value); }},
        {Column::both("fe", "FE / p_m").md_as({'g', 8}), [&](const MapRow &r) { return fe(r, r.fe.value); }},
        {Column::both("fe_estimate", "FE estimate").md_as({'e', 1}),
         [&](const MapRow &r) { return est(r, r.fe.value); }},
        {Column::both("depth_closed_form", "depth / a, closed form").md_as({'g', 6}),
         [&](const MapRow &r) { return closed(r.closed_form.z); }},
        {Column::both("depth_fe", "depth / a, FE").md_as({'g', 6}), [&](const MapRow &r) { return fe(r, r.fe.z); }},
        {Column::both("depth_estimate", "its estimate").md_as({'e', 1}), [&](const MapRow &r) { return est(r, r.fe.z); }},
        {Column::both("radius_closed_form", "radius / a, closed form").md_as({'g', 6}),
         [&](const MapRow &r) { return closed(r.closed_form.r); }},
        {Column::both("radius_fe", "radius / a, FE").md_as({'g', 6}), [&](const MapRow &r) { return fe(r, r.fe.r); }}};
      if (std::any_of(rows.begin(), rows.end(), [](const MapRow &r) { return !r.checked; }))
        fields.push_back({Column::both("deviation", "FE / power law - 1").md_as({'e', 2}), [](const MapRow &r) {
                            return r.refused.empty() && std::isfinite(r.closed_form.value) ?
                                     Cell(r.fe.value.value / r.closed_form.value - 1) :
                                     Cell();
                          }});
      fields.push_back({Column::both("seconds", "FE s").md_as({'f', 1}), [](const MapRow &r) { return Cell(r.seconds); }});
      fields.push_back({Column::both("refused", "FE refused").quoted(), [](const MapRow &r) { return Cell(r.refused); }});
      return tabulate(fields, rows);
    }

    /// The scene's errors rows: the FE's value and depth against the closed form, each within 3x its estimate.
    void add_checks(const MapRow &r, SceneResult &result)
    {
      std::ostringstream where;
      where << "k = " << r.k << ", nu = " << r.nu << ", ";
      const std::string quantity = "largest " + r.measure;
      if (!r.refused.empty())
        {
          result.rows.push_back(failed(quantity, "FE", "closed form", "refused: " + r.refused));
          return;
        }
      if (!r.checked)
        return; // a real grading off k = 0: no exact reference; the table reports its deviation from the power law
      const auto check = [&](const std::string &q, const double ref, const fem::Estimated &e) {
        const double scale = std::abs(ref) > 0 ? std::abs(ref) : 1.0;
        Row row = compare(q, where.str() + "relative, within 3x the FE estimate", "FE", "closed form", ref, e.value,
                          scale, 3 * e.error / scale, r.fe.run.level_dofs.empty() ? 0 : r.fe.run.level_dofs.back(),
                          r.seconds);
        row.estimate = e.error / scale;
        result.rows.push_back(row);
      };
      check(quantity, r.closed_form.value, r.fe.value);
      check(quantity + " depth", r.closed_form.z, r.fe.z);
    }

    /// The map as a strategy of the map pipeline: a panel per (nu, k), one point each (both measures of one FE
    /// search), map.csv and map.md one table.
    class StressMap final : public MapStrategy
    {
    public:
      explicit StressMap(const Scene &scene)
        : s(scene)
      {
        const std::vector<double> exponents = s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
        const std::vector<double> ratios =
          s.map.poisson_ratios.empty() ? std::vector<double>{s.material.nu} : s.map.poisson_ratios;
        for (const double nu : ratios)
          for (const double k : exponents)
            bodies.emplace_back(k, nu);
      }

      std::size_t panels() const override { return bodies.size(); }
      std::size_t points(std::size_t) const override { return 1; }

      void solve(const std::size_t panel, std::size_t, SceneResult &result, const bool verbose) override
      {
        const auto [k, nu]   = bodies.at(panel);
        const bool power_law = s.material.modulus == MaterialParameters::Modulus::power_law;
        UnitSphere sphere(s.material.modulus, k, nu, grading_length(s), s.discretization.force_tolerance);
        for (MapRow &row : rows_of(k, nu, power_law, sphere))
          {
            add_checks(row, result);
            if (verbose)
              std::cout << "  k = " << k << ", nu = " << nu << ", " << row.measure << ": closed form "
                        << row.closed_form.value << ", FE " << row.fe.value.value << "\n";
            rows.push_back(std::move(row));
          }
      }

      void close_panel(std::size_t, const std::filesystem::path &, SceneResult &, bool) override {}

      MapReport report(const std::filesystem::path &, bool) override
      {
        const Table        table = table_of(rows);
        std::ostringstream md;
        md << "# " << s.info.name << ": the largest stresses below a sphere\n\n"
           << "The paraboloid at contact radius a on " << grading_text(s) << ": the largest shear and von Mises stress "
           << "over p_m = F / (pi a^2), with their depth and radius over a. Closed form: the graded Boussinesq field of "
           << "the power law E0 (z/c0)^k superposed over its contact pressure (analytic/subsurface.h); FE: the recovered "
           << "stress field on the accuracy contract's ladder at an asked tolerance of "
           << format(s.discretization.force_tolerance) << ", with its estimates (cases/model/fe_stress.h). A row passes "
           << "when the FE is within 3x its estimate of the closed form, where that is exact (the power law; a real "
           << "grading at k = 0, a homogeneous body); elsewhere on a real grading the FE is the reference, its p_m its "
           << "own, and the last columns give its deviation from the power law's closed form (none on k < 0, where the "
           << "power law has no largest stress).\n\n"
           << table.md();
        return {table, md.str()};
      }

      void plot(const std::filesystem::path &) override {} // the map is a table

    private:
      const Scene                           &s;
      std::vector<std::pair<double, double>> bodies; ///< (k, nu), nu-major
      std::vector<MapRow>                    rows;
    };
  } // namespace

  std::unique_ptr<MapStrategy> stress_map_strategy(const Scene &s)
  {
    require_kind(s, SceneKind::map, "stress_map_strategy");
    return std::make_unique<StressMap>(s);
  }
} // namespace gradcontact::cases
