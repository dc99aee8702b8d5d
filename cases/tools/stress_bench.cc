#include "tools/stress_bench.h"
#include "tools/fe_oracle.h"
#include "report/table.h"

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <vector>

namespace gradcontact::cases
{
  using json = nlohmann::json;

  namespace
  {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();

    /// One row: a quantity of one (k, nu), closed form and FE, in units of p_m (a stress) or a (a length).
    struct Row
    {
      double      k = 0, nu = 0;
      std::string quantity;
      double      closed_form = nan, fe = nan, estimate = nan, seconds = 0;
      double      tolerance = nan; ///< the one the FE answered at
      unsigned    dofs = 0;
      std::string note;
    };

    /// The paraboloid of radius 1 at contact radius 1 on E = z^k (c0 = 1): the requests' common part.
    json sphere(const double k, const double nu)
    {
      return {{"case", "paraboloid"},
              {"material", {{"E0", 1.0}, {"c0", 1.0}, {"k", k}, {"nu", nu}}},
              {"geometry", {{"R", 1.0}}},
              {"a", 1.0}};
    }

    double closed_form(json request)
    {
      return batch::evaluate(batch::parse(request));
    }

    /// The stress component `component` at (r, z) by the closed form.
    double stress_at(const double k, const double nu, const std::string &component, const double r, const double z)
    {
      json q         = sphere(k, nu);
      q["quantity"]  = "stress";
      q["component"] = component;
      q["r"]         = r;
      q["z"]         = z;
      return closed_form(q);
    }

    /// The largest f over the box by a grid of n_r x n_z points and two refinements of a 5 x 5 grid about the best at a
    /// quarter of the steps (the closed-form side of the rows that have no maximum search of their own).
    /// `where` with a warning when (r, z) lies on an edge of the box [r0, r1] x [z0, z1] other than the axis: there is no
    /// interior maximum in the box, and the value is its edge's.
    std::string on_box_edge(std::string where, const double r, const double z, const double r1, const double z0,
                            const double z1)
    {
      if (r == r1 || (z0 < z1 && (z == z0 || z == z1)))
        where += " (on the searched box's edge: no maximum inside it)";
      return where;
    }

    std::pair<double, double> grid_maximum(const std::function<double(double, double)> &f, double r0, double r1,
                                           const unsigned n_r, double z0, double z1, const unsigned n_z)
    {
      double best = -std::numeric_limits<double>::infinity(), br = r0, bz = z0;
      double dr = n_r > 1 ? (r1 - r0) / (n_r - 1) : 0, dz = n_z > 1 ? (z1 - z0) / (n_z - 1) : 0;
      const auto consider = [&](const double r, const double z) {
        if (r < r0 || r > r1 || z < z0 || z > z1)
          return;
        const double v = f(r, z);
        if (v > best)
          best = v, br = r, bz = z;
      };
      for (unsigned i = 0; i < n_r; ++i)
        for (unsigned j = 0; j < n_z; ++j)
          consider(r0 + i * dr, z0 + j * dz);
      for (unsigned pass = 0; pass < 2; ++pass)
        {
          dr /= 4;
          dz /= 4;
          const double cr = br, cz = bz;
          for (int i = -2; i <= 2; ++i)
            for (int j = -2; j <= 2; ++j)
              consider(cr + i * dr, cz + j * dz);
        }
      return {br, bz};
    }

