#include "runners/fe_tangential.h"

#include "model/analytic_reference.h"
#include "model/scene_start.h"
#include "model/fe_contract.h"
#include "model/fe_model.h"
#include "model/mode1_model.h"

#include <analytic/batch.h>
#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/tangential.h>

#include <deal.II/base/quadrature_lib.h>


#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

namespace gradcontact::cases
{
  namespace fs = std::filesystem;
  using Study = TangentialParameters::Study;
  using Type = LoadParameters::Type;

  namespace
  {
    /// The quantities of the rows whose worst error a plot's title quotes: one name where the row is made and where
    /// it is read.
    const char *const stick_mean_u0 = "stick-zone mean u_x (u0)";
    const char *const unloading_u0  = "unloading u0 (9.83)";

    /// The largest relative error of the rows of `quantity` that did not fail (0 when none).
    double worst_error(const std::vector<Row> &rows, const std::string &quantity)
    {
      double worst = 0.;
      for (const Row &row : rows)
        if (row.quantity == quantity && row.error.empty())
          worst = std::max(worst, row.rel_error);
      return worst;
    }

    /// The inputs of a tangential_sphere request at the stick radius c, and of an oscillating_sphere request
    /// at the force Fx on a branch of the oscillation of amplitude FA.
    Inputs stick(const double c)
    {
      return [c](batch::Request &q) { q.c = c; };
    }
    Inputs branch_state(const double FA, const Branch branch, const double Fx)
    {
      return [FA, branch, Fx](batch::Request &q) {
        q.FA = FA;
        q.branch = branch;
        q.Fx = Fx;
      };
    }

    constexpr double pi = 3.14159265358979323846;

    /// The flat-punch displacement delta / a of the stiffness study (the problem is linear: any delta).
    constexpr double punch_displacement = 1e-3;

    /// Gauss-Legendre points in F of the dissipated energy W = \int_{-F_A}^{F_A} [u_un(F) + u_un(-F)] dF: the
    /// same rule on the closed-form u_un reproduces 9.86 far inside the energy's tolerance.
    constexpr unsigned int energy_gauss_points = 12;

    /// Radii / a of the sampled surface displacement (points A to E, the partial-slip profile).
    constexpr unsigned int profile_samples = 40;

    double seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// The scene with Tangential/Holl ratio applied (nu = 1 / (2 + k), the decoupled pairing of 9.3.1); the
    /// entries are checked by validate (k > 0 for the Holl ratio, the load of each study).
    Scene with_holl_ratio(const Scene &scene)
    {
      validate(scene, decide_kind(scene));
      Scene s = scene;
      if (s.tangential.holl_ratio)
        s.material.nu = 1. / (2. + s.material.k);
      return s;
    }

    /// The stick radii that grade the mode-1 mesh: those inside the contact (c = a is a mesh node already).
    std::vector<double> graded_radii(const Scene &s, const std::vector<double> &stick_radii)
    {
      std::vector<double> radii;
      for (const double c : stick_radii)
        if (c > 0. && c < s.load.a * (1. - 1e-12))
          radii.push_back(c);
      return radii;
    }

    /// The surface sample radii r <= a.
    std::vector<double> profile_radii(const double a)
    {
      std::vector<double> r;
      for (unsigned int i = 0; i <= profile_samples; ++i)
        r.push_back(a * i / profile_samples);
      return r;
    }

    /// Stick radii c/a of the F_x(u0) curve: i / steps, i = 1 .. steps - 1, and the scene's c/a, ascending.
    std::vector<double> curve_stick_radii(const TangentialParameters &t)
    {
      std::vector<double> x;
      for (unsigned int i = 1; i < t.load_steps; ++i)
        x.push_back(static_cast<double>(i) / t.load_steps);
      if (std::none_of(x.begin(), x.end(), [&](const double v) { return std::abs(v - t.stick_radius) < 1e-9; }))
        x.push_back(t.stick_radius);
      std::sort(x.begin(), x.end());
      return x;
    }

    /// The unloading forces F / F_A = 1 - 2 i / (steps - 1), i = 0 .. steps - 1 (A to E).
    std::vector<double> unloading_forces(const TangentialParameters &t)
    {
      std::vector<double> f;
      for (unsigned int i = 0; i < t.load_steps; ++i)
        f.push_back(1. - 2. * i / (t.load_steps - 1));
      return f;
    }

