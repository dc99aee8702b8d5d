#include <analytic/adhesion.h>
#include <analytic/batch.h>
#include <analytic/detail/quadrature.h>
#include <analytic/errors.h>
#include <analytic/material.h>
#include <analytic/mdr.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <istream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <sstream>

namespace gradcontact::batch
{
  namespace
  {
    using json = nlohmann::json;
    constexpr double pi = boost::math::constants::pi<double>();

    /// A request with typed, checked access to its entries.
    class Request
    {
    public:
      explicit Request(const json &j) : j_(j)
      {
        static const std::set<std::string> known = {
          "id", "case", "quantity", "material", "material2", "geometry", "method", "a", "r", "d", "F",
          "d0", "dgamma", "control", "sigma_th", "mechanism", "mu", "c", "Fx", "FA", "u0", "branch",
          "a_lo", "a_hi"};
        if (!j.is_object())
          throw DomainError("request: must be a JSON object");
        for (auto it = j.begin(); it != j.end(); ++it)
          if (!known.count(it.key()))
            throw DomainError("request: unknown key '" + it.key() + "' (see analytic/README.md)");
        case_name = text("case");
        quantity = text("quantity");
        const std::string method = j.contains("method") ? text("method") : "closed_form";
        if (method != "closed_form" && method != "numerical_mdr")
          throw DomainError("method = '" + method + "' must be 'closed_form' or 'numerical_mdr'");
        numerical = (method == "numerical_mdr");
      }

      std::string case_name, quantity;
      bool numerical = false;

      std::string text(const char *key) const
      {
        if (!j_.contains(key))
          throw DomainError(std::string(key) + ": missing (required for case '" + case_name +
                            "', quantity '" + quantity + "')");
        if (!j_.at(key).is_string())
          throw DomainError(std::string(key) + ": must be a string");
        return j_.at(key).get<std::string>();
      }

      bool has(const char *key) const { return j_.contains(key); }

      /// The request's entries without its id, for messages that name the inputs.
      std::string inputs() const
      {
        json copy = j_;
        copy.erase("id");
        return copy.dump();
      }

      double number(const char *key) const { return number_in(j_, key, ""); }

      double geometry(const char *key) const
      {
        if (!j_.contains("geometry") || !j_.at("geometry").is_object())
          throw DomainError(std::string("geometry: missing (case '") + case_name + "' needs geometry." + key +
                            ")");
        return number_in(j_.at("geometry"), key, "geometry.");
      }

      GradedHalfSpace body(const char *key) const
      {
        if (!j_.contains(key) || !j_.at(key).is_object())
          throw DomainError(std::string(key) + ": missing (an object {E0, c0, k, nu})");
        const json &m = j_.at(key);
        const std::string prefix = std::string(key) + ".";
        for (auto it = m.begin(); it != m.end(); ++it)
          if (it.key() != "E0" && it.key() != "c0" && it.key() != "k" && it.key() != "nu")
            throw DomainError(prefix + it.key() + ": unknown material key (E0, c0, k, nu)");
        return {number_in(m, "E0", prefix), number_in(m, "c0", prefix), number_in(m, "k", prefix),
                number_in(m, "nu", prefix)};
      }

      /// The equivalent medium, computed once per request.
      Medium medium() const
      {
        if (!medium_)
          medium_ = std::make_unique<Medium>(has("material2") ? gradcontact::medium(body("material"), body("material2"))
                                                              : gradcontact::medium(body("material")));
        return *medium_;
      }

      jkr::Control control() const
      {
        const std::string c = text("control");
        if (c == "force")
          return jkr::Control::force;
        if (c == "displacement")
          return jkr::Control::displacement;
        throw DomainError("control = '" + c + "' must be 'force' or 'displacement'");
      }

      tangential::Branch branch() const
      {
        const std::string b = text("branch");
        if (b == "loading")
          return tangential::Branch::loading;
        if (b == "unloading")
          return tangential::Branch::unloading;
        if (b == "reloading")
          return tangential::Branch::reloading;
        throw DomainError("branch = '" + b + "' must be 'loading', 'unloading' or 'reloading'");
      }

      jkr::Mechanism mechanism() const
      {
        if (!has("mechanism"))
          return jkr::Mechanism::governing;
        const std::string m = text("mechanism");
        if (m == "periphery")
          return jkr::Mechanism::periphery;
        if (m == "centre" || m == "center")
          return jkr::Mechanism::centre;
        if (m == "governing")
          return jkr::Mechanism::governing;
        throw DomainError("mechanism = '" + m + "' must be 'periphery', 'centre' or 'governing'");
      }

    private:
      double number_in(const json &object, const char *key, const std::string &prefix) const
      {
        const std::string name = prefix + key;
        if (!object.contains(key))
          throw DomainError(name + ": missing (required for case '" + case_name + "', quantity '" +
                            quantity + "')");
        const json &v = object.at(key);
        if (v.is_number())
          return v.get<double>();
        if (v.is_string())
          {
            // Exact decimal strings are accepted so that reference tables can carry exact doubles.
            const std::string s = v.get<std::string>();
            char *end = nullptr;
            const double x = std::strtod(s.c_str(), &end);
            if (!s.empty() && end == s.c_str() + s.size())
              return x;
          }
        throw DomainError(name + ": must be a number (got " + v.dump() + ")");
      }

      const json &j_;
      mutable std::unique_ptr<Medium> medium_;
    };

    using Evaluator = std::function<double(const Request &)>;
    using QuantityTable = std::map<std::string, Evaluator>;

    struct CaseTable
    {
      QuantityTable closed_form;
      QuantityTable numerical_mdr;
    };

    // --- helpers for the numerical path --------------------------------------------------------

