// The numerical MDR engine's speed and accuracy: time per call and error against the closed forms
// (normal.h, adhesion.h; accurate to about 1e-15) of pressure(), displacement(), force() and
// critical_state() for the paraboloid, cone, a power law and the flat punch at k = -0.9 ... 0.9.
//
//   bench_mdr_speed [--min-time seconds]      (default 0.05 s of calls per row; the minimum is printed)
//
// It prints a Markdown table; the requirement it measures is at most 1 ms per call with a relative
// error of at most 1e-12.
//
//   bench_mdr_speed --closed [--references file] [--min-time seconds]
//
// The closed forms instead: every row of the reference table (tests/data/references.jsonl, 34 digits)
// grouped by case and quantity, each request prepared once (batch::prepare, as `gradcontact bench --part
// analytic` does) and evaluated warm; per row the fastest of repeated batches of calls, per family the
// mean and the slowest row of those times, the median time of the first call of each request (the medium's
// coefficients and the per-thread caches of kappa and the 2F1 steps included, a single clock reading),
// and the worst relative error against the references and against the allowance of test_references.cc. The
// requirement it measures: at most 1 us per evaluation for every family, at most 5 us for adhesive contact radii.
#include <analytic/adhesion.h>
#include <analytic/batch.h>
#include <analytic/reference_rows.h>
#include <analytic/material.h>
#include <analytic/mdr.h>
#include <analytic/normal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

using namespace gradcontact;

namespace
{
  struct Row
  {
    std::string name;
    std::function<double()> numeric, closed;
  };

  /// The fastest of repeated calls [s] (at least three, until min_time has passed) and the value.
  std::pair<double, double> time_call(const std::function<double()> &f, const double min_time)
  {
    using clock = std::chrono::steady_clock;
    double best = 1e300, value = 0., total = 0.;
    for (int i = 0; i < 3 || total < min_time; ++i)
      {
        const auto start = clock::now();
        value = f();
        const double t = std::chrono::duration<double>(clock::now() - start).count();
        best = std::min(best, t);
        total += t;
        if (i > 10000)
          break;
      }
    return {best, value};
  }

  double median(std::vector<double> v)
  {
    if (v.empty())
      return 0.;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }

  struct Family
  {
    std::vector<batch::Prepared> requests;
    std::vector<double> references, allowances;
    std::vector<long> ids;
  };

  /// The closed forms of every family of the reference table: time per evaluation and error.
  int closed_forms(const std::string &file, const double min_time)
  {
    std::vector<batch::ReferenceRow> rows;
    try
      {
        rows = batch::read_reference_rows(file);
      }
    catch (const std::exception &e)
      {
        std::fprintf(stderr, "bench_mdr_speed: %s\n", e.what());
        return 1;
      }
    std::map<std::string, Family> families;
    for (batch::ReferenceRow &row : rows)
      {
        const std::string key =
          row.request.at("case").get<std::string>() + "/" + row.request.at("quantity").get<std::string>();
        // the allowance of tests/analytic/test_references.cc: the row's conditioning plus 1e-13
        families[key].allowances.push_back(row.conditioning + 1e-13);
        row.request["method"] = "closed_form";
        families[key].ids.push_back(row.request.value("id", -1L));
        families[key].requests.push_back(batch::prepare(batch::parse(row.request)));
        families[key].references.push_back(row.reference);
      }
    // A batch of calls per clock reading: the clock costs some 20-40 ns, as much as the fastest forms.
    constexpr int calls = 8;
    std::printf("| family | rows | mean [ns] | slowest row [ns] (id) | first call, median [ns] | worst relative error | "
                "worst error / allowance (id) |\n|---|---|---|---|---|---|---|\n");
    double worst_mean = 0., worst_error = 0.;
    for (const auto &[name, f] : families)
      {
        double sum = 0., slowest = 0., error = 0., ratio = 0.;
        std::vector<double> first;
        long slowest_id = -1, ratio_id = -1;
        std::size_t rows = 0;
        for (std::size_t i = 0; i < f.requests.size(); ++i)
          {
            double value;
            try
              {
                // the first call computes the medium of the request and fills the per-thread caches
                // (kappa, the 2F1 steps) if the previous row had other parameters
                const auto start = std::chrono::steady_clock::now();
                value = f.requests[i]();
                first.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
              }
            catch (const std::exception &)
              {
                continue; // a row that is an expected error (bad input kept in the table)
              }
            const auto [time, v] = time_call(
              [&] {
                double s = 0.;
                for (int j = 0; j < calls; ++j)
                  s += f.requests[i]();
                return s;
              },
              min_time / static_cast<double>(f.requests.size()));
            (void)v;
            const double t = time / calls, r = f.references[i];
            sum += t;
            if (t > slowest)
              {
                slowest = t;
                slowest_id = f.ids[i];
              }
            const double e = r == 0. ? std::abs(value) : std::abs(value - r) / std::abs(r);
            error = std::max(error, e);
            if (e / f.allowances[i] >= ratio)
              {
                ratio = e / f.allowances[i];
                ratio_id = f.ids[i];
              }
            ++rows;
          }
        const double mean = sum / static_cast<double>(std::max<std::size_t>(rows, 1));
        std::printf("| %s | %zu | %.0f | %.0f (%ld) | %.0f | %.1e | %.2f (%ld) |\n", name.c_str(), rows, mean * 1e9,
                    slowest * 1e9, slowest_id, median(first) * 1e9, error, ratio, ratio_id);
        std::fflush(stdout);
        worst_mean = std::max(worst_mean, mean);
        worst_error = std::max(worst_error, error);
      }
    std::printf("\nslowest family mean %.0f ns, worst relative error %.1e\n", worst_mean * 1e9, worst_error);
    return 0;
  }

