#include "runners/fe_map.h"
#include "report/map_pipeline.h"
#include "report/table.h"
#include "report/thresholds.h"

#include "model/analytic_reference.h"
#include "model/normal_model.h"
#include "model/scene_start.h"
#include "model/map_published.h"

#include <fem/bodies/axisymmetric_solver.h>
#include <fem/contact/unilateral_contact.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Type = LoadParameters::Type;

  namespace
  {
    /// One FE solve of a map: the FE state and its deviations from the power law at the FE depth.
    struct MapPoint
    {
      double ratio = 0.;                      ///< a/z0, a/H, a/w, E1/E0 or mu (0: the idealisation itself)
      double force = 0., radius = 0., pressure = 0.; ///< FE/closed form - 1 (radius: indenters only)
      double stick = std::numeric_limits<double>::quiet_NaN(); ///< friction: the stick radius / the contact radius
      unsigned int dofs = 0;
      double seconds = 0.;
      std::string error; ///< non-empty when the solve or the reference failed
    };

    /// The radius near the axis where p is sampled (the r-weighted recovery does not constrain the axis node).
    constexpr double axis_sample = 0.02;

    bool is_indenter(const Scene &s) { return s.load.type != Type::flat_punch; }

    /// The name of a map's ratio in map.md and in the header of map.csv.
    struct RatioName
    {
      std::string md, csv;
    };

    /// The real grading of a grading map: its ratio a/length, on which side of it the power law lies, its name in
    /// map.md, and how a scene takes it at a length.
    struct Grading
    {
      RatioName ratio;
      /// The power law is the limit a/z0 -> inf of a finite surface modulus (a/w -> inf of the error function),
      /// a/H -> 0 of a coating.
      bool toward_large = true;
      std::string text;
      void (*at)(MaterialParameters &m, double length) = nullptr;
      /// The error function: map.md compares its load-displacement exponent with Lee, Barber & Thouless (2009).
      bool published = false;
    };

    /// The grading of Map/parameter (the one place a grading map looks at it).
    Grading grading_of(const Scene &s)
    {
      using Modulus = MaterialParameters::Modulus;
      switch (s.map.parameter)
        {
          case MapParameters::Parameter::surface_depth:
            return {{"a/z0", "a_over_z0"}, true, "E(z) = E0 ((z + z0)/c0)^k (a finite surface modulus)",
                    [](MaterialParameters &m, const double z0) {
                      m.modulus       = Modulus::shifted_power_law;
                      m.surface_depth = z0;
                    }};
          case MapParameters::Parameter::erf_width:
            return {{"a/w", "a_over_w"}, true,
                    "E(z) = E0 [1 + (m - 1) erfc(z/w)], m = " + format(s.material.surface_modulus_ratio) +
                      " (the error-function grading of Lee, Barber & Thouless 2009)",
                    [](MaterialParameters &m, const double w) {
                      m.modulus   = Modulus::error_function;
                      m.erf_width = w;
                    },
                    true};
          case MapParameters::Parameter::coating_thickness:
            return {{"a/H", "a_over_H"}, false,
                    "a graded coating E0 (z/c0)^k on 0 < z <= H over the substrate E0 (H/c0)^k",
                    [](MaterialParameters &m, const double H) {
                      m.modulus           = Modulus::coating;
                      m.coating_thickness = H;
                    }};
          default:
            throw std::logic_error("grading_of: scene " + s.file + " is not a map of a real grading");
        }
    }

    /// The scene at exponent k with `grading` at a/length = `ratio` (0: the power law itself).
    Scene graded(const Scene &s, const Grading &grading, const double k, const double ratio)
    {
      Scene g = s;
      g.material.k = k;
      g.map.parameter = MapParameters::Parameter::none;
      if (ratio == 0.)
        g.material.modulus = MaterialParameters::Modulus::power_law;
      else
        grading.at(g.material, s.load.a / ratio);
      g.kind = SceneKind::normal;
      return g;
    }

    /// Solves `g` under contact-radius control and compares it with the power-law closed forms at the FE depth.
    MapPoint solve_graded(const Scene &g, const double ratio, const unsigned int extra_refinements = 0)
    {
      MapPoint p;
      p.ratio = ratio;
      const auto start = std::chrono::steady_clock::now();
      try
        {
          const FeModel model = fe_model(g, finest_refinement(g) + extra_refinements);
          fem::OutputRequest out;
          out.pressure_radii = {axis_sample * g.load.a};
          const fem::Result r = solve_disc(model, out).result;
          p.dofs = r.n_dofs;
          if (!r.reliable)
            throw std::runtime_error("the FE solve is flagged unreliable: " + r.message);
          // The chapter's state at the FE depth: for an indenter its contact radius follows from d.
          Scene at_depth = g;
          at_depth.material.modulus = MaterialParameters::Modulus::power_law;
          if (is_indenter(g))
            {
              at_depth.load.control = LoadParameters::Control::depth;
              at_depth.load.depth = r.depth;
            }
          else
            at_depth.load.depth = r.depth;
          const AnalyticReference ref(at_depth, batch::Method::closed_form, AnalyticReference::Problem::normal);
          p.force = r.force / ref.get("force") - 1;
          p.radius = is_indenter(g) ? g.load.a / ref.radius() - 1 : 0.;
          p.pressure = r.pressure.at(0).value / ref.at("pressure", axis_sample * g.load.a) - 1;
        }
      catch (const std::exception &e)
        {
          p.error = concise(e);
        }
      p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return p;
    }

    /// What a map compares at every point. Declared in the order in which map.md lists a panel's resolutions.
    enum class Quantity
    {
      contact_radius,
      force,
      pressure
    };

    /// The quantities of a map of `s`, in the order of its tables: the contact radius of an indenter only.
    std::vector<Quantity> map_quantities(const Scene &s)
    {
      return is_indenter(s) ? std::vector<Quantity>{Quantity::force, Quantity::contact_radius, Quantity::pressure}
                            : std::vector<Quantity>{Quantity::force, Quantity::pressure};
    }

    /// Every quantity (an elastic indenter's and a friction map's panels measure all three).
    const std::vector<Quantity> all_quantities{Quantity::force, Quantity::contact_radius, Quantity::pressure};

    /// The quantity's name in the plots' file names.
    std::string name(const Quantity q)
    {
      static const char *const names[] = {"contact radius", "force", "pressure"}; // in the order of Quantity
      return names[static_cast<int>(q)];
    }

    double deviation_of(const MapPoint &p, const Quantity q)
    {
      switch (q)
        {
          case Quantity::force:
            return p.force;
          case Quantity::contact_radius:
            return p.radius;
          case Quantity::pressure:
            break;
        }
      return p.pressure;
    }

    /// The radii (/ a) of a friction map's pressure: its deviation is the change of p(r) over them in the
    /// area-weighted L2 norm, relative to p's (a point near the axis alone would see the local, log-singular effect
    /// of the shear's jump at a small stick zone's edge). Inside the contact of every mu (friction shrinks it by a
    /// few %).
    const std::vector<double> friction_pressure_radii{0.02, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.45,
                                                      0.5,  0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9};

    /// The pressure as map.md and the plots name it: near the axis, or (friction) the change of p(r) in L2.
    std::string axis_pressure() { return "p(" + format(axis_sample) + " a)"; }
    const char *const friction_pressure = "p(r), L2 change";

    /// The quantity as map.md and the plots name it, the pressure as `pressure`.
    std::string label(const Quantity q, const std::string &pressure) { return q == Quantity::pressure ? pressure : name(q); }

    /// The points of one k, with what bounds their FE error.
    struct ExponentMap
    {
      std::vector<MapPoint> points;
      std::map<Quantity, double> resolution; ///< per quantity; missing: not computed
      std::string resolution_text;              ///< for map.md
    };

    /// The sharp-check rows of `check` (FE against closed forms where they are exact), named by `metric`.
    void add_check_rows(const Scene &s, const MapPoint &check, const std::string &metric, SceneResult &result,
                        const std::string &pressure_row = "pressure at r = " + format(axis_sample) + " a")
    {
      if (!check.error.empty())
        {
          result.rows.push_back(failed("force at the FE depth", "FE", "closed form", metric + ": " + check.error));
          return;
        }
      result.rows.push_back(compare("force at the FE depth", metric, "FE", "closed form", 1., 1. + check.force, 1.,
                                    s.tolerances.force, check.dofs, check.seconds));
      if (is_indenter(s))
        result.rows.push_back(compare("contact radius at the FE depth", metric, "FE", "closed form", 1., 1. + check.radius,
                                      1., s.tolerances.contact_radius, check.dofs, check.seconds));
      result.rows.push_back(compare(pressure_row, metric, "FE", "closed form", 1., 1. + check.pressure, 1.,
                                    s.tolerances.pressure, check.dofs, check.seconds));
    }

    /// The seconds `work` takes.
    template <typename Work>
    double seconds_of(const Work &work)
    {
      const auto start = std::chrono::steady_clock::now();
      work();
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// Why a unilateral result cannot be a map point (its contact is not one disc, or the solve is flagged
    /// unreliable); empty when it can.
    std::string disc_contact_error(const fem::UnilateralResult &r)
    {
      if (r.zones.size() != 1 || r.zones.front().r_in > 0)
        return "the contact is not one disc (" + std::to_string(r.zones.size()) + " zones)";
      if (!r.reliable)
        return "the FE solve is flagged unreliable: " + r.message;
      return {};
    }

    /// The change of p(r) of `r` from `reference` at friction_pressure_radii in the area-weighted L2 norm
    /// (trapezoidal in r dr), relative to the reference's, with the sign of the change at r = 0.5 a; a radius beyond
    /// the contact is an error (the sampler leaves it out).
    double pressure_change(const fem::UnilateralResult &r, const std::vector<double> &reference)
    {
      if (r.pressure.size() != reference.size())
        throw std::runtime_error("p(r) sampled at " + std::to_string(r.pressure.size()) + " of " +
                                 std::to_string(reference.size()) + " radii (beyond the contact?)");
      const std::vector<double> &x = friction_pressure_radii;
      double change = 0, norm = 0, sign = 1;
      for (std::size_t i = 0; i < x.size(); ++i)
        {
          const double weight = x[i] * (x[std::min(i + 1, x.size() - 1)] - x[i == 0 ? 0 : i - 1]) / 2;
          const double dp     = r.pressure[i].value - reference[i];
          change += weight * dp * dp;
          norm += weight * reference[i] * reference[i];
          if (x[i] == 0.5)
            sign = dp < 0 ? -1 : 1;
        }
      return sign * std::sqrt(change / norm);
    }

    /// The path's error is first order in the step (a vertex that comes into contact during a step carries no
    /// shear in it): a point extrapolated from N and 2N steps, 2 X(2N) - X(N) (c/a: at 2N).
    MapPoint extrapolated(const MapPoint &coarse, const MapPoint &fine)
    {
      MapPoint p = fine;
      p.seconds += coarse.seconds;
      if (!coarse.error.empty() && p.error.empty())
        p.error = coarse.error;
      if (p.error.empty())
        {
          p.force = 2 * fine.force - coarse.force;
          p.radius = 2 * fine.radius - coarse.radius;
          p.pressure = 2 * fine.pressure - coarse.pressure;
        }
      return p;
    }

    /// A failed map point at `ratio`.
    MapPoint failed_point(const double ratio, const std::string &error)
    {
      MapPoint p;
      p.ratio = ratio;
      p.error = error;
      return p;
    }

    /// Runs `f` at friction coefficient mu: its seconds, or the error.
    std::pair<double, std::string> run_friction(FrictionSolver &f, const double mu)
    {
      f.load.friction.coefficient = mu;
      try
        {
          return std::make_pair(seconds_of([&] { f.r = f.solver->run(f.load, f.request); }), std::string());
        }
      catch (const std::exception &e)
        {
          return std::make_pair(0., concise(e));
        }
    }

    /// One point of f's last result: deviations from `force`, `radius` and `pressure` (the closed forms, or the
    /// frictionless FE on the same mesh).
    MapPoint friction_point(const FrictionSolver &f, const double mu, const double seconds, const double force,
                            const double radius, const std::vector<double> &pressure)
    {
      MapPoint p;
      p.ratio = mu;
      p.dofs = f.solver->n_dofs();
      p.seconds = seconds;
      p.error = disc_contact_error(f.r);
      if (p.error.empty())
        {
          p.force = f.r.force / force - 1;
          p.radius = f.r.outer_edge / radius - 1;
          p.pressure = pressure_change(f.r, pressure);
          if (mu > 0)
            p.stick = f.r.stick_radius / f.r.outer_edge;
        }
      return p;
    }

    /// The sharp check: the frictionless FE (f's first run, its setup included) against the closed forms.
    MapPoint frictionless_check(FrictionSolver &f, const AnalyticReference &frictionless, const double a)
    {
      auto [seconds, error] = run_friction(f, 0.);
      seconds += f.setup;
      MapPoint check;
      if (error.empty())
        try
          {
            std::vector<double> closed_pressure;
            for (const double x : friction_pressure_radii)
              closed_pressure.push_back(frictionless.at("pressure", x * a));
            check = friction_point(f, 0., seconds, frictionless.get("force"), frictionless.radius(), closed_pressure);
          }
        catch (const std::exception &e)
          {
            error = concise(e);
          }
      check.error += error;
      return check;
    }

    /// A frictional point at `steps` load steps: FE(mu) against the frictionless FE `smooth` on the same mesh.
    MapPoint friction_at_steps(FrictionSolver &f, const fem::UnilateralResult &smooth, const double mu,
                               const unsigned int steps)
    {
      f.load.friction.load_steps = steps;
      const auto [seconds, error] = run_friction(f, mu);
      if (!error.empty())
        return failed_point(mu, error);
      std::vector<double> smooth_pressure;
      for (const fem::Sample &x : smooth.pressure)
        smooth_pressure.push_back(x.value);
      try
        {
          return friction_point(f, mu, seconds, smooth.force, smooth.outer_edge, smooth_pressure);
        }
      catch (const std::exception &e)
        {
          return failed_point(mu, concise(e));
        }
    }

    /// The FE resolution of a friction map into `out`: the change of the extrapolation from N/2 and N steps to N and
    /// 2N at the largest finite mu solved, where slip and stick meet (full stick only when no finite mu was solved;
    /// the mesh's error is the frictionless check's, which the text quotes).
    void friction_resolution(FrictionSolver &f, const fem::UnilateralResult &smooth, const unsigned int steps,
                             const bool holl, const MapPoint &smooth_check, ExponentMap &out)
    {
      auto largest = std::find_if(out.points.rbegin(), out.points.rend(), [](const MapPoint &p) {
        return p.error.empty() && std::isfinite(p.ratio);
      });
      if (largest == out.points.rend())
        largest = std::find_if(out.points.rbegin(), out.points.rend(), [](const MapPoint &p) { return p.error.empty(); });
      std::ostringstream md;
      if (largest != out.points.rend() && steps >= 2)
        {
          const MapPoint coarser = extrapolated(friction_at_steps(f, smooth, largest->ratio, steps / 2),
                                                friction_at_steps(f, smooth, largest->ratio, steps));
          if (coarser.error.empty())
            for (const Quantity q : all_quantities)
              out.resolution[q] = std::abs(deviation_of(*largest, q) - deviation_of(coarser, q));
          md << "Every point is extrapolated from " << steps << " and " << 2 * steps
             << " load steps (the path's error is first order). FE resolution (the change of that extrapolation from "
             << steps / 2 << " and " << steps << " steps, at mu = " << format(largest->ratio) << "; stick radius "
             << format(coarser.stick) << " at " << steps << " steps against " << format(largest->stick) << " at "
             << 2 * steps << "):";
          if (!coarser.error.empty())
            md << " not measured (" << md_escape(coarser.error) << ")";
        }
      else
        md << "FE resolution: not measured (" << (steps < 2 ? "Friction/load steps < 2" : "no frictional point was solved")
           << ")";
      for (const auto &[q, change] : out.resolution)
        md << " " << label(q, friction_pressure) << " " << format(change) << ";";
      if (holl)
        md << " Holl's ratio: every deviation below is the FE's own error (exact: 0).";
      md << " " << f.solver->n_dofs() << " DoFs; the frictionless FE against the closed forms: force "
         << format(smooth_check.force) << ", contact radius " << format(smooth_check.radius) << ".";
      out.resolution_text = md.str();
    }


    /// One panel of a map: an exponent k, and for a friction map a Poisson ratio nu.
    struct Panel
    {
      double k, nu;
    };

    /// The column spec of a map kind: map.csv (every point) and each panel's table in map.md, from the kind's ratio
    /// and what its points carry: an indenter's contact radius (map.csv has the column for every kind), friction's nu
    /// and stick radius.
    struct MapColumns
    {
      RatioName ratio;
      bool radius = false, friction = false;

      std::vector<Column> columns() const
      {
        std::vector<Column> c{Column::csv_only("k")};
        if (friction)
          c.push_back(Column::csv_only("nu").csv_as(Number{'f', 6}));
        c.push_back(Column::both(ratio.csv, ratio.md));
        c.push_back(Column::both("force_deviation", "force"));
        c.push_back(radius ? Column::both("contact_radius_deviation", "contact radius")
                           : Column::csv_only("contact_radius_deviation"));
        c.push_back(Column::both("pressure_deviation", friction ? friction_pressure : axis_pressure()));
        if (friction)
          c.push_back(Column::both("stick_radius_over_a", "c/a").csv_as(Number{}));
        for (const Column &last : {Column::both("dofs", "DoFs"), Column::both("seconds", "s"),
                                   Column::csv_only("error").quoted()})
          c.push_back(last);
        return c;
      }

      /// An empty table of these columns (map.csv's numbers with 10 digits).
      Table table() const { return Table(columns(), Number{'g', 10}); }

      /// A point's row: a failed one says so in the Markdown in place of its deviations.
      std::vector<Cell> cells(const Panel &panel, const MapPoint &p) const
      {
        const bool failed = !p.error.empty();
        const auto deviation = [failed](const double value) { return failed ? Cell(value).md_text("-") : Cell(value); };
        std::vector<Cell> c{panel.k};
        if (friction)
          c.push_back(panel.nu);
        c.push_back(std::isinf(p.ratio) ? Cell(p.ratio).md_text("inf (full stick)") : Cell(p.ratio));
        c.push_back(failed ? Cell(p.force).md_text("failed: " + p.error) : Cell(p.force));
        c.push_back(deviation(radius ? p.radius : std::nan("")));
        c.push_back(deviation(p.pressure));
        if (friction)
          c.push_back(deviation(p.stick));
        for (const Cell &last : {Cell(p.dofs), Cell(p.seconds), Cell(p.error)})
          c.push_back(last);
        return c;
      }
    };

    /// What the map kinds of this runner say in their shared tables and plots.
    struct MapWords
    {
      std::string reference; ///< what a point is compared with (a failed point's row)
      std::string pressure;  ///< the pressure's name
      std::string deviation; ///< the plots' title: |<quantity><deviation>|
      std::string holds;     ///< the threshold table's heading: "## Where <holds>"
    };

    /// The map kinds of this runner (a real grading, an elastic indenter, friction) as strategies of one shape: a
    /// panel per k (and nu), a point per ratio with its deviations from the chapter's idealisation (MapPoint), the
    /// panel's resolution, map.csv and the panels' tables (MapColumns), the threshold table and the plots of
    /// |deviation| over the ratio. A kind adds its solves, its sharp checks and its sections.
    class FeMap : public MapStrategy
    {
    public:
      std::size_t panels() const override { return panel_list.size(); }
      std::size_t points(std::size_t) const override { return values.size(); }
      void close_panel(std::size_t panel, const fs::path &folder, SceneResult &result, bool verbose) override;
      MapReport report(const fs::path &folder, bool plots) override;
      void plot(const fs::path &folder) override;

    protected:
      /// `values`: the points of a panel (the ratios ascending, for friction also full stick); `panel_heads`: the
      /// threshold table's columns before the quantity (panel_cells' heads).
      FeMap(const Scene &s, MapColumns columns, MapWords words, const std::vector<std::string> &panel_heads,
            std::vector<double> values);

      /// The panel as map.md names it, and its cells at the head of its rows of the threshold table.
      virtual std::string       panel_name(const Panel &p) const { return "k = " + format(p.k); }
      virtual std::vector<Cell> panel_cells(const Panel &p) const { return {format(p.k)}; }
      /// A threshold cell from the points that did not fail (ratios r, deviations d, and full stick's) when the
      /// FE resolution can place it.
      virtual std::string read_threshold(const std::vector<double> &r, const std::vector<double> &d,
                                         std::optional<double> full_stick, double t) const = 0;
      /// What a kind adds for a closed panel, and map.md's sections before the threshold table and after it.
      virtual void        panel_extras(const Panel &) {}
      virtual std::string before_thresholds() const { return {}; }
      virtual std::string after_thresholds() const { return {}; }
      virtual void        extra_plots(const fs::path &) const {}

      /// A new panel: no points, no failure.
      void start_panel()
      {
        map = ExponentMap{};
        failure.clear();
      }

      /// Runs a step of the open panel unless an earlier step of it failed; a step that throws fails the panel: a
      /// row named `what`, and the panel's FE resolution left uncomputed (its points solved so far stay).
      template <typename Step>
      void guarded(const std::size_t panel, const std::string &what, SceneResult &result, const Step &step)
      {
        if (!failure.empty())
          return;
        try
          {
            step();
          }
        catch (const std::exception &e)
          {
            failure = concise(e);
            result.rows.push_back(failed(what, "FE", "closed form", panel_name(panel_list.at(panel)) + ", " + failure));
            map.resolution_text = "not measured (" + md_escape(failure) + ")";
          }
      }

      std::string label(const Quantity q) const { return cases::label(q, words.pressure); }
      const std::string &x() const { return columns.ratio.md; }

      const Scene          &s;
      std::vector<double>   ratios, values; ///< Map/values ascending; the points of a panel
      std::vector<Quantity> quantities;
      MapColumns            columns;
      MapWords              words;
      std::vector<Panel>    panel_list;
      ExponentMap           map;     ///< the open panel's points and FE resolution
      std::string           failure; ///< why the open panel stopped (guarded)
      std::ostringstream    md;  ///< map.md up to the threshold table

    private:
      void tabulate_points(const Panel &panel, SceneResult &result, bool verbose);
      void tabulate_thresholds(const Panel &panel);
      std::string threshold_entry(const std::vector<double> &r, const std::vector<double> &d,
                                  std::optional<double> full_stick, Quantity q, double t) const;

      Table                                   csv, thresholds;
      std::map<Quantity, std::vector<Series>> curves; ///< |deviation| over the ratio, a curve per panel
    };

    /// Map/values ascending.
    std::vector<double> sorted_values(const Scene &s)
    {
      std::vector<double> v = s.map.values;
      std::sort(v.begin(), v.end());
      return v;
    }

    /// The map's exponents: Map/k values, or Material/k.
    std::vector<double> exponents(const Scene &s)
    {
      return s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
    }

    FeMap::FeMap(const Scene &scene, MapColumns c, MapWords w, const std::vector<std::string> &panel_heads,
                 std::vector<double> v)
      : s(scene)
      , ratios(sorted_values(scene))
      , values(std::move(v))
      , quantities(map_quantities(scene))
      , columns(std::move(c))
      , words(std::move(w))
      , csv(columns.table())
      , thresholds([&] {
        std::vector<std::string> heads = panel_heads;
        heads.push_back("quantity");
        return threshold_table(heads, scene.map.thresholds, "when " + columns.ratio.md);
      }())
    {
      md << "# " << s.info.name << ": applicability map\n\n"
         << (s.info.description.empty() ? "" : s.info.description + "\n\n");
    }

    /// The points of one panel: rows of map.csv and of the panel's table in map.md, and a failed row for each
    /// point that failed.
    void FeMap::tabulate_points(const Panel &panel, SceneResult &result, const bool verbose)
    {
      Table table = columns.table();
      for (const MapPoint &p : map.points)
        {
          table.add(columns.cells(panel, p));
          if (verbose)
            std::cerr << "  " << panel_name(panel) << ", " << x() << " = " << p.ratio << ": force " << p.force
                      << ", radius " << p.radius << ", pressure " << p.pressure
                      << (columns.friction ? ", c/a " + format(p.stick) : "") << (p.error.empty() ? "" : " (" + p.error + ")") << ", " << p.seconds << " s\n";
          if (!p.error.empty())
            result.rows.push_back(failed("map point", "FE", words.reference,
                                         panel_name(panel) + ", " + x() + " = " + format(p.ratio) + ": " + p.error));
        }
      md << "## " << panel_name(panel) << "\n\n" << table.md();
      csv.append(table);
    }

    /// One threshold cell: where |deviation| stays within t toward the idealisation, unless the FE resolution
    /// cannot place it (a deviation that changes by more than t/3 with the resolution's step).
    std::string FeMap::threshold_entry(const std::vector<double> &r, const std::vector<double> &d,
                                       const std::optional<double> full_stick, const Quantity q, const double t) const
    {
      if (r.empty() && !full_stick)
        return "no point";
      if (map.resolution.count(q) == 0)
        return "FE resolution not measured";
      if (!(map.resolution.at(q) <= t / 3))
        return "below the FE resolution (" + format(map.resolution.at(q)) + ")";
      return read_threshold(r, d, full_stick, t);
    }

    /// A panel's rows of the threshold table, one per quantity, and its curves of |deviation| for the plots.
    void FeMap::tabulate_thresholds(const Panel &panel)
    {
      for (const Quantity q : quantities)
        {
          std::vector<double> r, d;
          std::optional<double> full_stick;
          Series curve{panel_name(panel), {}, {}, false, true};
          for (const MapPoint &p : map.points)
            if (p.error.empty() && std::isinf(p.ratio))
              full_stick = deviation_of(p, q);
            else if (p.error.empty())
              {
                r.push_back(p.ratio);
                d.push_back(deviation_of(p, q));
                curve.x.push_back(p.ratio);
                curve.y.push_back(std::max(std::abs(deviation_of(p, q)), 1e-16));
              }
          curves[q].push_back(curve);
          std::vector<Cell> row = panel_cells(panel);
          row.push_back(label(q));
          for (const double threshold : s.map.thresholds)
            row.push_back(threshold_entry(r, d, full_stick, q, threshold));
          thresholds.add(std::move(row));
        }
    }

    void FeMap::close_panel(const std::size_t panel, const fs::path &, SceneResult &result, const bool verbose)
    {
      const Panel &p = panel_list.at(panel);
      tabulate_points(p, result, verbose);
      md << map.resolution_text << "\n\n";
      tabulate_thresholds(p);
      panel_extras(p);
    }

    /// map.md: the panels, the kind's sections, the thresholds and how they are read.
    MapReport FeMap::report(const fs::path &, bool)
    {
      return {csv, md.str() + before_thresholds() + "## Where " + words.holds + "\n\n" + thresholds.md() +
                     "\nThe thresholds interpolate log-log between the last ratio outside and the next one toward the "
                     "chapter's idealisation; every ratio of the map beyond it is within." +
                     after_thresholds() + "\n"};
    }

    /// The plots of |deviation| against the ratio with the thresholds as lines, and the kind's own.
    void FeMap::plot(const fs::path &folder)
    {
      for (auto &[q, series] : curves)
        {
          for (const double threshold : s.map.thresholds)
            series.push_back(Series{percent(threshold), {ratios.front(), ratios.back()}, {threshold, threshold},
                                    false, false});
          std::string stem = "map-" + name(q);
          std::replace(stem.begin(), stem.end(), ' ', '_');
          write_plot(folder, stem, s.info.name + ": |" + label(q) + words.deviation, x(), "|deviation|", series, true,
                     true);
        }
      extra_plots(folder);
    }


    /// A real grading (a finite surface modulus, a coating, the error function) against the power law: per k the
    /// sharp check with the power law itself, the ratios, and the FE resolution from one uniform refinement more at
    /// the ratio nearest the power law.
    class GradingMap final : public FeMap
    {
    public:
      GradingMap(const Scene &scene, Grading g)
        : FeMap(scene, MapColumns{g.ratio, is_indenter(scene), false},
                {"closed form (power-law idealisation E0, c0, k)", axis_pressure(), " / power law - 1|",
                 "the power law holds"},
                {"k"}, sorted_values(scene))
        , grading(std::move(g))
      {
        for (const double k : exponents(s))
          panel_list.push_back({k, s.material.nu});
        md << "The FE model of " << grading.text
           << " against the power-law closed forms (E0, c0, k; 9.1) at the FE depth: deviation = FE / closed form - 1"
           << " (force at the depth" << (is_indenter(s) ? ", contact radius at the depth" : "") << ", pressure at r = "
           << format(axis_sample) << " a). Load/a = " << format(s.load.a) << " m, the FE under contact-radius control.\n\n";
      }

      /// The sharp check: the same FE model with the power law itself, where the closed forms are exact.
      void open_panel(const std::size_t panel, SceneResult &result, const bool verbose) override
      {
        const double k = panel_list.at(panel).k;
        start_panel();
        if (grading.toward_large && k < 0)
          md << "k < 0 with a finite surface modulus: where z0 is thinner than the surface cells (outside r <= 1.05 a "
                "they are not halved), the plain Gauss rule under-integrates E ~ (z + z0)^k near z = 0, so the FE "
                "carries an error of about 1e-3 of the force at a/z0 >= 1e4 that one uniform refinement reduces only "
                "in part (fem/doc/limits.md); read the thresholds below 1 % with that in mind.\n\n";
        const MapPoint exact = solve_graded(graded(s, grading, k, 0.), 0.);
        add_check_rows(s, exact,
                       "k = " + format(k) + ", the power law itself (" + x() +
                         (grading.toward_large ? " -> inf)" : " -> 0)"),
                       result);
        if (verbose)
          std::cerr << "  k = " << k << ", the power law: force " << exact.force << ", radius " << exact.radius
                    << ", pressure " << exact.pressure << (exact.error.empty() ? "" : " (" + exact.error + ")") << '\n';
      }

      void solve(const std::size_t panel, const std::size_t point, SceneResult &, bool) override
      {
        const double ratio = values.at(point);
        map.points.push_back(solve_graded(graded(s, grading, panel_list.at(panel).k, ratio), ratio));
      }

      void close_panel(const std::size_t panel, const fs::path &folder, SceneResult &result, const bool verbose) override
      {
        resolve(panel_list.at(panel).k);
        FeMap::close_panel(panel, folder, result, verbose);
      }

    private:
      /// The FE resolution of the map: the point nearest the power law again with one uniform refinement more; a
      /// deviation that changes by more than a third of a threshold cannot place that threshold.
      void resolve(const double k)
      {
        const bool toward_large = grading.toward_large;
        std::vector<MapPoint>::const_iterator at = map.points.end();
        for (auto p = map.points.begin(); p != map.points.end(); ++p)
          if (p->error.empty() && (at == map.points.end() || (toward_large ? p->ratio > at->ratio : p->ratio < at->ratio)))
            at = p;
        const double nearest = at == map.points.end() ? ratios.front() : at->ratio;
        const MapPoint finer = at == map.points.end() ? MapPoint{} : solve_graded(graded(s, grading, k, nearest), nearest, 1);
        if (at != map.points.end() && finer.error.empty())
          for (const Quantity q : quantities)
            map.resolution[q] = std::abs(deviation_of(finer, q) - deviation_of(*at, q));
        std::ostringstream text;
        text << "FE resolution at " << x() << " = " << format(nearest)
             << " (the change with one uniform refinement more, " << finer.dofs << " DoFs):";
        if (map.resolution.empty())
          text << " not measured (" << (at == map.points.end() ? "no point was solved" : md_escape(finer.error)) << ")";
        for (const auto &[q, change] : map.resolution)
          text << " " << label(q) << " " << format(change) << ";";
        map.resolution_text = text.str();
      }

      std::string read_threshold(const std::vector<double> &r, const std::vector<double> &d, std::optional<double>,
                                 const double t) const override
      {
        return threshold_cell(r, d, t, grading.toward_large);
      }

      /// The error function's comparison with the published results, from the panel's own points.
      void panel_extras(const Panel &) override
      {
        if (!grading.published)
          return;
        std::vector<double> r, force, radius;
        for (const MapPoint &p : map.points)
          if (p.error.empty())
            {
              r.push_back(p.ratio);
              force.push_back(p.force);
              radius.push_back(p.radius);
            }
        md << published_comparison(s, r, force, radius);
      }

      Grading grading;
    };


    /// What the points of an indenter panel share: the half-space at k, its one two-body solver, the load, and the
    /// rigid limit's check on the same mesh.
    struct IndenterPanel
    {
      IndenterPanel(const Scene &s, const double k)
        : panel(unilateral_panel(s, k, s.material.nu))
        , load(panel.load)
      {
        request.pressure_radii = {axis_sample * s.load.a};
      }
      UnilateralPanel                               panel;
      fem::UnilateralLoad                           load;
      fem::OutputRequest                            request;
      std::unique_ptr<fem::UnilateralContactSolver> solver;
      MapPoint                                      rigid_check;
    };

    /// A homogeneous elastic indenter (E1 = ratio E0, Indenter/nu) on the power law at exponent k, at the rigid
    /// closed form's depth of Load/a: one two-body solver (fem::UnilateralContactSolver) for every ratio (the
    /// indenter's compliance rescaled, exact in linear elasticity) and the rigid limit (factor inf). Sharp checks
    /// on the same mesh and half-space: the rigid limit, and a graded indenter E0/2 (z/c0)^k by the equivalent
    /// medium (9.4), against the closed forms; the error of the FE's ratio there is the map's FE resolution. A panel
    /// that throws is one failed row; its points solved so far stay.
    class IndenterMap final : public FeMap
    {
    public:
      explicit IndenterMap(const Scene &scene)
        : FeMap(scene, MapColumns{{"E1/E0", "E1_over_E0"}, is_indenter(scene), false},
                {"closed form (rigid indenter)", axis_pressure(), " / rigid indenter - 1|",
                 "the rigid indenter's closed forms hold"},
                {"k"}, sorted_values(scene))
      {
        for (const double k : exponents(s))
          panel_list.push_back({k, s.material.nu});
        md << "The FE model of a homogeneous elastic indenter (E1 = ratio E0, nu = " << format(s.indenter.nu)
           << ", a half-space carrying the profile) on E0 (z/c0)^k, at the depth where the rigid indenter's closed form "
              "has the contact radius Load/a = "
           << format(s.load.a) << " m: deviation = FE(E1) / FE(rigid indenter) - 1 on one mesh (force, contact radius, "
              "pressure at r = "
           << format(axis_sample) << " a), the deviation from the rigid indenter's closed forms up to the rigid FE's "
              "own error (the sharp-check rows of errors.csv). One mesh and solver per k (fem::UnilateralContactSolver, "
              "the contact set found); E1 enters as the scale of the indenter's compliance.\n\n";
      }

      void open_panel(const std::size_t panel, SceneResult &result, bool) override
      {
        start_panel();
        open.reset();
        guarded(panel, "indenter-modulus map", result, [&] { open_solver(panel, result); });
      }

      /// A point: the FE at E1 against the rigid FE on the same mesh, which is the closed form up to the rigid
      /// check's error.
      void solve(const std::size_t panel, const std::size_t point, SceneResult &result, bool) override
      {
        guarded(panel, "indenter-modulus map", result, [&] {
          const double ratio = values.at(point);
          open->solver->set_indenter_modulus_factor(ratio);
          fem::UnilateralResult r;
          const double seconds = seconds_of([&] { r = open->solver->run(open->load, open->request); });
          map.points.push_back(relative(point_of(r, *open->panel.reference, ratio, seconds)));
        });
      }

      void close_panel(const std::size_t panel, const fs::path &folder, SceneResult &result, const bool verbose) override
      {
        guarded(panel, "indenter-modulus map", result, [&] { check_pair(panel, result, verbose); });
        FeMap::close_panel(panel, folder, result, verbose);
      }

    private:
      /// The panel's solver, and the rigid limit's sharp check (the solver's setup in its seconds).
      void open_solver(const std::size_t panel, SceneResult &result)
      {
        const double k = panel_list.at(panel).k, a = s.load.a;
        open = std::make_unique<IndenterPanel>(s, k);
        // The contact grows toward the homogeneous pairing's radius at this depth as E1 / E0 falls.
        Scene homogeneous = open->panel.scene;
        homogeneous.material.k = 0.;
        homogeneous.load.control = LoadParameters::Control::depth;
        homogeneous.load.depth = open->load.depth;
        const double widest = std::max(a, AnalyticReference(homogeneous, batch::Method::closed_form,
                                                            AnalyticReference::Problem::normal).radius());
        const double setup = seconds_of([&] { open->solver = elastic_indenter_solver(s, open->panel, 1.25 * widest); });
        fem::UnilateralResult r;
        open->solver->set_indenter_modulus_factor(std::numeric_limits<double>::infinity());
        const double seconds = setup + seconds_of([&] { r = open->solver->run(open->load, open->request); });
        open->rigid_check = point_of(r, *open->panel.reference, 0., seconds);
        add_check_rows(s, open->rigid_check, "k = " + format(k) + ", rigid indenter (E1/E0 -> inf)", result);
      }

      /// 9.4: a graded indenter of the same law, where the equivalent medium is exact, on the same solver (the
      /// half-space and its compliance are kept); the error of the FE's ratio two bodies / rigid indenter there is
      /// the FE resolution.
      void check_pair(const std::size_t panel, SceneResult &result, const bool verbose)
      {
        const double k = panel_list.at(panel).k, a = s.load.a;
        const Scene &g = open->panel.scene;
        Scene pair = g;
        pair.indenter.elasticity = IndenterParameters::Elasticity::graded;
        // Another E0 and nu than the half-space's: with the same ones the two bodies are one body twice and
        // the FE's ratio is exact on any mesh.
        pair.indenter.E = g.material.E0 / 2;
        pair.indenter.nu = g.material.nu < 0.4 ? 0.45 : 0.2;
        const AnalyticReference equivalent(pair, batch::Method::closed_form, AnalyticReference::Problem::normal);
        fem::UnilateralResult r;
        const double seconds = seconds_of([&] {
          open->solver->set_indenter_body(fe_indenter_body(pair));
          r = open->solver->run(open->load, open->request);
        });
        const MapPoint pair_check = point_of(r, equivalent, 0., seconds);
        add_check_rows(s, pair_check,
                       "k = " + format(k) + ", graded indenter E0/2 (z/c0)^k, nu = " + format(pair.indenter.nu) + " (9.4)",
                       result);
        if (verbose)
          std::cerr << "  k = " << k << ": rigid limit force " << open->rigid_check.force
                    << ", two graded bodies (9.4) force " << pair_check.force << '\n';
        const MapPoint pair_ratio = relative(pair_check);
        if (pair_ratio.error.empty())
          for (const Quantity q : all_quantities)
            map.resolution[q] = std::abs(deviation_of(pair_ratio, q)); // (FE / closed form of 9.4) / (the same, rigid) - 1
        std::ostringstream text;
        text << "FE resolution (the error of the FE's ratio two bodies / rigid indenter where 9.4 gives it, "
             << open->solver->n_dofs() << " DoFs):";
        if (map.resolution.empty())
          text << " not measured (" << md_escape(open->rigid_check.error + pair_check.error) << ")";
        for (const auto &[q, change] : map.resolution)
          text << " " << label(q) << " " << format(change) << ";";
        text << " E(a) = E0 (a/c0)^k = " << format(std::pow(a / g.material.c0, k)) << " E0, so E1/E(a) = "
             << format(std::pow(g.material.c0 / a, k)) << " E1/E0.";
        map.resolution_text = text.str();
      }

      /// The deviations of `r` from the closed forms `ref`.
      MapPoint point_of(const fem::UnilateralResult &r, const AnalyticReference &ref, const double ratio,
                        const double seconds) const
      {
        MapPoint p;
        p.ratio = ratio;
        p.dofs = open->solver->n_dofs();
        p.seconds = seconds;
        p.error = disc_contact_error(r);
        if (p.error.empty())
          {
            p.force = r.force / ref.get("force") - 1;
            p.radius = r.outer_edge / ref.radius() - 1;
            p.pressure = r.pressure.at(0).value / ref.at("pressure", axis_sample * s.load.a) - 1;
          }
        return p;
      }

      /// `p` against the rigid FE on the same mesh.
      MapPoint relative(MapPoint p) const
      {
        const MapPoint &rigid = open->rigid_check;
        if (p.error.empty() && rigid.error.empty())
          {
            p.force = (1 + p.force) / (1 + rigid.force) - 1;
            p.radius = (1 + p.radius) / (1 + rigid.radius) - 1;
            p.pressure = (1 + p.pressure) / (1 + rigid.pressure) - 1;
          }
        else if (p.error.empty())
          p.error = "the rigid limit failed: " + rigid.error;
        return p;
      }

      std::string read_threshold(const std::vector<double> &r, const std::vector<double> &d, std::optional<double>,
                                 const double t) const override
      {
        return threshold_cell(r, d, t, true);
      }

      std::unique_ptr<IndenterPanel> open;
    };


    /// What the points of a friction panel share: the half-space at (k, nu), its one solver, and the frictionless
    /// FE (the reference of every point) with its check against the closed forms.
    struct FrictionPanel
    {
      FrictionPanel(const Scene &s, const double k, const double nu)
        : panel(unilateral_panel(s, k, nu))
        , f(friction_solver(s, panel, friction_pressure_radii))
      {}
      UnilateralPanel       panel;
      FrictionSolver        f;
      MapPoint              smooth_check;
      fem::UnilateralResult smooth;
    };

    /// Holl's ratio nu = 1/(2 + k): pressure causes no radial displacement of E ~ z^k.
    bool at_holl_ratio(const Panel &p) { return std::abs(p.nu - 1. / (2. + p.k)) <= 1e-12; }

    /// A friction map's points: every mu of Map/values, ascending, and full stick (mu = inf) with Map/full stick.
    std::vector<double> friction_values(const Scene &s)
    {
      std::vector<double> mus = sorted_values(s);
      if (s.map.full_stick)
        mus.push_back(std::numeric_limits<double>::infinity());
      return mus;
    }

    /// Coulomb friction mu = ratio (and full stick, ratio inf) between a rigid indenter and the power law at
    /// exponent k and Poisson ratio nu during loading to the rigid closed form's depth of Load/a: one solver for
    /// the frictionless run and every mu (fem::UnilateralContactSolver, the shear operator built once). A point is
    /// FE(mu) / FE(frictionless) - 1 on one mesh, extrapolated from N and 2N load steps; the stick radius is the FE's.
    /// Sharp checks: the frictionless FE against the closed forms, and at Holl's ratio nu = 1/(2 + k) friction must
    /// change nothing. The FE resolution: the change of the largest-mu point with twice the load steps (the path's
    /// discretisation: a vertex that comes into contact during a step carries no shear in it), and, at Holl's
    /// ratio, the frictional FE's own deviation.
    class FrictionMap final : public FeMap
    {
    public:
      explicit FrictionMap(const Scene &scene)
        : FeMap(scene, MapColumns{{"mu", "mu"}, is_indenter(scene), true},
                {"FE frictionless", friction_pressure, " / frictionless - 1|", "the frictionless closed forms hold"},
                {"k", "nu"}, friction_values(scene))
        , largest(largest_table())
      {
        // Every k at every nu of Map/nu values (Material/nu), and Holl's ratio where it is a Poisson ratio.
        for (const double k : exponents(s))
          {
            std::vector<double> nus =
              s.map.poisson_ratios.empty() ? std::vector<double>{s.material.nu} : s.map.poisson_ratios;
            if (s.map.holl_ratio && 1. / (2. + k) <= 0.5 &&
                std::none_of(nus.begin(), nus.end(), [k](const double nu) { return at_holl_ratio({k, nu}); }))
              nus.push_back(1. / (2. + k));
            for (const double nu : nus)
              panel_list.push_back({k, nu});
          }
        md << intro();
      }

      /// The panel's solver and its sharp check, the frictionless FE against the closed forms; when that fails the
      /// panel has no points.
      void open_panel(const std::size_t panel, SceneResult &result, bool) override
      {
        start_panel();
        open.reset();
        guarded(panel, "friction map", result, [&] {
          const Panel &p = panel_list.at(panel);
          open = std::make_unique<FrictionPanel>(s, p.k, p.nu);
          open->smooth_check = frictionless_check(open->f, *open->panel.reference, s.load.a);
          add_check_rows(s, open->smooth_check, panel_name(p) + ", frictionless", result,
                         "pressure, L2 change over r/a in [" + format(friction_pressure_radii.front()) + ", " +
                           format(friction_pressure_radii.back()) + "] (area-weighted, relative)");
          if (!open->smooth_check.error.empty())
            map.resolution_text =
              "not measured (the frictionless FE failed: " + md_escape(open->smooth_check.error) + ")";
          else
            open->smooth = open->f.r;
        });
      }

      /// One mu, extrapolated from N and 2N steps. At Holl's ratio every point is a sharp check: the decoupled
      /// pairing's frictional FE against the frictionless FE.
      void solve(const std::size_t panel, const std::size_t point, SceneResult &result, bool) override
      {
        if (!frictionless_solved())
          return;
        const Panel &pn = panel_list.at(panel);
        const double mu = values.at(point);
        const unsigned int steps = s.friction.load_steps;
        map.points.push_back(extrapolated(friction_at_steps(open->f, open->smooth, mu, steps),
                                          friction_at_steps(open->f, open->smooth, mu, 2 * steps)));
        const MapPoint &p = map.points.back();
        if (at_holl_ratio(pn) && p.error.empty())
          {
            const std::string what = panel_name(pn) + ", mu = " + format(mu) + " against mu = 0 (decoupled: equal)";
            result.rows.push_back(compare("force at the depth (friction)", what, "FE", "FE frictionless", 1.,
                                          1. + p.force, 1., s.tolerances.force, p.dofs, p.seconds));
            result.rows.push_back(compare("contact radius (friction)", what, "FE", "FE frictionless", 1.,
                                          1. + p.radius, 1., s.tolerances.contact_radius, p.dofs, p.seconds));
          }
      }

      void close_panel(const std::size_t panel, const fs::path &folder, SceneResult &result, const bool verbose) override
      {
        const Panel &p = panel_list.at(panel);
        if (frictionless_solved())
          guarded(panel, "friction map", result, [&] {
            friction_resolution(open->f, open->smooth, s.friction.load_steps, at_holl_ratio(p), open->smooth_check, map);
            if (verbose)
              std::cerr << "  k = " << p.k << ", nu = " << p.nu << ": frictionless force " << open->smooth_check.force
                        << '\n';
          });
        FeMap::close_panel(panel, folder, result, verbose);
      }

    private:
      bool frictionless_solved() const { return failure.empty() && open && open->smooth_check.error.empty(); }

      std::string panel_name(const Panel &p) const override
      {
        return "k = " + format(p.k) + ", nu = " + (at_holl_ratio(p) ? "1/(2 + k) = " : "") + format(p.nu);
      }

      std::vector<Cell> panel_cells(const Panel &p) const override { return {format(p.k), format(p.nu)}; }

      std::string read_threshold(const std::vector<double> &r, const std::vector<double> &d,
                                 const std::optional<double> full_stick, const double t) const override
      {
        return friction_threshold_cell(r, d, full_stick, t);
      }

      /// What map.md says of the friction map.
      std::string intro() const
      {
        std::ostringstream text;
        text << "The FE model of a rigid indenter with Coulomb friction mu between it and E0 (z/c0)^k, loaded from zero "
                "(in "
             << s.friction.load_steps << " and " << 2 * s.friction.load_steps
             << " steps, extrapolated) to the depth where the frictionless closed form has the contact radius Load/a = "
             << format(s.load.a) << " m: deviation = FE(mu) / FE(frictionless) - 1 on one mesh (force at the depth, "
                "contact radius; for the pressure the change of p(r) sampled at r/a = "
             << format(friction_pressure_radii.front()) << ", ..., " << format(friction_pressure_radii.back())
             << " in the area-weighted L2 norm relative to p's, with the sign of the change at r = 0.5 a), the error of "
                "the chapter's frictionless closed forms up to the frictionless "
                "FE's own error (the sharp-check rows of errors.csv); c/a is the radius of the stick zone around the "
                "axis over the contact radius (slip outside it). One mesh and solver per (k, nu) "
                "(fem::UnilateralContactSolver, the contact, stick and slip sets found at every step). At Holl's ratio "
                "nu = 1/(2 + k) pressure causes no radial displacement and friction must change nothing: those rows are "
                "sharp checks.\n\n";
        return text.str();
      }

      /// The table of the largest effects, empty: a row per panel, a column per quantity.
      Table largest_table() const
      {
        std::vector<Column> c{Column::md_only("k"), Column::md_only("nu")};
        for (const Quantity q : quantities)
          c.push_back(Column::md_only(label(q)));
        c.push_back(Column::md_only("c/a at the largest finite mu"));
        return Table(c);
      }

      /// A panel's row of the largest effects (the largest |deviation| of each quantity, and c/a at the largest
      /// finite mu) and its curve of the stick radius c/a over the finite mu.
      void panel_extras(const Panel &panel) override
      {
        const std::vector<MapPoint> &points = map.points;
        std::vector<Cell> row{format(panel.k), format(panel.nu)};
        for (const Quantity q : quantities)
          {
            double worst = -1;
            for (const MapPoint &p : points)
              if (p.error.empty())
                worst = std::max(worst, std::abs(deviation_of(p, q)));
            row.push_back(worst < 0 ? std::string("no point") : format(worst));
          }
        const auto last = std::find_if(points.rbegin(), points.rend(),
                                       [](const MapPoint &p) { return p.error.empty() && std::isfinite(p.ratio); });
        row.push_back(last == points.rend() ? Cell() : Cell(format(last->stick)));
        largest.add(std::move(row));
        Series curve{panel_name(panel), {}, {}, false, true};
        for (const MapPoint &p : points)
          if (p.error.empty() && !std::isinf(p.ratio))
            {
              curve.x.push_back(p.ratio);
              curve.y.push_back(p.stick);
            }
        stick.push_back(curve);
      }

      std::string before_thresholds() const override
      {
        return std::string("## The largest effect of friction\n\nOver the map's mu") +
               (s.map.full_stick ? " and full stick" : "") +
               ": the largest |FE(mu) / FE(frictionless) - 1| and the stick radius c/a at the largest finite mu.\n\n" +
               largest.md() + "\n";
      }

      std::string after_thresholds() const override
      {
        return " Full stick (mu = inf) is read on its own: \"full stick included\" when it is within too.";
      }

      void extra_plots(const fs::path &folder) const override
      {
        write_plot(folder, "map-stick_radius", s.info.name + ": stick radius c/a", x(), "c/a", stick, true, false);
      }

      std::unique_ptr<FrictionPanel> open;
      Table                          largest;
      std::vector<Series>            stick; ///< c/a over mu, a curve per panel
    };

  } // namespace

  std::unique_ptr<MapStrategy> fe_map_strategy(const Scene &s)
  {
    require_kind(s, SceneKind::map, "fe_map_strategy");
    switch (s.map.parameter)
      {
        case MapParameters::Parameter::surface_depth:
        case MapParameters::Parameter::coating_thickness:
        case MapParameters::Parameter::erf_width:
          return std::make_unique<GradingMap>(s, grading_of(s));
        case MapParameters::Parameter::indenter_modulus:
          return std::make_unique<IndenterMap>(s);
        case MapParameters::Parameter::friction_coefficient:
          return std::make_unique<FrictionMap>(s);
        default:
          throw std::invalid_argument("fe_map_strategy: scene " + s.file + " is a map of another runner (Coulomb 3D: "
                                      "fe_coulomb_3d.h; Tabor parameter: fe_cohesive.h; largest stress: stress_map.h)");
      }
  }
} // namespace gradcontact::cases