    /// One partial-slip state (9.80) of the FE model under tau = mu [p(r; a) - p(r; c)], p the closed form.
    fem::TangentialResult solve_partial_slip(const Scene &s, Mode1Model &model, const gradcontact::Medium &medium,
                                             const double c, const std::vector<double> &radii)
    {
      const gradcontact::Paraboloid sphere{s.load.R};
      const auto pressure = [&medium, sphere](const double r, const double b) {
        return r < b ? gradcontact::pressure(medium, sphere, b, r) : 0.;
      };
      return model.partial_slip(pressure, s.friction.coefficient, s.load.a, c, radii);
    }

    /// The oscillation after loading to A (F_A = amplitude mu F_N): F_N, F_A and the stick radius c_A of A.
    struct Oscillation
    {
      double FN, FA, cA;
    };
    Oscillation oscillation_of(const Scene &s, const gradcontact::Medium &medium)
    {
      const double FN = gradcontact::force(medium, gradcontact::Paraboloid{s.load.R}, s.load.a);
      const double FA = s.tangential.amplitude * s.friction.coefficient * FN;
      const gradcontact::tangential::SphereSlip slip{s.load.R, s.friction.coefficient};
      return {FN, FA, gradcontact::tangential::stick_radius(medium, slip, s.load.a, FA)}; // 9.80
    }

    /// The FE state on the unloading branch at F_x (traction 9.82 with the factor mu, ERRATA.md). The rigid
    /// displacement u0 is the mean of u_x over r <= c_A, where nothing ever slipped (in c_A < r <= b the slip of
    /// the loading stays; fem/doc/loads-and-contact.md).
    fem::TangentialResult solve_unloading(const Scene &s, Mode1Model &model, const gradcontact::Medium &medium,
                                          const Oscillation &o, const double Fx, const std::vector<double> &radii)
    {
      namespace t = gradcontact::tangential;
      const t::SphereSlip slip{s.load.R, s.friction.coefficient};
      const double a = s.load.a;
      const double b = t::reversal_radius(medium, slip, a, o.FA, t::Branch::unloading, Fx); // 9.81
      std::vector<double> kinks;
      for (const double r : {o.cA, b})
        if (r > 0. && r < a * (1. - 1e-12))
          kinks.push_back(r);
      std::sort(kinks.begin(), kinks.end());
      kinks.erase(std::unique(kinks.begin(), kinks.end()), kinks.end());
      const auto tau = [&medium, slip, a, o, Fx](const double r) {
        return t::traction(medium, slip, a, o.FA, t::Branch::unloading, Fx, r);
      };
      return model.traction(tau, a, o.cA, kinks, radii);
    }

    gradcontact::Medium medium_of(const Scene &s)
    {
      const MaterialParameters &m = s.material;
      return gradcontact::medium(gradcontact::GradedHalfSpace{m.E0, m.c0, m.k, m.nu});
    }

    /// Rows and plots of one study; `result` collects the rows.
    class TangentialStudy
    {
    public:
      /// `contract_level`: solve on that level of the accuracy contract's ladder and record every FE value that
      /// check() compares (ladder_values, value_rows).
      TangentialStudy(const Scene &s, const fs::path &folder, const bool verbose, SceneResult &result,
                      const std::optional<unsigned int> contract_level = std::nullopt)
        : s(s), folder(folder), verbose(verbose), result(result), reference(s, batch::Method::closed_form, AnalyticReference::Problem::tangential), medium(medium_of(s))
        , contract_level(contract_level)
      {}

      void stiffness();
      void partial_slip();
      void oscillation();

      /// Under the contract: the FE values check() compared, the rows they went to, the largest DoF count.
      LadderLevel ladder_level;

    private:
      /// The plots of an oscillation: the FE branches and the surface displacements and tractions at A to E.
      struct HysteresisPlots
      {
        Series              fe_un{"FE unloading", {}, {}, true};
        Series              fe_re{"FE reloading (u_re(F) = -u_un(-F))", {}, {}, true};
        std::vector<Series> profiles, tractions;
      };
      /// u0 of the closed form on `branch` at force F (9.83-9.84).
      double branch_u(const Oscillation &o, Branch branch, double F) const;
      /// The unloading branch at `load steps` forces and the points A to E (9.82-9.83, figs. 9.34-9.35).
      void unloading_branch(Mode1Model &model, const Oscillation &o, double uA,
                            std::chrono::steady_clock::time_point start, HysteresisPlots &plots);
      /// The dissipated energy per cycle (9.86, and 9.87 at k = 0) from the FE unloading branch.
      void dissipated_energy(Mode1Model &model, const Oscillation &o, std::chrono::steady_clock::time_point start);
      void plot_hysteresis(const Oscillation &o, double uA, HysteresisPlots &plots) const;