  /// The geometry of the runs: contact radius, sphere radius, cone slope, power law, punch depth, work of adhesion.
  constexpr double a = 1e-4, R = 1e-2, tan_theta = 0.1, n = 1.5, d = 1e-6, dgamma = 0.05;
  const double     A = 1e-6 / std::pow(a, n);

  /// Warm calls per case, quantity and k: time and error against the closed forms.
  void warm_calls(const double min_time)
  {
    std::printf("| case | quantity | k | time [ms] | relative error |\n|---|---|---|---|---|\n");
    double worst_time = 0., worst_error = 0.;
    for (const double k : {-0.9, -0.5, 0., 0.5, 0.9})
      {
        const Medium m = medium(GradedHalfSpace{1e9, 1e-3, k, 0.3});
        const mdr::Profile parab = mdr::power_law(2., 1. / (2. * R)), cone = mdr::power_law(1., tan_theta),
                           power = mdr::power_law(n, A);
        const Paraboloid P{R};
        const Cone C{tan_theta};
        const PowerLaw W{n, A};
        const FlatPunch F{a};
        std::vector<Row> rows;
        const auto add_profile = [&](const std::string &name, const mdr::Profile &f, auto closed_shape) {
          rows.push_back({name + " | force", [&, f] { return mdr::force(mdr::indentation(f, m, a), m); },
                          [&, closed_shape] { return force(m, closed_shape, a); }});
          for (const double r : {0.5 * a, 0.99 * a})
            rows.push_back({name + " | pressure r/a = " + std::to_string(r / a).substr(0, 4),
                            [&, f, r] { return mdr::pressure(mdr::indentation(f, m, a), m, r); },
                            [&, closed_shape, r] { return pressure(m, closed_shape, a, r); }});
          for (const double r : {0.5 * a, 2. * a})
            rows.push_back({name + " | displacement r/a = " + std::to_string(r / a).substr(0, 4),
                            [&, f, r] { return mdr::displacement(mdr::indentation(f, m, a), m, r); },
                            [&, closed_shape, r] { return displacement(m, closed_shape, a, r); }});
        };
        add_profile("paraboloid", parab, P);
        add_profile("cone", cone, C);
        add_profile("power law n = 1.5", power, W);
        rows.push_back({"flat punch | force", [&] { return mdr::force(mdr::flat(a, d), m); },
                        [&] { return force(m, F, d); }});
        rows.push_back({"flat punch | pressure r/a = 0.5", [&] { return mdr::pressure(mdr::flat(a, d), m, 0.5 * a); },
                        [&] { return pressure(m, F, d, 0.5 * a); }});
        for (const double r : {0.5 * a, 2. * a})
          rows.push_back({"flat punch | displacement r/a = " + std::to_string(r / a).substr(0, 4),
                          [&, r] { return mdr::displacement(mdr::flat(a, d), m, r); },
                          [&, r] { return displacement(m, F, d, r); }});
        rows.push_back({"JKR paraboloid | pressure r/a = 0.5",
                        [&] { return mdr::pressure(mdr::indentation(parab, m, a, dgamma), m, 0.5 * a); },
                        [&] { return jkr::pressure(m, P, dgamma, a, 0.5 * a); }});
        rows.push_back({"JKR paraboloid | displacement r/a = 2.0",
                        [&] { return mdr::displacement(mdr::indentation(parab, m, a, dgamma), m, 2. * a); },
                        [&] { return jkr::displacement(m, P, dgamma, a, 2. * a); }});
        for (const Control control : {Control::force, Control::displacement})
          {
            const std::string c = control == Control::force ? "force" : "displacement";
            rows.push_back({"JKR paraboloid | critical force (" + c + " control)",
                            [&, control] { return mdr::critical_state(parab, m, dgamma, control).force; },
                            [&, control] { return jkr::critical_state(m, P, dgamma, control).force; }});
            rows.push_back({"JKR power law n = 1.5 | critical force (" + c + " control)",
                            [&, control] { return mdr::critical_state(power, m, dgamma, control).force; },
                            [&, control] { return jkr::critical_state(m, W, dgamma, control).force; }});
          }
        for (const Row &row : rows)
          {
            const auto [time, value] = time_call(row.numeric, min_time);
            const double reference = row.closed();
            const double error = std::abs(value - reference) / std::abs(reference);
            std::printf("| %s | %g | %.3f | %.1e |\n", row.name.c_str(), k, time * 1e3, error);
            std::fflush(stdout);
            worst_time = std::max(worst_time, time);
            worst_error = std::max(worst_error, error);
          }
      }
    std::printf("\nworst time %.3f ms, worst relative error %.1e\n", worst_time * 1e3, worst_error);
  }

