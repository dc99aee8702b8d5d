#include "fe_map.h"

#include "analytic_reference.h"
#include "fe_model.h"
#include "fe_scene.h"

#include <fem/axisymmetric_solver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Type = LoadParameters::Type;

  std::optional<double> threshold_ratio(const std::vector<double> &ratios, const std::vector<double> &deviations,
                                        const double threshold)
  {
    if (ratios.size() != deviations.size() || ratios.empty())
      throw std::invalid_argument("threshold_ratio: " + std::to_string(ratios.size()) + " ratios and " +
                                  std::to_string(deviations.size()) + " deviations (need the same number, >= 1)");
    std::optional<std::size_t> last_outside;
    for (std::size_t i = 0; i < ratios.size(); ++i)
      if (!(std::abs(deviations[i]) <= threshold))
        last_outside = i;
    if (!last_outside)
      return ratios.front();
    const std::size_t i = *last_outside;
    if (i + 1 == ratios.size())
      return std::nullopt;
    const double d0 = std::abs(deviations[i]), d1 = std::abs(deviations[i + 1]);
    if (!(d1 > 0.) || !std::isfinite(d0) || d1 >= d0)
      return ratios[i + 1];
    const double slope = std::log(ratios[i + 1] / ratios[i]) / std::log(d1 / d0);
    return ratios[i] * std::exp(std::log(threshold / d0) * slope);
  }

  std::string threshold_cell(const std::vector<double> &ratios, const std::vector<double> &deviations,
                             const double threshold, const bool toward_large)
  {
    if (!toward_large)
      {
        // the power law is the limit ratio -> 0: read the map in 1/ratio, which grows toward it
        std::vector<double> inverse, flipped;
        for (std::size_t i = ratios.size(); i-- > 0;)
          {
            inverse.push_back(1. / ratios[i]);
            flipped.push_back(deviations[i]);
          }
        const std::optional<double> at = threshold_ratio(inverse, flipped, threshold);
        if (!at)
          return "not within it down to " + format(ratios.front());
        if (*at == inverse.front() && std::abs(flipped.front()) <= threshold)
          return "at every ratio (up to " + format(ratios.back()) + ")";
        return "<= " + format(1. / *at);
      }
    const std::optional<double> at = threshold_ratio(ratios, deviations, threshold);
    if (!at)
      return "not within it up to " + format(ratios.back());
    if (*at == ratios.front() && std::abs(deviations.front()) <= threshold)
      return "at every ratio (from " + format(ratios.front()) + ")";
    return ">= " + format(*at);
  }

  namespace
  {
    /// One FE solve of a map: the FE state and its deviations from the power law at the FE depth.
    struct MapPoint
    {
      double ratio = 0.;                      ///< a/z0 or a/H (0: the power law itself)
      double force = 0., radius = 0., pressure = 0.; ///< FE/closed form - 1 (radius: indenters only)
      unsigned int dofs = 0;
      double seconds = 0.;
      std::string error; ///< non-empty when the solve or the reference failed
    };

    /// The radius near the axis where p is sampled (the r-weighted recovery does not constrain the axis node).
    constexpr double axis_sample = 0.02;

    bool is_indenter(const Scene &s) { return s.load.type != Type::flat_punch; }

    /// The scene at exponent k with the grading of `ratio` (0: the power law itself).
    Scene graded(const Scene &s, const double k, const double ratio)
    {
      Scene g = s;
      g.material.k = k;
      g.map.parameter = MapParameters::Parameter::none;
      if (ratio == 0.)
        g.material.modulus = MaterialParameters::Modulus::power_law;
      else if (s.map.parameter == MapParameters::Parameter::surface_depth)
        {
          g.material.modulus = MaterialParameters::Modulus::shifted_power_law;
          g.material.surface_depth = s.load.a / ratio;
        }
      else
        {
          g.material.modulus = MaterialParameters::Modulus::coating;
          g.material.coating_thickness = s.load.a / ratio;
        }
      g.kind = SceneKind::normal;
      return g;
    }

    /// Solves `g` under contact-radius control and compares it with the power-law closed forms at the FE depth.
    MapPoint solve(const Scene &g, const double ratio, const unsigned int extra_refinements = 0)
    {
      MapPoint p;
      p.ratio = ratio;
      const auto start = std::chrono::steady_clock::now();
      try
        {
          const FeModel model = fe_model(g, finest_refinement(g) + extra_refinements);
          fem::AxisymmetricSolver solver(model.material, model.settings.mesh, model.settings.discretization);
          fem::OutputRequest out;
          out.pressure_radii = {axis_sample * g.load.a};
          const fem::Result r = solver.run(model.load, out);
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

    std::string ratio_name(const Scene &s)
    {
      return s.map.parameter == MapParameters::Parameter::surface_depth ? "a/z0" : "a/H";
    }

    /// `text` for a markdown table cell: | escaped.
    std::string cell(const std::string &text)
    {
      std::string out;
      for (const char c : text)
        out += c == '|' ? std::string("\\|") : std::string(1, c);
      return out;
    }

    std::string percent(const double t)
    {
      std::ostringstream o;
      o << t * 100 << " %";
      return o.str();
    }
  } // namespace

  SceneResult run_map_scene(const Scene &s, const fs::path &folder, const bool verbose)
  {
    require_kind(s, SceneKind::map, "run_map_scene");
    const auto start = std::chrono::steady_clock::now();
    SceneResult result = started(s, folder);

    const std::vector<double> ks = s.map.exponents.empty() ? std::vector<double>{s.material.k} : s.map.exponents;
    std::vector<double> ratios = s.map.ratios;
    std::sort(ratios.begin(), ratios.end());
    const std::string x = ratio_name(s);
    const bool indenter = is_indenter(s);
    const std::vector<std::string> quantities =
      indenter ? std::vector<std::string>{"force", "contact radius", "pressure"} : std::vector<std::string>{"force", "pressure"};
    const auto deviation = [](const MapPoint &p, const std::string &q) {
      return q == "force" ? p.force : (q == "contact radius" ? p.radius : p.pressure);
    };
    const auto quantity_label = [](const std::string &q) {
      return q == "pressure" ? "p(" + format(axis_sample) + " a)" : q;
    };

    std::ofstream csv(folder / "map.csv");
    csv << "k," << (x == "a/z0" ? "a_over_z0" : "a_over_H") << ",force_deviation,contact_radius_deviation,"
        << "pressure_deviation,dofs,seconds,error\n";
    csv.precision(10);
    std::ostringstream md, thresholds_md;
    md << "# " << s.info.name << ": applicability map\n\n"
       << (s.info.description.empty() ? "" : s.info.description + "\n\n")
       << "The FE model of " << (x == "a/z0" ? "E(z) = E0 ((z + z0)/c0)^k (a finite surface modulus)"
                                             : "a graded coating E0 (z/c0)^k on 0 < z <= H over the substrate E0 (H/c0)^k")
       << " against the power-law closed forms (E0, c0, k; 9.1) at the FE depth: deviation = FE / closed form - 1"
       << " (force at the depth" << (indenter ? ", contact radius at the depth" : "") << ", pressure at r = "
       << format(axis_sample) << " a). Load/a = " << format(s.load.a) << " m, the FE under contact-radius control.\n\n";
    // The power law is the limit a/z0 -> inf of a finite surface modulus and a/H -> 0 of a coating.
    const bool toward_large = s.map.parameter == MapParameters::Parameter::surface_depth;
    thresholds_md << "## Where the power law holds\n\n| k | quantity |";
    for (const double t : s.map.thresholds)
      thresholds_md << " within " << percent(t) << " when " << x << " |";
    thresholds_md << "\n|---|---|";
    for (std::size_t i = 0; i < s.map.thresholds.size(); ++i)
      thresholds_md << "---|";
    thresholds_md << '\n';

    std::map<std::string, std::vector<Series>> plots;
    for (const double k : ks)
      {
        // The sharp check: the same FE model with the power law itself, where the closed forms are exact.
        const MapPoint exact = solve(graded(s, k, 0.), 0.);
        const std::string metric = "k = " + format(k) + ", the power law itself (" + x + (toward_large ? " -> inf)" : " -> 0)");
        if (!exact.error.empty())
          result.rows.push_back(failed("force at the FE depth", "FE", "closed form", metric + ": " + exact.error));
        else
          {
            result.rows.push_back(compare("force at the FE depth", metric, "FE", "closed form", 1., 1. + exact.force, 1.,
                                          s.tolerances.force, exact.dofs, exact.seconds));
            if (indenter)
              result.rows.push_back(compare("contact radius at the FE depth", metric, "FE", "closed form", 1.,
                                            1. + exact.radius, 1., s.tolerances.contact_radius, exact.dofs, exact.seconds));
            result.rows.push_back(compare("pressure at r = " + format(axis_sample) + " a", metric, "FE", "closed form", 1.,
                                          1. + exact.pressure, 1., s.tolerances.pressure, exact.dofs, exact.seconds));
          }
        if (verbose)
          std::cerr << "  k = " << k << ", the power law: force " << exact.force << ", radius " << exact.radius
                    << ", pressure " << exact.pressure << (exact.error.empty() ? "" : " (" + exact.error + ")") << '\n';

        if (toward_large && k < 0)
          md << "k < 0 with a finite surface modulus: where z0 is thinner than the surface cells (outside r <= 1.05 a "
                "they are not halved), the plain Gauss rule under-integrates E ~ (z + z0)^k near z = 0, so the FE "
                "carries an error of about 1e-3 of the force at a/z0 >= 1e4 that one uniform refinement reduces only "
                "in part (fem/README.md, \"Limits\"); read the thresholds below 1 % with that in mind.\n\n";
        md << "## k = " << format(k) << "\n\n| " << x << " | force | " << (indenter ? "contact radius | " : "")
           << "p(" << format(axis_sample) << " a) | DoFs | s |\n|---|---|" << (indenter ? "---|" : "") << "---|---|---|\n";
        std::vector<MapPoint> points;
        for (const double ratio : ratios)
          {
            points.push_back(solve(graded(s, k, ratio), ratio));
            const MapPoint &p = points.back();
            csv << k << ',' << ratio << ',' << p.force << ',' << (indenter ? p.radius : std::nan("")) << ','
                << p.pressure << ',' << p.dofs << ',' << p.seconds << ',' << csv_quote(p.error) << '\n';
            md << "| " << format(ratio);
            if (p.error.empty())
              {
                md << " | " << format(p.force) << " | " << (indenter ? format(p.radius) + " | " : "") << format(p.pressure);
              }
            else
              md << " | failed: " << cell(p.error) << " | " << (indenter ? "- | " : "") << "-";
            md << " | " << p.dofs << " | " << format(p.seconds) << " |\n";
            if (verbose)
              std::cerr << "  k = " << k << ", " << x << " = " << ratio << ": force " << p.force << ", radius "
                        << p.radius << ", pressure " << p.pressure << (p.error.empty() ? "" : " (" + p.error + ")")
                        << ", " << p.seconds << " s\n";
            if (!p.error.empty())
              result.rows.push_back(failed("map point", "FE", "closed form (power-law idealisation E0, c0, k)",
                                           "k = " + format(k) + ", " + x + " = " + format(ratio) + ": " + p.error));
          }
        // The FE resolution of the map: the point nearest the power law again with one uniform refinement
        // more; a deviation that changes by more than a third of a threshold cannot place that threshold.
        std::map<std::string, double> resolution;
        {
          // the solved point nearest the power law
          std::vector<MapPoint>::const_iterator at = points.end();
          for (auto p = points.begin(); p != points.end(); ++p)
            if (p->error.empty() && (at == points.end() || (toward_large ? p->ratio > at->ratio : p->ratio < at->ratio)))
              at = p;
          const double nearest = at == points.end() ? ratios.front() : at->ratio;
          const MapPoint finer = at == points.end() ? MapPoint{} : solve(graded(s, k, nearest), nearest, 1);
          if (at != points.end() && finer.error.empty())
            for (const std::string &q : quantities)
              resolution[q] = std::abs(deviation(finer, q) - deviation(*at, q));
          md << "FE resolution at " << x << " = " << format(nearest) << " (the change with one uniform refinement more, "
             << finer.dofs << " DoFs):";
          if (resolution.empty())
            md << " not measured (" << (at == points.end() ? "no point was solved" : cell(finer.error)) << ")";
          for (const auto &[q, change] : resolution)
            md << " " << quantity_label(q) << " " << format(change) << ";";
          md << "\n\n";
        }
        for (const std::string &q : quantities)
          {
            std::vector<double> r, d;
            Series curve{"k = " + format(k), {}, {}, false, true};
            for (const MapPoint &p : points)
              if (p.error.empty())
                {
                  r.push_back(p.ratio);
                  d.push_back(deviation(p, q));
                  curve.x.push_back(p.ratio);
                  curve.y.push_back(std::max(std::abs(deviation(p, q)), 1e-16));
                }
            plots[q].push_back(curve);
            thresholds_md << "| " << format(k) << " | " << quantity_label(q) << " |";
            for (const double t : s.map.thresholds)
              {
                if (r.empty())
                  {
                    thresholds_md << " no point |";
                    continue;
                  }
                if (resolution.count(q) == 0)
                  {
                    thresholds_md << " FE resolution not measured |";
                    continue;
                  }
                if (!(resolution[q] <= t / 3))
                  {
                    thresholds_md << " below the FE resolution (" << format(resolution[q]) << ") |";
                    continue;
                  }
                thresholds_md << " " << threshold_cell(r, d, t, toward_large) << " |";
              }
            thresholds_md << '\n';
          }
      }
    std::ofstream(folder / "map.md") << md.str() << thresholds_md.str()
                                     << "\nThe thresholds interpolate log-log between the last ratio outside and the next "
                                        "one toward the power law; every ratio of the map beyond it is within.\n";
    if (s.outputs.plots)
      for (auto &[q, series] : plots)
        {
          for (const double t : s.map.thresholds)
            series.push_back(Series{percent(t), {ratios.front(), ratios.back()}, {t, t}, false, false});
          std::string stem = "map-" + q;
          std::replace(stem.begin(), stem.end(), ' ', '_');
          write_plot(folder, stem, s.info.name + ": |" + quantity_label(q) + " / power law - 1|", x,
                     "|deviation|", series, true, true);
        }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
} // namespace gradcontact::cases