      /// A row against a batch reference; a reference that fails to evaluate is a failed row.
      template <class Reference>
      double check(const std::string &quantity, const std::string &metric, const double fe, const std::string &ref_name,
                   const Reference &ref, const double tolerance, const unsigned int dofs, const double seconds,
                   const double scale = 0.)
      {
        if (contract_level)
          {
            ladder_level.value(quantity + ", " + metric, fe, scale != 0. ? scale : fe);
            ladder_level.dofs = std::max(ladder_level.dofs, dofs);
          }
        try
          {
            const double r = ref();
            result.rows.push_back(compare(quantity, metric, "FE", ref_name, r, fe, scale != 0. ? scale : r, tolerance,
                                          dofs, seconds));
            if (contract_level)
              ladder_level.row(result.rows.size() - 1);
            return r;
          }
        catch (const std::exception &e)
          {
            result.rows.push_back(failed(quantity, "FE", ref_name, concise(e)));
            return 0.;
          }
      }
      /// The measured assumption error of 9.80 (rigid stick zone, traction in x only): both against 0.
      void assumption_rows(const fem::TangentialResult &r, const std::string &metric, const double seconds)
      {
        const double tol = s.tangential.assumption_tolerance;
        result.rows.push_back(compare("stick zone: spread of u_x / mean", metric, "FE", "rigid stick zone (0)", 0.,
                                      r.stick.relative_spread, 1., tol, r.n_dofs, seconds));
        result.rows.push_back(compare("stick zone: max |u_y| / mean u_x", metric, "FE", "traction in x only (0)", 0.,
                                      r.stick.relative_max_uy, 1., tol, r.n_dofs, seconds));
      }
      void reliability(const fem::TangentialResult &r, const std::string &what)
      {
        if (!r.reliable)
          result.rows.push_back(failed("FE solve", "FE", "-", what + ": " + r.message));
      }

      const Scene &s;
      const fs::path folder;
      const bool verbose;
      SceneResult &result;
      const AnalyticReference reference;
      const gradcontact::Medium medium;
      const std::optional<unsigned int> contract_level;
    };

    void TangentialStudy::stiffness()
    {
      const auto start = std::chrono::steady_clock::now();
      const double a = s.load.a, k = s.material.k, E0 = s.material.E0, c0 = s.material.c0, nu = s.material.nu;
      Mode1Model model(s, {}, contract_level);
      const double delta = punch_displacement * a;
      const fem::TangentialResult t = model.flat_punch(delta);
      reliability(t, "tangential flat punch");
      const double t_tangential = seconds_since(start);
      const double tol = s.tolerances.force;
      // MDR (9.78-9.79): K_T = 2 cT0 a^(1+k) / ((1+k) c0^k), cT0 = h_T E0 for a rigid punch on one graded body.
      check("tangential stiffness K_T", "relative", t.stiffness, "MDR 9.78-9.79 (h_T of coefficients)",
            [&] { return 2. * reference.get("coefficients", "h_T", {}) * E0 * std::pow(a, 1. + k) / ((1. + k) * std::pow(c0, k)); },
            tol, t.n_dofs, t_tangential);
      if (k == 0.)
        {
          // Mindlin (1949): the rigid tangential punch on the homogeneous half-space, K_T = 8 G a / (2 - nu).
          const double G = E0 / (2. * (1. + nu));
          result.rows.push_back(compare("tangential stiffness K_T", "relative", "FE", "Mindlin (1949) 8 G a/(2 - nu)",
                                        8. * G * a / (2. - nu), t.stiffness, 8. * G * a / (2. - nu), tol, t.n_dofs,
                                        t_tangential));
        }
      // alpha = K_N / K_T (9.78) with K_N from the normal flat punch on the same mesh and discretisation.
      const fem::Result n = model.normal_flat_punch(delta);
      if (!n.reliable)
        result.rows.push_back(failed("FE solve", "FE", "-", "normal flat punch: " + n.message));
      const double K_N = n.force / delta, seconds = seconds_since(start);
      check("normal stiffness K_N", "relative", K_N, "closed form F(d)/d (9.16)",
            [&] { return reference.get("flat_punch", "force", [delta](batch::Request &q) { q.d = delta; }) / delta; }, tol, n.n_dofs, seconds);
      check("alpha = K_N / K_T", "relative", K_N / t.stiffness, "9.78 (alpha of coefficients)",
            [&] { return reference.get("coefficients", "alpha", {}); }, tol, t.n_dofs + n.n_dofs, seconds);
      if (verbose)
        std::cerr << "  K_T = " << t.stiffness << ", K_N = " << K_N << " (" << t.n_dofs << " + " << n.n_dofs
                  << " DoFs, " << format(seconds) << " s)\n";
    }

