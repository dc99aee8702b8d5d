#include <fem/base/errors.h>
#include <fem/accuracy/convergence.h>

#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    [[noreturn]] void fail(const std::string &what, const double value, const std::string &range)
    {
      fem::fail("ConvergenceStudy", what, value, range);
    }
  } // namespace

  void ConvergenceStudy::validate() const
  {
    base.discretization.validate();
    material.validate(resolve_formulation(base.discretization, material.nu) == Formulation::mixed);
    base.mesh.validate();
    load.validate();
    if (n_levels < 1 || n_levels > 7)
      fail("n_levels", n_levels, "[1, 7]");
    if (refinement == Refinement::h && first_level + n_levels - 1 > 6)
      fail("first_level + n_levels - 1 (global refinements)", first_level + n_levels - 1, "[0, 6]");
    if (refinement == Refinement::p && (first_level < 1 || first_level + n_levels - 1 > 8))
      fail("degrees first_level .. first_level + n_levels - 1, last", first_level + n_levels - 1,
           "[1, 8] (first_level >= 1)");
    if (!std::isfinite(reference) || reference == 0)
      fail("reference", reference, "finite, non-zero");
    if (quantity == StudyQuantity::displacement && !(radius >= 0))
      fail("radius", radius, "[0, L]");
  }

  double observed_order(const std::vector<double> &x, const std::vector<double> &y)
  {
    if (x.size() != y.size() || x.size() < 3)
      throw std::invalid_argument("observed_order: need >= 3 points of equal count, got " +
                                  std::to_string(x.size()) + " and " + std::to_string(y.size()));
    const std::size_t n = x.size();
    double            mx = 0, my = 0;
    for (std::size_t i = n - 3; i < n; ++i)
      {
        mx += x[i] / 3;
        my += std::log(std::abs(y[i])) / 3;
      }
    double sxy = 0, sxx = 0;
    for (std::size_t i = n - 3; i < n; ++i)
      {
        sxy += (x[i] - mx) * (std::log(std::abs(y[i])) - my);
        sxx += (x[i] - mx) * (x[i] - mx);
      }
    return sxy / sxx;
  }

  std::vector<ConvergenceRow> run_convergence_study(const ConvergenceStudy &study)
  {
    study.validate();
    std::vector<ConvergenceRow> rows;
    std::vector<double>         x, err;
    for (unsigned int l = 0; l < study.n_levels; ++l)
      {
        const auto   start = std::chrono::steady_clock::now();
        Settings     s     = study.base;
        ConvergenceRow row;
        row.level = study.first_level + l;
        if (study.refinement == Refinement::h)
          {
            s.mesh.global_refinements = row.level;
            row.h                     = std::pow(0.5, row.level);
          }
        else
          {
            s.discretization.degree = row.level;
            row.h                   = 1.0 / row.level;
          }
        AxisymmetricSolver solver(study.material, s.mesh, s.discretization);
        OutputRequest      out;
        if (study.quantity == StudyQuantity::displacement)
          out.displacement_radii = {study.radius};
        const Result result = solver.run(study.load, out);
        row.n_dofs          = result.n_dofs;
        row.value           = study.quantity == StudyQuantity::force ? result.force :
                              study.quantity == StudyQuantity::depth ? result.depth :
                                                                       result.displacement.at(0).value;
        row.error    = row.value / study.reference - 1;
        row.reliable = result.reliable;
        // h: error ~ h^order, fit against log h; p: error ~ exp(-order p), fit against -p.
        x.push_back(study.refinement == Refinement::h ? std::log(row.h) : -double(row.level));
        err.push_back(row.error);
        row.order   = x.size() >= 3 ? observed_order(x, err) : std::numeric_limits<double>::quiet_NaN();
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rows.push_back(row);
      }
    return rows;
  }

  void write_markdown(std::ostream &out, const ConvergenceStudy &study, const std::vector<ConvergenceRow> &rows)
  {
    const bool h = study.refinement == Refinement::h;
    out << "| " << (h ? "refinements" : "degree") << " | DoFs | value | rel. error | order"
        << (h ? " (h)" : " (exp. rate in p)") << " | time [s] |\n|---|---|---|---|---|---|\n";
    for (const ConvergenceRow &r : rows)
      {
        out << "| " << r.level << " | " << r.n_dofs << " | " << std::setprecision(12) << r.value << " | "
            << std::setprecision(3) << std::scientific << r.error << std::defaultfloat << " | ";
        if (std::isnan(r.order))
          out << "-";
        else
          out << std::setprecision(3) << r.order;
        out << " | " << std::setprecision(3) << r.seconds << (r.reliable ? "" : " (unreliable)") << " |\n";
      }
  }
} // namespace gradcontact::fem