    // The numerical MDR's critical state in the request's bracket (a_lo, a_hi), or by default in nine
    // decades either side of c0, moved toward a minimum found on its end up to four times: the critical
    // radius of a tip with n + k -> 0 falls far below c0 (5.5e-16 m for n = 1, k = -0.9, c0 = 1.2e-4 m,
    // a row of the 34-digit references).
    mdr::CriticalState bracketed_critical_state(const Request &q, const mdr::Profile &f, const Medium &m,
                                                const double dgamma, const mdr::Control control)
    {
      const bool given = q.has("a_lo") || q.has("a_hi");
      return mdr::critical_state(f, m, dgamma, control, q.has("a_lo") ? q.number("a_lo") : m.c0 * 1e-9,
                                 q.has("a_hi") ? q.number("a_hi") : m.c0 * 1e9, given ? 0 : 4);
    }

    // Solves increasing(x) = target for x > 0 by expanding a bracket geometrically from `start`.
    double solve_increasing(const std::function<double(double)> &increasing, const double target,
                            const double start, const char *what)
    {
      double lo = start / 2., hi = start * 2.;
      for (int i = 0; i < 200 && increasing(lo) > target; ++i)
        lo /= 4.;
      for (int i = 0; i < 200 && increasing(hi) < target; ++i)
        hi *= 4.;
      const double f_lo = increasing(lo) - target, f_hi = increasing(hi) - target;
      if (f_lo == 0.)
        return lo;
      if (f_hi == 0.)
        return hi;
      if (!(f_lo <= 0. && f_hi >= 0.))
        throw DomainError(std::string(what) + ": no solution found for the target " + check::format(target));
      std::uintmax_t iterations = 200;
      const auto root = boost::math::tools::toms748_solve(
        [&](const double x) { return increasing(x) - target; }, lo, hi, f_lo, f_hi,
        boost::math::tools::eps_tolerance<double>(50), iterations);
      return 0.5 * (root.first + root.second);
    }

    // The root a > a_c of value(a) = target on the stable branch of an adhesive contact, where value
    // (d(a) or F_N(a)) increases from its minimum value_c at a_c.
    double stable_branch_radius(const std::function<double(double)> &value, const double target, const double ac,
                                const double value_c, const char *name)
    {
      if (target < value_c)
        check::fail("contact_radius", name, target,
                    "is below its critical value " + check::format(value_c) + ": no adhesive equilibrium");
      if (target == value_c)
        return ac;
      double hi = 2. * ac;
      for (int i = 0; i < 200 && value(hi) < target; ++i)
        hi *= 2.;
      std::uintmax_t iterations = 200;
      const auto root = boost::math::tools::toms748_solve([&](const double a) { return value(a) - target; }, ac, hi,
                                                          value_c - target, value(hi) - target,
                                                          boost::math::tools::eps_tolerance<double>(50), iterations);
      return 0.5 * (root.first + root.second);
    }

    constexpr double numerical_centre_margin = 0.1;

    mdr::Profile power_law_profile(const Request &q)
    {
      const std::string &c = q.case_name;
      if (c == "cone")
        return mdr::power_law(1., q.geometry("tan_theta"));
      if (c == "paraboloid" || c == "jkr_paraboloid" || c == "tangential_sphere" ||
          c == "oscillating_sphere")
        {
          const double R = q.geometry("R");
          check::positive("paraboloid", "geometry.R", R);
          return mdr::power_law(2., 1. / (2. * R));
        }
      return mdr::power_law(q.geometry("n"), q.geometry("A"));
    }

    PowerLaw closed_power_law(const Request &q)
    {
      const std::string &c = q.case_name;
      if (c == "cone")
        return as_power_law(Cone{q.geometry("tan_theta")});
      if (c == "paraboloid" || c == "jkr_paraboloid")
        return as_power_law(Paraboloid{q.geometry("R")});
      return {q.geometry("n"), q.geometry("A")};
    }

    double numeric_depth(const mdr::Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return mdr::depth(mdr::indentation(f, m, a, dgamma));
    }
    double numeric_force(const mdr::Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return mdr::force(mdr::indentation(f, m, a, dgamma), m);
    }

    mdr::Profile concave_profile(const double a, const double h0)
    {
      const double c = h0 / (a * a); // f = -h0 r^2 / a^2 (9.31)
      return {[c](double r) { return -c * r * r; }, [c](double r) { return -2. * c * r; },
              [c](double) { return -2. * c; }};
    }

    // --- the tables ---------------------------------------------------------------------------