    void TangentialStudy::partial_slip()
    {
      const auto start = std::chrono::steady_clock::now();
      const TangentialParameters &tp = s.tangential;
      const double a = s.load.a;
      const std::vector<double> c_over_a = curve_stick_radii(tp);
      std::vector<double> radii;
      for (const double x : c_over_a)
        radii.push_back(x * a);
      Mode1Model model(s, graded_radii(s, radii), contract_level);
      const double FN = gradcontact::force(medium, gradcontact::Paraboloid{s.load.R}, a);
      const double mu = s.friction.coefficient;
      double u_gross = 0.;
      try
        {
          u_gross = reference.get("tangential_sphere", "tangential_displacement", stick(0.));
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("tangential displacement", "closed form", "-", concise(e)));
          return;
        }
      Series curve{"closed form (9.80)", {}, {}, false}, points{"FE", {}, {}, true};
      for (int i = 0; i <= 200; ++i)
        {
          const double c = a * i / 200.;
          curve.x.push_back(reference.get("tangential_sphere", "tangential_displacement", stick(c)) / u_gross);
          curve.y.push_back(reference.get("tangential_sphere", "tangential_force", stick(c)) / (mu * FN));
        }
      Series ux{"FE u_x(r, theta = 0) = U", {}, {}, true}, ux90{"FE u_x(r, theta = 90 deg) = V", {}, {}, true};
      double u0_scene = 0.;
      for (const double x : c_over_a)
        {
          if (x >= 1.)
            {
              // c = a: no slip yet, tau = 0 and F_x = u0 = 0 exactly (the start of the curve); no FE solve, no row
              // (the stick-zone statistics of a zero field are 0/0).
              if (verbose)
                std::cerr << "  c/a = 1: the unloaded state (tau = 0), no FE row\n";
              continue;
            }
          const double c = x * a;
          const bool main = std::abs(x - tp.stick_radius) < 1e-9;
          const fem::TangentialResult r =
            solve_partial_slip(s, model, medium, c, main ? profile_radii(a) : std::vector<double>{});
          reliability(r, "c/a = " + format(x));
          const double seconds = seconds_since(start);
          const std::string metric = "c/a = " + format(x);
          // The force of the prescribed traction mu [p(r; a) - p(r; c)]: a check of the load's quadrature
          // (the FE takes the traction as its input), not an FE result.
          check("F_x of the imposed traction (input check)", metric + ", relative", r.force, "closed form 9.80",
                [&] { return reference.get("tangential_sphere", "tangential_force", stick(c)); }, s.tolerances.force,
                r.n_dofs, seconds);
          const double u0 = check(stick_mean_u0, metric + ", relative", r.stick.mean_ux, "closed form 9.80",
                                  [&] { return reference.get("tangential_sphere", "tangential_displacement", stick(c)); },
                                  s.tolerances.displacement, r.n_dofs, seconds);
          assumption_rows(r, metric, seconds);
          points.x.push_back(r.stick.mean_ux / u_gross);
          points.y.push_back(r.force / (mu * FN));
          if (main)
            {
              u0_scene = u0;
              for (const fem::SurfaceDisplacement &d : r.surface)
                {
                  ux.x.push_back(d.r / a);
                  ux.y.push_back(d.U / u0);
                  ux90.x.push_back(d.r / a);
                  ux90.y.push_back(d.V / u0);
                }
            }
          if (verbose)
            std::cerr << "  c/a = " << x << ": u0 = " << r.stick.mean_ux << ", spread " << r.stick.relative_spread
                      << " (" << r.n_dofs << " DoFs, " << format(seconds) << " s)\n";
        }
      if (!s.outputs.plots)
        return;
      const double worst = worst_error(result.rows, stick_mean_u0);
      write_plot(folder, "force_displacement",
                 s.info.name + ": F_x(u0) during loading (fig. 9.32), worst FE u0 error " + format(worst),
                 "u0 / u0(c = 0)", "F_x / (mu F_N)", {curve, points});
      if (u0_scene != 0.)
        {
          Series rigid{"theory: u_x = u0 on r <= c (9.80)", {0., tp.stick_radius}, {1., 1.}, false};
          write_plot(folder, "stick_zone_displacement",
                     s.info.name + ": surface u_x at c/a = " + format(tp.stick_radius) + " (stick zone r <= c)",
                     "r / a", "u_x / u0", {rigid, ux, ux90});
        }
    }

