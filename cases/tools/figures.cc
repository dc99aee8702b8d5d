#include "tools/figures.h"
#include "tools/fe_oracle.h"

#include "runners/fe_adhesion.h"
#include "runners/fe_scene.h"
#include "runners/fe_tangential.h"
#include "report/report.h"
#include "report/result_cache.h"
#include "report/table.h"
#include "runners/run_scene.h"
#include "scene/scene.h"

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    // The chapter's figures that show data (9.1-9.3, 9.6, 9.10, 9.13, 9.15, 9.20, 9.21, 9.26 and 9.30 are
    // sketches of the contact geometry or of the MDR model): the index names those not drawn yet.
    const std::vector<std::string> chapter_data_figures = {
      "9.4",  "9.5",  "9.7",  "9.8",  "9.9",  "9.11", "9.12", "9.14", "9.16", "9.17", "9.18", "9.19", "9.22",
      "9.23", "9.24", "9.25", "9.27", "9.28", "9.29", "9.31", "9.32", "9.33", "9.34", "9.35", "9.36"};

    // A title longer than this does not fit above a 1000 px wide plot in gnuplot's default font: it would be
    // cut off, so it is refused (the caption belongs in "caption").
    constexpr std::size_t max_title_characters = 95;

    // Bisection steps that solve x(t) = x_point between two drawn samples: 2^-60 of the sample spacing.
    constexpr int abscissa_bisection_steps = 60;

    // key may name a nested entry, e.g. "geometry.n"
    double request_value(json request, const std::string &key, const double t, const bool insert)
    {
      if (insert)
        {
          const auto dot = key.find('.');
          if (dot == std::string::npos)
            request[key] = t;
          else
            request[key.substr(0, dot)][key.substr(dot + 1)] = t;
        }
      return batch::evaluate(batch::parse(request));
    }

    // One coordinate of a curve point: the swept value, or a request at it (scaled, normalised).
    double coordinate(const json &spec, const std::string &key, const double t)
    {
      const double scale = spec.value("scale", 1.);
      // "value": a constant, e.g. FE / closed form = 1 where the closed form holds exactly
      if (spec.contains("value"))
        return spec.at("value").get<double>() * scale;
      if (spec.value("sweep", false))
        return t * scale;
      if (!spec.contains("request"))
        throw std::invalid_argument("figure: a coordinate needs \"sweep\": true, a \"value\" or a \"request\"");
      double value = request_value(spec["request"], key, t, true) * scale;
      // "minus": a request at fixed parameters subtracted before the division (e.g. the shift of 9.74)
      if (spec.contains("minus"))
        value -= request_value(spec["minus"], key, t, false) * scale;
      if (spec.contains("divide_by"))
        value /= request_value(spec["divide_by"], key, t, false);
      return value;
    }

    /// An analytic curve as drawn: its spec, and the parameter t of every drawn sample.
    struct AnalyticCurve
    {
      const json *spec = nullptr;
      std::string key;
      std::vector<double> t, x, y;
      double y_scale = 0; ///< max |y| over the drawn samples: the scale of a point's error
      double x_at(const double s) const { return coordinate(spec->at("x"), key, s); }
      double y_at(const double s) const { return coordinate(spec->at("y"), key, s); }
    };

    /// One checked point of a figure: the point, its closed-form reference at the same abscissa, the error.
    struct CheckedPoint
    {
      std::string series, reference_curve, note;
      double x = 0, y = 0, reference = std::numeric_limits<double>::quiet_NaN();
      double error = std::numeric_limits<double>::infinity(), tolerance = 0;
      bool pass = false;
      /// A measured deviation (a validation figure: how far the closed form is from a model that drops its
      /// idealisation): tabulated, never failed on its size; it still fails when not finite or off the curve.
      bool measured = false;
    };

    // The closed form's value at abscissa x on `curve`: every pair of drawn samples that brackets x is
    // refined by bisection of x(t) - x; the root whose y is closest to y_point is returned (several brackets
    // exist where x(t) is not monotone, e.g. the depth of an adhesive contact). Returns false when no pair
    // brackets x (x outside the drawn range). A point at the end of a curve that ends at a turning load (the
    // loop of 9.84 at F_x = +-F_A) carries the FE error in its abscissa too: within `slack` of an end of the
    // drawn curve the end itself is the reference.
    bool reference_at(const AnalyticCurve &curve, const double x, const double y_point, const double slack,
                      double &y_ref)
    {
      bool found = false;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i + 1 < curve.x.size(); ++i)
        {
          const double x0 = curve.x[i] - x, x1 = curve.x[i + 1] - x;
          if (x0 * x1 > 0)
            continue;
          double ta = curve.t[i], tb = curve.t[i + 1], fa = x0;
          double t = x0 == 0 ? ta : x1 == 0 ? tb : 0.5 * (ta + tb);
          if (x0 != 0 && x1 != 0)
            for (int k = 0; k < abscissa_bisection_steps; ++k)
              {
                t = 0.5 * (ta + tb);
                const double ft = curve.x_at(t) - x;
                if ((ft < 0) == (fa < 0))
                  ta = t, fa = ft;
                else
                  tb = t;
              }
          double y = std::numeric_limits<double>::quiet_NaN();
          try
            {
              y = curve.y_at(t);
            }
          catch (const std::exception &)
            {
              continue; // the root sits on the edge of the formula's domain; another bracket may serve
            }
          if (std::isfinite(y) && std::abs(y - y_point) < best)
            {
              best = std::abs(y - y_point);
              y_ref = y;
              found = true;
            }
        }
      if (!found)
        for (const std::size_t e : {std::size_t(0), curve.x.size() - 1})
          if (std::abs(curve.x[e] - x) <= slack && std::abs(curve.y[e] - y_point) < best)
            {
              best = std::abs(curve.y[e] - y_point);
              y_ref = curve.y[e];
              found = true;
            }
      return found;
    }

    /// Checks every point of `points` against the analytic curves named in `check`.
    std::vector<CheckedPoint> check_points(const Series &points, const json &check,
                                           const std::map<std::string, AnalyticCurve> &curves, const std::string &figure)
    {
      const std::string where = "figures: " + figure + ": point set '" + points.title + "'";
      if (!check.contains("curves") || !check.at("curves").is_array() || check.at("curves").empty())
        throw std::invalid_argument(where + ": \"check\" needs \"curves\", a non-empty list of analytic curve titles");
      const bool measured = check.value("measured", false);
      if (measured && check.contains("tolerance"))
        throw std::invalid_argument(where + ": a \"measured\" check has no \"tolerance\" (its deviation is the result)");
      if (!measured && (!check.contains("tolerance") || !check.at("tolerance").is_number()))
        throw std::invalid_argument(where + ": \"check\" needs a numeric \"tolerance\" (or \"measured\": true)");
      // A measured point may lie at most this far (relative to the curve's x-extent) beyond the drawn curve.
      constexpr double measured_slack = 1e-3;
      const double tolerance = measured ? measured_slack : check.at("tolerance").get<double>();
      if (!(tolerance > 0 && tolerance < 1))
        throw std::invalid_argument(where + ": check tolerance = " + format(tolerance) +
                                    " is outside the valid range (0, 1) (an error relative to the curve's largest |y|)");
      std::vector<const AnalyticCurve *> references;
      for (const json &title : check.at("curves"))
        {
          const auto c = curves.find(title.get<std::string>());
          if (c == curves.end())
            throw std::invalid_argument(where + ": check curve '" + title.get<std::string>() +
                                        "' is not an analytic curve of this figure");
          references.push_back(&c->second);
        }
      std::vector<CheckedPoint> out;
      for (std::size_t i = 0; i < points.x.size(); ++i)
        {
          CheckedPoint p;
          p.series = points.title;
          p.x = points.x[i];
          p.y = points.y[i];
          p.tolerance = measured ? std::numeric_limits<double>::quiet_NaN() : tolerance;
          p.measured = measured;
          double best = std::numeric_limits<double>::infinity();
          for (const AnalyticCurve *c : references)
            {
              double y_ref = 0;
              const auto [x_min, x_max] = std::minmax_element(c->x.begin(), c->x.end());
              if (!reference_at(*c, p.x, p.y, tolerance * (*x_max - *x_min), y_ref))
                continue;
              const double error = std::abs(p.y - y_ref) / std::max(c->y_scale, 1e-300);
              if (error < best)
                {
                  best = error;
                  p.reference = y_ref;
                  p.error = error;
                  p.reference_curve = c->spec->value("title", "");
                }
            }
          if (!std::isfinite(p.y))
            p.note = "the point is not a finite number";
          else if (p.reference_curve.empty())
            p.note = "abscissa " + format(p.x) + " outside the drawn range of the reference curve(s)";
          p.pass = p.note.empty() && (measured || p.error <= tolerance);
          if (p.note.empty() && !p.pass)
            p.note = "error above tolerance";
          out.push_back(p);
        }
      return out;
    }

    std::vector<Override> overrides_of(const json &fe, const std::vector<std::string> &extra = {})
    {
      std::vector<Override> overrides;
      for (const json &o : fe.value("set", json::array()))
        overrides.push_back(parse_override(o.get<std::string>()));
      for (const std::string &o : extra)
        overrides.push_back(parse_override(o));
      return overrides;
    }

    /// FE point sets cached by the scene's resolved parameters and the point set's request (ResultCache: with
    /// the program's build, so a rebuilt FE model recomputes its points), with the counts of one invocation.
    class PointCache
    {
    public:
      PointCache(fs::path folder, const bool enabled) : cache(std::move(folder), enabled) {}

      /// The cached points of `key`, else compute() stored under it.
      Series get(const std::string &request_key, const std::function<Series()> &compute)
      {
        if (const auto j = cache.get(request_key))
          try
            {
              ++hits;
              return {j->at("title"), j->at("x").get<std::vector<double>>(), j->at("y").get<std::vector<double>>(), true};
            }
          catch (const json::exception &)
            {
              --hits; // an entry of another shape is recomputed and replaced
            }
        Series s = compute();
        ++misses;
        cache.put(request_key, json{{"title", s.title}, {"x", s.x}, {"y", s.y}});
        return s;
      }
      int hits = 0, misses = 0;
      bool enabled() const { return cache.enabled(); }

    private:
      ResultCache cache;
    };

    /// FE points in the eval vocabulary: "request" with "method": "fe" (cases/tools/fe_oracle.h) at every one of
    /// "values" of its "key", times "scale"; the abscissa is the value times "x_scale". One oracle answers the set,
    /// so the points of one unit state share its ladder run.
    Series fe_eval_points(const json &fe, const std::string &title, PointCache &cache)
    {
      return cache.get("fe_eval\n" + fe.dump(), [&] {
        const std::string         key    = fe.at("key");
        const std::vector<double> values = fe.at("values").get<std::vector<double>>();
        std::vector<json>         requests;
        for (const double v : values)
          {
            json request      = fe.at("request");
            request[key]      = v;
            request["method"] = "fe";
            requests.push_back(request);
          }
        FeOracle oracle;
        for (const json &request : requests)
          oracle.plan(request);
        Series points{title, {}, {}, true};
        for (std::size_t i = 0; i < values.size(); ++i)
          {
            points.x.push_back(values[i] * fe.value("x_scale", 1.));
            points.y.push_back(oracle.evaluate(requests[i]).value * fe.value("scale", 1.));
          }
        return points;
      });
    }

    /// The FE point set of curve `c` (kinds "fe", "fe_eval", "fe_adhesion", "fe_tangential"), through the cache.
    Series fe_points(const json &c, PointCache &cache)
    {
      const std::string title = c.value("title", "FE");
      if (c.contains("fe"))
        {
          // FE points from a .prm scene (with overrides), normalised by the scene's closed form.
          const json &fe = c.at("fe");
          const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides_of(fe));
          json request = fe;
          request.erase("scene");
          request.erase("set");
          return cache.get("fe\n" + request.dump() + "\n" + scene.resolved, [&] {
            const Profile   quantity = profile_named(fe.at("quantity").get<std::string>(),
                                                     "figures: fe point set '" + title + "'");
            const FeProfile p = fe_profile(scene, quantity, fe.at("radii").get<std::vector<double>>(),
                                           fe.at("normaliser"), fe.value("normaliser_r", 0.), fe.value("per_area", false));
            return Series{title, p.x, p.y, true};
          });
        }
      if (c.contains("fe_eval"))
        return fe_eval_points(c.at("fe_eval"), title, cache);
      if (c.contains("fe_adhesion"))
        {
          // FE adhesive states (fem/adhesion/adhesion.h) of a .prm scene at a = x a_c (a_c: the FE critical radius
          // under the given control); each coordinate is "radius", "depth", "force" or "k" of the state, or,
          // with "pressure_radii" (r / a, each in [0, 1)), "r" and "pressure" of its pressure profile (9.53 for
          // the paraboloid: one point per state and radius); times "scale", divided by the value of the
          // request "divide_by" when given.
          const json &fe = c.at("fe_adhesion");
          const auto is_profile = [](const std::string &q) { return q == "r" || q == "pressure"; };
          const std::string qx = fe.at("x").at("quantity"), qy = fe.at("y").at("quantity");
          const bool profile = is_profile(qx) || is_profile(qy);
          const std::vector<double> pressure_radii = fe.value("pressure_radii", std::vector<double>{});
          const std::string where = "figures: fe_adhesion point set '" + title + "'";
          for (const std::string &q : {qx, qy})
            if (!is_profile(q) && q != "radius" && q != "depth" && q != "force" && q != "k")
              throw std::invalid_argument(where + ": quantity '" + q + "' is not radius, depth, force, k, r or pressure");
          if (profile && !(is_profile(qx) && is_profile(qy)))
            throw std::invalid_argument(where + ": x quantity '" + qx + "' and y quantity '" + qy +
                                        "' mix a pressure profile (r, pressure) with a state (radius, depth, force, k)");
          if (profile != !pressure_radii.empty())
            throw std::invalid_argument(where + (profile ? ": the quantities r and pressure need \"pressure_radii\""
                                                         : ": \"pressure_radii\" given but neither x nor y is r or "
                                                           "pressure"));
          // "variants": one FE point set per list of extra overrides (e.g. one per k); otherwise one scene.
          std::vector<std::vector<std::string>> variants = {{}};
          if (fe.contains("variants"))
            variants = fe.at("variants").get<std::vector<std::vector<std::string>>>();
          Series points{title, {}, {}, true};
          for (const std::vector<std::string> &variant : variants)
            {
              const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides_of(fe, variant));
              json request = fe;
              request.erase("scene");
              request.erase("set");
              request.erase("variants");
              const Series s = cache.get("fe_adhesion\n" + request.dump() + "\n" + scene.resolved, [&] {
                const FeAdhesiveCurve curve =
                  fe_adhesive_curve(scene, fe.at("a_over_ac").get<std::vector<double>>(),
                                    fe.value("control", "force") == "force", pressure_radii);
                const auto axis = [&](const json &spec) {
                  const std::string q = spec.at("quantity");
                  double factor = spec.value("scale", 1.);
                  if (spec.contains("divide_by"))
                    factor /= batch::evaluate(batch::parse(spec.at("divide_by")));
                  std::vector<double> out;
                  for (std::size_t i = 0; i < curve.radius.size(); ++i)
                    {
                      if (profile)
                        {
                          for (std::size_t j = 0; j < pressure_radii.size(); ++j)
                            out.push_back(factor * (q == "r" ? pressure_radii[j] * curve.radius[i]
                                                             : curve.pressure[i][j]));
                          continue;
                        }
                      out.push_back(factor * (q == "radius" ? curve.radius[i]
                                              : q == "depth" ? curve.depth[i]
                                              : q == "force" ? curve.force[i]
                                                             : scene.material.k));
                    }
                  return out;
                };
                return Series{title, axis(fe.at("x")), axis(fe.at("y")), true};
              });
              points.x.insert(points.x.end(), s.x.begin(), s.x.end());
              points.y.insert(points.y.end(), s.y.begin(), s.y.end());
            }
          return points;
        }
      // FE points of a tangential .prm scene (cases/runners/fe_tangential.h): partial slip, (u0, F_x) at the stick
      // radii of the F_x(u0) curve; oscillation, the hysteresis loop. Each coordinate is "displacement"
      // or "force", times "scale", divided by the value of the request "divide_by" when given.
      const json &fe = c.at("fe_tangential");
      const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides_of(fe));
      json request = fe;
      request.erase("scene");
      request.erase("set");
      return cache.get("fe_tangential\n" + request.dump() + "\n" + scene.resolved, [&] {
        const FeTangentialCurve curve = fe_tangential_curve(scene);
        const auto axis = [&](const json &spec) {
          const std::string q = spec.at("quantity");
          if (q != "displacement" && q != "force")
            throw std::invalid_argument("figures: fe_tangential quantity '" + q + "' is not displacement or force");
          double factor = spec.value("scale", 1.);
          if (spec.contains("divide_by"))
            factor /= batch::evaluate(batch::parse(spec.at("divide_by")));
          std::vector<double> out;
          for (const double x : q == "displacement" ? curve.displacement : curve.force)
            out.push_back(x * factor);
          return out;
        };
        return Series{title, axis(fe.at("x")), axis(fe.at("y")), true};
      });
    }

    /// The rows of a CSV file with a header (fields split at commas outside double quotes, "" an escaped quote).
    std::vector<std::map<std::string, std::string>> read_csv_table(const fs::path &file)
    {
      std::ifstream in(file);
      if (!in)
        throw std::runtime_error("figures: cannot open " + file.string());
      const auto split = [](const std::string &line) {
        std::vector<std::string> fields(1);
        bool quoted = false;
        for (std::size_t i = 0; i < line.size(); ++i)
          {
            const char ch = line[i];
            if (ch == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"')
              fields.back() += '"', ++i;
            else if (ch == '"')
              quoted = !quoted;
            else if (ch == ',' && !quoted)
              fields.emplace_back();
            else if (ch != '\r')
              fields.back() += ch;
          }
        return fields;
      };
      std::string line;
      std::getline(in, line);
      const std::vector<std::string> header = split(line);
      std::vector<std::map<std::string, std::string>> rows;
      while (std::getline(in, line))
        {
          if (line.empty())
            continue;
          const std::vector<std::string> fields = split(line);
          if (fields.size() != header.size())
            throw std::runtime_error("figures: " + file.string() + ": a row has " + std::to_string(fields.size()) +
                                     " fields, the header " + std::to_string(header.size()));
          std::map<std::string, std::string> row;
          for (std::size_t i = 0; i < header.size(); ++i)
            row[header[i]] = fields[i];
          rows.push_back(std::move(row));
        }
      return rows;
    }

    /// The map report of `scene` (Map section): the one a `gradcontact run` wrote to <reports>/<scene name>/ when
    /// its parameters.prm is the scene's resolved parameters, else the figures' own under
    /// <reports>/figures/maps/<scene name>-<hash of the parameters>/, run now when missing or different.
    fs::path map_report(const Scene &scene, const fs::path &reports, PointCache &cache)
    {
      const auto matches = [&](const fs::path &folder) {
        if (!fs::exists(folder / "map.csv") || !fs::exists(folder / "parameters.prm"))
          return false;
        std::ifstream in(folder / "parameters.prm");
        std::ostringstream text;
        text << in.rdbuf();
        return text.str() == scene.resolved;
      };
      if (cache.enabled() && matches(reports / scene.info.name))
        {
          ++cache.hits;
          return reports / scene.info.name;
        }
      Scene own = scene;
      std::ostringstream suffix;
      suffix << std::hex << std::setw(16) << std::setfill('0') << std::hash<std::string>{}(scene.resolved);
      own.info.name += "-" + suffix.str();
      const fs::path root = reports / "figures" / "maps", folder = root / own.info.name;
      if (cache.enabled() && matches(folder))
        {
          ++cache.hits;
          return folder;
        }
      std::cout << "figures: running the map " << scene.file << " (no report of its parameters in " << reports.string()
                << "; it goes to " << folder.string() << ")" << std::endl;
      fs::create_directories(root);
      run_report(own, root, false);
      ++cache.misses;
      return folder;
    }

    /// The points of a map scene's map.csv (kind "fe_map"): the rows whose columns equal "where" (numbers to
    /// 1e-9 relative, text exactly), x and y the named columns ("column" or {"column", "divide_by": column}). A row whose x is not finite (the full-stick
    /// row of a friction map, mu = inf) is left out and said so.
    Series map_points(const json &c, PointCache &cache, const fs::path &reports)
    {
      const std::string title = c.value("title", "FE map");
      const json &fe = c.at("fe_map");
      const std::string where = "figures: fe_map point set '" + title + "'";
      const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides_of(fe));
      if (scene.kind != SceneKind::map)
        throw std::invalid_argument(where + ": scene " + scene.file + " has no Map section (kind " +
                                    to_string(scene.kind) + "; valid: a map scene)");
      // an axis: a column, or a column divided by another
      const auto columns = [&](const json &axis) -> std::pair<std::string, std::string> {
        if (axis.is_string())
          return {axis.get<std::string>(), ""};
        if (!axis.is_object() || !axis.contains("column"))
          throw std::invalid_argument(where + ": an axis is a column name or {\"column\", \"divide_by\"}, not " +
                                      axis.dump());
        return {axis.at("column").get<std::string>(), axis.value("divide_by", "")};
      };
      const auto [qx, dx] = columns(fe.at("x"));
      const auto [qy, dy] = columns(fe.at("y"));
      const fs::path folder = map_report(scene, reports, cache);
      const auto rows = read_csv_table(folder / "map.csv");
      Series points{title, {}, {}, true};
      if (rows.empty())
        throw std::runtime_error(where + ": " + (folder / "map.csv").string() + " has no rows");
      for (const std::string &column : {qx, dx, qy, dy})
        if (!column.empty() && !rows.front().count(column))
          throw std::invalid_argument(where + ": map.csv of " + scene.file + " has no column '" + column + "'");
      const json condition = fe.value("where", json::object());
      for (const auto &[column, value] : condition.items())
        if (!rows.front().count(column))
          throw std::invalid_argument(where + ": \"where\" names the column '" + column + "', not in map.csv of " +
                                      scene.file);
      // a field as a number, NaN when it is none (an empty or failed entry)
      const auto number = [](const std::string &field) {
        char *end = nullptr;
        const double v = std::strtod(field.c_str(), &end);
        return end == field.c_str() ? std::numeric_limits<double>::quiet_NaN() : v;
      };
      std::size_t left_out = 0;
      for (const auto &row : rows)
        {
          bool selected = true;
          for (const auto &[column, value] : condition.items())
            {
              const std::string &field = row.at(column);
              if (value.is_number())
                selected = selected && std::abs(number(field) - value.get<double>()) <=
                                         1e-9 * std::max(1., std::abs(value.get<double>()));
              else
                selected = selected && field == value.get<std::string>();
            }
          if (!selected)
            continue;
          const auto value = [&](const std::string &column, const std::string &divisor) {
            return number(row.at(column)) / (divisor.empty() ? 1. : number(row.at(divisor)));
          };
          const double x = value(qx, dx), y = value(qy, dy);
          if (!std::isfinite(x))
            {
              ++left_out;
              continue;
            }
          points.x.push_back(x);
          points.y.push_back(y);
        }
      if (points.x.empty())
        throw std::invalid_argument(where + ": no row of " + (folder / "map.csv").string() + " matches \"where\" " +
                                    condition.dump());
      if (left_out)
        std::cout << "figures: " << title << ": " << left_out << " row(s) of " << (folder / "map.csv").string()
                  << " with a non-finite " << qx << " are not drawn\n";
      return points;
    }

    /// What the index page says about one figure.
    struct FigureSummary
    {
      std::string name, figure, caption;
      std::size_t points = 0, failed = 0; ///< checked against a tolerance (failed: measured ones too)
      double worst = 0;
      std::size_t measured = 0; ///< measured deviations (validation figures)
      double largest_deviation = 0;
      bool drawn = false;
      double seconds = 0;

      json to_json() const
      {
        return {{"name", name},         {"figure", figure},     {"caption", caption},
                {"points", points},     {"failed", failed},     {"worst", worst},
                {"measured", measured}, {"largest_deviation", largest_deviation}, {"drawn", drawn},
                {"seconds", seconds}};
      }
      static FigureSummary from_json(const json &j)
      {
        FigureSummary f;
        f.name = j.at("name");
        f.figure = j.at("figure");
        f.caption = j.at("caption");
        f.points = j.at("points");
        f.failed = j.at("failed");
        // JSON has no infinity: an infinite error (a point off its curve) is written as null
        const auto error = [&j](const char *key) {
          return j.at(key).is_null() ? std::numeric_limits<double>::infinity() : j.at(key).get<double>();
        };
        f.worst = error("worst");
        f.measured = j.at("measured");
        f.largest_deviation = error("largest_deviation");
        f.drawn = j.at("drawn");
        f.seconds = j.at("seconds");
        return f;
      }
    };

    /// The column spec of a figure's <name>.csv and of the table of its <name>.md: every checked point.
    Table points_table(const std::vector<CheckedPoint> &points)
    {
      Table table({Column::both("series", "series").quoted(), Column::both("x", "x"), Column::both("value", "value"),
                   Column::both("reference", "reference"), Column::both("reference_curve", "reference curve").quoted(),
                   Column::both("error", "error"), Column::both("tolerance", "tolerance"), Column::both("pass", "pass"),
                   Column::both("note", "note").quoted()},
                  Number{'g', 12});
      for (const CheckedPoint &p : points)
        table.add({p.series, p.x, p.y, p.reference, p.reference_curve, p.error,
                   p.measured ? Cell(p.tolerance).md_text("-") : Cell(p.tolerance),
                   Cell(!p.pass ? "false" : p.measured ? "measured" : "true")
                     .md_text(!p.pass ? "**FAIL**" : p.measured ? "measured" : "pass"),
                   p.note});
      return table;
    }

    std::string tables_md(const std::string &title, const std::string &name, const Table &points,
                          const std::map<std::string, std::string> &why)
    {
      std::ostringstream md;
      md << "# " << title << "\n\n![" << name << "](" << name << ".svg)\n\n";
      if (points.size() == 0)
        {
          md << "No checked points: the figure draws closed forms only.\n";
          return md.str();
        }
      md << "Each point against the closed form at the same abscissa; error = |value - reference| / max |y| of the "
            "reference curve as drawn. A point set with the tolerance \"-\" is measured, not checked: the deviation of "
            "the closed form from a model that drops its idealisation is the result (it fails only when it is not "
            "finite or lies off its curve).\n\n"
         << points.md() << "\nTolerances:\n\n";
      for (const auto &[series, reason] : why)
        md << "- " << series << ": " << reason << "\n";
      return md.str();
    }

    /// The figure file as JSON; a file that cannot be read or parsed is an error naming it.
    json read_figure(const fs::path &file)
    {
      std::ifstream in(file);
      if (!in)
        throw std::runtime_error("figures: cannot open " + file.string());
      json fig;
      try
        {
          fig = json::parse(in);
        }
      catch (const json::exception &e)
        {
          throw std::invalid_argument("figures: " + file.string() + " is not valid JSON (" + e.what() + ")");
        }
      return fig;
    }

    /// The analytic curves of the figure (its "sweep" entries), sampled where their formulas are defined, into
    /// `series` and by title into `analytic`; `skipped` counts the points outside a formula's domain.
    void analytic_curves(const json &fig, const fs::path &file, std::vector<Series> &series,
                         std::map<std::string, AnalyticCurve> &analytic, std::size_t &skipped)
    {
      for (const json &c : fig.at("curves"))
        {
          if (!c.contains("sweep"))
            continue;
          const json &sweep = c.at("sweep");
          AnalyticCurve curve;
          curve.spec = &c;
          curve.key = sweep.at("key");
          const double from = sweep.at("from"), to = sweep.at("to");
          const int points = sweep.value("points", 200);
          if (points < 2)
            throw std::invalid_argument("figures: " + file.string() + ": curve '" + c.value("title", "") +
                                        "' sweep points = " + std::to_string(points) + "; valid: 2 or more");
          const bool log = sweep.value("log", false);
          for (int i = 0; i < points; ++i)
            {
              const double f = static_cast<double>(i) / (points - 1);
              const double t = log ? from * std::pow(to / from, f) : from + (to - from) * f;
              try
                {
                  const double x = curve.x_at(t), y = curve.y_at(t);
                  if (std::isfinite(x) && std::isfinite(y))
                    {
                      curve.t.push_back(t);
                      curve.x.push_back(x);
                      curve.y.push_back(y);
                      curve.y_scale = std::max(curve.y_scale, std::abs(y));
                    }
                }
              catch (const std::exception &)
                {
                  ++skipped; // outside the formula's domain (e.g. r = a for a flat punch): no point
                }
            }
          const std::string t = c.value("title", "");
          if (curve.x.empty())
            throw std::invalid_argument("figures: " + file.string() + ": curve '" + t + "' has no valid point");
          if (analytic.count(t))
            throw std::invalid_argument("figures: " + file.string() + ": two analytic curves are titled '" + t + "'");
          series.push_back({t, curve.x, curve.y, c.value("points", false)});
          analytic.emplace(t, std::move(curve));
        }
    }

    /// The point sets of the figure (FE or tabulated; prescribed inputs are drawn, not checked), each checked
    /// against its analytic curves into `checked` with the reason of its tolerance in `why`, and drawn in its curve's
    /// colour when it is checked against one.
    void point_sets(const json &fig, const fs::path &file, const fs::path &reports, PointCache &cache,
                    const std::map<std::string, AnalyticCurve> &analytic, std::vector<Series> &series,
                    std::vector<CheckedPoint> &checked, std::map<std::string, std::string> &why)
    {
      for (const json &c : fig.at("curves"))
        {
          if (c.contains("sweep"))
            continue;
          if (c.contains("prescribed"))
            {
              // A prescribed input drawn as a line (a load history): not a result, so nothing to check.
              series.push_back({c.value("title", ""), c.at("prescribed").at("x").get<std::vector<double>>(),
                                c.at("prescribed").at("y").get<std::vector<double>>(), false});
              continue;
            }
          Series points;
          if (c.contains("points"))
            points = {c.value("title", "points"), c.at("points").at("x").get<std::vector<double>>(),
                      c.at("points").at("y").get<std::vector<double>>(), true};
          else if (c.contains("fe") || c.contains("fe_eval") || c.contains("fe_adhesion") || c.contains("fe_tangential"))
            points = fe_points(c, cache);
          else if (c.contains("fe_map"))
            points = map_points(c, cache, reports);
          else
            throw std::invalid_argument("figures: " + file.string() + ": curve '" + c.value("title", "") +
                                        "' has none of sweep, prescribed, points, fe, fe_eval, fe_adhesion, "
                                        "fe_tangential, fe_map");
          if (points.x.size() != points.y.size())
            throw std::invalid_argument("figures: " + file.string() + ": point set '" + points.title + "' has " +
                                        std::to_string(points.x.size()) + " abscissae and " +
                                        std::to_string(points.y.size()) + " values");
          // "scale_x", "scale_y", "offset_y": a constant change of normalisation applied to a point set after it
          // is made (e.g. from the scene's own contact radius to the Hertzian one; y -> y scale_y + offset_y).
          for (double &x : points.x)
            x *= c.value("scale_x", 1.);
          for (double &y : points.y)
            y = y * c.value("scale_y", 1.) + c.value("offset_y", 0.);
          if (!c.contains("check"))
            throw std::invalid_argument("figures: " + file.string() + ": point set '" + points.title +
                                        "' has no \"check\" (every point is compared with a closed form)");
          const std::vector<CheckedPoint> rows = check_points(points, c.at("check"), analytic, file.string());
          checked.insert(checked.end(), rows.begin(), rows.end());
          why[points.title] = c.at("check").value("why", "(no reason given)");
          // a point set checked against one curve is drawn in that curve's colour
          if (c.at("check").at("curves").size() == 1)
            for (std::size_t i = 0; i < series.size(); ++i)
              if (series[i].title == c.at("check").at("curves").front().get<std::string>())
                points.colour_of = static_cast<int>(i);
          series.push_back(points);
        }
    }

    /// The figure's line on the terminal: what was drawn, the worst error, every failed point.
    void print_summary(const FigureSummary &summary, const bool ok, const fs::path &png, const std::size_t curves,
                       const std::size_t skipped, const std::vector<CheckedPoint> &checked)
    {
      std::cout << (ok ? "drew " : "wrote data and script (gnuplot failed) ") << png.string()
                << " (" << curves << " curves"
                << (skipped ? ", " + std::to_string(skipped) + " points outside the domain" : "");
      if (summary.points)
        std::cout << ", " << summary.points << " checked points, worst error " << format(summary.worst);
      if (summary.measured)
        std::cout << ", " << summary.measured << " measured points, largest deviation "
                  << format(summary.largest_deviation);
      if (summary.failed)
        std::cout << ", " << summary.failed << " FAILED";
      std::cout << ", " << format(summary.seconds) << " s)\n";
      for (const CheckedPoint &p : checked)
        if (!p.pass)
          std::cout << "  FAIL " << p.series << " at x = " << format(p.x) << ": " << p.note << " (value "
                    << format(p.y) << ", reference " << format(p.reference) << ", error " << format(p.error)
                    << ", tolerance " << format(p.tolerance) << ")\n";
    }

    FigureSummary draw(const fs::path &file, const fs::path &reports, PointCache &cache)
    {
      const auto start = std::chrono::steady_clock::now();
      const json fig = read_figure(file);
      const std::string name = fig.value("name", file.stem().string());
      const std::string title = fig.value("title", name);
      if (title.size() > max_title_characters)
        throw std::invalid_argument("figures: " + file.string() + ": title has " + std::to_string(title.size()) +
                                    " characters; valid: at most " + std::to_string(max_title_characters) +
                                    " (longer titles are cut off in the plot; put the rest in \"caption\")");
      FigureSummary summary{name, fig.value("figure", ""), fig.value("caption", "")};

      // Analytic curves first: the point sets are checked against them by title.
      std::vector<Series> series;
      std::map<std::string, AnalyticCurve> analytic;
      std::size_t skipped = 0;
      analytic_curves(fig, file, series, analytic, skipped);

      // Point sets (FE or tabulated), each checked against the closed form.
      std::vector<CheckedPoint> checked;
      std::map<std::string, std::string> why;
      point_sets(fig, file, reports, cache, analytic, series, checked, why);

      const fs::path folder = reports / "figures";
      fs::create_directories(folder);
      // The plot files are made in a temporary folder and moved beside the tables when all are written.
      const fs::path tmp = temporary_sibling(folder / name);
      fs::remove_all(tmp);
      fs::create_directories(tmp);
      for (const CheckedPoint &p : checked)
        {
          summary.failed += !p.pass;
          if (p.measured)
            {
              ++summary.measured;
              if (std::isfinite(p.error))
                summary.largest_deviation = std::max(summary.largest_deviation, p.error);
            }
          else
            {
              ++summary.points;
              summary.worst = std::max(summary.worst, p.error);
            }
        }
      bool ok = false;
      try
        {
          ok = write_plot(tmp, name, title, fig.value("xlabel", "x"), fig.value("ylabel", "y"), series,
                          fig.value("logx", false), fig.value("logy", false));
          summary.drawn = ok;
          summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const Table points = points_table(checked);
          write_table_files(tmp, name, points, tables_md(title, name, points, why));
          write_text_atomically(tmp / (name + ".summary.json"), summary.to_json().dump(1) + "\n");
          for (const auto &e : fs::directory_iterator(tmp))
            fs::rename(e.path(), folder / e.path().filename());
          fs::remove_all(tmp);
        }
      catch (...)
        {
          fs::remove_all(tmp);
          throw;
        }

      print_summary(summary, ok, folder / (name + ".png"), series.size(), skipped, checked);
      return summary;
    }

    // The index of every figure drawn into `folder` so far (its <name>.summary.json): the chapter's (figure
    // numbers 9.x), then the validation figures, which draw the maps of the models that drop an idealisation.
    std::string index_md(const fs::path &folder)
    {
      std::vector<FigureSummary> chapter, beyond, validation;
      for (const auto &e : fs::directory_iterator(folder))
        {
          const std::string file = e.path().filename().string();
          const std::string suffix = ".summary.json";
          if (file.size() <= suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
          std::ifstream in(e.path());
          FigureSummary f;
          try
            {
              f = FigureSummary::from_json(json::parse(in));
            }
          catch (const json::exception &error)
            {
              throw std::runtime_error("figures: " + e.path().string() + " is not a figure summary (" + error.what() +
                                       "); delete it and draw the figure again");
            }
          (f.figure.rfind("9.", 0) == 0 ? chapter : f.figure.rfind("S.", 0) == 0 ? beyond : validation).push_back(f);
        }
      const auto by_name = [](const FigureSummary &a, const FigureSummary &b) { return a.name < b.name; };
      std::sort(chapter.begin(), chapter.end(), by_name);
      std::sort(beyond.begin(), beyond.end(), by_name);
      std::sort(validation.begin(), validation.end(), by_name);
      const auto link = [](const FigureSummary &f) {
        return "[" + f.name + "](" + f.name + ".svg) | " + f.caption + " | " + std::to_string(f.points) + " | " +
               (f.points ? format(f.worst) : "-") + " | ";
      };
      std::ostringstream md;
      md << "# The chapter's figures\n\nEach figure draws the closed forms of the chapter; its FE (or tabulated) "
            "points are each compared with the closed form at the same abscissa (error relative to the curve's "
            "largest |y|), in the table linked beside it.\n\n| figure | plot | caption | checked points | worst "
            "error | failed | table |\n|---|---|---|---|---|---|---|\n";
      for (const FigureSummary &f : chapter)
        md << "| " << f.figure << " | " << link(f) << f.failed << " | [" << f.name << ".md](" << f.name << ".md) |\n";
      std::vector<std::string> missing;
      for (const std::string &n : chapter_data_figures)
        if (std::none_of(chapter.begin(), chapter.end(), [&](const FigureSummary &f) { return f.figure == n; }))
          missing.push_back(n);
      md << "\nChapter figures with data not drawn yet: ";
      for (std::size_t i = 0; i < missing.size(); ++i)
        md << (i ? ", " : "") << missing[i];
      md << (missing.empty() ? "none.\n" : ".\n");
      if (!beyond.empty())
        {
          md << "\n## Beyond the chapter\n\nQuantities the chapter does not give (figure numbers S.x: the stresses below "
                "the contact, analytic/subsurface.h), drawn and checked like the chapter's.\n\n| figure | plot | caption "
                "| checked points | worst error | failed | table |\n|---|---|---|---|---|---|---|\n";
          for (const FigureSummary &f : beyond)
            md << "| " << f.figure << " | " << link(f) << f.failed << " | [" << f.name << ".md](" << f.name << ".md) |\n";
        }
      md << "\n## Validation figures\n\nThe maps of the FE models that drop one of the chapter's idealisations "
            "(`gradcontact figures cases/figures/validation`, reusing the map reports of `gradcontact run "
            "cases/validation`): each point set is either checked against a closed form that is exact there (a sharp "
            "check: a tolerance) or measured (its deviation from the chapter's closed form is the result).\n\n";
      if (validation.empty())
        md << "None drawn yet.\n";
      else
        {
          md << "| figure | plot | caption | checked points | worst error | measured points | largest deviation | "
                "failed | table |\n|---|---|---|---|---|---|---|---|---|\n";
          for (const FigureSummary &f : validation)
            md << "| " << (f.figure.empty() ? "-" : f.figure) << " | " << link(f) << f.measured << " | "
               << (f.measured ? format(f.largest_deviation) : "-") << " | " << f.failed << " | [" << f.name << ".md]("
               << f.name << ".md) |\n";
        }
      return md.str();
    }
  } // namespace

  int figures(const std::vector<std::string> &args)
  {
    fs::path reports = "reports";
    bool use_cache = true;
    std::vector<fs::path> files;
    for (std::size_t i = 0; i < args.size(); ++i)
      {
        if (args[i] == "--reports")
          {
            if (i + 1 == args.size())
              throw std::invalid_argument("figures: --reports needs a folder");
            reports = args[++i];
          }
        else if (args[i] == "--no-cache")
          use_cache = false;
        else if (fs::is_directory(args[i]))
          {
            for (const auto &e : fs::directory_iterator(args[i]))
              if (e.path().extension() == ".json")
                files.push_back(e.path());
          }
        else if (fs::is_regular_file(args[i]))
          files.push_back(args[i]);
        else
          throw std::invalid_argument("figures: no figure file or folder '" + args[i] + "'");
      }
    if (files.empty())
      throw std::invalid_argument("figures: name a figure file (.json) or a folder of them");
    std::sort(files.begin(), files.end());
    PointCache cache(reports / "figures" / "cache", use_cache);
    std::vector<FigureSummary> drawn;
    for (const fs::path &f : files)
      drawn.push_back(draw(f, reports, cache));
    write_document(reports / "figures", "index", index_md(reports / "figures"));
    std::size_t failed = 0;
    for (const FigureSummary &f : drawn)
      failed += f.failed;
    std::cout << "figures: " << (reports / "figures" / "index.md").string() << " (" << drawn.size() << " figures, FE "
              << "point sets " << cache.hits << " cached, " << cache.misses << " computed"
              << (failed ? ", " + std::to_string(failed) + " points FAILED)" : ", all points pass)") << "\n";
    return failed ? 1 : 0;
  }
} // namespace gradcontact::cases