    /// Answers `request` by the FE oracle into `row` (value / scale, estimate / scale, time, DoFs): at `tolerance`, or
    /// when refused at ten times it, up to 1e-2 (the refusals noted, the tolerance answered in the row).
    void fe_answer(FeOracle &oracle, json request, const double tolerance, const double scale, Row &row)
    {
      request["method"] = "fe";
      const auto start  = std::chrono::steady_clock::now();
      for (double asked = tolerance; asked <= 1e-2 * (1 + 1e-9) && !std::isfinite(row.fe); asked *= 10)
        try
          {
            request["tolerance"]     = asked;
            const FeOracle::Answer a = oracle.evaluate(request);
            row.fe                   = a.value / scale;
            row.estimate             = a.error_estimate / scale;
            row.dofs                 = a.dofs;
            row.tolerance            = asked;
          }
        catch (const std::exception &e)
          {
            row.note += (row.note.empty() ? "" : "; ") + std::string(e.what());
          }
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// The rows of one (k, nu).
    std::vector<Row> rows_of(const double k, const double nu, const double tolerance)
    {
      FeOracle   oracle;
      json       force = sphere(k, nu);
      force["quantity"] = "force";
      const double p_m  = closed_form(force) / M_PI;
      std::vector<Row> rows;
      const auto add = [&](const std::string &quantity, const json &request, const double cf, const double scale,
                           const std::string &note) {
        Row row;
        row.k           = k;
        row.nu          = nu;
        row.quantity    = quantity;
        row.closed_form = cf / scale;
        fe_answer(oracle, request, tolerance, scale, row);
        if (!note.empty())
          row.note = note + (row.note.empty() ? "" : "; " + row.note);
        rows.push_back(row);
      };
      if (k >= 0)
        for (const auto &[quantity, what, scale] :
             {std::tuple{"max_stress", "largest shear / p_m", p_m}, std::tuple{"max_stress_depth", "its depth / a", 1.0},
              std::tuple{"max_stress_radius", "its radius / a", 1.0}})
          {
            json q         = sphere(k, nu);
            q["quantity"]  = quantity;
            q["component"] = "max_shear";
            add(what, q, closed_form(q), scale, "");
          }
      else
        {
          const auto [r, z] = grid_maximum(
            [&](const double x, const double y) { return stress_at(k, nu, "max_shear", x, y); }, 0, 2, 41, 0.05, 1,
            20);
          json q = sphere(k, nu);
          q.update({{"quantity", "stress"}, {"component", "max_shear"}, {"r", r}, {"z", z}});
          std::ostringstream where;
          where << "largest shear for z >= 0.05 a, at (r, z) = (" << r << ", " << z << ") a";
          add("largest shear / p_m (z >= 0.05 a)", q, stress_at(k, nu, "max_shear", r, z), p_m,
              on_box_edge(where.str(), r, z, 2, 0.05, 1));
        }
      const double z_surface = 1e-3;
      const auto   ring      = grid_maximum(
        [&](const double x, const double y) { return stress_at(k, nu, "rr", x, y); }, 1, 2, 101, z_surface, z_surface, 1);
      json q = sphere(k, nu);
      q.update({{"quantity", "stress"}, {"component", "rr"}, {"r", ring.first}, {"z", z_surface}});
      std::ostringstream where;
      where << "at r = " << ring.first << " a";
      add("largest sigma_rr / p_m at z = 1e-3 a, r >= a", q, stress_at(k, nu, "rr", ring.first, z_surface), p_m,
          on_box_edge(where.str(), ring.first, z_surface, 2, z_surface, z_surface));
      return rows;
    }

    Table table_of(const std::vector<Row> &rows)
    {
      const auto difference = [](const Row &r) { return std::abs(r.fe - r.closed_form); };
      const std::vector<Field<Row>> fields = {
        {Column::both("k", "k"), [](const Row &r) { return Cell(r.k); }},
        {Column::both("nu", "nu"), [](const Row &r) { return Cell(r.nu); }},
        {Column::both("quantity", "quantity").quoted(), [](const Row &r) { return Cell(r.quantity); }},
        {Column::both("closed_form", "closed form").md_as({'g', 8}),
         [](const Row &r) { return Cell(r.closed_form); }},
        {Column::both("fe", "FE").md_as({'g', 8}),
         [](const Row &r) { return std::isfinite(r.fe) ? Cell(r.fe) : Cell(); }},
        {Column::both("difference", "FE - closed form").md_as({'e', 1}),
         [&](const Row &r) { return std::isfinite(r.fe) ? Cell(difference(r)) : Cell(); }},
        {Column::both("estimate", "FE estimate").md_as({'e', 1}),
         [](const Row &r) { return std::isfinite(r.estimate) ? Cell(r.estimate) : Cell(); }},
        {Column::both("tolerance", "asked"),
         [](const Row &r) { return std::isfinite(r.tolerance) ? Cell(r.tolerance) : Cell(); }},
        {Column::both("seconds", "FE s").md_as({'f', 1}), [](const Row &r) { return Cell(r.seconds); }},
        {Column::both("dofs", "DoFs"), [](const Row &r) { return r.dofs ? Cell(r.dofs) : Cell(); }},
        {Column::both("note", "note").quoted(), [](const Row &r) { return Cell(r.note); }}};
      return tabulate(fields, rows);
    }
  } // namespace

  int run_stress_bench(const StressBenchOptions &options, const std::filesystem::path &folder,
                       const std::string &machine)
  {
    std::vector<Row> rows;
    const std::vector<double> exponents = options.quick ? std::vector<double>{0.0} : std::vector<double>{-0.5, 0, 0.5};
    const std::vector<double> ratios    = options.quick ? std::vector<double>{0.3} : std::vector<double>{0.3, 0.45};
    for (const double nu : ratios)
      for (const double k : exponents)
        for (const Row &r : rows_of(k, nu, options.tolerance))
          rows.push_back(r);
    int broken = 0;
    for (const Row &r : rows)
      if (std::isfinite(r.fe) ? !(std::abs(r.fe - r.closed_form) <= 3 * r.estimate + 1e-12) : r.note.empty())
        ++broken;
    const Table        table = table_of(rows);
    std::ostringstream md;
    md << "# The stresses below a sphere: closed form against FE\n\n"
       << "Written by `gradcontact bench --part stresses` on " << machine << ". The paraboloid at contact radius a on "
       << "E0 (z/c0)^k; stresses over p_m = F / (pi a^2), lengths over a. Closed form: the graded Boussinesq field "
       << "superposed over the contact pressure (analytic/subsurface.h); FE: `gradcontact eval` with \"method\": "
       << "\"fe\" at an asked tolerance of " << format(options.tolerance, Number{}) << " (the accuracy contract, its "
       << "estimate beside it), or where refused at ten times it and so on up to 1e-2 (column asked; the note keeps "
       << "the refusals and the limits they name). On k < 0 no largest stress exists (the skin's radial and hoop stresses grow without "
       << "bound toward the surface): the row gives the largest shear below z = 0.05 a on a grid of the closed form, "
       << "and the FE at that point. Answers further from the closed form than 3x their estimate: " << broken
       << ".\n\n"
       << table.md();
    write_table_files(folder, "stresses", table, md.str());
    return broken;
  }
} // namespace gradcontact::cases