    double TangentialStudy::branch_u(const Oscillation &o, const Branch branch, const double F) const
    {
      return reference.get("oscillating_sphere", "tangential_displacement", branch_state(o.FA, branch, F));
    }

    void TangentialStudy::oscillation()
    {
      const auto        start = std::chrono::steady_clock::now();
      const Oscillation o     = oscillation_of(s, medium);
      Mode1Model        model(s, graded_radii(s, {o.cA}), contract_level);
      double            uA = 0.;
      try
        {
          uA = branch_u(o, Branch::loading, o.FA);
        }
      catch (const std::exception &e)
        {
          result.rows.push_back(failed("u_A (9.85)", "closed form", "-", concise(e)));
          return;
        }
      HysteresisPlots plots;
      unloading_branch(model, o, uA, start, plots);
      dissipated_energy(model, o, start);
      if (s.outputs.plots)
        plot_hysteresis(o, uA, plots);
    }

    void TangentialStudy::unloading_branch(Mode1Model &model, const Oscillation &o, const double uA,
                                           const std::chrono::steady_clock::time_point start, HysteresisPlots &plots)
    {
      namespace t = gradcontact::tangential;
      const double a = s.load.a, mu = s.friction.coefficient;
      // Unloading branch at `load steps` forces (the first is A, the last E) and the points A to E (9.34-9.35).
      const std::vector<double> forces = unloading_forces(s.tangential);
      const std::vector<std::pair<std::string, double>> labelled{{"A", 1.}, {"B", 0.5}, {"C", 0.}, {"D", -0.5}, {"E", -1.}};
      std::vector<double> all = forces;
      for (const auto &[name, f] : labelled)
        if (std::none_of(forces.begin(), forces.end(), [f = f](const double x) { return std::abs(x - f) < 1e-12; }))
          all.push_back(f);
      for (const double f : all)
        {
          const double F = f * o.FA;
          const auto label = std::find_if(labelled.begin(), labelled.end(),
                                          [f](const auto &p) { return std::abs(p.second - f) < 1e-12; });
          const bool is_point = label != labelled.end();
          const fem::TangentialResult r = solve_unloading(s, model, medium, o, F, is_point ? profile_radii(a) : std::vector<double>{});
          const double seconds = seconds_since(start);
          const std::string metric = "F/F_A = " + format(f);
          reliability(r, metric);
          // The force of the prescribed traction (9.82): a check of the load's quadrature.
          result.rows.push_back(compare("F_x of the imposed unloading traction (input check)", metric + ", relative to F_A", "FE quadrature",
                                        "F_x", F, r.force, o.FA, s.tolerances.force, r.n_dofs, seconds));
          if (std::find(forces.begin(), forces.end(), f) != forces.end())
            {
              check(unloading_u0, metric + ", relative to u_A", r.stick.mean_ux, "closed form 9.83",
                    [&] { return branch_u(o, Branch::unloading, F); }, s.tolerances.displacement, r.n_dofs, seconds, uA);
              plots.fe_un.x.push_back(r.stick.mean_ux / uA);
              plots.fe_un.y.push_back(f);
              plots.fe_re.x.push_back(-r.stick.mean_ux / uA);
              plots.fe_re.y.push_back(-f);
            }
          if (is_point)
            {
              assumption_rows(r, "point " + label->first + " (" + metric + "), r <= c_A", seconds);
              Series u{"FE " + label->first + ": F = " + format(f) + " F_A", {}, {}, true};
              Series tau{label->first + ": F = " + format(f) + " F_A", {}, {}, false};
              const double p0 = gradcontact::pressure(medium, gradcontact::Paraboloid{s.load.R}, a, 0.);
              for (const fem::SurfaceDisplacement &d : r.surface)
                {
                  u.x.push_back(d.r / a);
                  u.y.push_back(d.U / uA);
                }
              const t::SphereSlip slip{s.load.R, mu};
              for (int i = 0; i <= 400; ++i)
                {
                  const double x = i / 400.;
                  tau.x.push_back(x);
                  tau.y.push_back(t::traction(medium, slip, a, o.FA, t::Branch::unloading, F, x * a) / (mu * p0));
                }
              plots.profiles.push_back(u);
              plots.tractions.push_back(tau);
              try
                {
                  // 9.83: the stick zone r <= c_A moves rigidly by u0(F).
                  const double u_theory = branch_u(o, Branch::unloading, F) / uA;
                  plots.profiles.push_back({"9.83: " + label->first, {0., o.cA / a}, {u_theory, u_theory}, false});
                }
              catch (const std::exception &)
                {
                  // the unloading u0 row above reports the failed reference
                }
            }
          if (verbose)
            std::cerr << "  F/F_A = " << f << ": u0 = " << r.stick.mean_ux << " (" << r.n_dofs << " DoFs, "
                      << format(seconds) << " s)\n";
        }
    }

