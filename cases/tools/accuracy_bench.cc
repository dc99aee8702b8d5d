#include "tools/accuracy_bench.h"

#include "report/table.h"

#include <analytic/batch.h>
#include <fem/accuracy/accuracy.h>
#include <fem/modulus/modulus.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    /// The closed forms are exact to about 1e-13: a relative difference below this is no error.
    constexpr double reference_floor = 1e-12;

    std::string fmt(const double x, const char *f = "%.2g")
    {
      char b[32];
      std::snprintf(b, sizeof b, f, x);
      return b;
    }

    /// One profile of the unit problem (a = E0 = c0 = 1): its FE load and its closed-form request.
    struct Profile
    {
      std::string name; ///< the eval case
      double      n = 0; ///< power law f = r^n
      fem::LoadCase load() const
      {
        fem::LoadCase l;
        if (name == "flat_punch")
          {
            l.type  = fem::LoadType::flat_punch;
            l.depth = 1;
            return l;
          }
        l.type    = fem::LoadType::indenter;
        l.profile = name == "paraboloid" ? fem::Profile::paraboloid(1) :
                    name == "cone"       ? fem::Profile::cone(1) :
                                           fem::Profile::power_law(n, 1);
        return l;
      }
      json request(const double k, const double nu, const std::string &quantity) const
      {
        json q = {{"case", name}, {"quantity", quantity}, {"a", 1.0},
                  {"material", {{"E0", 1.0}, {"c0", 1.0}, {"k", k}, {"nu", nu}}}};
        if (name == "flat_punch")
          q["d"] = 1.0;
        else if (name == "paraboloid")
          q["geometry"] = {{"R", 1.0}};
        else if (name == "cone")
          q["geometry"] = {{"tan_theta", 1.0}};
        else
          q["geometry"] = {{"n", n}, {"A", 1.0}};
        return q;
      }
    };

    /// The radii every answer samples: p(r) inside the contact, w(r) outside.
    const std::vector<double> pressure_radii{0.25, 0.5, 0.9}, displacement_radii{2.0};

    /// One estimated quantity of one answer, against the closed form.
    struct Row
    {
      std::string set;   ///< grid | random
      std::string group; ///< the answer the row belongs to: "F, d, w" (the scalars and w) or "p" (the pressures)
      double      k, nu, tolerance;
      std::string profile;
      unsigned int degree, levels;
      double       dofs, seconds; ///< of the ladder (seconds: this load's run, with the levels it set up)
      bool         met;
      std::string  limit;
      std::string  quantity;
      double       true_error, estimate; ///< relative, with the contract's scale
      std::string  values;               ///< the value on every level (space-separated)
      double       reference = 0;        ///< the closed form
    };

    double closed_form(const Profile &p, const double k, const double nu, const std::string &quantity, const double r = -1)
    {
      json q = p.request(k, nu, quantity);
      if (r >= 0)
        q["r"] = r;
      return batch::evaluate(batch::parse(q));
    }

    /// Runs one load on `solver` for one answer group and appends a row per quantity: "F, d, w" asks the force,
    /// the depth and w(2 a); "p" the pressures (a second run on the same levels).
    void solve_group(fem::ContractSolver &solver, const std::string &set, const std::string &group, const double k,
                     const double nu, const Profile &p, std::vector<Row> &rows)
    {
      fem::OutputRequest outputs;
      (group == "p" ? outputs.pressure_radii : outputs.displacement_radii) =
        group == "p" ? pressure_radii : displacement_radii;
      const fem::ContractResult c = solver.run(p.load(), outputs);
      Row base{set, group, k, nu, solver.tolerance(),
               p.name + (p.name == "power_law" ? " n = " + fmt(p.n, "%.2f") : ""), c.degree,
               static_cast<unsigned>(c.level_dofs.size()), c.level_dofs.empty() ? 0. : double(c.level_dofs.back()),
               c.seconds, c.met, c.limit, "", 0, 0, ""};
      const auto add = [&](const std::string &name, const fem::Estimated &e, const double exact) {
        Row row        = base;
        row.quantity   = name;
        row.true_error = std::abs(e.value - exact) / e.scale;
        row.estimate   = e.relative();
        row.reference  = exact;
        for (const double v : e.levels)
          row.values += (row.values.empty() ? "" : " ") + fmt(v, "%.10g");
        rows.push_back(row);
      };
      if (c.level_dofs.size() < 2)
        {
          base.quantity = "-";
          base.true_error = base.estimate = std::nan("");
          rows.push_back(base);
          return;
        }
      if (group == "p")
        {
          for (std::size_t i = 0; i < c.pressure.size(); ++i)
            add("p(" + fmt(pressure_radii[i]) + " a)", c.pressure[i],
                closed_form(p, k, nu, "pressure", pressure_radii[i]));
          return;
        }
      add("force", c.force, closed_form(p, k, nu, "force"));
      if (p.name != "flat_punch")
        add("depth", c.depth, closed_form(p, k, nu, "depth"));
      for (std::size_t i = 0; i < c.displacement.size(); ++i)
        add("w(" + fmt(displacement_radii[i]) + " a)", c.displacement[i],
            closed_form(p, k, nu, "displacement", displacement_radii[i]));
    }

    /// Both answer groups of one load, with a line of progress.
    void solve_point(fem::ContractSolver &solver, const std::string &set, const double k, const double nu,
                     const Profile &p, std::vector<Row> &rows)
    {
      for (const std::string group : {"F, d, w", "p"})
        {
          solve_group(solver, set, group, k, nu, p, rows);
          std::cerr << "accuracy: " << set << ", k = " << fmt(k, "%.3f") << ", nu = " << fmt(nu, "%.3f") << ", "
                    << p.name << ", tolerance " << fmt(solver.tolerance()) << ", " << group << ": "
                    << (rows.back().met ? "met" : "refused: " + rows.back().limit) << "\n";
        }
    }

    fem::Material unit_material(const double k, const double nu)
    {
      return {std::make_shared<fem::PowerLawModulus>(1.0, 1.0, k), nu};
    }

    /// The grid: every (k, nu, tolerance) one ladder, solved for each profile on the same levels.
    void run_grid(const bool quick, const std::vector<double> &asked_ks, std::vector<Row> &rows)
    {
      const std::vector<double> ks = !asked_ks.empty() ? asked_ks :
                                     quick             ? std::vector<double>{-0.9, 0., 0.9} :
                                                         std::vector<double>{-0.95, -0.9, -0.5, 0., 0.5, 0.9, 0.95};
      const std::vector<double> nus = quick ? std::vector<double>{0.3} : std::vector<double>{0.3, 0.5};
      const std::vector<double> tolerances =
        quick ? std::vector<double>{1e-3} : std::vector<double>{1e-2, 1e-4, 1e-6, 1e-8};
      for (const double k : ks)
        for (const double nu : nus)
          for (const double tolerance : tolerances)
            {
              const fem::Material material = unit_material(k, nu);
              fem::ContractSolver solver(material,
                                         fem::contract_settings(1.0, material, tolerance, displacement_radii.back()),
                                         tolerance);
              // The quick grid keeps the paraboloid (the flat punch's p(r) at k = -0.9 takes the largest ladder).
              for (const char *name : {"flat_punch", "paraboloid"})
                if (!quick || std::string(name) == "paraboloid")
                  solve_point(solver, "grid", k, nu, Profile{name}, rows);
            }
    }

    /// Held-out requests: k, nu, tolerance and profile drawn at random (a fixed seed).
    void run_random(const bool quick, std::vector<Row> &rows)
    {
      std::mt19937_64 random(20261127);
      const auto uniform = [&random](const double lo, const double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
      };
      const unsigned int n = quick ? 2 : 16;
      for (unsigned int i = 0; i < n; ++i)
        {
          const double k = uniform(-0.95, 0.95), nu = uniform(0., 0.5);
          const double tolerance = std::pow(10., quick ? uniform(-4, -2) : uniform(-8, -2));
          const int    which     = static_cast<int>(uniform(0, 4));
          const Profile p{which == 0 ? "flat_punch" : which == 1 ? "paraboloid" : which == 2 ? "cone" : "power_law",
                          uniform(1.2, 3.)};
          const fem::Material material = unit_material(k, nu);
          fem::Settings settings = fem::contract_settings(1.0, material, tolerance, displacement_radii.back());
          fem::grade_axis(settings, p.load());
          fem::ContractSolver solver(material, settings, tolerance);
          solve_point(solver, "random", k, nu, p, rows);
        }
    }

    /// A promise is broken by an answer that misses its tolerance, and by a refusal that does not name its limit. The
    /// estimate's reliability goes into a table of the report (write_estimate_table), not a promise per answer.
    bool broken(const Row &r)
    {
      if (!r.met)
        return r.limit.empty();
      return r.true_error > r.tolerance + reference_floor;
    }

    /// accuracy.csv: every answer's row.
    Table answers_table(const std::vector<Row> &rows)
    {
      Table csv({Column::csv_only("set"), Column::csv_only("group").quoted(), Column::csv_only("k"),
                 Column::csv_only("nu"), Column::csv_only("profile"), Column::csv_only("tolerance"),
                 Column::csv_only("degree"), Column::csv_only("levels"), Column::csv_only("dofs"),
                 Column::csv_only("seconds"), Column::csv_only("met"), Column::csv_only("limit").quoted(),
                 Column::csv_only("quantity"), Column::csv_only("true_error"), Column::csv_only("estimate"),
                 Column::csv_only("true_over_asked"), Column::csv_only("true_over_estimate"),
                 Column::csv_only("reference").csv_as(Number{'g', 10}), Column::csv_only("level_values")});
      for (const Row &r : rows)
        csv.add({r.set, r.group, r.k, r.nu, r.profile, r.tolerance, r.degree, r.levels, r.dofs, r.seconds, r.met ? 1 : 0,
                 r.limit, r.quantity, r.true_error, r.estimate, r.true_error / r.tolerance, r.true_error / r.estimate,
                 r.reference, r.values});
      return csv;
    }

    /// The contract per (k, tolerance) of one answer group: the worst true error / asked of the answers, or the
    /// refusals' limits.
    void write_contract_table(const std::vector<Row> &rows, const std::string &group, std::ostream &md)
    {
      struct Cell
      {
        double      worst = 0;
        bool        answered = false;
        std::string refusals;
      };
      std::map<double, std::map<double, Cell>> cells; // k -> tolerance
      std::vector<double> tolerances;
      for (const Row &r : rows)
        {
          if (r.set != "grid" || r.group != group)
            continue;
          if (std::find(tolerances.begin(), tolerances.end(), r.tolerance) == tolerances.end())
            tolerances.push_back(r.tolerance);
          Cell &cell = cells[r.k][r.tolerance];
          const std::string limit = r.limit.substr(0, r.limit.find_first_of(":;"));
          if (r.met)
            cell.answered = true, cell.worst = std::max(cell.worst, r.true_error / r.tolerance);
          else if (cell.refusals.find(limit) == std::string::npos)
            cell.refusals += (cell.refusals.empty() ? "" : ", ") + limit;
        }
      std::sort(tolerances.rbegin(), tolerances.rend());
      md << "\n## The contract on the grid: " << (group == "p" ? "the pressures p(r) at r = 0.25, 0.5, 0.9 a" :
                                                                   "the force, the depth and w(2 a)")
         << "\n\nWorst true error / asked tolerance over nu and the profiles of the answers that met the contract "
            "(\"-\": none did); \"refused\" names the limits of the others (accuracy.csv has each).\n\n| k |";
      for (const double t : tolerances)
        md << " asked " << fmt(t, "%.0e") << " |";
      md << "\n|---|";
      for (std::size_t i = 0; i < tolerances.size(); ++i)
        md << "---|";
      md << '\n';
      for (const auto &[k, by_tolerance] : cells)
        {
          md << "| " << k << " |";
          for (const double t : tolerances)
            {
              const auto found = by_tolerance.find(t);
              if (found == by_tolerance.end())
                {
                  md << " |";
                  continue;
                }
              const Cell &c = found->second;
              md << ' ' << (c.answered ? fmt(c.worst, "%.2f") : "-")
                 << (c.refusals.empty() ? "" : "; refused: " + c.refusals) << " |";
            }
          md << '\n';
        }
    }

    double quantile(std::vector<double> v, const double f)
    {
      if (v.empty())
        return std::nan("");
      std::sort(v.begin(), v.end());
      return v[static_cast<std::size_t>(f * (v.size() - 1))];
    }

    /// Reliability and efficiency of the estimate, per set.
    void write_estimate_table(const std::vector<Row> &rows, std::ostream &md)
    {
      md << "\n## The error estimate\n\nOver every estimated quantity, of the answers and of the refusals (whose "
            "ladders stopped before their estimates converged). Reliable: the true "
            "error is below the estimate; true errors below "
         << fmt(reference_floor, "%.0e")
         << " (the closed forms' own precision) count as zero. Efficiency: estimate / true error.\n\n"
            "| set | quantities | true <= estimate | worst true / estimate | estimate / true: median | 90 % | "
            "above 10 | reliable (>= 95 %, never above 3x) |\n|---|---|---|---|---|---|---|---|\n";
      for (const std::string set : {"grid", "random"})
        for (const std::string group : {"F, d, w", "p"})
        for (const bool met : {true, false})
        {
          std::vector<double> over, efficiency;
          std::size_t         below = 0, inefficient = 0;
          for (const Row &r : rows)
            if (r.set == set && r.group == group && r.met == met && !std::isnan(r.true_error))
              {
                const double t = std::max(r.true_error, reference_floor);
                over.push_back(t / r.estimate);
                below += r.true_error <= r.estimate + reference_floor;
                efficiency.push_back(r.estimate / t);
                inefficient += r.estimate > 10 * t;
              }
          if (over.empty())
            continue;
          md << "| " << set << ", " << group << (met ? ", answered" : ", refused") << " | " << over.size() << " | " << fmt(100. * below / over.size(), "%.1f") << " % | "
             << fmt(quantile(over, 1), "%.2f") << " | " << fmt(quantile(efficiency, 0.5), "%.2f") << " | "
             << fmt(quantile(efficiency, 0.9), "%.1f") << " | " << inefficient << " | "
             << (below >= 0.95 * over.size() && quantile(over, 1) <= 3 ? "yes" : "no") << " |\n";
        }
    }

    /// The cost per k and tolerance: DoFs of the finest level, levels and seconds (the largest over nu and the
    /// profiles).
    void write_cost_table(const std::vector<Row> &rows, std::ostream &md)
    {
      std::map<std::pair<double, double>, Row> worst;
      for (const Row &r : rows)
        if (r.set == "grid")
          {
            Row &w = worst.try_emplace({r.k, r.tolerance}, r).first->second;
            w.dofs    = std::max(w.dofs, r.dofs);
            w.levels  = std::max(w.levels, r.levels);
            w.seconds = std::max(w.seconds, r.seconds);
          }
      md << "\n## Work and precision\n\nPer k and asked tolerance: the degree of the ladder's finest level, its levels and the DoFs of "
            "that level, and the wall time of one answer with the levels it set up (the largest over nu and the "
            "profiles; one core).\n\n| k | asked | degree | levels | DoFs | s |\n|---|---|---|---|---|---|\n";
      for (const auto &[key, r] : worst)
        md << "| " << key.first << " | " << fmt(key.second, "%.0e") << " | " << r.degree << " | " << r.levels << " | "
           << fmt(r.dofs, "%.0f") << " | " << fmt(r.seconds, "%.1f") << " |\n";
    }
  } // namespace



  int run_accuracy_bench(const AccuracyBenchOptions &options, const fs::path &folder, const std::string &machine)
  {
    for (const double k : options.ks)
      if (!(k > -1 && k < 1))
        throw std::invalid_argument("bench: --k = " + fmt(k) + " is outside (-1, 1)");
    std::vector<Row> rows;
    run_grid(options.quick, options.ks, rows);
    if (options.ks.empty())
      run_random(options.quick, rows);

    int n_broken = 0, refusals = 0, answers = 0;
    for (const Row &r : rows)
      n_broken += broken(r);
    for (const Row &r : rows)
      if (r.quantity == "force" || r.quantity == "p(0.25 a)" || r.quantity == "-") // the first row of an answer
        ++answers, refusals += !r.met;
    std::ostringstream md;
    md << "# The accuracy contract: asked tolerance, true error, estimate and cost\n\nMachine: " << machine
       << ".  \nThe FE ladder of fem/accuracy/accuracy.h (hp: one degree more and a finer geometric mesh at the "
          "contact edge per level) until the Richardson estimate of every quantity is within the asked tolerance "
          "(on k < 0 with the rounding probe's change added), or a refusal naming the limit, against the chapter's "
          "closed forms, unit problem a = E0 = c0 = 1"
       << (options.quick ? " (quick grid)" : "") << ". " << answers << " answers, " << refusals << " refused, "
       << n_broken << " broken promises (an answer off by more than its tolerance, or a refusal that does not name its "
       << "limit).\n";
    write_contract_table(rows, "F, d, w", md);
    write_contract_table(rows, "p", md);
    write_estimate_table(rows, md);
    write_cost_table(rows, md);
    write_table_files(folder, "accuracy", answers_table(rows), md.str());
    std::cerr << "accuracy: " << answers << " answers, " << refusals << " refused, " << n_broken
              << " broken promises\n";
    return n_broken;
  }
} // namespace gradcontact::cases