  /// Cold calls: a new k on every call, so that no Gauss-Jacobi rule is in the thread's cache (each call builds the
  /// rules it needs).
  void cold_calls()
  {
    std::printf("\n| cold call (new k each call) | time [ms] | worst relative error |\n|---|---|---|\n");
    const mdr::Profile power = mdr::power_law(n, A);
    const PowerLaw W{n, A};
    const auto cold = [&](const char *name, const auto &numeric, const auto &closed) {
      double best = 1e300, worst = 0.;
      for (int i = 0; i < 20; ++i)
        {
          const Medium m = medium(GradedHalfSpace{1e9, 1e-3, 0.3 + 1e-6 * i, 0.3});
          const auto start = std::chrono::steady_clock::now();
          const double value = numeric(m);
          best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
          worst = std::max(worst, std::abs(value / closed(m) - 1.));
        }
      std::printf("| %s | %.3f | %.1e |\n", name, best * 1e3, worst);
    };
    cold("power law n = 1.5 pressure r/a = 0.5",
         [&](const Medium &m) { return mdr::pressure(mdr::indentation(power, m, a), m, 0.5 * a); },
         [&](const Medium &m) { return pressure(m, W, a, 0.5 * a); });
    cold("power law n = 1.5 displacement r/a = 2",
         [&](const Medium &m) { return mdr::displacement(mdr::indentation(power, m, a), m, 2. * a); },
         [&](const Medium &m) { return displacement(m, W, a, 2. * a); });
    cold("JKR power law n = 1.5 critical force (force control)",
         [&](const Medium &m) { return mdr::critical_state(power, m, dgamma, Control::force).force; },
         [&](const Medium &m) { return jkr::critical_state(m, W, dgamma, Control::force).force; });
  }

  /// The edges: k -> +-1, r -> 0 and r -> a from both sides, p(0) with n + k -> 1.
  void edges(const double min_time)
  {
    std::printf("\n| edge | k | time [ms] | relative error |\n|---|---|---|---|\n");
    for (const double k : {-0.999, -0.99, 0.99, 0.999})
      {
        const Medium m = medium(GradedHalfSpace{1e9, 1e-3, k, 0.3});
        const mdr::Profile power = mdr::power_law(n, A);
        const PowerLaw W{n, A};
        std::vector<Row> rows;
        for (const double r : {1e-6 * a, 1e-3 * a, 0.5 * a, (1. - 1e-5) * a})
          rows.push_back({"power law pressure r/a = " + std::to_string(r / a),
                          [&, r] { return mdr::pressure(mdr::indentation(power, m, a), m, r); },
                          [&, r] { return pressure(m, W, a, r); }});
        for (const double r : {1e-6 * a, (1. - 1e-5) * a, (1. + 1e-10) * a, (1. + 1e-5) * a, 1e3 * a})
          rows.push_back({"power law displacement r/a = " + std::to_string(r / a),
                          [&, r] { return mdr::displacement(mdr::indentation(power, m, a), m, r); },
                          [&, r] { return displacement(m, W, a, r); }});
        for (const Row &row : rows)
          {
            const auto [time, value] = time_call(row.numeric, min_time);
            const double reference = row.closed();
            std::printf("| %s | %g | %.3f | %.1e |\n", row.name.c_str(), k, time * 1e3,
                        std::abs(value - reference) / std::abs(reference));
            std::fflush(stdout);
          }
      }
    for (const double k : {-0.5, 0.5})
      for (const double excess : {1e-1, 1e-3})
        {
          // p(0) of a tip with n + k - 1 = excess (1 + k)
          const Medium m = medium(GradedHalfSpace{1e9, 1e-3, k, 0.3});
          const double nn = (1. - k) + excess * (1. + k);
          const mdr::Profile tip = mdr::power_law(nn, 1.);
          const auto [time, value] = time_call([&] { return mdr::pressure(mdr::indentation(tip, m, a), m, 0.); }, min_time);
          const double reference = pressure(m, PowerLaw{nn, 1.}, a, 0.);
          std::printf("| p(0), n + k - 1 = %g (1 + k) | %g | %.3f | %.1e |\n", excess, k, time * 1e3,
                      std::abs(value - reference) / std::abs(reference));
        }
  }
} // namespace

int main(int argc, char **argv)
{
  double min_time = 0.05;
  bool closed = false;
  std::string references = GRADCONTACT_DATA_DIR "/references.jsonl";
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--min-time" && i + 1 < argc)
      min_time = std::atof(argv[++i]);
    else if (std::string(argv[i]) == "--closed")
      closed = true;
    else if (std::string(argv[i]) == "--references" && i + 1 < argc)
      references = argv[++i];
    else
      {
        std::fprintf(stderr, "usage: bench_mdr_speed [--closed [--references file]] [--min-time seconds]\n");
        return 2;
      }
  if (closed)
    return closed_forms(references, min_time);

  warm_calls(min_time);
  cold_calls();
  edges(min_time);
  return 0;
}