    void TangentialStudy::dissipated_energy(Mode1Model &model, const Oscillation &o,
                                            const std::chrono::steady_clock::time_point start)
    {
      const double a = s.load.a, nu = s.material.nu, E0 = s.material.E0, mu = s.friction.coefficient;
      // Dissipated energy per cycle, W = \int_{-F_A}^{F_A} [u_un(F) - u_re(F)] dF, u_re(F) = -u_un(-F), by
      // Gauss-Legendre in F on the FE u_un (the nodes are symmetric: sum_q w_q [u(F_q) + u(-F_q)] = 2 sum_q w_q u(F_q)).
      const dealii::QGauss<1> gauss(energy_gauss_points);
      double W = 0.;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double F = o.FA * (2. * gauss.point(q)[0] - 1.), w = 2. * o.FA * gauss.weight(q);
          W += 2. * w * solve_unloading(s, model, medium, o, F, {}).stick.mean_ux;
        }
      const double seconds = seconds_since(start);
      const unsigned int dofs = model.n_dofs();
      check("dissipated energy per cycle W", "relative", W, "9.86 corrected (ERRATA.md)",
            [&] { return reference.get("oscillating_sphere", "dissipated_energy", [&](batch::Request &q) { q.FA = o.FA; }); }, s.tolerances.force, dofs,
            seconds);
      if (s.material.k == 0.)
        {
          // Mindlin-Deresiewicz (9.87) from Hertz alone: a rigid sphere on the homogeneous half-space,
          // W = 9 mu^2 F_N^2 (2 - nu) / (10 G a) [1 - (1 - phi)^(5/3) - 5/6 phi (1 + (1 - phi)^(2/3))],
          // F_N = 4 E* a^3 / (3 R), E* = E0 / (1 - nu^2), phi = F_A / (mu F_N).
          const double G = E0 / (2. * (1. + nu)), Estar = E0 / (1. - nu * nu);
          const double FN = 4. * Estar * a * a * a / (3. * s.load.R), phi = s.tangential.amplitude;
          const double W_md = 9. * mu * mu * FN * FN * (2. - nu) / (10. * G * a) *
                              (1. - std::pow(1. - phi, 5. / 3.) - 5. / 6. * phi * (1. + std::pow(1. - phi, 2. / 3.)));
          result.rows.push_back(compare("dissipated energy per cycle W", "relative", "FE",
                                        "Mindlin-Deresiewicz (1953) 9.87", W_md, W, W_md, s.tolerances.force, dofs,
                                        seconds));
        }
      if (verbose)
        std::cerr << "  W = " << W << " (" << dofs << " DoFs, " << format(seconds) << " s)\n";
    }

    void TangentialStudy::plot_hysteresis(const Oscillation &o, const double uA, HysteresisPlots &plots) const
    {
      const double a = s.load.a;
      Series un{"closed form unloading (9.83)", {}, {}, false}, re{"closed form reloading", {}, {}, false};
      for (int i = 0; i <= 200; ++i)
        {
          const double f = -1. + 2. * i / 200.;
          un.x.push_back(branch_u(o, Branch::unloading, f * o.FA) / uA);
          un.y.push_back(f);
          re.x.push_back(branch_u(o, Branch::reloading, f * o.FA) / uA);
          re.y.push_back(f);
        }
      const double worst = worst_error(result.rows, unloading_u0);
      write_plot(folder, "hysteresis",
                 s.info.name + ": hysteresis loop (fig. 9.36), F_A = " + format(s.tangential.amplitude) + " mu F_N, worst FE u0 error " +
                   format(worst),
                 "u0 / u_A", "F_x / F_A", {un, re, plots.fe_un, plots.fe_re});
      plots.profiles.insert(plots.profiles.begin(), Series{"stick zone r <= c_A", {o.cA / a, o.cA / a}, {-1., 1.}, false});
      write_plot(folder, "displacement_A_to_E",
                 s.info.name + ": FE surface u_x(r) (theta = 0) at the points A to E under the traction of 9.82",
                 "r / a", "u_x / u_A", plots.profiles);
      write_plot(folder, "traction_A_to_E", s.info.name + ": the prescribed traction at A to E (9.82, figs. 9.34-9.35)",
                 "r / a", "tau / (mu p(0))", plots.tractions);
    }
  } // namespace

  FeTangentialCurve fe_tangential_curve(const Scene &scene)
  {
    const Scene s = with_holl_ratio(scene);
    const gradcontact::Medium medium = medium_of(s);
    const double a = s.load.a;
    FeTangentialCurve curve;
    if (s.tangential.study == Study::partial_slip)
      {
        std::vector<double> radii;
        for (const double x : curve_stick_radii(s.tangential))
          radii.push_back(x * a);
        Mode1Model model(s, graded_radii(s, radii));
        for (const double c : radii)
          {
            if (c >= a)
              continue; // the unloaded state c = a (tau = 0)
            const fem::TangentialResult r = solve_partial_slip(s, model, medium, c, {});
            curve.displacement.push_back(r.stick.mean_ux);
            curve.force.push_back(r.force);
          }
        return curve;
      }
    if (s.tangential.study == Study::oscillation)
      {
        const Oscillation o = oscillation_of(s, medium);
        Mode1Model model(s, graded_radii(s, {o.cA}));
        for (const double f : unloading_forces(s.tangential))
          {
            const double u = solve_unloading(s, model, medium, o, f * o.FA, {}).stick.mean_ux;
            curve.displacement.push_back(u);
            curve.force.push_back(f * o.FA);
            curve.displacement.push_back(-u); // reloading: u_re(F) = -u_un(-F)
            curve.force.push_back(-f * o.FA);
          }
        return curve;
      }
    throw std::invalid_argument("scene " + s.file + ": an FE tangential curve needs Tangential/study = partial slip or "
                                "oscillation");
  }

  namespace
  {
    /// Runs the scene's study; false when the FE failed (a row says why).
    bool run_study(const Scene &s, TangentialStudy &study, SceneResult &result)
    {
      try
        {
          switch (s.tangential.study)
            {
              case Study::stiffness:
                study.stiffness();
                break;
              case Study::partial_slip:
                study.partial_slip();
                break;
              case Study::oscillation:
                study.oscillation();
                break;
              case Study::none:
                break;
            }
          return true;
        }
      catch (const std::runtime_error &e)
        {
          result.rows.push_back(failed("FE tangential", "FE", "-", concise(e)));
          return false;
        }
    }

    /// Discretization/accuracy = contract (cases/model/fe_contract.h): the study on the ladder's levels.
    void run_contract(const Scene &s, const fs::path &folder, const bool verbose, SceneResult &result)
    {
      const fem::Material material = fe_material(s);
      run_on_ladder(material, mode1_contract_settings(s, material, 0), s.discretization.force_tolerance, verbose,
                    result, [&](const unsigned int level, LadderLevel &out) {
                      TangentialStudy study(s, folder, verbose, result, level);
                      const bool      solved = run_study(s, study, result);
                      out                    = study.ladder_level;
                      return solved;
                    });
    }
  } // namespace

  SceneResult run_tangential_scene(const Scene &scene, const fs::path &folder, const bool verbose)
  {
    const auto start = std::chrono::steady_clock::now();
    require_kind(scene, SceneKind::tangential, "run_tangential_scene");
    const Scene s = with_holl_ratio(scene);
    SceneResult result = started(s, folder);
    if (s.discretization.contract)
      run_contract(s, folder, verbose, result);
    else
      {
        TangentialStudy study(s, folder, verbose, result);
        run_study(s, study, result);
      }
    result.seconds = seconds_since(start);
    return result;
  }
} // namespace gradcontact::cases