    // Normal contact of a convex power-law-type indenter (cone, paraboloid, power_law).
    CaseTable convex_table()
    {
      CaseTable t;
      // Closed forms. The cone and the paraboloid have their own formulas (9.20, 9.26); the cone's
      // are those of 9.30 at n = 1.
      t.closed_form["depth"] = [](const Request &q) {
        const Medium m = q.medium();
        if (q.case_name == "paraboloid")
          return depth(m, Paraboloid{q.geometry("R")}, q.number("a"));
        return depth(m, closed_power_law(q), q.number("a"));
      };
      t.closed_form["force"] = [](const Request &q) {
        const Medium m = q.medium();
        if (q.case_name == "paraboloid")
          return force(m, Paraboloid{q.geometry("R")}, q.number("a"));
        return force(m, closed_power_law(q), q.number("a"));
      };
      t.closed_form["pressure"] = [](const Request &q) {
        const Medium m = q.medium();
        if (q.case_name == "paraboloid")
          return pressure(m, Paraboloid{q.geometry("R")}, q.number("a"), q.number("r"));
        return pressure(m, closed_power_law(q), q.number("a"), q.number("r"));
      };
      t.closed_form["displacement"] = [](const Request &q) {
        const Medium m = q.medium();
        if (q.case_name == "paraboloid")
          return displacement(m, Paraboloid{q.geometry("R")}, q.number("a"), q.number("r"));
        return displacement(m, closed_power_law(q), q.number("a"), q.number("r"));
      };
      t.closed_form["contact_radius"] = [](const Request &q) {
        const Medium m = q.medium();
        if (q.has("d"))
          return contact_radius_from_depth(m, closed_power_law(q), q.number("d"));
        return contact_radius_from_force(m, closed_power_law(q), q.number("F"));
      };
      // Numerical MDR.
      t.numerical_mdr["depth"] = [](const Request &q) {
        return numeric_depth(power_law_profile(q), q.medium(), q.number("a"));
      };
      t.numerical_mdr["force"] = [](const Request &q) {
        return numeric_force(power_law_profile(q), q.medium(), q.number("a"));
      };
      t.numerical_mdr["pressure"] = [](const Request &q) {
        const Medium m = q.medium();
        const double r = q.number("r");
        const PowerLaw p = closed_power_law(q);
        if (r == 0. && !(p.n + m.k > 1.))
          check::fail("power_law pressure", "n + k", p.n + m.k,
                      "must be > 1 for a finite pressure at r = 0 (the tip is too sharp)");
        // p(0) ~ int_0 x^(n+k-2) dx: a fraction (1e-308)^((n+k-1)/(k+1)) of it lies below the smallest
        // double, out of reach of any quadrature; (n+k-1)/(k+1) >= 0.1 keeps it below 1e-30.
        if (r == 0. && p.n + m.k - 1. < numerical_centre_margin * (1. + m.k))
          check::fail("power_law pressure (numerical MDR)", "n + k - 1", p.n + m.k - 1.,
                      "is too close to 0: the numerical MDR cannot resolve p(0) (its integrand's mass lies below "
                      "the smallest double); use r > 0 or the closed form");
        return mdr::pressure(mdr::indentation(power_law_profile(q), m, q.number("a")), m, r);
      };
      t.numerical_mdr["displacement"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::displacement(mdr::indentation(power_law_profile(q), m, q.number("a")), m, q.number("r"));
      };
      t.numerical_mdr["contact_radius"] = [](const Request &q) {
        const Medium m = q.medium();
        const mdr::Profile f = power_law_profile(q);
        if (q.has("d"))
          {
            const double d = q.number("d");
            check::positive("contact_radius", "d", d);
            return solve_increasing([&](double a) { return numeric_depth(f, m, a); }, d, m.c0,
                                    "contact_radius");
          }
        const double F = q.number("F");
        check::positive("contact_radius", "F", F);
        return solve_increasing([&](double a) { return numeric_force(f, m, a); }, F, m.c0, "contact_radius");
      };
      return t;
    }

    CaseTable flat_punch_table(const bool adhesive)
    {
      CaseTable t;
      // The flat punch is loaded by d; with adhesion it can also be asked for its critical state.
      t.closed_form["force"] = [](const Request &q) {
        return force(q.medium(), FlatPunch{q.number("a")}, q.number("d"));
      };
      t.closed_form["pressure"] = [](const Request &q) {
        return pressure(q.medium(), FlatPunch{q.number("a")}, q.number("d"), q.number("r"));
      };
      t.closed_form["displacement"] = [](const Request &q) {
        return displacement(q.medium(), FlatPunch{q.number("a")}, q.number("d"), q.number("r"));
      };
      t.numerical_mdr["force"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::force(mdr::flat(q.number("a"), q.number("d")), m);
      };
      t.numerical_mdr["pressure"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::pressure(mdr::flat(q.number("a"), q.number("d")), m, q.number("r"));
      };
      t.numerical_mdr["displacement"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::displacement(mdr::flat(q.number("a"), q.number("d")), m, q.number("r"));
      };
      if (adhesive)
        {
          t.closed_form["critical_depth"] = [](const Request &q) {
            return jkr::critical_state(q.medium(), FlatPunch{q.number("a")}, q.number("dgamma")).depth;
          };
          t.closed_form["critical_force"] = [](const Request &q) {
            return jkr::critical_state(q.medium(), FlatPunch{q.number("a")}, q.number("dgamma")).force;
          };
          t.closed_form["critical_radius"] = [](const Request &q) {
            return jkr::critical_state(q.medium(), FlatPunch{q.number("a")}, q.number("dgamma")).radius;
          };
          // Numerically: the separation condition w1D(a) = -Delta_l(a) (9.46) of the rigid translation,
          // with the force from 9.11.
          const auto critical_numeric = [](const Request &q, const int which) {
            const Medium m = q.medium();
            const double a = q.number("a"), dgamma = q.number("dgamma");
            // d = g(a) - Delta_l(a) with g = 0 (the punch face is flat)
            const double d = mdr::depth(mdr::indentation(mdr::power_law(1., 0.), m, a, dgamma));
            if (which == 0)
              return d;
            if (which == 1)
              return mdr::force(mdr::flat(a, d), m);
            return a;
          };
          t.numerical_mdr["critical_depth"] = [critical_numeric](const Request &q) { return critical_numeric(q, 0); };
          t.numerical_mdr["critical_force"] = [critical_numeric](const Request &q) { return critical_numeric(q, 1); };
          t.numerical_mdr["critical_radius"] = [critical_numeric](const Request &q) { return critical_numeric(q, 2); };
        }
      return t;
    }

