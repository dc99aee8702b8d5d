#include "runners/fe_coulomb_3d.h"
#include "report/map_pipeline.h"

#include "report/table.h"
#include "report/thresholds.h"
#include "model/coulomb_sphere.h"
#include "model/fe_model.h"
#include "model/scene_start.h"
#include "model/mpi_session.h"

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <memory>
#include <sstream>

namespace gradcontact::cases
{
  namespace
  {
    /// One panel of the Coulomb 3D map.
    struct CoulombPanel
    {
      double k = 0, nu = 0;
      bool   holl = false; ///< nu = 1/(2 + k): decoupled
      double mu = 0;
      bool   show_mu = false; ///< the map has several mu: names and lists show it
      CoulombSphereResult result;
      std::string error; ///< why the panel has no result
    };

    /// A quantity of the map: its name, the coupling's effect, the FE floor (the decoupled path against the
    /// chapter) and the FE model against the chapter, of a panel; for the tangential quantities also the slip
    /// direction's effect (decoupled against idealised) and the idealised path against the chapter (null otherwise).
    struct MapQuantity
    {
      std::string name, chapter;
      double (*coupling)(const CoulombSphereResult &);
      double (*floor)(const CoulombSphereResult &);
      double (*direct)(const CoulombSphereResult &);
      double (*direction)(const CoulombSphereResult &) = nullptr;
      double (*idealised)(const CoulombSphereResult &) = nullptr;
    };

    double energy_deviation(const CoulombPath &p, const CoulombSphereResult &r) { return p.energy / r.energy_theory - 1; }

    const std::vector<MapQuantity> &map_quantities()
    {
      static const std::vector<MapQuantity> q{
        {"normal force", "F_N(a) (9.24 family) at the depth d",
         [](const CoulombSphereResult &r) { return r.coupling_force_z; },
         [](const CoulombSphereResult &r) { return r.decoupled.force_z_deviation; },
         [](const CoulombSphereResult &r) { return r.fe.force_z_deviation; }},
        {"tangential force", "F_x(delta) on loading (9.80)", [](const CoulombSphereResult &r) { return r.coupling_loading; },
         [](const CoulombSphereResult &r) { return r.decoupled.loading_deviation; },
         [](const CoulombSphereResult &r) { return r.fe.loading_deviation; },
         [](const CoulombSphereResult &r) { return r.direction_loading; },
         [](const CoulombSphereResult &r) { return r.idealised.loading_deviation; }},
        {"hysteresis loop", "F_x(delta) on unloading and reloading (9.84), / F_A",
         [](const CoulombSphereResult &r) { return r.coupling_branch; },
         [](const CoulombSphereResult &r) { return r.decoupled.branch_deviation; },
         [](const CoulombSphereResult &r) { return r.fe.branch_deviation; },
         [](const CoulombSphereResult &r) { return r.direction_branch; },
         [](const CoulombSphereResult &r) { return r.idealised.branch_deviation; }},
        {"dissipated energy", "the loop area (9.86)", [](const CoulombSphereResult &r) { return r.coupling_energy; },
         [](const CoulombSphereResult &r) { return energy_deviation(r.decoupled, r); },
         [](const CoulombSphereResult &r) { return energy_deviation(r.fe, r); },
         [](const CoulombSphereResult &r) { return r.direction_energy; },
         [](const CoulombSphereResult &r) { return energy_deviation(r.idealised, r); }},
        {"stick radius", "c (9.80) and b (9.81) along +x, -x, +y, / a",
         [](const CoulombSphereResult &r) { return r.coupling_stick; },
         [](const CoulombSphereResult &r) { return r.decoupled.stick_deviation; },
         [](const CoulombSphereResult &r) { return r.fe.stick_deviation; }}};
      return q;
    }

