#include "figures.h"

#include "fe_adhesion.h"
#include "fe_scene.h"
#include "fe_tangential.h"
#include "report.h"
#include "scene.h"

#include <analytic/batch.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
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
      if (spec.value("sweep", false))
        return t * scale;
      if (!spec.contains("request"))
        throw std::invalid_argument("figure: a coordinate needs \"sweep\": true or a \"request\"");
      double value = request_value(spec["request"], key, t, true) * scale;
      if (spec.contains("divide_by"))
        value /= request_value(spec["divide_by"], key, t, false);
      return value;
    }

    void draw(const fs::path &file, const fs::path &reports)
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
      const std::string name = fig.value("name", file.stem().string());
      std::vector<Series> series;
      std::size_t skipped = 0;
      for (const json &c : fig.at("curves"))
        {
          if (c.contains("fe"))
            {
              // FE points from a .prm scene (with overrides), normalised by the scene's closed form.
              const json &fe = c.at("fe");
              std::vector<Override> overrides;
              for (const json &o : fe.value("set", json::array()))
                overrides.push_back(parse_override(o.get<std::string>()));
              const fs::path scene_file = fs::path(fe.at("scene").get<std::string>());
              const Scene scene = read_scene(scene_file.string(), overrides);
              const FeProfile p = fe_profile(scene, fe.at("quantity"), fe.at("radii").get<std::vector<double>>(),
                                             fe.at("normaliser"), fe.value("normaliser_r", 0.), fe.value("per_area", false));
              series.push_back({c.value("title", "FE"), p.x, p.y, true});
              continue;
            }
          if (c.contains("fe_adhesion"))
            {
              // FE adhesive states (fem/adhesion.h) of a .prm scene at a = x a_c (a_c: the FE critical radius
              // under the given control); each coordinate is "radius", "depth" or "force", times "scale",
              // divided by the value of the request "divide_by" when given.
              const json &fe = c.at("fe_adhesion");
              // "variants": one FE point per list of extra overrides (e.g. one per k); otherwise one scene.
              std::vector<std::vector<std::string>> variants = {{}};
              if (fe.contains("variants"))
                variants = fe.at("variants").get<std::vector<std::vector<std::string>>>();
              Series points{c.value("title", "FE"), {}, {}, true};
              for (const std::vector<std::string> &variant : variants)
                {
                  std::vector<Override> overrides;
                  for (const json &o : fe.value("set", json::array()))
                    overrides.push_back(parse_override(o.get<std::string>()));
                  for (const std::string &o : variant)
                    overrides.push_back(parse_override(o));
                  const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides);
                  const FeAdhesiveCurve curve = fe_adhesive_curve(scene, fe.at("a_over_ac").get<std::vector<double>>(),
                                                                  fe.value("control", "force") == "force");
                  const auto axis = [&](const json &spec) {
                    const std::string q = spec.at("quantity");
                    if (q != "radius" && q != "depth" && q != "force" && q != "k")
                      throw std::invalid_argument("figures: fe_adhesion quantity '" + q + "' is not radius, depth, force or k");
                    double factor = spec.value("scale", 1.);
                    if (spec.contains("divide_by"))
                      factor /= batch::evaluate(batch::parse(spec.at("divide_by")));
                    std::vector<double> out;
                    for (std::size_t i = 0; i < curve.radius.size(); ++i)
                      out.push_back(factor * (q == "radius" ? curve.radius[i]
                                              : q == "depth" ? curve.depth[i]
                                              : q == "force" ? curve.force[i]
                                                             : scene.material.k));
                    return out;
                  };
                  const std::vector<double> x = axis(fe.at("x")), y = axis(fe.at("y"));
                  points.x.insert(points.x.end(), x.begin(), x.end());
                  points.y.insert(points.y.end(), y.begin(), y.end());
                }
              series.push_back(points);
              continue;
            }
          if (c.contains("fe_tangential"))
            {
              // FE points of a tangential .prm scene (cases/fe_tangential.h): partial slip, (u0, F_x) at the stick
              // radii of the F_x(u0) curve; oscillation, the hysteresis loop. Each coordinate is "displacement"
              // or "force", times "scale", divided by the value of the request "divide_by" when given.
              const json &fe = c.at("fe_tangential");
              std::vector<Override> overrides;
              for (const json &o : fe.value("set", json::array()))
                overrides.push_back(parse_override(o.get<std::string>()));
              const Scene scene = read_scene(fe.at("scene").get<std::string>(), overrides);
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
              series.push_back({c.value("title", "FE"), axis(fe.at("x")), axis(fe.at("y")), true});
              continue;
            }
          const json &sweep = c.at("sweep");
          const std::string key = sweep.at("key");
          const double from = sweep.at("from"), to = sweep.at("to");
          const int points = sweep.value("points", 200);
          const bool log = sweep.value("log", false);
          Series s{c.value("title", ""), {}, {}, c.value("points", false)};
          for (int i = 0; i < points; ++i)
            {
              const double f = points > 1 ? static_cast<double>(i) / (points - 1) : 0.;
              const double t = log ? from * std::pow(to / from, f) : from + (to - from) * f;
              try
                {
                  const double x = coordinate(c.at("x"), key, t), y = coordinate(c.at("y"), key, t);
                  if (std::isfinite(x) && std::isfinite(y))
                    {
                      s.x.push_back(x);
                      s.y.push_back(y);
                    }
                }
              catch (const std::exception &)
                {
                  ++skipped; // outside the formula's domain (e.g. r = a for a flat punch): no point
                }
            }
          if (s.x.empty())
            throw std::invalid_argument("figures: " + file.string() + ": curve '" + s.title + "' has no valid point");
          series.push_back(s);
        }
      const fs::path folder = reports / "figures";
      fs::create_directories(folder);
      const bool ok = write_plot(folder, name, fig.value("title", name), fig.value("xlabel", "x"), fig.value("ylabel", "y"),
                                 series, fig.value("logx", false), fig.value("logy", false));
      std::cout << (ok ? "drew " : "wrote data and script (gnuplot failed) ") << (folder / (name + ".png")).string()
                << " (" << series.size() << " curves" << (skipped ? ", " + std::to_string(skipped) + " points outside the domain" : "")
                << ")\n";
    }
  } // namespace

  int figures(const std::vector<std::string> &args)
  {
    fs::path reports = "reports";
    std::vector<fs::path> files;
    for (std::size_t i = 0; i < args.size(); ++i)
      {
        if (args[i] == "--reports")
          {
            if (i + 1 == args.size())
              throw std::invalid_argument("figures: --reports needs a folder");
            reports = args[++i];
          }
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
    for (const fs::path &f : files)
      draw(f, reports);
    return 0;
  }
} // namespace gradcontact::cases
