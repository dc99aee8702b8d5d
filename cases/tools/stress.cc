#include "tools/stress.h"

#include "report/report.h"
#include "report/table.h"

#include <analytic/batch.h>
#include <analytic/reference_rows.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using json = nlohmann::json;

  namespace
  {
    /// The allowance of a row: what the rounding of its inputs justifies, plus the method's own rounding.
    ///   allowance = conditioning + floor
    /// conditioning: the `conditioning` column of the references, the relative change of the 34-digit value when
    ///   each input alone moves by half an ulp (the larger of up and down, summed over the inputs), made by
    ///   tests/data/generate_references.py from the same MDR rules as the reference. An evaluation that loses
    ///   digits beyond what the inputs justify (a cancellation of its own: p(0) with (n + k) - 1, 1 - (1 - x)^p
    ///   at small x, the loop area from a cancelling integrand) exceeds it.
    /// floor: the rounding of a well-conditioned evaluation, not a tolerance for losses: the closed forms are
    ///   10-40 operations with Boost special functions whose rounded exponents (k + 3, (1+k)/2, ...) are
    ///   amplified by log(length) at the scale variants (1e-13 = 450 eps; the worst row is in
    ///   reports/benchmarks/stability.md of `gradcontact stress`); the numerical MDR locates critical states by
    ///   central differences of its quadratures to ~1e-11 (1e-10; its worst row is the critical force of
    ///   jkr_power_law under displacement control).
    constexpr double closed_form_floor = 1e-13;
    constexpr double numerical_mdr_floor = 1e-10;

    /// Dimensions of a request entry or a quantity: (power of the modulus, power of the length).
    using Dimension = std::pair<int, int>;

    Dimension quantity_dimension(const std::string &q)
    {
      static const std::set<std::string> length = {"depth", "contact_radius", "displacement", "critical_radius",
                                                   "critical_depth", "tangential_displacement", "stick_radius",
                                                   "profile", "transition_h0"};
      static const std::set<std::string> force = {"force", "critical_force", "tangential_force", "hysteresis_force"};
      static const std::set<std::string> stress = {"pressure", "traction"};
      if (length.count(q))
        return {0, 1};
      if (force.count(q))
        return {1, 2};
      if (stress.count(q))
        return {1, 0};
      if (q == "dissipated_energy")
        return {1, 3};
      return {0, 0}; // coefficients
    }

    /// The request with every length times 2^m and every modulus times 2^j (exact in binary).
    json scaled(json q, const int j, const int m)
    {
      const auto scale = [](json &v, const int e) { v = std::ldexp(v.get<double>(), e); };
      for (const char *key : {"a", "r", "c", "d", "d0", "u0", "a_lo", "a_hi"})
        if (q.contains(key))
          scale(q[key], m);
      for (const char *key : {"F", "Fx", "FA"})
        if (q.contains(key))
          scale(q[key], j + 2 * m);
      if (q.contains("sigma_th"))
        scale(q["sigma_th"], j);
      if (q.contains("dgamma"))
        scale(q["dgamma"], j + m);
      for (const char *body : {"material", "material2"})
        if (q.contains(body))
          {
            scale(q[body]["E0"], j);
            scale(q[body]["c0"], m);
          }
      if (q.contains("geometry"))
        {
          json &g = q["geometry"];
          for (const char *key : {"R", "h0"})
            if (g.contains(key))
              scale(g[key], m);
          if (g.contains("p0"))
            scale(g["p0"], j);
          if (g.contains("A") && g.contains("n"))
            {
              // f = A r^n is a length: A ~ L^(1-n); 2^(m(1-n)) is exact only when m(1-n) is an integer,
              // otherwise the rounding of A (half an ulp) is part of the tested input.
              g["A"] = g["A"].get<double>() * std::exp2(m * (1. - g["n"].get<double>()));
            }
        }
      return q;
    }

    /// F_N, d and alpha of a tangential request's sphere (closed forms, only to classify the row).
    struct SphereScale
    {
      double force, depth, alpha;
    };

    SphereScale sphere_scale(const json &q)
    {
      json normal = {{"case", "paraboloid"}, {"material", q.at("material")}, {"geometry", q.at("geometry")},
                     {"a", q.at("a")}};
      json coefficient = {{"case", "coefficients"}, {"quantity", "alpha"}, {"material", q.at("material")}};
      if (q.contains("material2"))
        {
          normal["material2"] = q["material2"];
          coefficient["material2"] = q["material2"];
        }
      normal["quantity"] = "force";
      const double force = batch::evaluate(batch::parse(normal));
      normal["quantity"] = "depth";
      return {force, batch::evaluate(batch::parse(normal)), batch::evaluate(batch::parse(coefficient))};
    }

    /// The exponent n of a tip f = A r^n (cone 1, paraboloids 2), 0 for other cases.
    double tip_exponent(const json &q)
    {
      const std::string c = q.at("case");
      if (c == "cone")
        return 1.;
      if (c == "paraboloid" || c == "jkr_paraboloid")
        return 2.;
      if (c == "power_law" || c == "jkr_power_law")
        return q.at("geometry").at("n");
      return 0.;
    }

    /// The regions of parameter space a reference row belongs to (several, or "interior").
    std::vector<std::string> regions(const json &q)
    {
      std::vector<std::string> out;
      const json &mat = q.at("material");
      const double k = mat.at("k"), nu = mat.at("nu"), c0 = mat.at("c0");
      if (k < -0.98)
        out.push_back("k -> -1 (k < -0.98)");
      if (k > 0.98)
        out.push_back("k -> +1 (k > 0.98)");
      if (k != 0. && std::abs(k) < 1e-3)
        out.push_back(std::string("k -> 0") + (k < 0 ? "-" : "+") + " (0 < |k| < 1e-3)");
      if (k == 0.)
        out.push_back("k = 0 (classical)");
      if (nu > 0.49)
        out.push_back("nu -> 0.5 (nu > 0.49)");
      if (nu == 0.)
        out.push_back("nu = 0");
      const std::string c = q.at("case");
      if (q.contains("a"))
        {
          const double a = q.at("a");
          if (c0 / a < 1e-3)
            out.push_back("c0/a < 1e-3");
          if (c0 / a > 1e3)
            out.push_back("c0/a > 1e3");
          if (q.contains("r"))
            {
              const double r = q.at("r"), x = r / a;
              if (x < 1. && x > 1. - 1e-3)
                out.push_back("r -> a- (1 - r/a < 1e-3)");
              if (x > 1. && x < 1. + 1e-3)
                out.push_back("r -> a+ (r/a - 1 < 1e-3)");
              if (r != a && std::abs(a - r) < 1e-5 * a)
                out.push_back("r within 1e-5 of a (0 < |1 - r/a| < 1e-5)");
              if (x < 1e-3)
                out.push_back("r -> 0 (r/a < 1e-3)");
              if (x > 1e2)
                out.push_back("r -> inf (r/a > 100)");
              // p(0) ~ 1/(n + k - 1) of a tip: n + k - 1 formed with or without cancellation (class A)
              const double n = tip_exponent(q);
              const bool centre_pressure = r == 0. && n > 0. && q.at("quantity") == "pressure";
              if (centre_pressure && k != 0. && std::abs(k) < 1e-3)
                out.push_back("p(0) at tiny |k| (0 < |k| < 1e-3)");
              if (centre_pressure && (n - 1.) + k > 0. && (n - 1.) + k < 1e-3)
                out.push_back("p(0) with n + k -> 1 (0 < n + k - 1 < 1e-3)");
            }
          if (q.contains("c"))
            {
              const double cr = q.at("c");
              if (cr < a && a - cr < 1e-5 * a)
                out.push_back("c within 1e-5 of a (0 < 1 - c/a < 1e-5)");
            }
          // tangential fractions: 1 - (1 - x)^p with small x (classes B, C)
          if (c == "tangential_sphere" || c == "oscillating_sphere")
            {
              const SphereScale s = sphere_scale(q);
              const double mu = q.at("mu"), limit = mu * s.force;
              const bool loading = c == "tangential_sphere" || q.value("branch", "") == "loading";
              if (q.contains("FA") && q.at("FA").get<double>() < 1e-2 * limit)
                out.push_back("small amplitude (F_A/(mu F_N) < 1e-2)");
              double x = 1.;
              if (loading && q.contains("Fx"))
                x = q.at("Fx").get<double>() / limit;
              if (loading && q.contains("u0"))
                x = q.at("u0").get<double>() / (mu * s.alpha * s.depth);
              if (x > 0. && x < 1e-3)
                out.push_back("small x of 1 - (1 - x)^p on loading (F_x/(mu F_N), u0/(mu alpha d) < 1e-3)");
            }
        }
      if (out.empty())
        out.push_back("interior");
      return out;
    }

    struct Tally
    {
      std::size_t rows = 0, refused = 0, nonfinite = 0;
      double worst = 0;       ///< worst relative error
      double worst_ratio = 0; ///< worst error / allowance (> 1 fails)
      double worst_allowance = 0;
      std::string worst_row, refusal_example;

      void add(const double error, const double allowance, const std::string &row)
      {
        worst = std::max(worst, error);
        if (error / allowance > worst_ratio || worst_row.empty())
          {
            worst_ratio = std::max(worst_ratio, error / allowance);
            worst_allowance = allowance;
            worst_row = row;
          }
      }
    };

    struct Options
    {
      fs::path reports = "reports";
      fs::path references = fs::path(GRADCONTACT_SOURCE_DIR) / "tests/data/references.jsonl";
      std::size_t mdr_stride = 1;
    };

    Options parse(const std::vector<std::string> &args)
    {
      Options o;
      for (std::size_t i = 0; i < args.size(); ++i)
        {
          const auto value = [&](const std::string &name) {
            if (i + 1 >= args.size())
              throw std::invalid_argument("stress: " + name + " needs a value");
            return args[++i];
          };
          if (args[i] == "--reports")
            o.reports = value("--reports");
          else if (args[i] == "--references")
            o.references = value("--references");
          else if (args[i] == "--mdr-stride")
            {
              const std::string v = value("--mdr-stride");
              const long n = std::strtol(v.c_str(), nullptr, 10);
              if (n < 1 || n > 100000)
                throw std::invalid_argument("stress: --mdr-stride = " + v + " outside [1, 100000]");
              o.mdr_stride = static_cast<std::size_t>(n);
            }
          else
            throw std::invalid_argument("stress: unknown argument '" + args[i] +
                                        "' (valid: --reports DIR, --references FILE, --mdr-stride N)");
        }
      return o;
    }
  } // namespace


  namespace
  {
    /// An absolute-scale variant: the modulus times 2^j and every length times 2^m, and its label.
    struct ScaleVariant
    {
      std::string label;
      int j, m;
    };

    /// The absolute-scale variants. The references use E0 ~ 1e9 Pa and lengths ~ 1e-4 m.
    const std::vector<ScaleVariant> &scale_variants()
    {
      static const std::vector<ScaleVariant> variants = {{"as generated (E0 ~ 1e9 Pa, lengths ~ 1e-4 m)", 0, 0},
                                                         {"E0 x 2^-40 (~1e-3 Pa)", -40, 0},
                                                         {"E0 x 2^10 (~1e12 Pa)", 10, 0},
                                                         {"lengths x 2^-17 (~1e-9 m)", 0, -17},
                                                         {"lengths x 2^23 (~1e3 m)", 0, 23},
                                                         {"E0 x 2^-40, lengths x 2^-17", -40, -17},
                                                         {"E0 x 2^10, lengths x 2^23", 10, 23}};
      return variants;
    }

    /// (method, region) -> tally; the scale variants are regions of their own.
    using StressTable = std::map<std::pair<std::string, std::string>, Tally>;

    /// One reference row at every scale variant and method (the numerical MDR on every mdr_stride-th row as
    /// generated, every 10 mdr_stride-th of the variants), tallied in its regions (as generated) or its variant.
    void tally_reference_row(const Options &o, const batch::ReferenceRow &row, const std::size_t line_no,
                             StressTable &table, std::size_t &evaluated)
    {
      const double reference = row.reference;
      const double conditioning = row.conditioning;
      const std::string quantity = row.request.at("quantity");
      const Dimension dim = quantity_dimension(quantity);
      json request = row.request;
      request.erase("id");
      const std::vector<std::string> where = regions(request);
      for (const ScaleVariant &v : scale_variants())
        {
          const bool base = v.j == 0 && v.m == 0;
          for (const std::string method : {"closed_form", "numerical_mdr"})
            {
              if (method == "numerical_mdr" && line_no % (base ? o.mdr_stride : 10 * o.mdr_stride) != 0)
                continue;
              json q = scaled(request, v.j, v.m);
              q["method"] = method;
              const double expected = std::ldexp(reference, dim.first * v.j + dim.second * v.m);
              double value = 0;
              bool refused = false;
              std::string why;
              try
                {
                  value = batch::evaluate(batch::parse(q));
                }
              catch (const std::exception &e)
                {
                  why = e.what();
                  if (why.find("is not available for case") != std::string::npos)
                    continue; // the method has no path for this quantity: not a refusal
                  refused = true;
                }
              ++evaluated;
              const std::vector<std::string> keys = base ? where : std::vector<std::string>{v.label};
              for (const std::string &region : keys)
                {
                  Tally &t = table[{method == "closed_form" ? "closed form" : "numerical MDR", region}];
                  ++t.rows;
                  if (refused)
                    {
                      ++t.refused;
                      if (t.refusal_example.empty())
                        t.refusal_example = why.substr(0, 160);
                      continue;
                    }
                  if (!std::isfinite(value))
                    {
                      ++t.nonfinite;
                      continue;
                    }
                  const double err = expected == 0. ? std::abs(value) : std::abs(value / expected - 1.);
                  const double allowance =
                    conditioning + (method == "closed_form" ? closed_form_floor : numerical_mdr_floor);
                  std::ostringstream r;
                  r << "id " << row.request.at("id") << " " << row.request.at("case").get<std::string>() << "." << quantity
                    << " k=" << request["material"]["k"] << " nu=" << request["material"]["nu"];
                  t.add(err, allowance, r.str());
                }
            }
        }
    }

    /// The requests probed at k near +-1 (material set per k).
    std::vector<json> near_one_probes()
    {
      const double a = 1e-4;
      return {
        {{"case", "flat_punch"}, {"quantity", "force"}, {"a", a}, {"d", 1e-6}},
        {{"case", "flat_punch"}, {"quantity", "displacement"}, {"a", a}, {"d", 1e-6}, {"r", 1.5 * a}},
        {{"case", "paraboloid"}, {"quantity", "force"}, {"geometry", {{"R", 1e-2}}}, {"a", a}},
        {{"case", "paraboloid"}, {"quantity", "depth"}, {"geometry", {{"R", 1e-2}}}, {"a", a}},
        {{"case", "paraboloid"}, {"quantity", "pressure"}, {"geometry", {{"R", 1e-2}}}, {"a", a}, {"r", 0.5 * a}},
        {{"case", "paraboloid"}, {"quantity", "displacement"}, {"geometry", {{"R", 1e-2}}}, {"a", a}, {"r", 1.5 * a}},
        {{"case", "cone"}, {"quantity", "force"}, {"geometry", {{"tan_theta", 0.1}}}, {"a", a}},
        {{"case", "constant_pressure"}, {"quantity", "depth"}, {"geometry", {{"p0", 1e6}}}, {"a", a}},
        {{"case", "jkr_paraboloid"}, {"quantity", "critical_force"}, {"geometry", {{"R", 1e-2}}}, {"dgamma", 0.05},
         {"control", "force"}},
        {{"case", "tangential_sphere"}, {"quantity", "tangential_force"}, {"geometry", {{"R", 1e-2}}}, {"a", a},
         {"mu", 0.3}, {"c", 0.5 * a}}};
    }

    /// k closer to +-1 than the reference grid (+-0.990234375): the closed form against the numerical MDR,
    /// two independent double-precision paths (special functions vs quadrature of 9.2, 9.10-9.13).
    void tally_near_one(StressTable &table, std::size_t &evaluated)
    {
      const json material = {{"E0", 1e9}, {"c0", 1e-4}, {"nu", 0.3}};
      const std::vector<json> probes = near_one_probes();
      for (const double k : {-0.999999, -0.999, 0.999, 0.999999})
        for (json q : probes)
          {
            q["material"] = material;
            q["material"]["k"] = k;
            std::ostringstream region;
            region << "k = " << k << " (closed form vs numerical MDR)";
            Tally &t = table[{"closed form vs numerical MDR", region.str()}];
            // Conditioning: one ulp of k is a relative change eps / (1 - |k|) of 1 -+ k, which every
            // quantity inherits (exponents (1 + k)/2, (1 - k)/2, Beta functions of them): allow 10 such ulps
            // (both paths are double evaluations, neither is a reference) on top of the numerical MDR's floor.
            const double allowance =
              numerical_mdr_floor + 10 * std::numeric_limits<double>::epsilon() / (1 - std::abs(k));
            ++t.rows;
            try
              {
                q["method"] = "closed_form";
                const double closed = batch::evaluate(batch::parse(q));
                q["method"] = "numerical_mdr";
                const double numeric = batch::evaluate(batch::parse(q));
                evaluated += 2;
                if (!std::isfinite(closed) || !std::isfinite(numeric))
                  {
                    ++t.nonfinite;
                    continue;
                  }
                const double err = std::abs(closed / numeric - 1.);
                t.add(err, allowance, q["case"].get<std::string>() + "." + q["quantity"].get<std::string>());
              }
            catch (const std::exception &e)
              {
                ++t.refused;
                if (t.refusal_example.empty())
                  t.refusal_example = std::string(e.what()).substr(0, 160);
              }
          }
    }

    /// The head of stability.md: what is evaluated and what each row is held to.
    std::string stability_head(const Options &o, const std::size_t line_no)
    {
      std::ostringstream md;
      md << "# Numerical stability of the analytic module\n\n"
         << "Every row of `" << o.references.filename().string() << "` (" << line_no
         << " rows, 34-digit references of the MDR integrals from mpmath) by region of parameter space, and the same rows "
            "at other absolute scales by exact similarity (lengths and moduli times powers of two; the reference times "
            "the power of two of the quantity's dimension). Closed forms on every row; the numerical MDR on every "
         << o.mdr_stride << "th row as generated and every " << 10 * o.mdr_stride
         << "th row of the scale variants. A refusal is an explicit error that explains a limit (e.g. no critical "
            "state, gross slip, p(0) of a tip whose integrand lies below the smallest double).\n\n"
         << "Each row is held to its own allowance: its conditioning (the `conditioning` column of the references: the "
            "relative change of the 34-digit value when each input alone moves by half an ulp, summed over the inputs) "
            "plus the method's floor ("
         << format(closed_form_floor) << " closed form, " << format(numerical_mdr_floor)
         << " numerical MDR). A loss of digits beyond what the inputs justify makes error/allowance exceed 1 and fails "
            "the run. Near k = +-1 (closed form vs numerical MDR, no reference) the allowance is 10 eps / (1 - |k|) plus "
            "the numerical MDR's floor: an ulp of k changes 1 -+ k by eps / (1 - |k|) relative, which every quantity "
            "inherits.\n\n";
      return md.str();
    }

    /// The rows of every (method, region), the table of stability.md and stability.csv, into `cells`, and the
    /// refusals' examples into `md`; true when every cell is within its allowance.
    bool tabulate_stress(const StressTable &table, std::ostream &md, Table &cells)
    {
      bool ok = true;
      cells = Table({Column::both("method", "method"), Column::both("region", "region").quoted(),
                   Column::both("rows", "rows"), Column::both("refused", "refused"), Column::both("nonfinite", "NaN/inf"),
                   Column::both("worst_relative_error", "worst rel. error"),
                   Column::both("worst_error_over_allowance", "worst error/allowance (its allowance)"),
                   Column::csv_only("allowance_of_worst"), Column::both("worst_row", "row of the worst ratio").quoted(),
                   Column::csv_only("refusal_example").quoted(), Column::md_only("within allowance")});
      for (const auto &[key, t] : table)
        {
          const bool pass = t.nonfinite == 0 && t.worst_ratio <= 1.;
          ok = ok && pass;
          cells.add({key.first, key.second, t.rows, t.refused, t.nonfinite, t.worst,
                     Cell(t.worst_ratio).md_text(format(t.worst_ratio) + " (" + format(t.worst_allowance) + ")"),
                     t.worst_allowance, t.worst_row, t.refusal_example, pass ? "yes" : "**NO**"});
        }
      md << cells.md();
      md << "\nRefusals, one example per region:\n\n";
      for (const auto &[key, t] : table)
        if (!t.refusal_example.empty())
          md << "- " << key.first << ", " << key.second << ": " << t.refusal_example << "\n";
      return ok;
    }

    /// Writes stability.md and stability.csv, each under a temporary name renamed when complete.
    fs::path write_stability(const Options &o, const std::string &md, const Table &cells)
    {
      const fs::path folder = o.reports / "benchmarks";
      fs::create_directories(folder);
      remove_stale_temporaries(folder); // what a killed run left
      write_table_files(folder, "stability", cells, md);
      return folder;
    }
  } // namespace

  int stress(const std::vector<std::string> &args)
  {
    const Options o = parse(args);
    if (!fs::exists(o.references))
      throw std::invalid_argument("stress: cannot open the references '" + o.references.string() + "'");
    const auto start = std::chrono::steady_clock::now();
    StressTable table;
    std::size_t line_no = 0, evaluated = 0;
    for (const batch::ReferenceRow &row : batch::read_reference_rows(o.references.string()))
      tally_reference_row(o, row, ++line_no, table, evaluated);
    tally_near_one(table, evaluated);
    std::ostringstream md;
    md << stability_head(o, line_no);
    Table cells(std::vector<Column>{});
    const bool ok = tabulate_stress(table, md, cells);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    md << "\n" << evaluated << " evaluations in " << format(seconds) << " s.\n";
    const fs::path folder = write_stability(o, md.str(), cells);
    std::cout << "wrote " << (folder / "stability.md").string() << " (" << table.size() << " method x region cells, "
              << evaluated << " evaluations, " << format(seconds) << " s)" << (ok ? "" : ": a region FAILS its bound")
              << "\n";
    return ok ? 0 : 1;
  }
} // namespace gradcontact::cases