    CaseTable concave_table()
    {
      CaseTable t;
      const auto punch = [](const Request &q) { return ConcavePunch{q.number("a"), q.geometry("h0")}; };
      t.closed_form["force"] = [punch](const Request &q) { return force(q.medium(), punch(q), q.number("d0")); };
      t.closed_form["pressure"] = [punch](const Request &q) {
        return pressure(q.medium(), punch(q), q.number("d0"), q.number("r"));
      };
      t.closed_form["displacement"] = [punch](const Request &q) {
        return displacement(q.medium(), punch(q), q.number("d0"), q.number("r"));
      };
      const auto foundation = [punch](const Request &q, const Medium &m) {
        const ConcavePunch p = punch(q);
        // The same validity condition (complete contact, 9.35) applies to the numerical path.
        force(m, p, q.number("d0"));
        return mdr::indentation_to_depth(concave_profile(p.a, p.h0), m.k, p.a, q.number("d0"));
      };
      t.numerical_mdr["force"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::force(foundation(q, m), m);
      };
      t.numerical_mdr["pressure"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::pressure(foundation(q, m), m, q.number("r"));
      };
      t.numerical_mdr["displacement"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::displacement(foundation(q, m), m, q.number("r"));
      };
      return t;
    }

    // Prescribed surface pressure: constant_pressure (p0) and optimal_profile (p = -sigma_th).
    CaseTable pressure_load_table(const bool optimal)
    {
      CaseTable t;
      const auto load_pressure = [optimal](const Request &q) {
        return optimal ? -q.number("sigma_th") : q.geometry("p0");
      };
      const auto check_load = [optimal](const Request &q) {
        if (optimal)
          check::positive("optimal_profile", "sigma_th", q.number("sigma_th"));
        return UniformPressure{q.number("a"), optimal ? -q.number("sigma_th") : q.geometry("p0")};
      };
      t.closed_form["depth"] = [check_load](const Request &q) { return centre_displacement(q.medium(), check_load(q)); };
      t.closed_form["pressure"] = [check_load](const Request &q) {
        const UniformPressure load = check_load(q);
        const double r = q.number("r");
        check::non_negative("pressure", "r", r);
        return r <= load.a ? load.p0 : 0.; // the load itself (9.37, 9.69)
      };
      t.closed_form["force"] = [check_load](const Request &q) { return force(check_load(q)); };
      t.closed_form["displacement"] = [check_load](const Request &q) {
        return displacement(q.medium(), check_load(q), q.number("r"));
      };
      const auto foundation = [load_pressure, check_load](const Request &q, const Medium &m) {
        const UniformPressure load = check_load(q);
        const double p0 = load_pressure(q), a = load.a;
        return mdr::from_pressure([p0, a](double r) { return r <= a ? p0 : 0.; }, m, a);
      };
      t.numerical_mdr["depth"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::depth(foundation(q, m));
      };
      t.numerical_mdr["force"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::force(foundation(q, m), m);
      };
      t.numerical_mdr["displacement"] = [foundation](const Request &q) {
        const Medium m = q.medium();
        return mdr::displacement(foundation(q, m), m, q.number("r"));
      };
      if (optimal)
        {
          t.closed_form["profile"] = [](const Request &q) {
            return jkr::profile(q.medium(), jkr::OptimalProfile{q.number("a"), q.number("sigma_th")}, q.number("r"));
          };
          t.numerical_mdr["profile"] = [foundation](const Request &q) {
            const Medium m = q.medium();
            const double r = q.number("r"), a = q.number("a");
            check::closed_interval("optimal_profile profile", "r", r, 0., a);
            const mdr::Foundation w1d = foundation(q, m);
            return mdr::displacement(w1d, m, 0.) - mdr::displacement(w1d, m, r); // f = w(0) - w(r)
          };
        }
      return t;
    }