    /// One cell of a threshold table: the panels (Holl's ratio with `with_holl`) whose |effect| is within t, and
    /// those outside.
    std::string threshold_cell(const std::vector<CoulombPanel> &panels, const double t,
                               const std::function<double(const CoulombSphereResult &)> &effect, const bool with_holl,
                               const bool multiple_mu, const std::string &tuple)
    {
      std::string within, outside;
      for (const CoulombPanel &p : panels)
        if (p.error.empty() && (with_holl || !p.holl))
          {
            std::string &list = std::abs(effect(p.result)) <= t ? within : outside;
            list += (list.empty() ? "(" : ", (") + format(p.k) + ", " + format(p.nu) +
                    (multiple_mu ? ", " + format(p.mu) : "") + ")";
          }
      return outside.empty() ? "every " + tuple + " of the map"
             : within.empty() ? "none of the map (" + outside + " outside)"
                              : within + "; not " + outside;
    }

    /// The plot `stem` of |effect| over nu, one curve per (k, mu) (Holl's ratio with `with_holl`), the thresholds
    /// drawn across the nu of the curves.
    void write_nu_plot(const std::filesystem::path &folder, const std::string &stem, const std::string &title,
                       const std::string &ylabel, const std::vector<CoulombPanel> &panels,
                       const std::function<double(const CoulombSphereResult &)> &effect, const bool with_holl,
                       const bool multiple_mu, const std::vector<double> &thresholds)
    {
      std::map<std::pair<double, double>, std::vector<std::pair<double, double>>> points; // (k, mu): (nu, |effect|)
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const CoulombPanel &p : panels)
        if (p.error.empty() && (with_holl || !p.holl))
          {
            points[{p.k, p.mu}].emplace_back(p.nu, std::max(std::abs(effect(p.result)), 1e-16));
            lo = std::min(lo, p.nu);
            hi = std::max(hi, p.nu);
          }
      if (points.empty())
        return;
      std::vector<Series> series;
      for (auto &[key, xy] : points)
        {
          std::sort(xy.begin(), xy.end());
          Series curve;
          curve.title       = "k = " + format(key.first) + (multiple_mu ? ", mu = " + format(key.second) : "");
          curve.linespoints = true;
          for (const auto &[x, y] : xy)
            {
              curve.x.push_back(x);
              curve.y.push_back(y);
            }
          series.push_back(curve);
        }
      for (const double t : thresholds)
        series.push_back(Series{percent(t), {lo, hi}, {t, t}, false, false});
      std::string file = stem;
      std::replace(file.begin(), file.end(), ' ', '_');
      write_plot(folder, file, title, "nu", ylabel, series, false, true);
    }

    std::string panel_name(const CoulombPanel &p)
    {
      return "k = " + format(p.k) + ", nu = " + (p.holl ? "1/(2 + k) = " : "") + format(p.nu) +
             (p.show_mu ? ", mu = " + format(p.mu) : "");
    }

    /// What a Coulomb 3D map solves: the bodies (k, nu) and the friction coefficients.
    struct CoulombMapPlan
    {
      std::vector<std::pair<double, double>> bodies; ///< (k, nu)
      std::vector<double>                    mus;
      bool                                   multiple_mu = false;
      std::string                            tuple;
    };

    /// The panels: every k and nu, and Holl's ratio where it is a Poisson ratio (k >= 0; 1/2 at k = 0, with the
    /// mixed formulation), each at every mu of Map/values (Friction/coefficient when empty); the mu of one
    /// body share its surface compliance.
    CoulombMapPlan plan_coulomb_map(const Scene &s)
    {
      CoulombMapPlan plan;
      const std::vector<double> ks  = s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
      const std::vector<double> nus = s.map.poisson_ratios.empty() ? std::vector<double>{s.material.nu} : s.map.poisson_ratios;
      plan.mus = s.map.values.empty() ? std::vector<double>{s.friction.coefficient} : s.map.values;
      std::sort(plan.mus.begin(), plan.mus.end());
      for (const double k : ks)
        {
          for (const double nu : nus)
            plan.bodies.emplace_back(k, nu);
          if (s.map.holl_ratio && k >= 0 && std::none_of(nus.begin(), nus.end(), [k](const double nu) {
                return std::abs(nu - 1. / (2. + k)) <= 1e-12;
              }))
            plan.bodies.emplace_back(k, 1. / (2. + k));
        }
      plan.multiple_mu = plan.mus.size() > 1;
      plan.tuple = plan.multiple_mu ? "(k, nu, mu)" : "(k, nu)";
      return plan;
    }


