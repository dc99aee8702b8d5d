#include <analytic/errors.h>
#include <analytic/request.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace gradcontact::batch
{
  namespace
  {
    using json = nlohmann::json;

    // --- JSON -----------------------------------------------------------------------------------

    // The names of the enumerations in requests.
    const std::map<std::string, Control> control_names = {{"force", Control::force},
                                                           {"displacement", Control::displacement}};
    const std::map<std::string, Branch> branch_names = {
      {"loading", Branch::loading}, {"unloading", Branch::unloading}, {"reloading", Branch::reloading}};
    const std::map<std::string, Mechanism> mechanism_names = {{"periphery", Mechanism::periphery},
                                                               {"centre", Mechanism::centre},
                                                               {"center", Mechanism::centre},
                                                               {"governing", Mechanism::governing}};

    template <typename T>
    std::string name_of(const std::map<std::string, T> &names, const T value)
    {
      for (const auto &[name, v] : names)
        if (v == value)
          return name;
      return "?";
    }

    std::string text(const json &j, const char *key)
    {
      if (!j.at(key).is_string())
        throw DomainError(std::string(key) + ": must be a string");
      return j.at(key).get<std::string>();
    }

    // A number, or a string holding an exact decimal (reference tables carry exact doubles that way).
    double number(const json &v, const std::string &name)
    {
      if (v.is_number())
        return v.get<double>();
      if (v.is_string())
        {
          const std::string s = v.get<std::string>();
          char *end = nullptr;
          const double x = std::strtod(s.c_str(), &end);
          if (!s.empty() && end == s.c_str() + s.size())
            return x;
        }
      throw DomainError(name + ": must be a number (got " + v.dump() + ")");
    }

    template <typename T>
    T choice(const json &j, const char *key, const std::map<std::string, T> &names)
    {
      const std::string value = text(j, key);
      const auto it = names.find(value);
      if (it == names.end())
        throw DomainError(std::string(key) + " = '" + value + "' must be one of " + check::keys(names));
      return it->second;
    }

    GradedHalfSpace body(const json &j, const char *key, const Request &q)
    {
      const json &m = j.at(key);
      if (!m.is_object())
        throw DomainError(std::string(key) + ": must be an object {E0, c0, k, nu}");
      const std::string prefix = std::string(key) + ".";
      for (auto it = m.begin(); it != m.end(); ++it)
        if (it.key() != "E0" && it.key() != "c0" && it.key() != "k" && it.key() != "nu")
          throw DomainError(prefix + it.key() + ": unknown material key (E0, c0, k, nu)");
      const auto get = [&](const char *name) {
        if (!m.contains(name))
          throw DomainError(prefix + name + ": missing (required for case '" + q.case_name + "', quantity '" +
                            q.quantity + "')");
        return number(m.at(name), prefix + name);
      };
      return {get("E0"), get("c0"), get("k"), get("nu")};
    }

    // The optional numbers of a request and of its geometry, by key.
    using Number = std::optional<double> Request::*;
    using GeometryNumber = std::optional<double> Geometry::*;
    const std::map<std::string, Number> number_keys = {
      {"a", &Request::a},           {"r", &Request::r},     {"d", &Request::d},   {"F", &Request::F},
      {"d0", &Request::d0},         {"dgamma", &Request::dgamma}, {"sigma_th", &Request::sigma_th},
      {"mu", &Request::mu},         {"c", &Request::c},     {"Fx", &Request::Fx}, {"FA", &Request::FA},
      {"u0", &Request::u0},         {"a_lo", &Request::a_lo}, {"a_hi", &Request::a_hi},
      {"h0", &Request::h0},         {"z0", &Request::z0},     {"z", &Request::z}};
    const std::map<std::string, GeometryNumber> geometry_keys = {
      {"R", &Geometry::R}, {"tan_theta", &Geometry::tan_theta}, {"n", &Geometry::n},
      {"A", &Geometry::A}, {"h0", &Geometry::h0},               {"p0", &Geometry::p0}};

    /// h0 or z0 (Request) as the Dugdale stress sigma_th of a maugis_dugdale request.
    void adhesive_range_to_stress(Request &q)
    {
      if (!q.h0 && !q.z0)
        return;
      const char *name = q.h0 ? "h0" : "z0";
      if (q.case_name != "maugis_dugdale")
        throw DomainError(std::string(name) + ": the adhesive's range is read by case 'maugis_dugdale' only (case '" +
                          q.case_name + "' takes sigma_th)");
      if (q.h0 && q.z0)
        throw DomainError("h0, z0: give one range (h0 the Dugdale range, z0 the Lennard-Jones spacing), not both");
      if (q.sigma_th)
        throw DomainError(std::string(name) + ": give the range or sigma_th, not both (sigma_th = " +
                          check::format(*q.sigma_th) + ")");
      if (!q.dgamma)
        throw DomainError(std::string(name) + ": needs dgamma (the stress is dgamma over the range)");
      const double range = q.h0 ? *q.h0 : *q.z0;
      check::positive("maugis_dugdale", name, range);
      check::positive("maugis_dugdale", "dgamma", *q.dgamma);
      q.sigma_th = q.h0 ? *q.dgamma / range : 16 * *q.dgamma / (9 * std::sqrt(3.0) * range);
    }
  } // namespace

  const char *method_name(const Method method)
  {
    return method == Method::numerical_mdr ? "numerical_mdr" : "closed_form";
  }

  Request parse(const json &j)
  {
    static const std::set<std::string> other_keys = {"id",       "case",      "quantity", "material", "material2",
                                                     "geometry", "method",    "control",  "mechanism", "branch",
                                                     "component"};
    if (!j.is_object())
      throw DomainError("request: must be a JSON object");
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!other_keys.count(it.key()) && !number_keys.count(it.key()))
        throw DomainError("request: unknown key '" + it.key() + "' (see analytic/README.md)");
    Request q;
    for (const char *key : {"case", "quantity"})
      if (!j.contains(key))
        throw DomainError(std::string(key) + ": missing (every request names its case and quantity)");
    q.case_name = text(j, "case");
    q.quantity = text(j, "quantity");
    if (j.contains("method"))
      {
        const std::string method = text(j, "method");
        if (method != "closed_form" && method != "numerical_mdr")
          throw DomainError("method = '" + method + "' must be 'closed_form' or 'numerical_mdr'");
        q.method = method == "numerical_mdr" ? Method::numerical_mdr : Method::closed_form;
      }
    if (j.contains("material"))
      q.material = body(j, "material", q);
    if (j.contains("material2"))
      q.material2 = body(j, "material2", q);
    if (j.contains("geometry"))
      {
        const json &g = j.at("geometry");
        if (!g.is_object())
          throw DomainError("geometry: must be an object");
        for (auto it = g.begin(); it != g.end(); ++it)
          {
            const auto key = geometry_keys.find(it.key());
            if (key == geometry_keys.end())
              throw DomainError("geometry." + it.key() + ": unknown geometry key (" + check::keys(geometry_keys) + ")");
            q.geometry.*(key->second) = number(it.value(), "geometry." + it.key());
          }
      }
    for (const auto &[key, member] : number_keys)
      if (j.contains(key))
        q.*member = number(j.at(key), key);
    adhesive_range_to_stress(q);
    if (j.contains("control"))
      q.control = choice(j, "control", control_names);
    if (j.contains("branch"))
      q.branch = choice(j, "branch", branch_names);
    if (j.contains("mechanism"))
      q.mechanism = choice(j, "mechanism", mechanism_names);
    if (j.contains("component"))
      q.component = text(j, "component");
    return q;
  }

  Request parse(const std::string &line)
  {
    json j;
    try
      {
        j = json::parse(line);
      }
    catch (const json::exception &e)
      {
        throw DomainError(std::string("request: not valid JSON (") + e.what() + ")");
      }
    return parse(j);
  }

  json to_json(const Request &q)
  {
    json j = {{"case", q.case_name}, {"quantity", q.quantity}, {"method", method_name(q.method)}};
    const auto material = [](const GradedHalfSpace &b) {
      return json{{"E0", b.E0}, {"c0", b.c0}, {"k", b.k}, {"nu", b.nu}};
    };
    if (q.material)
      j["material"] = material(*q.material);
    if (q.material2)
      j["material2"] = material(*q.material2);
    for (const auto &[key, member] : geometry_keys)
      if (q.geometry.*member)
        j["geometry"][key] = *(q.geometry.*member);
    for (const auto &[key, member] : number_keys)
      if (q.*member)
        j[key] = *(q.*member);
    if (q.control)
      j["control"] = name_of(control_names, *q.control);
    if (q.branch)
      j["branch"] = name_of(branch_names, *q.branch);
    if (q.mechanism)
      j["mechanism"] = name_of(mechanism_names, *q.mechanism);
    if (q.component)
      j["component"] = *q.component;
    return j;
  }
} // namespace gradcontact::batch
