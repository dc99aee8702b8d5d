// Test helpers: random valid eval requests over every case of the vocabulary (analytic/README.md),
// for the property tests. Fixed seeds: a failing point can be replayed.
#ifndef GRADCONTACT_TESTS_ANALYTIC_RANDOM_REQUESTS_H
#define GRADCONTACT_TESTS_ANALYTIC_RANDOM_REQUESTS_H

#include <analytic/material.h>
#include <analytic/normal.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace gradcontact::testing
{
  class RandomRequests
  {
  public:
    explicit RandomRequests(const unsigned long seed) : rng_(seed) {}

    nlohmann::json next()
    {
      using nlohmann::json;
      static const std::vector<std::string> cases = {
        "flat_punch", "cone", "paraboloid", "power_law", "concave_paraboloid", "constant_pressure",
        "jkr_flat_punch", "jkr_paraboloid", "jkr_power_law", "jkr_concave", "optimal_profile",
        "tangential_sphere", "oscillating_sphere"};
      const std::string c = cases[index(cases.size())];
      const double k = uniform(-0.95, 0.95);
      const double c0 = log_uniform(1e-6, 1.);
      json q = {{"case", c},
                {"material", {{"E0", log_uniform(1e6, 1e12)}, {"c0", c0}, {"k", k}, {"nu", uniform(0., 0.4999)}}}};
      const double a = c0 * log_uniform(1e-3, 1e3);
      const auto r_value = [&](const bool inside_only) {
        const double s = inside_only ? uniform(0., 0.999) : (coin() ? uniform(0., 0.999) : log_uniform(1.001, 1e3));
        return s * a;
      };
      const double R = a * log_uniform(3., 1e3);
      const double dgamma = log_uniform(1e-3, 1.);
      if (c == "flat_punch" || c == "jkr_flat_punch")
        {
          q["a"] = a;
          q["d"] = a * log_uniform(1e-6, 1e-2);
          pick(q, c == "flat_punch" ? std::vector<std::string>{"force", "pressure", "displacement"}
                                    : std::vector<std::string>{"critical_depth", "critical_force"});
          if (c == "jkr_flat_punch")
            q["dgamma"] = dgamma;
          q["r"] = r_value(q["quantity"] == "pressure");
        }
      else if (c == "cone" || c == "paraboloid" || c == "power_law")
        {
          q["a"] = a;
          if (c == "cone")
            q["geometry"] = {{"tan_theta", log_uniform(1e-3, 1.)}};
          else if (c == "paraboloid")
            q["geometry"] = {{"R", R}};
          else
            {
              const double n = uniform(0.3, 4.);
              // A such that f(a) = a * 10^U(-3,-1)
              q["geometry"] = {{"n", n}, {"A", a * log_uniform(1e-3, 0.1) / std::pow(a, n)}};
            }
          pick(q, {"depth", "force", "pressure", "displacement"});
          q["r"] = r_value(q["quantity"] == "pressure");
          if (q["quantity"] == "pressure" && c != "paraboloid" && q["r"].get<double>() < 1e-3 * a)
            q["r"] = 1e-3 * a; // sharp tips: p(0) is unbounded for n + k <= 1
        }
      else if (c == "concave_paraboloid")
        {
          const double h0 = a * log_uniform(1e-4, 1e-2);
          q["a"] = a;
          q["geometry"] = {{"h0", h0}};
          q["d0"] = 2. * (1. - k) * h0 / ((1. + k) * (1. + k)) + h0 * log_uniform(1e-2, 1e2);
          pick(q, {"force", "pressure", "displacement"});
          q["r"] = r_value(q["quantity"] == "pressure");
        }
      else if (c == "constant_pressure" || c == "optimal_profile")
        {
          q["a"] = a;
          if (c == "constant_pressure")
            q["geometry"] = {{"p0", log_uniform(1e3, 1e9)}};
          else
            q["sigma_th"] = log_uniform(1e3, 1e9);
          pick(q, c == "constant_pressure" ? std::vector<std::string>{"depth", "force", "displacement"}
                                           : std::vector<std::string>{"depth", "force", "displacement", "profile"});
          q["r"] = r_value(q["quantity"] == "profile");
          // f_opt = w(0) - w(r) of the numerical MDR cancels like (a/r)^2: keep r >= a/100 there
          if (q["quantity"] == "profile" && q["r"].get<double>() < 0.01 * a)
            q["r"] = 0.01 * a;
        }
      else if (c == "jkr_paraboloid" || c == "jkr_power_law")
        {
          q["a"] = a;
          q["dgamma"] = dgamma;
          if (c == "jkr_paraboloid")
            q["geometry"] = {{"R", R}};
          else
            {
              const double n = uniform(0.8, 4.); // 2n + k - 1 > 0: a critical state exists
              q["geometry"] = {{"n", n}, {"A", a * log_uniform(1e-3, 0.1) / std::pow(a, n)}};
            }
          pick(q, {"depth", "force", "pressure", "displacement"});
          q["r"] = r_value(q["quantity"] == "pressure");
          if (q["quantity"] == "pressure" && q["r"].get<double>() < 1e-3 * a)
            q["r"] = 1e-3 * a;
        }
      else if (c == "jkr_concave")
        {
          q["a"] = a;
          q["geometry"] = {{"h0", a * log_uniform(1e-5, 1e-2)}};
          q["dgamma"] = dgamma;
          q["sigma_th"] = log_uniform(1e5, 1e9);
          q["mechanism"] = std::vector<std::string>{"periphery", "centre", "governing"}[index(3)];
          pick(q, {"critical_depth", "critical_force", "pressure"});
          q["r"] = r_value(true);
        }
      else
        {
          q["a"] = a;
          q["geometry"] = {{"R", R}};
          q["mu"] = uniform(0.05, 1.);
          // loads as fractions of mu F_N: the evaluator checks the ranges itself
          if (c == "tangential_sphere")
            {
              q["c"] = a * uniform(0., 1.);
              pick(q, {"traction", "tangential_force", "tangential_displacement"});
              q["r"] = r_value(true);
            }
          else
            {
              fraction_ = uniform(0.05, 0.95);
              q["FA_fraction"] = fraction_;
              q["branch"] = std::vector<std::string>{"unloading", "reloading"}[index(2)];
              q["Fx_fraction"] = uniform(-1., 1.);
              pick(q, {"traction", "tangential_displacement", "dissipated_energy"});
              q["r"] = r_value(true);
            }
        }
      return q;
    }

    double uniform(const double lo, const double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    double log_uniform(const double lo, const double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

  private:
    std::size_t index(const std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }
    bool coin() { return index(2) == 0; }
    void pick(nlohmann::json &q, const std::vector<std::string> &quantities) { q["quantity"] = quantities[index(quantities.size())]; }

    std::mt19937_64 rng_;
    double fraction_ = 0.5;
  };

  /// Replaces the test-only fraction keys of a request by absolute loads (F_N from the closed form only
  /// picks a valid load; comparisons do not depend on it).
  inline nlohmann::json resolve(nlohmann::json q)
  {
    if (q.contains("FA_fraction"))
      {
        const nlohmann::json material = q["material"];
        const Medium m = medium(GradedHalfSpace{material["E0"], material["c0"], material["k"], material["nu"]});
        const double FN = force(m, Paraboloid{q["geometry"]["R"].get<double>()}, q["a"].get<double>());
        const double FA = q["FA_fraction"].get<double>() * q["mu"].get<double>() * FN;
        q["FA"] = FA;
        q["Fx"] = q["Fx_fraction"].get<double>() * FA;
        q.erase("FA_fraction");
        q.erase("Fx_fraction");
      }
    return q;
  }
} // namespace gradcontact::testing

#endif