    /// F_x at the last step of `phase` (0 when none).
    double last_force(const CoulombPath &path, const std::string &phase)
    {
      for (auto it = path.steps.rbegin(); it != path.steps.rend(); ++it)
        if (it->phase == phase)
          return it->state.force_x;
      return 0.;
    }

    /// The sharp checks of a panel at Holl's ratio (decoupled): the FE model and its idealisation against the
    /// chapter (9.24 family, 9.80, 9.84, 9.86), and the coupling's effect on F_x at delta_A.
    void holl_rows(const CoulombPanel &p, const double tolerance, SceneResult &result)
    {
      const CoulombSphereResult &r = p.result;
      const unsigned int dofs = static_cast<unsigned int>(r.dofs);
      const std::string what = panel_name(p) + " (decoupled)";
      result.rows.push_back(compare("normal force", what + ", F_z at d", "FE", "closed form (9.24 family)", r.force_n_theory,
                                    (1 + r.fe.force_z_deviation) * r.force_n_theory, r.force_n_theory, tolerance, dofs,
                                    r.seconds));
      result.rows.push_back(compare("tangential force", what + ", loading, largest relative difference (9.80)", "FE",
                                    "closed form (9.80)", 0., r.fe.loading_deviation, 1., tolerance, dofs, r.seconds));
      result.rows.push_back(compare("hysteresis loop", what + ", unloading and reloading, largest difference / F_A (9.84)",
                                    "FE", "closed form (9.84)", 0., r.fe.branch_deviation, 1., tolerance, dofs, r.seconds));
      result.rows.push_back(compare("dissipated energy", what + ", loop area (Simpson's rule over the steps)", "FE",
                                    "closed form (9.86)", r.energy_theory, r.fe.energy, r.energy_theory, tolerance, dofs,
                                    r.seconds));
      result.rows.push_back(compare("dissipated energy", what + ", friction work over the cycle (sum of mu P |slip|)", "FE",
                                    "closed form (9.86)", r.energy_theory, r.fe.friction_work, r.energy_theory, tolerance,
                                    dofs, r.seconds));
      // The chapter's idealisation on the same body (decoupled, forces along x): the FE's own error.
      const std::string idealised = panel_name(p) + " (decoupled, tangential forces along x)";
      result.rows.push_back(compare("tangential force", idealised + ", loading, largest relative difference (9.80)",
                                    "FE idealised", "closed form (9.80)", 0., r.idealised.loading_deviation, 1., tolerance,
                                    dofs, r.seconds));
      result.rows.push_back(compare("hysteresis loop", idealised + ", unloading and reloading, largest difference / F_A (9.84)",
                                    "FE idealised", "closed form (9.84)", 0., r.idealised.branch_deviation, 1., tolerance,
                                    dofs, r.seconds));
      result.rows.push_back(compare("dissipated energy", idealised + ", loop area (Simpson's rule over the steps)",
                                    "FE idealised", "closed form (9.86)", r.energy_theory, r.idealised.energy,
                                    r.energy_theory, tolerance, dofs, r.seconds));
      result.rows.push_back(compare("tangential force", what + ", the coupling's effect: F_x at delta_A", "FE",
                                    "FE decoupled", last_force(r.decoupled, "loading"), last_force(r.fe, "loading"),
                                    last_force(r.decoupled, "loading"), tolerance, dofs, r.seconds));
    }

    /// The resolution of the coupling measures: their value at Holl's ratio, where the coupling vanishes.
    std::map<std::string, double> coupling_resolution(const std::vector<CoulombPanel> &panels)
    {
      std::map<std::string, double> resolution;
      for (const CoulombPanel &p : panels)
        if (p.holl && p.error.empty())
          for (const MapQuantity &q : map_quantities())
            resolution[q.name] = std::max(resolution[q.name], std::abs(q.coupling(p.result)));
      return resolution;
    }