    CaseTable jkr_convex_table()
    {
      CaseTable t;
      const auto is_parabola = [](const Request &q) { return q.case_name == "jkr_paraboloid"; };
      t.closed_form["depth"] = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        if (is_parabola(q))
          return jkr::depth(m, Paraboloid{q.geometry("R")}, q.number("dgamma"), q.number("a"));
        return jkr::depth(m, closed_power_law(q), q.number("dgamma"), q.number("a"));
      };
      t.closed_form["force"] = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        if (is_parabola(q))
          return jkr::force(m, Paraboloid{q.geometry("R")}, q.number("dgamma"), q.number("a"));
        return jkr::force(m, closed_power_law(q), q.number("dgamma"), q.number("a"));
      };
      t.closed_form["pressure"] = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        if (is_parabola(q))
          return jkr::pressure(m, Paraboloid{q.geometry("R")}, q.number("dgamma"), q.number("a"), q.number("r"));
        return jkr::pressure(m, closed_power_law(q), q.number("dgamma"), q.number("a"), q.number("r"));
      };
      t.closed_form["displacement"] = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        if (is_parabola(q))
          return jkr::displacement(m, Paraboloid{q.geometry("R")}, q.number("dgamma"), q.number("a"),
                                   q.number("r"));
        return jkr::displacement(m, closed_power_law(q), q.number("dgamma"), q.number("a"), q.number("r"));
      };
      const auto critical = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        if (is_parabola(q))
          return jkr::critical_state(m, Paraboloid{q.geometry("R")}, q.number("dgamma"), q.control());
        return jkr::critical_state(m, closed_power_law(q), q.number("dgamma"), q.control());
      };
      t.closed_form["critical_radius"] = [critical](const Request &q) { return critical(q).radius; };
      t.closed_form["critical_depth"] = [critical](const Request &q) { return critical(q).depth; };
      t.closed_form["critical_force"] = [critical](const Request &q) { return critical(q).force; };
      // a from d or F on the stable branch a > a_c (a_c of displacement control for d, of force
      // control for F), where d(a) and F(a) increase.
      t.closed_form["contact_radius"] = [is_parabola](const Request &q) {
        const Medium m = q.medium();
        const double dgamma = q.number("dgamma");
        const bool by_depth = q.has("d");
        const double target = by_depth ? q.number("d") : q.number("F");
        check::finite("contact_radius", by_depth ? "d" : "F", target);
        const jkr::Control control = by_depth ? jkr::Control::displacement : jkr::Control::force;
        const auto value = [&](const double a) {
          if (is_parabola(q))
            return by_depth ? jkr::depth(m, Paraboloid{q.geometry("R")}, dgamma, a)
                            : jkr::force(m, Paraboloid{q.geometry("R")}, dgamma, a);
          return by_depth ? jkr::depth(m, closed_power_law(q), dgamma, a) : jkr::force(m, closed_power_law(q), dgamma, a);
        };
        const jkr::CriticalState c = is_parabola(q) ? jkr::critical_state(m, Paraboloid{q.geometry("R")}, dgamma, control)
                                                    : jkr::critical_state(m, closed_power_law(q), dgamma, control);
        return stable_branch_radius(value, target, c.radius, by_depth ? c.depth : c.force, by_depth ? "d" : "F");
      };

      t.numerical_mdr["depth"] = [](const Request &q) {
        return numeric_depth(power_law_profile(q), q.medium(), q.number("a"), q.number("dgamma"));
      };
      t.numerical_mdr["force"] = [](const Request &q) {
        return numeric_force(power_law_profile(q), q.medium(), q.number("a"), q.number("dgamma"));
      };
      t.numerical_mdr["pressure"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::pressure(mdr::indentation(power_law_profile(q), m, q.number("a"), q.number("dgamma")), m,
                             q.number("r"));
      };
      t.numerical_mdr["displacement"] = [](const Request &q) {
        const Medium m = q.medium();
        return mdr::displacement(mdr::indentation(power_law_profile(q), m, q.number("a"), q.number("dgamma")),
                                 m, q.number("r"));
      };
      const auto numeric_critical = [](const Request &q) {
        const mdr::Control control =
          q.control() == jkr::Control::force ? mdr::Control::force : mdr::Control::displacement;
        return bracketed_critical_state(q, power_law_profile(q), q.medium(), q.number("dgamma"), control);
      };
      t.numerical_mdr["contact_radius"] = [](const Request &q) {
        const Medium m = q.medium();
        const double dgamma = q.number("dgamma");
        const bool by_depth = q.has("d");
        const double target = by_depth ? q.number("d") : q.number("F");
        check::finite("contact_radius", by_depth ? "d" : "F", target);
        const mdr::Profile f = power_law_profile(q);
        const mdr::CriticalState c = bracketed_critical_state(
          q, f, m, dgamma, by_depth ? mdr::Control::displacement : mdr::Control::force);
        const auto value = [&](const double a) {
          return by_depth ? numeric_depth(f, m, a, dgamma) : numeric_force(f, m, a, dgamma);
        };
        return stable_branch_radius(value, target, c.radius, by_depth ? c.depth : c.force, by_depth ? "d" : "F");
      };
      t.numerical_mdr["critical_radius"] = [numeric_critical](const Request &q) { return numeric_critical(q).radius; };
      t.numerical_mdr["critical_depth"] = [numeric_critical](const Request &q) { return numeric_critical(q).depth; };
      t.numerical_mdr["critical_force"] = [numeric_critical](const Request &q) { return numeric_critical(q).force; };
      return t;
    }

    CaseTable jkr_concave_table()
    {
      CaseTable t;
      const auto punch = [](const Request &q) { return ConcavePunch{q.number("a"), q.geometry("h0")}; };
      const auto state = [punch](const Request &q) {
        return jkr::critical_state(q.medium(), punch(q), q.number("dgamma"), q.number("sigma_th"), q.mechanism());
      };
      t.closed_form["critical_depth"] = [state](const Request &q) { return state(q).depth; };
      t.closed_form["critical_force"] = [state](const Request &q) { return state(q).force; };
      t.closed_form["critical_radius"] = [state](const Request &q) { return state(q).radius; };
      t.closed_form["pressure"] = [punch](const Request &q) {
        return jkr::critical_pressure(q.medium(), punch(q), q.number("dgamma"), q.number("sigma_th"),
                                      q.mechanism(), q.number("r"));
      };
      t.closed_form["transition_h0"] = [](const Request &q) {
        return jkr::transition_h0(q.medium(), q.number("a"), q.number("dgamma"), q.number("sigma_th"));
      };

      // Numerically: the periphery state from w1D(a) = -Delta_l(a) (9.46), the centre state from
      // p(0) = -sigma_th with p(0) linear in d0; the rim depth is d0 + h0 (9.65).
      struct Numeric
      {
        double d0;     // centre displacement in the critical state
        double rim;    // rim depth d = d0 + h0
        double force;
      };
      const auto numeric_state = [punch](const Request &q, jkr::Mechanism mech) {
        const Medium m = q.medium();
        const ConcavePunch p = punch(q);
        const double dgamma = q.number("dgamma"), sigma = q.number("sigma_th");
        check::positive("jkr_concave", "sigma_th", sigma);
        check::non_negative("jkr_concave", "geometry.h0", p.h0);
        const mdr::Profile f = concave_profile(p.a, p.h0);
        const auto periphery = [&]() {
          const double d0 = mdr::depth(mdr::indentation(f, m, p.a, dgamma)); // g(a) - Delta_l(a)
          return Numeric{d0, d0 + p.h0, mdr::force(mdr::indentation_to_depth(f, m.k, p.a, d0), m)};
        };
        const auto centre = [&]() {
          const double p_shape = mdr::pressure(mdr::indentation_to_depth(f, m.k, p.a, 0.), m, 0.);
          const double p_unit = mdr::pressure(mdr::flat(p.a, 1.), m, 0.);
          const double d0 = (-sigma - p_shape) / p_unit;
          return Numeric{d0, d0 + p.h0, mdr::force(mdr::indentation_to_depth(f, m.k, p.a, d0), m)};
        };
        if (mech == jkr::Mechanism::periphery)
          return periphery();
        if (mech == jkr::Mechanism::centre)
          return centre();
        const Numeric P = periphery(), C = centre();
        return P.rim >= C.rim ? P : C;
      };
      t.numerical_mdr["critical_depth"] = [numeric_state](const Request &q) {
        return numeric_state(q, q.mechanism()).rim;
      };
      t.numerical_mdr["critical_force"] = [numeric_state](const Request &q) {
        return numeric_state(q, q.mechanism()).force;
      };
      t.numerical_mdr["critical_radius"] = [](const Request &q) { return q.number("a"); };
      t.numerical_mdr["pressure"] = [numeric_state, punch](const Request &q) {
        const Medium m = q.medium();
        const ConcavePunch p = punch(q);
        const Numeric s = numeric_state(q, q.mechanism());
        return mdr::pressure(mdr::indentation_to_depth(concave_profile(p.a, p.h0), m.k, p.a, s.d0), m,
                             q.number("r"));
      };
      t.numerical_mdr["transition_h0"] = [numeric_state](const Request &q) {
        // rim_P(h0) - rim_C(h0) is linear in h0: two evaluations give its root.
        const auto difference = [&](const double h0) {
          const Medium m = q.medium();
          const double a = q.number("a"), dgamma = q.number("dgamma"), sigma = q.number("sigma_th");
          check::positive("jkr_concave", "sigma_th", sigma);
          const mdr::Profile f = concave_profile(a, h0);
          const double d0P = mdr::depth(mdr::indentation(f, m, a, dgamma));
          const double p_shape = mdr::pressure(mdr::indentation_to_depth(f, m.k, a, 0.), m, 0.);
          const double p_unit = mdr::pressure(mdr::flat(a, 1.), m, 0.);
          const double d0C = (-sigma - p_shape) / p_unit;
          return d0P - d0C;
        };
        const double a = q.number("a");
        const double scale = a; // any non-zero h0 works for a linear function
        const double f0 = difference(0.), f1 = difference(scale);
        const double h0 = -f0 * scale / (f1 - f0);
        if (!(h0 > 0.))
          check::fail("jkr_concave transition_h0", "sigma_th", q.number("sigma_th"),
                      "is too small: the centre separates first for every h0 >= 0 (no transition)");
        return h0;
      };
      return t;
    }

    // --- tangential ---------------------------------------------------------------------------
    tangential::SphereSlip slip(const Request &q) { return {q.geometry("R"), q.number("mu")}; }

    // Numerical Ciavarella-Jaeger (9.77, 9.81) from the MDR of the paraboloid.
    struct NumericSphere
    {
      const Request &q;
      Medium m;
      mdr::Profile f;
      double mu, a;

      explicit NumericSphere(const Request &request)
        : q(request), m(request.medium()), f(power_law_profile(request)), mu(request.number("mu")),
          a(request.number("a"))
      {
        check::positive("tangential", "mu (friction coefficient)", mu);
        check::positive("tangential", "a", a);
      }
      double FN(const double radius) const { return radius > 0. ? numeric_force(f, m, radius) : 0.; }
      double d(const double radius) const { return radius > 0. ? numeric_depth(f, m, radius) : 0.; }
      double p(const double radius, const double r) const
      {
        return radius > 0. ? mdr::pressure(mdr::indentation(f, m, radius), m, r) : 0.;
      }
      // The radius b in [0, a] with FN(a) - FN(b) = dF / mu (dF = mu [FN(a) - FN(b)]).
      double radius_for(const double dF) const
      {
        const double FNa = FN(a);
        const double target = FNa - dF / mu;
        if (!(target >= 0. && target <= FNa))
          check::fail("tangential", "Fx", dF, "gives gross slip (|dF| must stay below mu F_N)");
        if (target == 0.)
          return 0.;
        std::uintmax_t it = 200;
        const auto g = [&](double b) { return FN(b) - target; };
        const double g_lo = -target, g_hi = FNa - target;
        if (g_hi == 0.)
          return a;
        const auto root = boost::math::tools::toms748_solve(g, 0., a, g_lo, g_hi,
                                                            boost::math::tools::eps_tolerance<double>(50), it);
        return 0.5 * (root.first + root.second);
      }
      double alpha() const { return m.alpha(); }
    };

    CaseTable tangential_sphere_table()
    {
      CaseTable t;
      const auto stick = [](const Request &q) {
        if (q.has("c"))
          return q.number("c");
        return tangential::stick_radius(q.medium(), slip(q), q.number("a"), q.number("Fx"));
      };
      t.closed_form["traction"] = [stick](const Request &q) {
        return tangential::traction(q.medium(), slip(q), q.number("a"), stick(q), q.number("r"));
      };
      t.closed_form["tangential_force"] = [stick](const Request &q) {
        return tangential::tangential_force(q.medium(), slip(q), q.number("a"), stick(q));
      };
      t.closed_form["tangential_displacement"] = [stick](const Request &q) {
        return tangential::tangential_displacement(q.medium(), slip(q), q.number("a"), stick(q));
      };
      t.closed_form["stick_radius"] = [](const Request &q) {
        return tangential::stick_radius(q.medium(), slip(q), q.number("a"), q.number("Fx"));
      };
      const auto numeric_stick = [](const NumericSphere &s) {
        if (s.q.has("c"))
          {
            const double c = s.q.number("c");
            check::closed_interval("tangential_sphere", "c (stick radius)", c, 0., s.a);
            return c;
          }
        const double Fx = s.q.number("Fx");
        check::non_negative("tangential_sphere", "Fx", Fx);
        return s.radius_for(Fx);
      };
      t.numerical_mdr["traction"] = [numeric_stick](const Request &q) {
        const NumericSphere s(q);
        const double c = numeric_stick(s), r = q.number("r");
        return s.mu * (s.p(s.a, r) - s.p(c, r)); // 9.77
      };
      t.numerical_mdr["tangential_force"] = [numeric_stick](const Request &q) {
        const NumericSphere s(q);
        return s.mu * (s.FN(s.a) - s.FN(numeric_stick(s)));
      };
      t.numerical_mdr["tangential_displacement"] = [numeric_stick](const Request &q) {
        const NumericSphere s(q);
        return s.mu * s.alpha() * (s.d(s.a) - s.d(numeric_stick(s)));
      };
      t.numerical_mdr["stick_radius"] = [numeric_stick](const Request &q) {
        const NumericSphere s(q);
        return numeric_stick(s);
      };
      return t;
    }

    CaseTable oscillating_sphere_table()
    {
      CaseTable t;
      t.closed_form["traction"] = [](const Request &q) {
        return tangential::traction(q.medium(), slip(q), q.number("a"), q.number("FA"), q.branch(),
                                    q.number("Fx"), q.number("r"));
      };
      t.closed_form["tangential_displacement"] = [](const Request &q) {
        return tangential::tangential_displacement(q.medium(), slip(q), q.number("a"), q.number("FA"),
                                                   q.branch(), q.number("Fx"));
      };
      t.closed_form["hysteresis_force"] = [](const Request &q) {
        return tangential::hysteresis_force(q.medium(), slip(q), q.number("a"), q.number("FA"), q.branch(),
                                            q.number("u0"));
      };
      t.closed_form["tangential_force"] = t.closed_form["hysteresis_force"];
      t.closed_form["dissipated_energy"] = [](const Request &q) {
        return tangential::dissipated_energy(q.medium(), slip(q), q.number("a"), q.number("FA"));
      };

      // Numerically, along a branch the state is the radius b of the reversed-slip annulus.
      const auto check_amplitude = [](const NumericSphere &s, const double FA) {
        const double limit = s.mu * s.FN(s.a);
        if (!(FA > 0. && FA < limit))
          check::fail("oscillating_sphere", "FA", FA,
                      "is outside (0, mu F_N) = (0, " + check::format(limit) + "): gross slip");
      };
      t.numerical_mdr["traction"] = [check_amplitude](const Request &q) {
        const NumericSphere s(q);
        const double FA = q.number("FA"), Fx = q.number("Fx"), r = q.number("r");
        check_amplitude(s, FA);
        const tangential::Branch branch = q.branch();
        const double c = s.radius_for(FA);
        const auto pair = [&](const double outer, const double inner) { return s.p(outer, r) - s.p(inner, r); };
        if (branch == tangential::Branch::loading)
          return s.mu * pair(s.a, s.radius_for(Fx));
        check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
        const double dF = branch == tangential::Branch::unloading ? FA - Fx : Fx + FA;
        const double b = s.radius_for(dF / 2.);
        const double tau_A = s.mu * pair(s.a, c);
        const double change = 2. * s.mu * pair(s.a, b); // 9.81
        return branch == tangential::Branch::unloading ? tau_A - change : -tau_A + change;
      };
      t.numerical_mdr["tangential_displacement"] = [check_amplitude](const Request &q) {
        const NumericSphere s(q);
        const double FA = q.number("FA"), Fx = q.number("Fx");
        check_amplitude(s, FA);
        const tangential::Branch branch = q.branch();
        const double c = s.radius_for(FA);
        const double uA = s.mu * s.alpha() * (s.d(s.a) - s.d(c));
        if (branch == tangential::Branch::loading)
          return s.mu * s.alpha() * (s.d(s.a) - s.d(s.radius_for(Fx)));
        check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
        const double dF = branch == tangential::Branch::unloading ? FA - Fx : Fx + FA;
        const double b = s.radius_for(dF / 2.);
        const double change = 2. * s.mu * s.alpha() * (s.d(s.a) - s.d(b));
        return branch == tangential::Branch::unloading ? uA - change : -uA + change;
      };
      const auto numeric_hysteresis = [check_amplitude](const Request &q) {
        const NumericSphere s(q);
        const double FA = q.number("FA"), u0 = q.number("u0");
        check_amplitude(s, FA);
        const tangential::Branch branch = q.branch();
        const double c = s.radius_for(FA);
        const double da = s.d(s.a);
        const double uA = s.mu * s.alpha() * (da - s.d(c));
        const double span = branch == tangential::Branch::loading ? u0 : (branch == tangential::Branch::unloading ? uA - u0 : u0 + uA);
        const double factor = branch == tangential::Branch::loading ? 1. : 2.;
        const double lo = branch == tangential::Branch::loading ? 0. : -uA;
        check::closed_interval("oscillating_sphere", "u0", u0, lo, uA);
        // span = factor mu alpha (d(a) - d(b)): solve d(b) for b, then the force change.
        const double target = da - span / (factor * s.mu * s.alpha());
        double b = 0.;
        if (target > 0.)
          b = solve_increasing([&](double x) { return s.d(x); }, target, s.a / 2., "hysteresis b");
        const double change = factor * s.mu * (s.FN(s.a) - s.FN(b));
        if (branch == tangential::Branch::loading)
          return change;
        return branch == tangential::Branch::unloading ? FA - change : -FA + change;
      };
      t.numerical_mdr["hysteresis_force"] = numeric_hysteresis;
      t.numerical_mdr["tangential_force"] = numeric_hysteresis;
      t.numerical_mdr["dissipated_energy"] = [check_amplitude](const Request &q) {
        // The loop area int (F_reloading - F_unloading) du over [-uA, uA] = -2 int F_unloading(u) du
        // (F_reloading(u) = -F_unloading(-u); the reloading branch lies above), parametrised by the
        // annulus radius b in [c, a]: u(b) = uA - 2 mu alpha (d(a) - d(b)), F(b) = FA - 2 mu (F_N(a) - F_N(b)).
        const NumericSphere s(q);
        const double FA = q.number("FA");
        check_amplitude(s, FA);
        const double c = s.radius_for(FA), FNa = s.FN(s.a);
        const auto integrand = [&](const double b, double, double) {
          const double F = FA - 2. * s.mu * (FNa - s.FN(b));
          const double du_db = 2. * s.mu * s.alpha() * mdr::equivalent_profile_slope(s.f, s.m.k, b);
          return F * du_db;
        };
        return -2. * detail::integrate_with_distances(integrand, c, s.a, 1e-12);
      };
      return t;
    }

    CaseTable coefficients_table()
    {
      CaseTable t;
      const auto body = [](const Request &q) {
        const GradedHalfSpace b = q.body("material");
        validate("coefficients", b);
        return b;
      };
      t.closed_form["beta"] = [body](const Request &q) { const auto b = body(q); return beta(b.k, b.nu); };
      t.closed_form["C"] = [body](const Request &q) { const auto b = body(q); return C(b.k, b.nu); };
      t.closed_form["h_N"] = [body](const Request &q) { const auto b = body(q); return h_N(b.k, b.nu); };
      t.closed_form["h_T"] = [body](const Request &q) { const auto b = body(q); return h_T(b.k, b.nu); };
      t.closed_form["alpha"] = [](const Request &q) { return q.medium().alpha(); };
      t.closed_form["kappa"] = [](const Request &q) { return kappa(q.geometry("n"), q.body("material").k); };
      return t;
    }

    const std::map<std::string, CaseTable> &tables()
    {
      static const std::map<std::string, CaseTable> all = [] {
        std::map<std::string, CaseTable> t;
        t["flat_punch"] = flat_punch_table(false);
        t["cone"] = convex_table();
        t["paraboloid"] = convex_table();
        t["power_law"] = convex_table();
        t["concave_paraboloid"] = concave_table();
        t["constant_pressure"] = pressure_load_table(false);
        t["jkr_flat_punch"] = flat_punch_table(true);
        t["jkr_paraboloid"] = jkr_convex_table();
        t["jkr_power_law"] = jkr_convex_table();
        t["jkr_concave"] = jkr_concave_table();
        t["optimal_profile"] = pressure_load_table(true);
        t["tangential_sphere"] = tangential_sphere_table();
        t["oscillating_sphere"] = oscillating_sphere_table();
        t["coefficients"] = coefficients_table();
        return t;
      }();
      return all;
    }

    std::string names(const QuantityTable &t)
    {
      std::string s;
      for (const auto &entry : t)
        s += (s.empty() ? "" : ", ") + entry.first;
      return s;
    }

    const Evaluator &find_evaluator(const Request &q)
    {
      const auto &all = tables();
      const auto c = all.find(q.case_name);
      if (c == all.end())
        {
          std::string list;
          for (const auto &entry : all)
            list += (list.empty() ? "" : ", ") + entry.first;
          throw DomainError("case = '" + q.case_name + "' is unknown (valid: " + list + ")");
        }
      const QuantityTable &table = q.numerical ? c->second.numerical_mdr : c->second.closed_form;
      const auto f = table.find(q.quantity);
      if (f == table.end())
        throw DomainError("quantity = '" + q.quantity + "' is not available for case '" + q.case_name +
                          "' with method '" + (q.numerical ? "numerical_mdr" : "closed_form") +
                          "' (valid: " + names(table) + ")");
      return f->second;
    }

    /// The value, or a DomainError naming the request when it is not finite (an overflow past the
    /// range of double, or an expression undefined at these inputs).
    double checked(const double value, const Request &q)
    {
      if (!std::isfinite(value))
        throw DomainError("case '" + q.case_name + "', quantity '" + q.quantity + "' (" +
                          (q.numerical ? "numerical_mdr" : "closed_form") + "): non-finite result " +
                          check::format(value) + " for the inputs " + q.inputs() +
                          " (outside the range of double precision, or undefined there)");
      return value;
    }

    double dispatch(const Request &q) { return checked(find_evaluator(q)(q), q); }
  } // namespace

  struct Prepared::Impl
  {
    explicit Impl(const std::string &line) : j(json::parse(line)), q(j), f(find_evaluator(q)) {}
    json j;
    Request q;
    const Evaluator &f;
  };

  double Prepared::operator()() const { return checked(impl_->f(impl_->q), impl_->q); }

  Prepared prepare(const std::string &line)
  {
    Prepared p;
    try
      {
        p.impl_ = std::make_shared<const Prepared::Impl>(line);
      }
    catch (const json::exception &e)
      {
        throw DomainError(std::string("request: not valid JSON (") + e.what() + ")");
      }
    return p;
  }

  Answer evaluate(const std::string &line)
  {
    Answer answer{"null", false, 0., ""};
    try
      {
        const json j = json::parse(line);
        if (j.is_object() && j.contains("id"))
          answer.id_json = j.at("id").dump();
        const Request q(j);
        answer.value = dispatch(q);
        answer.ok = true;
      }
    catch (const json::exception &e)
      {
        answer.error = std::string("request: not valid JSON (") + e.what() + ")";
      }
    catch (const std::exception &e)
      {
        answer.error = e.what();
      }
    return answer;
  }

  std::string to_json(const Answer &answer)
  {
    std::string out = "{\"id\":" + answer.id_json + ",";
    if (answer.ok)
      {
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "%.17g", answer.value);
        out += "\"value\":" + std::string(buffer);
      }
    else
      out += "\"error\":" + json(answer.error).dump();
    return out + "}";
  }

  int evaluate_stream(std::istream &in, std::ostream &out)
  {
    int errors = 0;
    std::string line;
    while (std::getline(in, line))
      {
        if (line.find_first_not_of(" \t\r") == std::string::npos)
          continue;
        const Answer answer = evaluate(line);
        errors += answer.ok ? 0 : 1;
        out << to_json(answer) << '\n';
      }
    out.flush();
    return errors;
  }
} // namespace gradcontact::batch
