#include "runners/candidate.h"

#include "runners/candidate_coulomb.h"
#include "model/fe_model.h"
#include "model/fe_adhesive.h"
#include "model/mode1_model.h"
#include "model/scene_start.h"
#include "report/table.h"


#include <analytic/material.h>
#include <analytic/mdr_contact.h>

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <optional>
#include <tuple>
#include <stdexcept>
#include <vector>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;

  std::map<std::string, double> candidate_constants(const Scene &s)
  {
    const MaterialParameters &m = s.material;
    const Medium medium_ = medium(GradedHalfSpace{m.E0, m.c0, m.k, m.nu});
    std::map<std::string, double> c{{"E0", m.E0},
                                    {"c0", m.c0},
                                    {"k", m.k},
                                    {"nu", m.nu},
                                    {"pi", 3.14159265358979323846},
                                    {"cN0", medium_.cN0},
                                    {"c_N0", medium_.cN0},
                                    {"cT0", medium_.cT0},
                                    {"c_T0", medium_.cT0},
                                    {"alpha", medium_.alpha()},
                                    {"h_N", h_N(m.k, m.nu)},
                                    {"h_T", h_T(m.k, m.nu)},
                                    {"beta", beta(m.k, m.nu)},
                                    {"C", C(m.k, m.nu)},
                                    {"dgamma", s.adhesion.work_of_adhesion},
                                    {"mu", s.friction.coefficient}};
    // name = expression, ...: each expression may use the names before it and the functions; commas inside
    // parentheses belong to a function's arguments
    std::vector<std::string> items(1);
    int depth = 0;
    for (const char ch : s.candidate.constants)
      {
        depth += (ch == '(') - (ch == ')');
        if (ch == ',' && depth == 0)
          items.emplace_back();
        else
          items.back() += ch;
      }
    for (const std::string &entry : items)
      {
        const std::string item = dealii::Utilities::trim(entry);
        if (item.empty())
          continue;
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
          throw std::invalid_argument("Candidate/constants: '" + item + "' is not name = expression");
        const std::string name = dealii::Utilities::trim(item.substr(0, eq));
        if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') ||
            !std::all_of(name.begin(), name.end(),
                         [](const char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }))
          throw std::invalid_argument("Candidate/constants: '" + name +
                                      "' is no name (a letter or '_', then letters, digits or '_')");
        try
          {
            c[name] = Expression(item.substr(eq + 1), {}, c).value(std::vector<double>{});
          }
        catch (const std::exception &e)
          {
            throw std::invalid_argument("Candidate/constants: " + name + " = '" +
                                        dealii::Utilities::trim(item.substr(eq + 1)) + "': " + e.what());
          }
      }
    return c;
  }



  template <int dim>
  CandidateFunction<dim>::CandidateFunction(const std::string &entry, const std::vector<std::string> &variables,
                                            const std::string &expression,
                                            const std::map<std::string, double> &constants)
    : entry(entry)
    , expression(expression, variables, constants)
  {
    if (variables.size() != dim)
      throw std::logic_error("CandidateFunction<" + std::to_string(dim) + ">: " + std::to_string(variables.size()) +
                             " variables");
  }

  template <int dim>
  double CandidateFunction<dim>::value(const dealii::Point<dim> &p) const
  {
    double x[dim];
    for (unsigned int d = 0; d < dim; ++d)
      x[d] = p[d];
    try
      {
        return expression.value(x);
      }
    catch (const std::domain_error &e)
      {
        throw std::domain_error("Candidate/" + entry + " = " + e.what());
      }
  }

  template <int dim>
  std::shared_ptr<const CandidateFunction<dim>> parse_candidate_expression(const std::string &entry,
                                                                          const std::string &variables,
                                                                          const std::string &expression,
                                                                          const std::map<std::string, double> &constants)
  {
    std::vector<std::string> names;
    for (const std::string &name : dealii::Utilities::split_string_list(variables))
      names.push_back(name);
    try
      {
        return std::make_shared<const CandidateFunction<dim>>(entry, names, expression, constants);
      }
    catch (const ExpressionError &e)
      {
        throw std::invalid_argument("Candidate/" + entry + " = '" + expression + "' (variables " + variables +
                                    "): " + e.what());
      }
  }

  template class CandidateFunction<1>;
  template class CandidateFunction<2>;
  template class CandidateFunction<3>;
  template std::shared_ptr<const CandidateFunction<1>>
  parse_candidate_expression<1>(const std::string &, const std::string &, const std::string &,
                                const std::map<std::string, double> &);
  template std::shared_ptr<const CandidateFunction<2>>
  parse_candidate_expression<2>(const std::string &, const std::string &, const std::string &,
                                const std::map<std::string, double> &);
  template std::shared_ptr<const CandidateFunction<3>>
  parse_candidate_expression<3>(const std::string &, const std::string &, const std::string &,
                                const std::map<std::string, double> &);



  mdr::Profile candidate_profile(const Scene &s, const std::map<std::string, double> &constants)
  {
    const CandidateParameters &c = s.candidate;
    const auto at = [](const CandidateFunction<1> &g, const double r) { return g.value(dealii::Point<1>(r)); };
    const auto f  = parse_candidate_expression<1>("profile", "r", c.profile, constants);
    mdr::Profile profile;
    profile.f = [f, at](const double r) { return at(*f, r); };
    if (!c.slope.empty())
      {
        const auto g = parse_candidate_expression<1>("profile slope", "r", c.slope, constants);
        profile.df   = [g, at](const double r) { return at(*g, r); };
      }
    else
      profile.df = [f, at](const double r) {
        const double h = 1e-3 * std::max(r, 1e-300);
        return (8. * (at(*f, r + h) - at(*f, r - h)) - (at(*f, r + 2 * h) - at(*f, r - 2 * h))) / (12. * h);
      };
    if (!c.curvature.empty())
      {
        const auto g  = parse_candidate_expression<1>("profile curvature", "r", c.curvature, constants);
        profile.d2f   = [g, at](const double r) { return at(*g, r); };
      }
    return profile;
  }



  namespace
  {
    /// One candidate curve: the candidate and its reference at the points x of the varied quantity.
    struct Curve
    {
      std::string quantity;  ///< "adhesive force", as in the Candidate entry
      std::string variable;  ///< the varied quantity as the table names it: "a [m]", "c / a", ...
      std::string unit;      ///< of the values, for the plot's axis
      std::vector<double> x; ///< the varied quantity
      std::function<double(std::size_t)> candidate, reference; ///< at point i
      /// The scale of the deviation: false: |reference| at the point; true: max |reference| over the curve (the
      /// adhesive branch's d(a) and F(a), and the branches of a loop, pass through zero).
      bool relative_to_largest = false;
    };

    /// FE values of the candidate's quantities at points of their curves: quantity -> x -> value.
    using FeValues = std::map<std::string, std::map<double, double>>;

    double elapsed(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// The rows of a curve (one per point), its table and plot in `folder` (with the FE values `fe` of its quantity
    /// where there are any), and the sentence naming its largest deviation (empty when no point was evaluated).
    std::string report_curve(const Curve &curve, const double tolerance, const bool plots, const fs::path &folder,
                             const FeValues &fe_values, std::vector<Row> &rows)
    {
      static const std::map<double, double> none;
      const auto found = fe_values.find(curve.quantity);
      const std::map<double, double> &fe = found == fe_values.end() ? none : found->second;
      const std::size_t n = curve.x.size();
      std::vector<double> candidate(n, std::numeric_limits<double>::quiet_NaN()), reference(candidate);
      std::vector<double> seconds(n, 0.);
      std::vector<std::string> errors(n);
      for (std::size_t i = 0; i < n; ++i)
        try
          {
            reference[i] = curve.reference(i);
            const auto start = std::chrono::steady_clock::now();
            candidate[i]     = curve.candidate(i);
            seconds[i]       = elapsed(start);
          }
        catch (const std::exception &e)
          {
            errors[i] = concise(e);
          }
      double largest = 0.;
      for (const double r : reference)
        if (std::isfinite(r))
          largest = std::max(largest, std::abs(r));

      const std::string stem = "candidate_" + dealii::Utilities::replace_in_string(curve.quantity, " ", "_");
      Table table({Column::csv_only(csv_quote(curve.variable)), Column::csv_only("candidate"),
                   Column::csv_only("numerical MDR"), Column::csv_only("deviation"), Column::csv_only("FE")},
                  Number{'g', 16});
      double worst = -1., worst_x = 0.;
      for (std::size_t i = 0; i < n; ++i)
        {
          const std::string metric = curve.variable + " = " + format(curve.x[i]) +
                                     (curve.relative_to_largest ? ", rel. to the largest |MDR| of the curve" :
                                                                  ", relative");
          if (!errors[i].empty())
            {
              rows.push_back(failed(curve.quantity, "candidate", "numerical MDR", errors[i]));
              rows.back().metric = metric;
              continue;
            }
          const double scale = curve.relative_to_largest ? largest : reference[i];
          rows.push_back(compare(curve.quantity, metric, "candidate", "numerical MDR", reference[i], candidate[i],
                                 scale, tolerance, 0, seconds[i]));
          const double deviation = rows.back().rel_error;
          const auto at = fe.find(curve.x[i]);
          table.add({curve.x[i], candidate[i], reference[i], deviation, at != fe.end() ? Cell(at->second) : Cell()});
          if (!(deviation <= worst))
            worst = deviation, worst_x = curve.x[i];
        }
      write_table_csv(folder, stem, table);
      if (plots)
        {
          Series mdr_series{"numerical MDR", curve.x, reference, false, true};
          Series candidate_series{"candidate", curve.x, candidate, true, false};
          std::vector<Series> series{mdr_series, candidate_series};
          if (!fe.empty())
            {
              Series fe_series{"FE", {}, {}, true, false};
              for (const auto &[x, y] : fe)
                fe_series.x.push_back(x), fe_series.y.push_back(y);
              series.push_back(fe_series);
            }
          write_plot(folder, stem,
                     "Candidate " + curve.quantity + " against the numerical MDR" + (fe.empty() ? "" : " and the FE"),
                     curve.variable, curve.quantity + " " + curve.unit, series);
        }
      if (worst < 0.)
        return "";
      return "largest deviation of the " + curve.quantity + ": " + format(worst) + " at " + curve.variable + " = " +
             format(worst_x) + " (tolerance " + format(tolerance) + ")";
    }

    /// x_i = lo + (hi - lo) i / (n - 1).
    std::vector<double> spaced(const double lo, const double hi, const unsigned int n)
    {
      std::vector<double> x(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = lo + (hi - lo) * i / (n - 1);
      return x;
    }

    /// The fractions (i + 1) / (n + 1), i < n, of an open interval (0, 1): stick radii c / a, forces F_x / (mu F_N)
    /// and amplitudes F_A / (mu F_N) short of gross slip.
    std::vector<double> fractions(const unsigned int n)
    {
      std::vector<double> x(n);
      for (unsigned int i = 0; i < n; ++i)
        x[i] = double(i + 1) / (n + 1);
      return x;
    }

    /// A scalar candidate (an expression without variables) against its reference.
    void scalar_row(const std::string &quantity, const std::string &expression,
                    const std::map<std::string, double> &constants, const std::function<double()> &reference,
                    const double tolerance, std::vector<Row> &rows)
    {
      if (expression.empty())
        return;
      try
        {
          const double ref   = reference();
          const auto   start = std::chrono::steady_clock::now();
          const double value = parse_candidate_expression<1>(quantity, "x", expression, constants)->value(
            dealii::Point<1>(0.));
          rows.push_back(compare(quantity, "relative", "candidate", "numerical MDR", ref, value, ref, tolerance, 0,
                                 elapsed(start)));
        }
      catch (const std::exception &e)
        {
          rows.push_back(failed(quantity, "candidate", "numerical MDR", concise(e)));
        }
    }

    void add_note(SceneResult &result, const std::string &note)
    {
      if (!note.empty())
        result.description += (result.description.empty() ? "" : "; ") + note;
    }

    /// Candidate/critical control as the analytic control.
    Control control_of(const bool force_control)
    {
      return force_control ? Control::force : Control::displacement;
    }

    /// An adhesive FE state as the family's rows compare it, and what it cost.
    struct FeAdhesiveState
    {
      double       radius = 0, depth = 0, force = 0;
      unsigned int dofs    = 0;
      double       seconds = 0;
    };

    /// The adhesive family against one adhesive FE model: d(a) and F(a) at the ends and the middle of the range
    /// (`state(a)`) and the critical state under Candidate/critical control (`critical(force_control)`). Each row is
    /// against `method` with Tolerances/* (it includes the FE's own error) and `suffix` ends its metric; the FE's
    /// d(a), F(a) go into `fe` when it is given (the curves' plots).
    void adhesive_model_rows(const Scene &s, const std::string &method, const std::string &suffix,
                             const std::function<FeAdhesiveState(double)> &state,
                             const std::function<FeAdhesiveState(bool)> &critical, const std::vector<double> &radii,
                             const std::map<std::string, double> &constants, std::vector<Row> &rows, FeValues *fe)
    {
      const CandidateParameters &c   = s.candidate;
      const auto                 row = [&](const std::string &quantity, const std::string &metric,
                           const std::string &expression, const double x, const double fe_value,
                           const double tolerance, const FeAdhesiveState &st) {
        if (expression.empty())
          return;
        try
          {
            const double value =
              parse_candidate_expression<1>(quantity, "a", expression, constants)->value(dealii::Point<1>(x));
            rows.push_back(compare(quantity, metric + suffix, "candidate", method, fe_value, value, fe_value,
                                   tolerance, st.dofs, st.seconds));
          }
        catch (const std::exception &e)
          {
            rows.push_back(failed(quantity, "candidate", method, concise(e)));
          }
      };
      for (const std::size_t i : {std::size_t(0), radii.size() / 2, radii.size() - 1})
        {
          if (c.adhesive_depth.empty() && c.adhesive_force.empty())
            break;
          try
            {
              const FeAdhesiveState st     = state(radii[i]);
              const std::string     metric = "a [m] = " + format(radii[i]) + ", relative";
              row("adhesive depth", metric, c.adhesive_depth, radii[i], st.depth, s.tolerances.depth, st);
              row("adhesive force", metric, c.adhesive_force, radii[i], st.force, s.tolerances.force, st);
              if (fe)
                {
                  (*fe)["adhesive depth"][radii[i]] = st.depth;
                  (*fe)["adhesive force"][radii[i]] = st.force;
                }
            }
          catch (const std::exception &e)
            {
              rows.push_back(failed("adhesive state", "candidate", method, concise(e)));
            }
        }
      if (c.critical_radius.empty() && c.critical_force.empty() && c.critical_depth.empty())
        return;
      const std::string under = c.critical_force_control ? " (force control)" : " (displacement control)";
      try
        {
          const FeAdhesiveState st = critical(c.critical_force_control);
          row("critical radius" + under, "relative", c.critical_radius, 0, st.radius, s.tolerances.contact_radius, st);
          row("critical force" + under, "relative", c.critical_force, 0, st.force, s.tolerances.force, st);
          row("critical depth" + under, "relative", c.critical_depth, 0, st.depth, s.tolerances.depth, st);
        }
      catch (const std::exception &e)
        {
          rows.push_back(failed("critical state" + under, "candidate", method, concise(e)));
        }
    }

    /// The adhesive pressure candidate against the JKR FE's own p(r) at Load/a (p_n - delta p_1 with the FE's
    /// pull-back delta(a), 9.53 for the paraboloid) at Outputs/pressure radii, relative to the largest |p| among them
    /// (the pressure is tensile and singular at the edge); Tolerances/pressure.
    void adhesive_pressure_fe_rows(const Scene &s, AdhesiveModel &model,
                                   const std::map<std::string, double> &constants, std::vector<Row> &rows,
                                   FeValues &fe)
    {
      const CandidateParameters &c = s.candidate;
      const std::vector<double> &x = s.outputs.pressure_radii;
      const double               a = s.load.a;
      if (c.adhesive_pressure.empty() || x.empty())
        return;
      try
        {
          const auto          start = std::chrono::steady_clock::now();
          std::vector<double> r;
          for (const double xi : x)
            r.push_back(xi * a);
          const std::vector<fem::Sample> p = model.surface(a, r, {}).pressure;
          const double seconds = elapsed(start);
          const double largest = largest_magnitude(p);
          const auto g = parse_candidate_expression<2>("adhesive pressure", "r,a", c.adhesive_pressure, constants);
          for (std::size_t i = 0; i < p.size(); ++i)
            {
              fe["adhesive pressure"][x[i]] = p[i].value;
              try
                {
                  const double value = g->value(dealii::Point<2>(p[i].r, a));
                  rows.push_back(compare("adhesive pressure", "r/a = " + format(x[i]) + ", rel. to the largest |p|",
                                         "candidate", "FE", p[i].value, value, largest, s.tolerances.pressure, 0,
                                         seconds));
                }
              catch (const std::exception &e)
                {
                  rows.push_back(failed("adhesive pressure", "candidate", "FE", concise(e)));
                }
            }
        }
      catch (const std::exception &e)
        {
          rows.push_back(failed("adhesive pressure", "candidate", "FE", concise(e)));
        }
    }

    /// The adhesive family against the JKR FE of fem/adhesion/adhesion.h (the FE's own energy release rate and critical
    /// search; the profile a rigid custom indenter).
    void adhesive_fe_rows(const Scene &s, const mdr::Profile &profile, const std::vector<double> &radii,
                          const std::map<std::string, double> &constants, std::vector<Row> &rows, FeValues &fe)
    {
      AdhesiveModel model(s, candidate_indenter(profile));
      const auto    state = [&](const double a) {
        const auto          start = std::chrono::steady_clock::now();
        const AdhesivePoint st    = model.state(a);
        return FeAdhesiveState{st.radius, st.depth, st.force, 0, elapsed(start)};
      };
      const auto critical = [&](const bool force_control) {
        const auto          start = std::chrono::steady_clock::now();
        const AdhesivePoint st    = model.critical_state(control_of(force_control), s.load.a).state;
        return FeAdhesiveState{st.radius, st.depth, st.force, 0, elapsed(start)};
      };
      adhesive_model_rows(s, "FE", "", state, critical, radii, constants, rows, &fe);
      adhesive_pressure_fe_rows(s, model, constants, rows, fe);
    }

    /// Adhesion/law = Dugdale: the adhesive family against the cohesive-zone FE of fem/adhesion/cohesive_zone.h (adhesion of
    /// the finite range dgamma / sigma_0; no JKR assumption): how far the candidate's JKR-type form is from that
    /// adhesive. Its rows say "(JKR idealisation)": a deviation there measures the JKR assumption, not the
    /// candidate's algebra.
    void dugdale_fe_rows(const Scene &s, const mdr::Profile &profile, const std::vector<double> &radii,
                         const std::map<std::string, double> &constants, std::vector<Row> &rows)
    {
      DugdaleModel model(s, candidate_indenter(profile));
      const auto   state = [&](const double a) {
        const CohesivePoint st = model.state(a);
        return FeAdhesiveState{st.radius, st.depth, st.force, st.n_dofs, st.seconds};
      };
      const auto critical = [&](const bool force_control) {
        const CohesiveCriticalPoint c = model.critical_state(control_of(force_control), s.load.a);
        return FeAdhesiveState{c.state.radius, c.state.depth, c.state.force, c.max_dofs, c.seconds};
      };
      adhesive_model_rows(s, "FE (Dugdale)", " (JKR idealisation)", state, critical, radii, constants, rows, nullptr);
    }

    /// Adhesion/law = Lennard-Jones: the adhesive family against the smooth Lennard-Jones FE of fem/adhesion/smooth_cohesion.h
    /// (repulsion included, its largest attraction Adhesion/cohesive strength): one path from the surfaces apart
    /// through snap-in and both pull-offs to the force of the largest radius of the range. Its rows say "(JKR
    /// idealisation)": a deviation there measures the JKR assumption against a finite-range adhesive.
    void lennard_jones_fe_rows(const Scene &s, const mdr::Profile &profile, const Medium &m,
                               const std::vector<double> &radii, const std::map<std::string, double> &constants,
                               std::vector<Row> &rows)
    {
      const double dgamma = s.adhesion.work_of_adhesion;
      // past the largest radius of the range: its JKR force, and a margin for the finite range's lower force
      const double stop_force = std::max(0., 1.1 * mdr::force(mdr::indentation(profile, m, radii.back(), dgamma), m));
      const double a_c        = mdr::critical_state(profile, m, dgamma, Control::force).radius;
      const std::string       method = "FE (Lennard-Jones)";
      const LennardJonesTrace trace  = trace_lennard_jones(s, candidate_indenter(profile), a_c, stop_force);
      if (!trace.failure.empty())
        {
          rows.push_back(failed("Lennard-Jones path", "candidate", method, trace.failure));
          return;
        }
      const auto of_trace = [&trace](const AdhesivePoint &p) {
        return FeAdhesiveState{p.radius, p.depth, p.force, trace.n_dofs(), trace.seconds()};
      };
      const auto state    = [&](const double a) { return of_trace(trace.state(a)); };
      const auto critical = [&](const bool force_control) { return of_trace(trace.pull_off(control_of(force_control))); };
      adhesive_model_rows(s, method, " (JKR idealisation)", state, critical, radii, constants, rows, nullptr);
    }

    /// The mode-1 FE's loading states under the theory's traction tau = mu [p(r; a) - p(r; rho)] of stick radius rho
    /// (9.77), each solved once: the branches and the dissipated energy of the oscillation are sums of them, since
    /// the FE is linear (Ciavarella-Jaeger, 9.81-9.84).
    class LoadingStates
    {
    public:
      LoadingStates(const mdr::PartialSlip &slip, Mode1Model &model, const double a)
        : slip(slip), model(model), a(a)
      {}
      /// u0 (the mean u_x over the stick zone) and the DoFs of the loading to stick radius rho.
      const fem::TangentialResult &at(const double rho)
      {
        auto found = states.find(rho);
        if (found == states.end())
          {
            const auto start = std::chrono::steady_clock::now();
            const mdr::PartialSlip &theory = slip;
            found = states
                      .emplace(rho, model.traction([&theory, rho](const double r) { return theory.traction(rho, r); },
                                                   a, rho, {rho}))
                      .first;
            spent += elapsed(start);
          }
        return found->second;
      }
      double seconds() const { return spent; }

    private:
      const mdr::PartialSlip                   &slip;
      Mode1Model                               &model;
      const double                              a;
      std::map<double, fem::TangentialResult>   states;
      double                                    spent = 0;
    };

    /// The stick radii at which the mode-1 FE's loading states give the loop of the oscillation +-FA, FA =
    /// Tangential/amplitude mu F_N(a). With G(c) the u0 of the loading to stick radius c, whose force is
    /// t(c) = mu [F_N(a) - F_N(c)] (9.78), the unloading branch is G(c_A) - 2 G(b) at F_x = FA - 2 t(b) and the
    /// reloading one its mirror (Ciavarella-Jaeger, 9.81-9.84), so the loop's area is
    ///   W = 2 int_{-FA}^{FA} u0_unloading dF_x = 4 FA G(c_A) - 8 int_0^FA G dt
    ///     = 4 FA G(c_A) - 8 int_{c_A}^a G(c) mu F_N'(c) dc
    /// (Masing's rule). In c the integrand is smooth up to gross slip, where in t it is not; the rule is the smallest
    /// n-point Gauss-Legendre rule on [c_A, a], 2 <= n <= 8, whose W on the numerical MDR's G meets a tenth of
    /// Tolerances/force against the MDR's own W (PartialSlip::dissipated_energy, a non-cancelling integral). Its
    /// nodes are also the points of the branches' rows, so the loop and its energy share the FE's solves.
    struct LoopRule
    {
      double              FA = 0, c_A = 0;
      std::vector<double> radii, weights; ///< nodes b in (c_A, a); weights of int_0^FA G dt (mu F_N'(b) included)
      unsigned int        n = 0;
      double              error = 0;      ///< of the rule's W on the MDR, relative

      LoopRule(const Scene &s, const mdr::PartialSlip &slip)
      {
        const double a = s.load.a;
        FA             = s.tangential.amplitude * s.friction.coefficient * slip.normal_force(a);
        c_A            = slip.stick_radius(FA);
        const double exact = slip.dissipated_energy(FA);
        for (n = 2;; ++n)
          {
            const dealii::QGauss<1> gauss(n);
            radii.assign(n, 0.), weights.assign(n, 0.);
            for (unsigned int q = 0; q < n; ++q)
              {
                radii[q]   = c_A + (a - c_A) * gauss.point(q)[0];
                weights[q] = (a - c_A) * gauss.weight(q) * s.friction.coefficient *
                             slip.normal_force_slope(radii[q]);
              }
            error = energy([&](const double c) { return slip.tangential_displacement(c); }) / exact - 1;
            if (n == 8 || std::abs(error) <= 0.1 * s.tolerances.force)
              break;
          }
      }
      /// W of the rule from G(c).
      double energy(const std::function<double(double)> &G) const
      {
        double integral = 0;
        for (unsigned int q = 0; q < n; ++q)
          integral += weights[q] * G(radii[q]);
        return 4 * FA * G(c_A) - 8 * integral;
      }
      /// How much the rule's cancellation magnifies a relative error of G: sum |terms| / |W|, on G of the MDR.
      double magnification(const mdr::PartialSlip &slip) const
      {
        double terms = 4 * FA * std::abs(slip.tangential_displacement(c_A));
        for (unsigned int q = 0; q < n; ++q)
          terms += 8 * std::abs(weights[q] * slip.tangential_displacement(radii[q]));
        return terms / std::abs(energy([&](const double c) { return slip.tangential_displacement(c); }));
      }
    };

    /// The branches of the loop between +-FA on the mode-1 FE at the rule's nodes b, F_x = +-(FA - 2 t(b)): u0 =
    /// G(c_A) - 2 G(b) of the FE's loading states (each u0 the mean u_x over its stick zone, which contains the zone
    /// that never slipped), the FE being linear. Tolerances/displacement, relative to u0(FA).
    void loop_fe_rows(const Scene &s, const mdr::PartialSlip &slip, const LoopRule &rule, LoadingStates &loading,
                      const std::map<std::string, double> &constants, std::vector<Row> &rows, FeValues &fe)
    {
      const CandidateParameters &c       = s.candidate;
      const double               a       = s.load.a, FA = rule.FA;
      const double               largest = slip.tangential_displacement(rule.c_A);
      for (const auto &[quantity, expression, branch] :
           {std::tuple<std::string, std::string, Branch>{"unloading displacement", c.unloading_displacement,
                                                         Branch::unloading},
            {"reloading displacement", c.reloading_displacement, Branch::reloading}})
        {
          if (expression.empty())
            continue;
          const auto   g    = parse_candidate_expression<3>(quantity, "Fx,FA,a", expression, constants);
          const double sign = branch == Branch::unloading ? 1 : -1; // the reloading loop is the mirror image
          for (const double b : rule.radii)
            {
              const double Fx = sign * (FA - 2 * slip.tangential_force(b));
              const fem::TangentialResult &A = loading.at(rule.c_A), &B = loading.at(b);
              const double                 u = sign * (A.displacement - 2 * B.displacement);
              rows.push_back(compare(quantity, "Fx / FA = " + format(Fx / FA) + ", rel. to u0(FA)", "candidate",
                                     "FE (mode 1)", u, g->value(dealii::Point<3>(Fx, FA, a)), largest,
                                     s.tolerances.displacement, B.n_dofs, loading.seconds()));
              fe[quantity][Fx / FA] = u;
            }
        }
    }

    /// The dissipated energy of the oscillation +-FA on the mode-1 FE: the rule's W on the FE's G. W is a difference
    /// of u0 values, so its tolerance is Tolerances/displacement (the u0's) times the rule's magnification of a
    /// relative error of G. The row names the rule, its error on the MDR and the magnification.
    void energy_fe_rows(const Scene &s, const mdr::PartialSlip &slip, const LoopRule &rule, LoadingStates &loading,
                        const std::map<std::string, double> &constants, std::vector<Row> &rows, FeValues &fe)
    {
      unsigned int dofs  = 0;
      const double value = rule.energy([&](const double c) {
        const fem::TangentialResult &r = loading.at(c);
        dofs                           = r.n_dofs;
        return r.displacement;
      });
      const double candidate = parse_candidate_expression<2>("dissipated energy", "FA,a", s.candidate.dissipated_energy,
                                                             constants)->value(dealii::Point<2>(rule.FA, s.load.a));
      const double magnification = rule.magnification(slip);
      rows.push_back(compare("dissipated energy",
                             "FA / (mu F_N) = " + format(s.tangential.amplitude) + ", relative (" +
                               std::to_string(rule.n) + "-point Gauss rule in the stick radius over the FE's "
                               "loading states, its error on the MDR " + format(rule.error) + "; tolerance " +
                               format(magnification) + " x that of u0, the rule's cancellation)",
                             "candidate", "FE (mode 1)", value, candidate, value,
                             magnification * s.tolerances.displacement, dofs, loading.seconds()));
      fe["dissipated energy"][s.tangential.amplitude] = value;
    }

    /// The tangential family against the Fourier mode-1 FE model (fem/tangential/fourier_mode1_solver.h) at Load/a, the
    /// scene's mesh at its finest refinement, refined toward the stick radii: K_T from the tangential flat punch, and
    /// at three stick radii the FE under the theory's traction tau = mu [p(r; a) - p(r; c)] (9.77, p from the
    /// numerical MDR): u0 as the mean u_x over the stick zone (the FE's own), F_x as the traction's integral (the
    /// theory's load, integrated on the FE's surface). Tolerances/force and displacement.
    void tangential_fe_rows(const Scene &s, const mdr::PartialSlip *slip, const std::vector<double> &fractions_c,
                            const std::map<std::string, double> &constants, std::vector<Row> &rows, FeValues &fe)
    {
      const CandidateParameters &c = s.candidate;
      const double               a = s.load.a;
      std::vector<double>        stick;
      std::map<double, double>   fraction_of; ///< the curve's c / a of a stick radius (its x, not c / a rounded)
      if (slip && !fractions_c.empty())
        for (const std::size_t i : {std::size_t(0), fractions_c.size() / 2, fractions_c.size() - 1})
          {
            stick.push_back(fractions_c[i] * a);
            fraction_of[stick.back()] = fractions_c[i];
          }
      const bool of_c = slip && (!c.tangential_force.empty() || !c.tangential_displacement.empty());
      const bool loop = slip && (!c.unloading_displacement.empty() || !c.reloading_displacement.empty() ||
                                 !c.dissipated_energy.empty());
      if (c.tangential_stiffness.empty() && !of_c && !loop)
        return;
      const auto start = std::chrono::steady_clock::now();
      const auto row   = [&](const std::string &quantity, const std::string &metric, const double value,
                           const double fe_value, const double tolerance, const unsigned int dofs) {
        rows.push_back(compare(quantity, metric, "candidate", "FE (mode 1)", fe_value, value, fe_value, tolerance, dofs,
                               elapsed(start)));
      };
      try
        {
          Mode1Model model(s, stick);
          if (!c.tangential_stiffness.empty())
            {
              const fem::TangentialResult r = model.flat_punch(1e-3 * a);
              const double value = parse_candidate_expression<1>("tangential stiffness", "a", c.tangential_stiffness,
                                                                 constants)->value(dealii::Point<1>(a));
              row("tangential stiffness", "a [m] = " + format(a) + ", relative", value, r.stiffness,
                  s.tolerances.force, r.n_dofs);
              fe["tangential stiffness"][a] = r.stiffness;
            }
          for (const double cc : of_c ? stick : std::vector<double>{})
            {
              // tau(r) = mu [p(r; a) - p(r; c)] as PartialSlip::traction forms it: one integral over [c, a] (9.12).
              const fem::TangentialResult r =
                model.traction([slip, cc](const double rr) { return slip->traction(cc, rr); }, a, cc, {cc});
              const std::string metric = "c / a = " + format(cc / a) + ", relative";
              const dealii::Point<2> at(cc, a);
              if (!c.tangential_force.empty())
                row("tangential force", metric,
                    parse_candidate_expression<2>("tangential force", "c,a", c.tangential_force, constants)->value(at),
                    r.force, s.tolerances.force, r.n_dofs);
              if (!c.tangential_displacement.empty())
                row("tangential displacement", metric,
                    parse_candidate_expression<2>("tangential displacement", "c,a", c.tangential_displacement,
                                                  constants)->value(at),
                    r.displacement, s.tolerances.displacement, r.n_dofs);
              fe["tangential force"][fraction_of.at(cc)]        = r.force;
              fe["tangential displacement"][fraction_of.at(cc)] = r.displacement;
            }
          if (loop)
            {
              LoadingStates  loading(*slip, model, a);
              const LoopRule rule(s, *slip);
              loop_fe_rows(s, *slip, rule, loading, constants, rows, fe);
              if (!c.dissipated_energy.empty())
                energy_fe_rows(s, *slip, rule, loading, constants, rows, fe);
            }
        }
      catch (const std::exception &e)
        {
          rows.push_back(failed("tangential FE", "candidate", "FE (mode 1)", concise(e)));
        }
    }

    /// The numerical MDR's d(a) and F_N(a) at each radius of a curve (9.10, 9.11; with dgamma > 0 the adhesive
    /// foundation of 9.46), one indentation per radius for both; a radius where it fails keeps its error, which the
    /// curves' rows report at that point.
    struct IndentationStates
    {
      std::vector<double>             radii, depth, force;
      std::vector<std::exception_ptr> error;
      double                          dgamma = 0;

      IndentationStates(const std::vector<double> &radii, const mdr::Profile &profile, const Medium &m,
                        const double dgamma)
        : radii(radii)
        , depth(radii.size())
        , force(radii.size())
        , error(radii.size())
        , dgamma(dgamma)
      {
        for (std::size_t i = 0; i < radii.size(); ++i)
          try
            {
              const mdr::Foundation w1d = mdr::indentation(profile, m, radii[i], dgamma);
              depth[i]                  = mdr::depth(w1d);
              force[i]                  = mdr::force(w1d, m);
            }
          catch (...)
            {
              error[i] = std::current_exception();
            }
      }

      double at(const std::size_t i, const bool of_force) const
      {
        if (error[i])
          std::rethrow_exception(error[i]);
        return of_force ? force[i] : depth[i];
      }
    };

    /// A candidate's d(a) or F_N(a) against the numerical MDR's at the states' radii: a row per radius, a table and a
    /// plot, the largest deviation noted. The adhesive branch passes through F = 0, so its deviations are relative to
    /// the curve's largest |MDR|.
    void indentation_curve(const std::string &quantity, const std::string &expression, const bool force,
                           const IndentationStates &states, const std::map<std::string, double> &constants,
                           const Scene &s, const FeValues &fe, const fs::path &folder, SceneResult &result)
    {
      if (expression.empty())
        return;
      const auto g = parse_candidate_expression<1>(quantity, "a", expression, constants);
      Curve      curve{quantity, "a [m]", force ? "[N]" : "[m]", states.radii,
                  [&, g](const std::size_t i) { return g->value(dealii::Point<1>(states.radii[i])); },
                  [&](const std::size_t i) { return states.at(i, force); },
                  states.dgamma > 0};
      add_note(result, report_curve(curve, s.candidate.tolerance, s.outputs.plots, folder, fe, result.rows));
    }

    Medium scene_medium(const Scene &s)
    {
      const MaterialParameters &m = s.material;
      return medium(GradedHalfSpace{m.E0, m.c0, m.k, m.nu});
    }
  } // namespace



  void normal_candidate_curves(const Scene &s, const std::map<std::string, double> &constants,
                               const mdr::Profile &profile, const std::map<std::string, double> &fe_at_a,
                               const fs::path &folder, SceneResult &result)
  {
    const CandidateParameters &c = s.candidate;
    const Medium               m = scene_medium(s);
    const double               a = s.load.a;
    std::vector<double>        radii = spaced(c.range[0] * a, c.range[1] * a, c.points);
    radii.push_back(a); // the FE's radius is a point of every curve
    std::sort(radii.begin(), radii.end());
    radii.erase(std::unique(radii.begin(), radii.end(),
                            [](const double x, const double y) { return std::abs(x - y) <= 1e-12 * std::abs(y); }),
                radii.end());
    FeValues fe;
    for (const auto &[quantity, value] : fe_at_a)
      fe[quantity][a] = value;
    const IndentationStates states(radii, profile, m, 0.);
    indentation_curve("depth", c.depth, false, states, constants, s, fe, folder, result);
    indentation_curve("force", c.force, true, states, constants, s, fe, folder, result);
    // A profile whose indentation pulls (a sign slip in its constants) has no non-adhesive contact to check.
    for (std::size_t i = 0; i < radii.size(); ++i)
      if (!states.error[i] && states.force[i] < 0)
        {
          result.rows.push_back(failed("contact state", "candidate", "numerical MDR",
                                       "the profile gives a tensile contact, F_N(a) = " + format(states.force[i]) +
                                         " < 0 at a = " + format(radii[i]) + " m, which frictionless contact "
                                         "without adhesion cannot hold: check the signs of the profile's constants"));
          break;
        }
  }

  void normal_profile_curves(const Scene &s, const std::map<std::string, double> &constants,
                             const mdr::Profile &profile, const std::map<std::string, std::map<double, double>> &fe,
                             const fs::path &folder, SceneResult &result)
  {
    const CandidateParameters &c   = s.candidate;
    const Medium               m   = scene_medium(s);
    const double               a   = s.load.a;
    const mdr::Foundation      w1d = mdr::indentation(profile, m, a);
    const auto curve = [&](const std::string &quantity, const std::string &expression, const std::vector<double> &x,
                           const std::string &unit, const std::function<double(double)> &reference) {
      if (expression.empty() || x.empty())
        return;
      const auto g = parse_candidate_expression<2>(quantity, "r,a", expression, constants);
      Curve curve{quantity, "r / a", unit, x,
                  [&, g](const std::size_t i) { return g->value(dealii::Point<2>(x[i] * a, a)); },
                  [&](const std::size_t i) { return reference(x[i] * a); }};
      add_note(result, report_curve(curve, c.tolerance, s.outputs.plots, folder, fe, result.rows));
    };
    curve("pressure", c.pressure, s.outputs.pressure_radii, "[Pa]", [&](const double r) { return mdr::pressure(w1d, m, r); });
    curve("displacement", c.displacement, s.outputs.displacement_radii, "[m]",
          [&](const double r) { return mdr::displacement(w1d, m, r); });
  }



  SceneResult run_adhesive_candidate(const Scene &s, const fs::path &folder)
  {
    const CandidateParameters &c         = s.candidate;
    const auto                 constants = candidate_constants(s);
    const mdr::Profile         profile   = candidate_profile(s, constants);
    const Medium               m         = scene_medium(s);
    const double               dgamma = s.adhesion.work_of_adhesion, a = s.load.a;
    SceneResult                result;
    const std::vector<double>  radii = spaced(c.range[0] * a, c.range[1] * a, c.points);
    FeValues fe;
    if (s.material.modulus != MaterialParameters::Modulus::power_law)
      {
        result.description = "a grading outside the chapter: against the FE only";
        adhesive_fe_rows(s, profile, radii, constants, result.rows, fe);
        if (s.adhesion.law == AdhesionParameters::Law::dugdale)
          dugdale_fe_rows(s, profile, radii, constants, result.rows);
        if (s.adhesion.law == AdhesionParameters::Law::lennard_jones)
          lennard_jones_fe_rows(s, profile, m, radii, constants, result.rows);
        return result;
      }
    // The FE first, so that the curves' plots carry its points; its rows follow the MDR's.
    std::vector<Row> fe_rows;
    if (s.references.fem)
      adhesive_fe_rows(s, profile, radii, constants, fe_rows, fe);
    result.description = !s.references.fem ? "against the numerical MDR"
                         : c.coulomb_3d ? "against the numerical MDR, the FE (mode 1) and the 3D Coulomb model"
                                        : "against the numerical MDR and the FE";

    // d(a) and F_N(a) on the adhesive branch (both branches of the JKR curve: every a has its state, 9.46).
    if (!(c.adhesive_depth.empty() && c.adhesive_force.empty()))
      {
        const IndentationStates states(radii, profile, m, dgamma);
        indentation_curve("adhesive depth", c.adhesive_depth, false, states, constants, s, fe, folder, result);
        indentation_curve("adhesive force", c.adhesive_force, true, states, constants, s, fe, folder, result);
      }

    // p(r, a) of the adhesive state at Load/a, relative to the largest |p| of the radii asked (it is tensile at the
    // edge, where it is singular).
    if (!c.adhesive_pressure.empty() && !s.outputs.pressure_radii.empty())
      {
        const auto g = parse_candidate_expression<2>("adhesive pressure", "r,a", c.adhesive_pressure, constants);
        const std::vector<double> &x   = s.outputs.pressure_radii;
        const mdr::Foundation      w1d = mdr::indentation(profile, m, a, dgamma);
        Curve curve{"adhesive pressure", "r / a", "[Pa]", x,
                    [&, g](const std::size_t i) { return g->value(dealii::Point<2>(x[i] * a, a)); },
                    [&](const std::size_t i) { return mdr::pressure(w1d, m, x[i] * a); }, true};
        add_note(result, report_curve(curve, c.tolerance, s.outputs.plots, folder, fe, result.rows));
      }

    // The critical state by the MDR's own search of the minimum of F_N(a) or d(a).
    if (!(c.critical_radius.empty() && c.critical_force.empty() && c.critical_depth.empty()))
      {
        const Control control = c.critical_force_control ? Control::force : Control::displacement;
        const std::string under = c.critical_force_control ? " (force control)" : " (displacement control)";
        std::optional<mdr::CriticalState> state;
        std::string                       why;
        try
          {
            state = mdr::critical_state(profile, m, dgamma, control);
          }
        catch (const std::exception &e)
          {
            why = concise(e);
          }
        const auto critical = [&](const std::string &name, const std::string &expression, double mdr::CriticalState::*member) {
          if (expression.empty())
            return;
          if (!state)
            {
              result.rows.push_back(failed(name + under, "candidate", "numerical MDR", why));
              return;
            }
          scalar_row(name + under, expression, constants, [&] { return (*state).*member; }, c.tolerance, result.rows);
        };
        critical("critical radius", c.critical_radius, &mdr::CriticalState::radius);
        critical("critical force", c.critical_force, &mdr::CriticalState::force);
        critical("critical depth", c.critical_depth, &mdr::CriticalState::depth);
      }
    result.rows.insert(result.rows.end(), fe_rows.begin(), fe_rows.end());
    if (s.references.fem && s.adhesion.law == AdhesionParameters::Law::dugdale)
      dugdale_fe_rows(s, profile, radii, constants, result.rows);
    if (s.references.fem && s.adhesion.law == AdhesionParameters::Law::lennard_jones)
      lennard_jones_fe_rows(s, profile, m, radii, constants, result.rows);
    return result;
  }



  SceneResult run_tangential_candidate(const Scene &s, const fs::path &folder)
  {
    const CandidateParameters &c         = s.candidate;
    const auto                 constants = candidate_constants(s);
    const mdr::Profile         profile   = candidate_profile(s, constants);
    const Medium               m         = scene_medium(s);
    const double               mu = s.friction.coefficient, a = s.load.a;
    const bool                 plots = s.outputs.plots;
    SceneResult                result;
    FeValues fe;
    if (s.material.modulus != MaterialParameters::Modulus::power_law)
      {
        result.description = "a grading outside the chapter: its stiffness against the FE only";
        tangential_fe_rows(s, nullptr, {}, constants, result.rows, fe);
        if (c.coulomb_3d)
          result.rows.push_back(failed("3D Coulomb path", "candidate", "FE (3D Coulomb)",
                                       "Candidate/Coulomb 3D takes its depth and amplitude from the numerical MDR, "
                                       "which needs Material/modulus = power law"));
        return result;
      }
    const mdr::PartialSlip    slip(profile, m, mu, a);
    const double              sliding = mu * slip.normal_force(a); // mu F_N(a): gross slip
    const std::vector<double> f       = fractions(c.points);
    // The FE first, so that the curves' plots carry its points; its rows follow the MDR's.
    std::vector<Row> fe_rows;
    if (s.references.fem)
      tangential_fe_rows(s, &slip, f, constants, fe_rows, fe);
    if (s.references.fem && c.coulomb_3d)
      coulomb_3d_candidate_rows(s, profile, slip, constants, fe_rows);
    result.description = !s.references.fem ? "against the numerical MDR"
                         : c.coulomb_3d ? "against the numerical MDR, the FE (mode 1) and the 3D Coulomb model"
                                        : "against the numerical MDR and the FE";
    const auto note = [&](const Curve &curve) {
      add_note(result, report_curve(curve, c.tolerance, plots, folder, fe, result.rows));
    };

    // K_T(a) = K_N(a) / alpha (9.78), K_N(a) = dF_N/dd, the flat punch's stiffness at radius a (9.11 with w1D = 1).
    if (!c.tangential_stiffness.empty())
      {
        const std::vector<double> radii = spaced(c.range[0] * a, c.range[1] * a, c.points);
        const auto g = parse_candidate_expression<1>("tangential stiffness", "a", c.tangential_stiffness, constants);
        note(Curve{"tangential stiffness", "a [m]", "[N/m]", radii,
                   [&, g](const std::size_t i) { return g->value(dealii::Point<1>(radii[i])); },
                   [&](const std::size_t i) { return mdr::force(mdr::flat(radii[i], 1.), m) / m.alpha(); }});
      }

    const auto of_c = [&](const std::string &quantity, const std::string &expression, const std::string &unit,
                          const std::function<double(double)> &reference) {
      if (expression.empty())
        return;
      const auto g = parse_candidate_expression<2>(quantity, "c,a", expression, constants);
      note(Curve{quantity, "c / a", unit, f,
                 [&, g](const std::size_t i) { return g->value(dealii::Point<2>(f[i] * a, a)); },
                 [&](const std::size_t i) { return reference(f[i] * a); }});
    };
    of_c("tangential force", c.tangential_force, "[N]", [&](const double cc) { return slip.tangential_force(cc); });
    of_c("tangential displacement", c.tangential_displacement, "[m]",
         [&](const double cc) { return slip.tangential_displacement(cc); });

    const auto of_force = [&](const std::string &quantity, const std::string &expression, const std::string &unit,
                              const std::string &variable, const std::function<double(double)> &reference) {
      if (expression.empty())
        return;
      const auto g = parse_candidate_expression<2>(quantity, variable + ",a", expression, constants);
      note(Curve{quantity, variable + " / (mu F_N)", unit, f,
                 [&, g](const std::size_t i) { return g->value(dealii::Point<2>(f[i] * sliding, a)); },
                 [&](const std::size_t i) { return reference(f[i] * sliding); }});
    };
    of_force("stick radius", c.stick_radius, "[m]", "Fx", [&](const double F) { return slip.stick_radius(F); });
    of_force("dissipated energy", c.dissipated_energy, "[J]", "FA",
             [&](const double F) { return slip.dissipated_energy(F); });

    // The branches of the loop between +-FA: u0 against F_x from FA down to -FA (unloading) and back (reloading).
    const double FA = s.tangential.amplitude * sliding;
    const std::vector<double> forces = spaced(-1., 1., c.points);
    const auto loop = [&](const std::string &quantity, const std::string &expression, const Branch branch) {
      if (expression.empty())
        return;
      const auto g = parse_candidate_expression<3>(quantity, "Fx,FA,a", expression, constants);
      note(Curve{quantity, "Fx / FA", "[m]", forces,
                 [&, g](const std::size_t i) { return g->value(dealii::Point<3>(forces[i] * FA, FA, a)); },
                 [&](const std::size_t i) { return slip.tangential_displacement(FA, branch, forces[i] * FA); },
                 true});
    };
    loop("unloading displacement", c.unloading_displacement, Branch::unloading);
    loop("reloading displacement", c.reloading_displacement, Branch::reloading);
    result.rows.insert(result.rows.end(), fe_rows.begin(), fe_rows.end());
    return result;
  }

  namespace
  {
    using Control = LoadParameters::Control;

    // --- candidate closed forms of a user's profile ---------------------------------------------------
    /// Load/contact = unilateral: the candidate's closed forms against the FE with the contact set found (a
    /// disc, an annulus, several zones, or up to the indenter's edge), the profile a rigid (or Indenter) indenter
    /// of Candidate/indenter radius under Load/control depth or force. The expressions take the FE's depth d and
    /// force F; the numerical MDR assumes a disc and is not compared (the scene's description says so).
    SceneResult run_unilateral_candidate(const Scene &s, const std::map<std::string, double> &constants)
    {
      SceneResult result;
      const CandidateParameters &c = s.candidate;
      const auto t0 = std::chrono::steady_clock::now();
      const FeModel model = fe_model(s, finest_refinement(s));
      std::function<double(double)> profile; // the expression's, when there is no Candidate/profile table
      if (c.profile_table.empty())
        {
          const auto f = parse_candidate_expression<1>("profile", "r", c.profile, constants);
          profile      = [f](const double r) { return f->value(dealii::Point<1>(r)); };
        }
      fem::Indenter         indenter = candidate_unilateral_indenter(s, profile);
      const bool            by_force = s.load.control == Control::force;
      fem::UnilateralResult fe;
      try
        {
          fe = solve_unilateral(s, model, std::move(indenter), by_force, output_request(s));
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("FE solve", "FE", "-", concise(e)));
          return result;
        }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (!fe.reliable)
        result.rows.push_back(failed("FE solve", "FE", "-", fe.message));
      const double inner = fe.zones.empty() ? 0. : fe.zones.front().r_in;
      const auto row = [&](const std::string &quantity, const std::string &metric, const std::string &expression,
                           const double fe_value, const double tolerance, const std::optional<double> r,
                           const double scale) {
        if (expression.empty())
          return;
        try
          {
            const double value = r ? parse_candidate_expression<3>(quantity, "r,d,F", expression, constants)
                                       ->value(dealii::Point<3>(*r, fe.depth, fe.force))
                                   : parse_candidate_expression<2>(quantity, "d,F", expression, constants)
                                       ->value(dealii::Point<2>(fe.depth, fe.force));
            result.rows.push_back(compare(quantity, metric, "candidate", "FE (unilateral)", fe_value, value, scale,
                                          tolerance, fe.n_dofs, seconds));
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed(quantity, "candidate", "FE (unilateral)", concise(e)));
          }
      };
      const double a = s.load.a;
      if (by_force)
        row("depth", "relative", c.depth, fe.depth, s.tolerances.depth, std::nullopt, fe.depth);
      else
        row("force", "relative", c.force, fe.force, s.tolerances.force, std::nullopt, fe.force);
      row("outer radius", "relative", c.outer_radius, fe.outer_edge, s.tolerances.contact_radius, std::nullopt,
          fe.outer_edge);
      // The inner edge lies between two vertices (its bracket is the mesh's spacing there): relative to the
      // outer edge.
      row("inner radius", "relative to the outer radius", c.inner_radius, inner, s.tolerances.contact_radius,
          std::nullopt, fe.outer_edge);
      const double p_max = largest_magnitude(fe.pressure);
      for (const fem::Sample &p : fe.pressure)
        row("pressure", "r/a = " + format(p.r / a) + ", rel. to max |p|", c.pressure, p.value, s.tolerances.pressure,
            p.r, p_max);
      for (std::size_t i = 0; i < fe.displacement.size(); ++i)
        {
          const double w = fe.displacement[i].value + (fe.indenter_displacement.empty() ? 0. : fe.indenter_displacement[i].value);
          row("displacement", "r/a = " + format(fe.displacement[i].r / a) + ", relative", c.displacement, w,
              s.tolerances.displacement, fe.displacement[i].r, w);
        }
      return result;
    }

    /// The normal family against the FE model: the profile as a custom indenter under contact-radius control at
    /// Load/a on the recommended mesh, one solve for every quantity; its rows go into `rows`, and its depth and force
    /// are returned by name for the curves' plots.
    std::map<std::string, double> candidate_fe_rows(const Scene &s, const std::map<std::string, double> &constants,
                                                    const mdr::Profile &profile, std::vector<Row> &rows,
                                                    std::map<std::string, std::map<double, double>> &profiles)
    {
      const CandidateParameters &c = s.candidate;
      const double a = s.load.a;
      const auto at = [](const CandidateFunction<1> &g, const double r) { return g.value(dealii::Point<1>(r)); };
      const auto t0 = std::chrono::steady_clock::now();
      const fem::Result fe = solve_candidate(s, profile);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const auto fe_row = [&](const std::string &quantity, const std::string &metric, const std::string &expression,
                              const double fe_value, const double tolerance, const std::optional<double> r) {
        if (expression.empty())
          return;
        try
          {
            const double value = r ? parse_candidate_expression<2>(quantity, "r,a", expression, constants)->value(dealii::Point<2>(*r, a))
                                   : at(*parse_candidate_expression<1>(quantity, "a", expression, constants), a);
            rows.push_back(compare(quantity, metric, "candidate", "FE", fe_value, value, fe_value, tolerance,
                                          fe.n_dofs, seconds));
          }
        catch (const std::exception &e)
          {
            rows.push_back(failed(quantity, "candidate", "FE", concise(e)));
          }
      };
      fe_row("depth", "relative", c.depth, fe.depth, s.tolerances.depth, std::nullopt);
      fe_row("force", "relative", c.force, fe.force, s.tolerances.force, std::nullopt);
      for (const fem::Sample &p : fe.pressure)
        fe_row("pressure", "r/a = " + format(p.r / a) + ", relative", c.pressure, p.value, s.tolerances.pressure, p.r);
      for (const fem::Sample &w : fe.displacement)
        fe_row("displacement", "r/a = " + format(w.r / a) + ", relative", c.displacement, w.value,
               s.tolerances.displacement, w.r);
      for (const fem::Sample &p : fe.pressure)
        profiles["pressure"][p.r / a] = p.value;
      for (const fem::Sample &w : fe.displacement)
        profiles["displacement"][w.r / a] = w.value;
      return {{"depth", fe.depth}, {"force", fe.force}};
    }

    /// The normal family (not unilateral): the FE at Load/a first, so that the curves' plots carry its points; then
    /// d(a) and F_N(a) over Candidate/range and p, w at Load/a against the numerical MDR; the FE's rows last.
    SceneResult run_candidate(const Scene &s, const fs::path &folder)
    {
      const auto constants = candidate_constants(s);
      if (s.load.contact == LoadParameters::Contact::unilateral)
        return run_unilateral_candidate(s, constants);
      SceneResult result;
      const mdr::Profile profile = candidate_profile(s, constants);
      // (a pressure candidate without f'' is refused by validate: see there why)
      std::vector<Row> fe_rows;
      std::map<std::string, double> fe_at_a;
      std::map<std::string, std::map<double, double>> fe_profiles;
      if (s.references.fem)
        fe_at_a = candidate_fe_rows(s, constants, profile, fe_rows, fe_profiles);
      normal_candidate_curves(s, constants, profile, fe_at_a, folder, result);
      normal_profile_curves(s, constants, profile, fe_profiles, folder, result);
      result.rows.insert(result.rows.end(), fe_rows.begin(), fe_rows.end());
      return result;
    }
  } // namespace

  SceneResult run_candidate_scene(const Scene &s, const fs::path &folder)
  {
    require_kind(s, SceneKind::candidate, "run_candidate_scene");
    const auto start = std::chrono::steady_clock::now();
    SceneResult r = started(s, folder);
    if (s.load.contact == LoadParameters::Contact::unilateral)
      r.description += (r.description.empty() ? "" : " ") +
                       std::string("(unilateral contact: the candidate against the FE only; the numerical MDR assumes a "
                                   "disc and does not apply)");
    if (s.candidate.family() != CandidateParameters::Family::normal)
      {
        const bool  adhesive = s.candidate.family() == CandidateParameters::Family::adhesive;
        SceneResult family   = adhesive ? run_adhesive_candidate(s, folder) : run_tangential_candidate(s, folder);
        r.rows               = std::move(family.rows);
        r.description += (r.description.empty() ? "" : " ") + std::string("(") + family.description + ")";
      }
    else
      {
        SceneResult normal = run_candidate(s, folder);
        r.rows             = std::move(normal.rows);
        if (!normal.description.empty())
          r.description += (r.description.empty() ? "" : " ") + std::string("(") + normal.description + ")";
      }
    r.seconds = elapsed(start);
    return r;
  }
} // namespace gradcontact::cases