    /// The column spec of the map's map.csv: a row per panel, every number of its paths.
    std::vector<Field<CoulombPanel>> coulomb_fields(const Scene &s)
    {
      using Panel  = const CoulombPanel &;
      using Result = const CoulombSphereResult &;
      std::vector<Field<CoulombPanel>> f{
        {Column::csv_only("k"), [](Panel p) { return Cell(p.k); }},
        {Column::csv_only("nu"), [](Panel p) { return Cell(p.nu); }},
        {Column::csv_only("holl"), [](Panel p) { return Cell(p.holl ? 1 : 0); }},
        {Column::csv_only("mu"), [](Panel p) { return Cell(p.mu); }},
        {Column::csv_only("amplitude"), [&s](Panel) { return Cell(s.tangential.amplitude); }},
        {Column::csv_only("far_field_over_a"), [&s](Panel p) { return Cell(coulomb_far_field(s, p.k)); }}};
      const auto of_result = [&f](const std::string &name, const std::function<Cell(Result)> &get) {
        f.push_back({Column::csv_only(name), [get](Panel p) { return get(p.result); }});
      };
      of_result("dofs", [](Result r) { return Cell(r.dofs); });
      of_result("surface_nodes", [](Result r) { return Cell(r.surface_nodes); });
      of_result("seconds", [](Result r) { return Cell(r.seconds); });
      of_result("compliance_seconds", [](Result r) { return Cell(r.compliance_seconds); });
      of_result("memory_mb", [](Result r) { return Cell(r.memory_mb); });
      of_result("largest_iterations", [](Result r) { return Cell(r.fe.max_iterations); });
      of_result("normal_slip_nodes", [](Result r) { return Cell(r.fe.normal_slip); });
      const auto name = [](std::string n) {
        std::replace(n.begin(), n.end(), ' ', '_');
        return n;
      };
      for (const MapQuantity &q : map_quantities())
        {
          of_result(name(q.name) + "_coupling", q.coupling);
          of_result(name(q.name) + "_floor", q.floor);
          of_result(name(q.name) + "_fe", q.direct);
        }
      for (const MapQuantity &q : map_quantities())
        if (q.direction)
          of_result(name(q.name) + "_direction", q.direction);
      for (const MapQuantity &q : map_quantities())
        if (q.idealised)
          of_result(name(q.name) + "_idealised_floor", q.idealised);
      of_result("stick_bracket_half_width", [](Result r) { return Cell(r.fe.stick_resolution); });
      of_result("stick_spread", [](Result r) { return Cell(r.fe.out_of_round); });
      of_result("stick_spread_decoupled", [](Result r) { return Cell(r.decoupled.out_of_round); });
      of_result("slip_force_y", [](Result r) { return Cell(r.fe.slip_force_y); });
      of_result("slip_force_y_decoupled", [](Result r) { return Cell(r.decoupled.slip_force_y); });
      of_result("closure", [](Result r) { return Cell(r.fe.closure); });
      f.push_back({Column::csv_only("error").quoted(), [](Panel p) { return Cell(p.error); }});
      return f;
    }

    /// The title of map.md and what the map compares.
    std::string coulomb_intro(const Scene &s, const CoulombMapPlan &plan)
    {
      std::string mus;
      for (const double mu : plan.mus)
        mus += (mus.empty() ? "" : ", ") + format(mu);
      std::ostringstream md;
      md << "# " << s.info.name << ": where the chapter's tangential theory holds (3D Coulomb contact)\n\n"
         << (s.info.description.empty() ? "" : s.info.description + "\n\n")
         << "The 3D FE model of a rigid sphere R = " << format(s.load.R) << " m on E0 (z/c0)^k (E0 = "
         << format(s.material.E0) << " Pa, c0 = " << format(s.material.c0) << " m) with Coulomb friction mu = " << mus
         << " (fem/tangential/coulomb_contact_3d.h: the contact, stick zone and slip directions found node by node), loaded to "
            "the chapter's depth of contact radius a = "
         << format(s.load.a) << " m, sheared to the chapter's delta_A of F_A = " << format(s.tangential.amplitude)
         << " mu F_N and cycled once to -delta_A and back, " << s.tangential.load_steps
         << " steps per quarter cycle. The chapter's theory (9.80-9.86) assumes that the normal and tangential "
            "problems decouple. The map is the coupling's effect: the FE model against the same FE model with the "
            "coupling entries of its surface compliance removed (fem::without_coupling; the same mesh and truncation, "
            "so the FE's own errors cancel). The FE floor is that decoupled model against the chapter (mesh, "
            "truncation at L, and Cattaneo-Mindlin's slip parallel to x). It splits in two: the same decoupled model "
            "with every tangential force along x (fem::along_load, Cattaneo-Mindlin's assumption, which their traction "
            "satisfies exactly) against the chapter is the FE's own error, and the decoupled model against it is the "
            "effect of the slip direction that Cattaneo-Mindlin fixes along the load (in the slip annulus the true slip "
            "has a y part), a departure of 9.80-9.86 from Coulomb's law even where the problems decouple. At Holl's "
            "ratio nu = 1/(2 + k) the coupling vanishes: the coupling measured there is the resolution of the map.\n\n";
      return md.str();
    }

    /// The table of the coupling's effect, one row per panel, and the note on the stick zone's spread.
    std::string coupling_table(const std::vector<CoulombPanel> &panels)
    {
      std::vector<Column> columns{Column::md_only("k"), Column::md_only("nu"), Column::md_only("mu")};
      for (const MapQuantity &q : map_quantities())
        columns.push_back(Column::md_only(q.name));
      for (const char *head : {"FE floor: F_x (9.80), loop area (9.86)", "slip direction's effect: F_x, loop area",
                               "stick zone spread / a", "slip direction sum|Q_y|/sum|Q|", "DoFs", "s", "memory MiB"})
        columns.push_back(Column::md_only(head));
      Table table(columns);
      for (const CoulombPanel &p : panels)
        {
          const CoulombSphereResult &r = p.result;
          std::vector<Cell> row{format(p.k), (p.holl ? "1/(2 + k) = " : "") + format(p.nu), format(p.mu)};
          if (!p.error.empty())
            {
              row.push_back("failed: " + p.error);
              row.resize(row.size() + map_quantities().size() + 3); // missing: "-"
            }
          else
            {
              for (const MapQuantity &q : map_quantities())
                row.push_back(format(std::abs(q.coupling(r))));
              row.push_back(format(std::abs(r.decoupled.loading_deviation)) + ", " +
                            format(std::abs(energy_deviation(r.decoupled, r))));
              row.push_back(format(r.direction_loading) + ", " + format(std::abs(r.direction_energy)));
              row.push_back(format(r.fe.out_of_round) + " (" + format(r.decoupled.out_of_round) + " decoupled)");
              row.push_back(format(r.fe.slip_force_y) + " (" + format(r.decoupled.slip_force_y) + " decoupled)");
            }
          for (const Cell &last : {Cell(r.dofs), Cell(format(r.seconds)), Cell(format(r.memory_mb))})
            row.push_back(last);
          table.add(std::move(row));
        }
      std::ostringstream md;
      md << "## The coupling's effect |FE / FE decoupled - 1|\n\n" << table.md();
      md << "\nA stick-zone spread is the largest difference of the stick radius between the rays +x, -x and +y "
            "(a disc: 0, up to the node spacing there, "
         << "the bracket half-width of the stick radius reaching "
         << format(std::max_element(panels.begin(), panels.end(),
                                    [](const CoulombPanel &x, const CoulombPanel &y) {
                                      return x.result.fe.stick_resolution < y.result.fe.stick_resolution;
                                    })
                     ->result.fe.stick_resolution)
         << " a). The slip direction's departure from x is the force-weighted sum |Q_y| / sum |Q| over the slipping "
            "nodes, largest over the steps.\n\n";
      return md.str();
    }

    /// Where the coupling's effect on each quantity is within each threshold, read only above three times the
    /// map's resolution.
    std::string coupling_thresholds(const Scene &s, const CoulombMapPlan &plan, const std::vector<CoulombPanel> &panels,
                                    const std::map<std::string, double> &resolution)
    {
      std::ostringstream md;
      md << "## Where the chapter's tangential theory holds\n\nThe " << plan.tuple << " of the map where the coupling's "
            "effect on a quantity is within each threshold (the chapter's decoupled theory holds there up to the FE "
            "floor).\n\n";
      Table table = threshold_table({"quantity", "chapter"}, s.map.thresholds, "at");
      for (const MapQuantity &q : map_quantities())
        {
          std::vector<Cell> row{q.name, q.chapter};
          for (const double t : s.map.thresholds)
            if (resolution.count(q.name) == 0)
              row.push_back("FE resolution not measured (no Holl's-ratio panel)");
            else if (!(resolution.at(q.name) <= t / 3))
              row.push_back("below the FE resolution (" + format(resolution.at(q.name)) + ")");
            else
              row.push_back(threshold_cell(panels, t, q.coupling, false, plan.multiple_mu, plan.tuple));
          table.add(std::move(row));
        }
      md << table.md() << "\nThe resolution of each quantity is its coupling at Holl's ratio (";
      bool first = true;
      for (const auto &[name, value] : resolution)
        {
          md << (first ? "" : ", ") << name << " " << format(value);
          first = false;
        }
      md << "); a threshold below three times it is not read.\n";
      return md.str();
    }

    /// The other half of the chapter's idealisation: Cattaneo-Mindlin's slip along the load, on the decoupled body.
    std::string direction_thresholds(const Scene &s, const CoulombMapPlan &plan, const std::vector<CoulombPanel> &panels)
    {
      std::ostringstream md;
      md << "\n## Cattaneo-Mindlin's slip direction |FE decoupled / FE idealised - 1|\n\nEven where the problems "
            "decouple, 9.80-9.86 assume the tangential traction along the load; Coulomb's law turns it with the slip "
            "in the annulus. The decoupled model against the same model with every tangential force along x "
            "(fem::along_load) is that assumption's effect (a difference on one mesh, in which its FE error largely "
            "cancels; its mesh convergence: fem/doc/distributed-and-3d.md, \"3D model\"). The "
         << plan.tuple << " of the map (Holl's ratio included) where it is within each threshold:\n\n";
      Table table = threshold_table({"quantity", "chapter"}, s.map.thresholds, "at");
      for (const MapQuantity &q : map_quantities())
        if (q.direction)
          {
            std::vector<Cell> row{q.name, q.chapter};
            for (const double t : s.map.thresholds)
              row.push_back(threshold_cell(panels, t, q.direction, true, plan.multiple_mu, plan.tuple));
            table.add(std::move(row));
          }
      return md.str() + table.md();
    }

    /// The plots over nu: the coupling's effect on every quantity, and the slip direction's (Holl's ratio included).
    void plot_coulomb_map(const Scene &s, const std::filesystem::path &folder, const CoulombMapPlan &plan,
                          const std::vector<CoulombPanel> &panels)
    {
      for (const MapQuantity &q : map_quantities())
        {
          write_nu_plot(folder, "map-" + q.name, s.info.name + ": the coupling's effect on the " + q.name,
                        "|FE / FE decoupled - 1|", panels, q.coupling, false, plan.multiple_mu, s.map.thresholds);
          if (q.direction)
            write_nu_plot(folder, "map-slip_direction-" + q.name,
                          s.info.name + ": Cattaneo-Mindlin's slip direction, effect on the " + q.name,
                          "|FE decoupled / FE idealised - 1|", panels, q.direction, true, plan.multiple_mu,
                          s.map.thresholds);
        }
    }

    /// The Coulomb 3D map as a strategy of the map pipeline: a panel per body (k, nu), a point per mu on the body's
    /// one surface compliance (a body that cannot be built fails every mu); the rows of errors.csv per body, and
    /// map.csv, map.md and the plots from every panel, written by the root process only.
    class CoulombMap final : public MapStrategy
    {
    public:
      explicit CoulombMap(const Scene &scene)
        : s(scene)
        , world(mpi_world()) // MPI's start (when this is the first distributed scene) not timed
        , root(dealii::Utilities::MPI::this_mpi_process(world) == 0)
        , plan(plan_coulomb_map(scene))
      {}

      std::size_t panels() const override { return plan.bodies.size(); }
      std::size_t points(std::size_t) const override { return plan.mus.size(); }
      bool        writes_report() const override { return root; }

      void open_panel(const std::size_t body, SceneResult &, bool) override
      {
        const auto &[k, nu] = plan.bodies.at(body);
        c.emplace(coulomb_case(s, k, nu));
        surface.reset();
        body_error.clear();
        first = panel_list.size();
      }

      /// One mu on the body: the chapter's depth of contact radius a and its delta_A of F_A = amplitude mu F_N(a)
      /// (9.80), the paths on the body's surface compliance (prepared by its first mu).
      void solve(const std::size_t body, const std::size_t point, SceneResult &, const bool verbose) override
      {
        const auto &[k, nu] = plan.bodies.at(body);
        const double mu = plan.mus.at(point), a = s.load.a;
        CoulombPanel panel{k, nu, std::abs(nu - 1. / (2. + k)) <= 1e-12, mu, plan.multiple_mu, {}, body_error};
        c->mu = c->mu_normal = mu;
        if (body_error.empty())
          try
            {
              const Medium medium = gradcontact::medium(GradedHalfSpace{c->E0, c->c0, c->k, c->nu});
              c->depth            = gradcontact::depth(medium, Paraboloid{c->R}, a);
              c->delta            = tangential::tangential_displacement_at_force(
                medium, tangential::SphereSlip{c->R, mu}, a,
                s.tangential.amplitude * mu * gradcontact::force(medium, Paraboloid{c->R}, a));
              if (!surface)
                surface = prepare_coulomb_sphere(world, *c);
              panel.result = run_coulomb_sphere(world, *c, *surface);
              panel.error  = path_error(panel.result);
            }
          catch (const std::exception &e)
            {
              panel.error = concise(e);
              if (!surface)
                body_error = panel.error; // the body could not be built: no mu can run on it
            }
        if (verbose && root)
          std::cerr << "  " << panel_name(panel) << ": " << (panel.error.empty() ? "" : panel.error + "; ")
                    << "F_x coupling " << panel.result.coupling_loading << ", floor "
                    << panel.result.decoupled.loading_deviation << ", " << panel.result.dofs << " DoFs, "
                    << panel.result.seconds << " s\n";
        panel_list.push_back(std::move(panel));
      }

      /// errors.csv: the sharp checks of the decoupled pairing, and every path that failed.
      void close_panel(std::size_t, const std::filesystem::path &, SceneResult &result, bool) override
      {
        for (std::size_t i = first; i < panel_list.size(); ++i)
          {
            const CoulombPanel &p = panel_list[i];
            if (!p.error.empty())
              result.rows.push_back(failed("Coulomb 3D path", "FE", "closed form", panel_name(p) + ": " + p.error));
            else if (p.holl)
              holl_rows(p, s.tolerances.force, result);
          }
      }

      MapReport report(const std::filesystem::path &, bool) override
      {
        return {tabulate(coulomb_fields(s), panel_list, Number{'g', 10}),
                coulomb_intro(s, plan) + coupling_table(panel_list) +
                  coupling_thresholds(s, plan, panel_list, coupling_resolution(panel_list)) +
                  direction_thresholds(s, plan, panel_list)};
      }

      void plot(const std::filesystem::path &folder) override { plot_coulomb_map(s, folder, plan, panel_list); }

    private:
      /// Why a path did not converge; empty when every path did.
      static std::string path_error(const CoulombSphereResult &r)
      {
        if (!r.fe.converged)
          return r.fe.message;
        if (!r.decoupled.converged)
          return "decoupled path: " + r.decoupled.message;
        if (!r.idealised.converged)
          return "idealised path: " + r.idealised.message;
        return {};
      }

      const Scene                        &s;
      const MPI_Comm                      world;
      const bool                          root;
      const CoulombMapPlan                plan;
      std::vector<CoulombPanel>           panel_list;
      std::optional<CoulombSphereCase>    c;          ///< the open body
      std::optional<CoulombSphereSurface> surface;    ///< its surface compliance, from its first mu
      std::string                         body_error; ///< why the open body could not be built
      std::size_t                         first = 0;  ///< its first panel in panel_list
    };
  } // namespace

  std::unique_ptr<MapStrategy> coulomb_map_strategy(const Scene &s)
  {
    require_kind(s, SceneKind::map, "coulomb_map_strategy");
    if (s.map.parameter != MapParameters::Parameter::coulomb_3d)
      throw std::invalid_argument("coulomb_map_strategy: scene " + s.file + " is not a Coulomb 3D map");
    return std::make_unique<CoulombMap>(s);
  }
} // namespace gradcontact::cases
