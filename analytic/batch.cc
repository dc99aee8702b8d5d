#include <analytic/adhesion.h>
#include <analytic/batch.h>
#include <analytic/detail/roots.h>
#include <analytic/errors.h>
#include <analytic/maugis_dugdale.h>
#include <analytic/mdr.h>
#include <analytic/mdr_contact.h>
#include <analytic/normal.h>
#include <analytic/subsurface.h>
#include <analytic/tangential.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <istream>
#include <map>
#include <ostream>

namespace gradcontact::batch
{
  namespace
  {
    using json = nlohmann::json;

    // --- reading a request ------------------------------------------------------------------------

    /// A request's inputs as the tables read them: a missing one is a DomainError naming it and the
    /// case; the equivalent medium is computed once.
    class In
    {
    public:
      explicit In(Request request) : q(std::move(request)) {}

      const Request q;

      double a() const { return need(q.a, "a"); }
      double r() const { return need(q.r, "r"); }
      double d() const { return need(q.d, "d"); }
      double F() const { return need(q.F, "F"); }
      double d0() const { return need(q.d0, "d0"); }
      double dgamma() const { return need(q.dgamma, "dgamma"); }
      double sigma_th() const { return need(q.sigma_th, "sigma_th"); }
      double mu() const { return need(q.mu, "mu"); }
      double c() const { return need(q.c, "c"); }
      double Fx() const { return need(q.Fx, "Fx"); }
      double FA() const { return need(q.FA, "FA"); }
      double u0() const { return need(q.u0, "u0"); }
      double z() const { return need(q.z, "z"); }
      std::string component() const { return need(q.component, "component"); }
      double R() const { return need(q.geometry.R, "geometry.R"); }
      double tan_theta() const { return need(q.geometry.tan_theta, "geometry.tan_theta"); }
      double n() const { return need(q.geometry.n, "geometry.n"); }
      double A() const { return need(q.geometry.A, "geometry.A"); }
      double h0() const { return need(q.geometry.h0, "geometry.h0"); }
      double p0() const { return need(q.geometry.p0, "geometry.p0"); }
      Control control() const { return need(q.control, "control"); }
      Branch branch() const { return need(q.branch, "branch"); }
      Mechanism mechanism() const { return q.mechanism.value_or(Mechanism::governing); }

      GradedHalfSpace body() const
      {
        if (!q.material)
          throw DomainError("material: missing (an object {E0, c0, k, nu})");
        return *q.material;
      }

      Medium medium() const
      {
        if (!medium_)
          medium_ = q.material2 ? gradcontact::medium(body(), *q.material2) : gradcontact::medium(body());
        return *medium_;
      }

      bool is(const char *case_name) const { return q.case_name == case_name; }

    private:
      template <typename T>
      T need(const std::optional<T> &value, const char *name) const
      {
        if (!value)
          throw DomainError(std::string(name) + ": missing (required for case '" + q.case_name + "', quantity '" +
                            q.quantity + "')");
        return *value;
      }

      mutable std::optional<Medium> medium_;
    };

    using Evaluator = std::function<double(const In &)>;
    using QuantityTable = std::map<std::string, Evaluator>;

    struct CaseTable
    {
      QuantityTable closed_form;
      QuantityTable numerical_mdr;
    };

    // --- the profiles of the cases ----------------------------------------------------------------

    // The profile of a power-law-type case for the numerical MDR: the cone is n = 1, every sphere
    // (normal, adhesive or tangential) n = 2 with A = 1/(2R).
    mdr::Profile power_law_profile(const In &q)
    {
      if (q.is("cone"))
        return mdr::power_law(1., q.tan_theta());
      if (q.is("paraboloid") || q.is("jkr_paraboloid") || q.is("tangential_sphere") || q.is("oscillating_sphere"))
        {
          const double R = q.R();
          check::positive("paraboloid", "geometry.R", R);
          return mdr::power_law(2., 1. / (2. * R));
        }
      return mdr::power_law(q.n(), q.A());
    }

    PowerLaw closed_power_law(const In &q)
    {
      if (q.is("cone"))
        return as_power_law(Cone{q.tan_theta()});
      if (q.is("paraboloid") || q.is("jkr_paraboloid"))
        return as_power_law(Paraboloid{q.R()});
      return {q.n(), q.A()};
    }

    // Calls shape(Paraboloid) for the paraboloid cases, which have their own closed forms (9.26, 9.53-9.56),
    // and shape(PowerLaw) for the cone (9.30 at n = 1) and the power law.
    template <typename F>
    auto with_shape(const In &q, const F &shape)
    {
      if (q.is("paraboloid") || q.is("jkr_paraboloid"))
        return shape(Paraboloid{q.R()});
      return shape(closed_power_law(q));
    }

    // The numerical MDR's critical state in the request's bracket (a_lo, a_hi), or in the default one.
    mdr::CriticalState numeric_critical_state(const In &q, const mdr::Profile &f, const Control control)
    {
      if (!q.q.a_lo && !q.q.a_hi)
        return mdr::critical_state(f, q.medium(), q.dgamma(), control);
      const Medium m = q.medium();
      return mdr::critical_state(f, m, q.dgamma(), control, q.q.a_lo.value_or(m.c0 * 1e-9),
                                 q.q.a_hi.value_or(m.c0 * 1e9));
    }

    mdr::Foundation numeric_indentation(const In &q, const double dgamma = 0.)
    {
      return mdr::indentation(power_law_profile(q), q.medium(), q.a(), dgamma);
    }

    // p(0) of a power-law tip by the numerical MDR (with or without adhesion): infinite for n + k <= 1, and
    // for n + k -> 1 out of the quadrature's reach: p(0) ~ int_0 x^(n+k-2) dx, a fraction
    // (1e-308)^((n+k-1)/(k+1)) of which lies below the smallest double; (n+k-1)/(k+1) >= 0.1 keeps it below
    // 1e-30. An explicit refusal, not a wrong number.
    void check_numeric_centre(const In &q, const char *fn)
    {
      if (q.r() != 0.)
        return;
      const double k = q.medium().k;
      const PowerLaw p = closed_power_law(q);
      const double e = (p.n - 1.) + k; // n + k - 1 without the rounding of n + k
      if (!(e > 0.))
        check::fail(fn, "n + k", p.n + k, "must be > 1 for a finite pressure at r = 0 (the tip is too sharp)");
      constexpr double centre_margin = 0.1;
      if (e < centre_margin * (1. + k))
        check::fail((std::string(fn) + " (numerical MDR)").c_str(), "n + k - 1", e,
                    "is too close to 0: the numerical MDR cannot resolve p(0) (its integrand's mass lies below "
                    "the smallest double); use r > 0 or the closed form");
    }

    // --- stresses below a normal contact (subsurface.h) -----------------------------------------------

    /// The one graded body of a stress request (a rigid indenter on it), nu < 1/2.
    GradedHalfSpace stress_body(const In &q)
    {
      if (q.q.material2)
        throw DomainError("material2: the stress below the contact is that of one graded body on a rigid indenter "
                          "(the stress quantities take material only)");
      const GradedHalfSpace body = q.body();
      validate("stress", body);
      if (!(body.nu < 0.5))
        check::fail("stress", "material.nu", body.nu, "must be < 0.5 for the stress field");
      return body;
    }

    /// von_mises or max_shear: the measure a maximum or a scalar stress asks.
    StressMeasure stress_measure(const In &q)
    {
      const std::string component = q.component();
      if (component == "von_mises")
        return StressMeasure::von_mises;
      if (component == "max_shear")
        return StressMeasure::max_shear;
      throw DomainError("component = '" + component + "' must be von_mises or max_shear for a largest stress");
    }

    /// The component `q.component()` of the stress at (r, z) under `load`: the graded Boussinesq field of one body
    /// superposed over the contact's pressure.
    double stress_component(const In &q, const AxisymmetricPressure &load)
    {
      const GradedHalfSpace body = stress_body(q);
      return gradcontact::stress_component(subsurface_stress(PointLoadField(body.k, body.nu), load, q.r(), q.z()),
                                           q.component());
    }

    /// The largest von Mises stress or shear below `load` (largest_stress) and where it is.
    StressMaximum stress_maximum(const In &q, const AxisymmetricPressure &load)
    {
      const GradedHalfSpace body = stress_body(q);
      return largest_stress(PointLoadField(body.k, body.nu), load, stress_measure(q));
    }

    /// The stress quantities of a case whose contact pressure `load(q)` gives.
    template <typename Load>
    void add_stress(CaseTable &t, const Load &load)
    {
      t.closed_form["stress"] = [load](const In &q) { return stress_component(q, load(q)); };
      t.closed_form["max_stress"] = [load](const In &q) { return stress_maximum(q, load(q)).value; };
      t.closed_form["max_stress_radius"] = [load](const In &q) { return stress_maximum(q, load(q)).r; };
      t.closed_form["max_stress_depth"] = [load](const In &q) { return stress_maximum(q, load(q)).z; };
    }

    // --- normal contact -------------------------------------------------------------------------

    // Cone, paraboloid and power law: closed forms 9.20, 9.26, 9.30, and the numerical MDR.
    CaseTable convex_table()
    {
      CaseTable t;
      t.closed_form["depth"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return depth(q.medium(), shape, q.a()); });
      };
      t.closed_form["force"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return force(q.medium(), shape, q.a()); });
      };
      t.closed_form["pressure"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return pressure(q.medium(), shape, q.a(), q.r()); });
      };
      t.closed_form["displacement"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return displacement(q.medium(), shape, q.a(), q.r()); });
      };
      add_stress(t, [](const In &q) {
        return with_shape(q, [&](auto shape) { return contact_pressure(q.medium(), shape, q.a()); });
      });
      t.closed_form["contact_radius"] = [](const In &q) {
        if (q.q.d)
          return contact_radius_from_depth(q.medium(), closed_power_law(q), q.d());
        return contact_radius_from_force(q.medium(), closed_power_law(q), q.F());
      };
      t.numerical_mdr["depth"] = [](const In &q) { return mdr::depth(numeric_indentation(q)); };
      t.numerical_mdr["force"] = [](const In &q) { return mdr::force(numeric_indentation(q), q.medium()); };
      t.numerical_mdr["pressure"] = [](const In &q) {
        check_numeric_centre(q, "power_law pressure");
        return mdr::pressure(numeric_indentation(q), q.medium(), q.r());
      };
      t.numerical_mdr["displacement"] = [](const In &q) {
        return mdr::displacement(numeric_indentation(q), q.medium(), q.r());
      };
      t.numerical_mdr["contact_radius"] = [](const In &q) {
        if (q.q.d)
          return mdr::contact_radius(power_law_profile(q), q.medium(), Control::displacement, q.d());
        return mdr::contact_radius(power_law_profile(q), q.medium(), Control::force, q.F());
      };
      return t;
    }

    // The flat punch (9.14-9.19), loaded by d; with adhesion also its critical state (9.50-9.52).
    CaseTable flat_punch_table(const bool adhesive)
    {
      CaseTable t;
      const auto punch = [](const In &q) { return FlatPunch{q.a()}; };
      t.closed_form["force"] = [punch](const In &q) { return force(q.medium(), punch(q), q.d()); };
      t.closed_form["pressure"] = [punch](const In &q) { return pressure(q.medium(), punch(q), q.d(), q.r()); };
      t.closed_form["displacement"] = [punch](const In &q) {
        return displacement(q.medium(), punch(q), q.d(), q.r());
      };
      add_stress(t, [punch](const In &q) { return contact_pressure(q.medium(), punch(q), q.d()); });
      t.numerical_mdr["force"] = [](const In &q) { return mdr::force(mdr::flat(q.a(), q.d()), q.medium()); };
      t.numerical_mdr["pressure"] = [](const In &q) {
        return mdr::pressure(mdr::flat(q.a(), q.d()), q.medium(), q.r());
      };
      t.numerical_mdr["displacement"] = [](const In &q) {
        return mdr::displacement(mdr::flat(q.a(), q.d()), q.medium(), q.r());
      };
      if (!adhesive)
        return t;
      const auto critical = [punch](const In &q) { return jkr::critical_state(q.medium(), punch(q), q.dgamma()); };
      t.closed_form["critical_depth"] = [critical](const In &q) { return critical(q).depth; };
      t.closed_form["critical_force"] = [critical](const In &q) { return critical(q).force; };
      t.closed_form["critical_radius"] = [critical](const In &q) { return critical(q).radius; };
      // Numerically: the separation condition w1D(a) = -Delta_l(a) (9.46) of the rigid translation
      // (d = g(a) - Delta_l(a) with g = 0: the punch face is flat), the force from 9.11.
      const auto critical_depth = [](const In &q) {
        return mdr::depth(mdr::indentation(mdr::power_law(1., 0.), q.medium(), q.a(), q.dgamma()));
      };
      t.numerical_mdr["critical_depth"] = critical_depth;
      t.numerical_mdr["critical_force"] = [critical_depth](const In &q) {
        return mdr::force(mdr::flat(q.a(), critical_depth(q)), q.medium());
      };
      t.numerical_mdr["critical_radius"] = [](const In &q) { return q.a(); };
      return t;
    }

    // The concave punch in complete contact (9.31-9.36), loaded by its centre displacement d0.
    CaseTable concave_table()
    {
      CaseTable t;
      const auto punch = [](const In &q) { return ConcavePunch{q.a(), q.h0()}; };
      t.closed_form["force"] = [punch](const In &q) { return force(q.medium(), punch(q), q.d0()); };
      t.closed_form["pressure"] = [punch](const In &q) { return pressure(q.medium(), punch(q), q.d0(), q.r()); };
      t.closed_form["displacement"] = [punch](const In &q) {
        return displacement(q.medium(), punch(q), q.d0(), q.r());
      };
      // Complete contact ends at the punch's edge like a flat punch's: the edge exponent (k - 1)/2 (9.34).
      add_stress(t, [punch](const In &q) {
        const Medium       m = q.medium();
        const ConcavePunch p = punch(q);
        const double       d0 = q.d0();
        force(m, p, d0); // complete contact (9.35), or an error naming d0
        return contact_pressure(p.a, (m.k - 1) / 2, [m, p, d0](const double rho) { return pressure(m, p, d0, rho); });
      });
      const auto foundation = [punch](const In &q) {
        const ConcavePunch p = punch(q);
        force(q.medium(), p, q.d0()); // the validity condition of complete contact (9.35) holds here too
        return mdr::indentation_to_depth(mdr::concave_paraboloid(p.a, p.h0), q.medium().k, p.a, q.d0());
      };
      t.numerical_mdr["force"] = [foundation](const In &q) { return mdr::force(foundation(q), q.medium()); };
      t.numerical_mdr["pressure"] = [foundation](const In &q) {
        return mdr::pressure(foundation(q), q.medium(), q.r());
      };
      t.numerical_mdr["displacement"] = [foundation](const In &q) {
        return mdr::displacement(foundation(q), q.medium(), q.r());
      };
      return t;
    }

    // A prescribed uniform pressure on r < a: constant_pressure (p0, 9.37-9.40) and optimal_profile
    // (p = -sigma_th, 9.69-9.74).
    CaseTable pressure_load_table(const bool optimal)
    {
      CaseTable t;
      const auto load = [optimal](const In &q) {
        if (optimal)
          check::positive("optimal_profile", "sigma_th", q.sigma_th());
        return UniformPressure{q.a(), optimal ? -q.sigma_th() : q.p0()};
      };
      t.closed_form["depth"] = [load](const In &q) { return centre_displacement(q.medium(), load(q)); };
      t.closed_form["pressure"] = [load](const In &q) {
        const UniformPressure l = load(q);
        const double r = q.r();
        check::non_negative("pressure", "r", r);
        return r <= l.a ? l.p0 : 0.; // the load itself
      };
      t.closed_form["force"] = [load](const In &q) { return force(load(q)); };
      t.closed_form["displacement"] = [load](const In &q) { return displacement(q.medium(), load(q), q.r()); };
      add_stress(t, [load](const In &q) { return contact_pressure(load(q)); });
      const auto foundation = [load](const In &q) {
        const UniformPressure l = load(q);
        return mdr::from_pressure([l](double r) { return r <= l.a ? l.p0 : 0.; }, q.medium(), l.a);
      };
      t.numerical_mdr["depth"] = [foundation](const In &q) { return mdr::depth(foundation(q)); };
      t.numerical_mdr["force"] = [foundation](const In &q) { return mdr::force(foundation(q), q.medium()); };
      t.numerical_mdr["displacement"] = [foundation](const In &q) {
        return mdr::displacement(foundation(q), q.medium(), q.r());
      };
      if (!optimal)
        return t;
      t.closed_form["profile"] = [](const In &q) {
        return jkr::profile(q.medium(), jkr::OptimalProfile{q.a(), q.sigma_th()}, q.r());
      };
      t.numerical_mdr["profile"] = [foundation](const In &q) {
        const double r = q.r();
        check::closed_interval("optimal_profile profile", "r", r, 0., q.a());
        const mdr::Foundation w1d = foundation(q);
        return mdr::displacement(w1d, q.medium(), 0.) - mdr::displacement(w1d, q.medium(), r); // f = w(0) - w(r)
      };
      return t;
    }

    // --- adhesion -------------------------------------------------------------------------------

    // JKR paraboloid and power law (9.53-9.63).
    CaseTable jkr_convex_table()
    {
      CaseTable t;
      t.closed_form["depth"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return jkr::depth(q.medium(), shape, q.dgamma(), q.a()); });
      };
      t.closed_form["force"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return jkr::force(q.medium(), shape, q.dgamma(), q.a()); });
      };
      t.closed_form["pressure"] = [](const In &q) {
        return with_shape(q, [&](auto shape) { return jkr::pressure(q.medium(), shape, q.dgamma(), q.a(), q.r()); });
      };
      // The adhesive term is the flat punch's: the edge exponent (k - 1)/2.
      add_stress(t, [](const In &q) {
        return with_shape(q, [&](auto shape) {
          const Medium m = q.medium();
          const double dgamma = q.dgamma(), a = q.a();
          return contact_pressure(a, (m.k - 1) / 2, [m, shape, dgamma, a](const double rho) {
            return jkr::pressure(m, shape, dgamma, a, rho);
          });
        });
      });
      t.closed_form["displacement"] = [](const In &q) {
        return with_shape(q,
                          [&](auto shape) { return jkr::displacement(q.medium(), shape, q.dgamma(), q.a(), q.r()); });
      };
      const auto critical = [](const In &q, const Control control) {
        return with_shape(q, [&](auto shape) { return jkr::critical_state(q.medium(), shape, q.dgamma(), control); });
      };
      t.closed_form["critical_radius"] = [critical](const In &q) { return critical(q, q.control()).radius; };
      t.closed_form["critical_depth"] = [critical](const In &q) { return critical(q, q.control()).depth; };
      t.closed_form["critical_force"] = [critical](const In &q) { return critical(q, q.control()).force; };
      // a from d or F on the stable branch a > a_c (a_c of displacement control for d, of force control
      // for F), where d(a) and F(a) increase.
      t.closed_form["contact_radius"] = [critical](const In &q) {
        const bool by_depth = q.q.d.has_value();
        const double target = by_depth ? q.d() : q.F();
        check::finite("contact_radius", by_depth ? "d" : "F", target);
        const jkr::CriticalState c = critical(q, by_depth ? Control::displacement : Control::force);
        // d(a) = g(a) - Delta_l(a) and F_N(a) = F(a) - F_punch(a, Delta_l(a)) (9.49): jkr::depth and jkr::force
        // as their two power laws.
        const Medium m = q.medium();
        const double k = m.k, dgamma = q.dgamma();
        const double n = q.is("paraboloid") || q.is("jkr_paraboloid") ? 2. : closed_power_law(q).n;
        const auto parts = [&](const double a) {
          return with_shape(q, [&](auto shape) {
            const double dl = jkr::delta_ell(m, dgamma, a);
            return by_depth ? detail::PowerLawParts{depth(m, shape, a), dl}
                            : detail::PowerLawParts{force(m, shape, a), force(m, FlatPunch{a}, dl)};
          });
        };
        return detail::stable_branch_root(parts, by_depth ? n : n + k + 1., by_depth ? (1. - k) / 2. : (3. + k) / 2.,
                                          target, c.radius, by_depth ? c.depth : c.force, by_depth ? "d" : "F");
      };

      t.numerical_mdr["depth"] = [](const In &q) { return mdr::depth(numeric_indentation(q, q.dgamma())); };
      t.numerical_mdr["force"] = [](const In &q) {
        return mdr::force(numeric_indentation(q, q.dgamma()), q.medium());
      };
      t.numerical_mdr["pressure"] = [](const In &q) {
        check_numeric_centre(q, q.is("jkr_paraboloid") ? "jkr_paraboloid pressure" : "jkr_power_law pressure");
        return mdr::pressure(numeric_indentation(q, q.dgamma()), q.medium(), q.r());
      };
      t.numerical_mdr["displacement"] = [](const In &q) {
        return mdr::displacement(numeric_indentation(q, q.dgamma()), q.medium(), q.r());
      };
      t.numerical_mdr["contact_radius"] = [](const In &q) {
        const Control given = q.q.d ? Control::displacement : Control::force;
        const double target = q.q.d ? q.d() : q.F();
        check::finite("contact_radius", q.q.d ? "d" : "F", target);
        const mdr::Profile f = power_law_profile(q);
        return mdr::contact_radius(f, q.medium(), given, target, q.dgamma(), numeric_critical_state(q, f, given));
      };
      const auto numeric_critical = [](const In &q) {
        return numeric_critical_state(q, power_law_profile(q), q.control());
      };
      t.numerical_mdr["critical_radius"] = [numeric_critical](const In &q) { return numeric_critical(q).radius; };
      t.numerical_mdr["critical_depth"] = [numeric_critical](const In &q) { return numeric_critical(q).depth; };
      t.numerical_mdr["critical_force"] = [numeric_critical](const In &q) { return numeric_critical(q).force; };
      return t;
    }

    // The concave punch's two separation mechanisms and their transition (9.64-9.68).
    CaseTable jkr_concave_table()
    {
      CaseTable t;
      const auto punch = [](const In &q) { return ConcavePunch{q.a(), q.h0()}; };
      const auto state = [punch](const In &q) {
        return jkr::critical_state(q.medium(), punch(q), q.dgamma(), q.sigma_th(), q.mechanism());
      };
      t.closed_form["critical_depth"] = [state](const In &q) { return state(q).depth; };
      t.closed_form["critical_force"] = [state](const In &q) { return state(q).force; };
      t.closed_form["critical_radius"] = [state](const In &q) { return state(q).radius; };
      t.closed_form["pressure"] = [punch](const In &q) {
        return jkr::critical_pressure(q.medium(), punch(q), q.dgamma(), q.sigma_th(), q.mechanism(), q.r());
      };
      t.closed_form["transition_h0"] = [](const In &q) {
        return jkr::transition_h0(q.medium(), q.a(), q.dgamma(), q.sigma_th());
      };
      const auto numeric = [](const In &q) {
        return mdr::concave_critical_state(q.medium(), q.a(), q.h0(), q.dgamma(), q.sigma_th(), q.mechanism());
      };
      t.numerical_mdr["critical_depth"] = [numeric](const In &q) { return numeric(q).depth; };
      t.numerical_mdr["critical_force"] = [numeric](const In &q) { return numeric(q).force; };
      t.numerical_mdr["critical_radius"] = [](const In &q) { return q.a(); };
      t.numerical_mdr["pressure"] = [numeric](const In &q) {
        const Medium m = q.medium();
        const mdr::Foundation w1d =
          mdr::indentation_to_depth(mdr::concave_paraboloid(q.a(), q.h0()), m.k, q.a(), numeric(q).d0);
        return mdr::pressure(w1d, m, q.r());
      };
      t.numerical_mdr["transition_h0"] = [](const In &q) {
        return mdr::concave_transition_h0(q.medium(), q.a(), q.dgamma(), q.sigma_th());
      };
      return t;
    }

    // --- tangential -----------------------------------------------------------------------------

    tangential::SphereSlip slip(const In &q) { return {q.R(), q.mu()}; }

    mdr::PartialSlip numeric_slip(const In &q) { return {power_law_profile(q), q.medium(), q.mu(), q.a()}; }

    // Partial slip of a sphere under a rising tangential force (9.80).
    CaseTable tangential_sphere_table()
    {
      CaseTable t;
      // At the stick radius c when given, else under the force Fx (without forming c: 1 - (c/a)^e from
      // the force fraction, tangential.h).
      t.closed_form["traction"] = [](const In &q) {
        return q.q.c ? tangential::traction(q.medium(), slip(q), q.a(), q.c(), q.r())
                     : tangential::traction_at_force(q.medium(), slip(q), q.a(), q.Fx(), q.r());
      };
      t.closed_form["tangential_force"] = [](const In &q) {
        return q.q.c ? tangential::tangential_force(q.medium(), slip(q), q.a(), q.c())
                     : tangential::tangential_force_at_force(q.medium(), slip(q), q.a(), q.Fx());
      };
      t.closed_form["tangential_displacement"] = [](const In &q) {
        return q.q.c ? tangential::tangential_displacement(q.medium(), slip(q), q.a(), q.c())
                     : tangential::tangential_displacement_at_force(q.medium(), slip(q), q.a(), q.Fx());
      };
      t.closed_form["stick_radius"] = [](const In &q) {
        return tangential::stick_radius(q.medium(), slip(q), q.a(), q.Fx());
      };
      const auto numeric_stick = [](const In &q, const mdr::PartialSlip &s) {
        if (!q.q.c)
          return s.stick_radius(q.Fx());
        check::closed_interval("tangential_sphere", "c (stick radius)", q.c(), 0., q.a());
        return q.c();
      };
      t.numerical_mdr["traction"] = [numeric_stick](const In &q) {
        const mdr::PartialSlip s = numeric_slip(q);
        return q.q.c ? s.traction(numeric_stick(q, s), q.r()) : s.traction_at_force(q.Fx(), q.r());
      };
      t.numerical_mdr["tangential_force"] = [numeric_stick](const In &q) {
        const mdr::PartialSlip s = numeric_slip(q);
        return q.q.c ? s.tangential_force(numeric_stick(q, s)) : s.tangential_force_at_force(q.Fx());
      };
      t.numerical_mdr["tangential_displacement"] = [numeric_stick](const In &q) {
        const mdr::PartialSlip s = numeric_slip(q);
        return q.q.c ? s.tangential_displacement(numeric_stick(q, s)) : s.tangential_displacement_at_force(q.Fx());
      };
      t.numerical_mdr["stick_radius"] = [numeric_stick](const In &q) { return numeric_stick(q, numeric_slip(q)); };
      return t;
    }

    // The oscillation between +-F_A after the loading (9.81-9.87).
    CaseTable oscillating_sphere_table()
    {
      CaseTable t;
      t.closed_form["traction"] = [](const In &q) {
        return tangential::traction(q.medium(), slip(q), q.a(), q.FA(), q.branch(), q.Fx(), q.r());
      };
      t.closed_form["tangential_displacement"] = [](const In &q) {
        return tangential::tangential_displacement(q.medium(), slip(q), q.a(), q.FA(), q.branch(), q.Fx());
      };
      t.closed_form["hysteresis_force"] = [](const In &q) {
        return tangential::hysteresis_force(q.medium(), slip(q), q.a(), q.FA(), q.branch(), q.u0());
      };
      t.closed_form["tangential_force"] = t.closed_form["hysteresis_force"];
      t.closed_form["dissipated_energy"] = [](const In &q) {
        return tangential::dissipated_energy(q.medium(), slip(q), q.a(), q.FA());
      };
      t.numerical_mdr["traction"] = [](const In &q) {
        return numeric_slip(q).traction(q.FA(), q.branch(), q.Fx(), q.r());
      };
      t.numerical_mdr["tangential_displacement"] = [](const In &q) {
        return numeric_slip(q).tangential_displacement(q.FA(), q.branch(), q.Fx());
      };
      t.numerical_mdr["hysteresis_force"] = [](const In &q) {
        return numeric_slip(q).hysteresis_force(q.FA(), q.branch(), q.u0());
      };
      t.numerical_mdr["tangential_force"] = t.numerical_mdr["hysteresis_force"];
      t.numerical_mdr["dissipated_energy"] = [](const In &q) { return numeric_slip(q).dissipated_energy(q.FA()); };
      return t;
    }

    // The coefficients of one graded body (9.5-9.7, 9.78-9.79) and kappa of the power law.
    CaseTable coefficients_table()
    {
      CaseTable t;
      const auto body = [](const In &q) {
        const GradedHalfSpace b = q.body();
        validate("coefficients", b);
        return b;
      };
      t.closed_form["beta"] = [body](const In &q) { const auto b = body(q); return beta(b.k, b.nu); };
      t.closed_form["C"] = [body](const In &q) { const auto b = body(q); return C(b.k, b.nu); };
      t.closed_form["h_N"] = [body](const In &q) { const auto b = body(q); return h_N(b.k, b.nu); };
      t.closed_form["h_T"] = [body](const In &q) { const auto b = body(q); return h_T(b.k, b.nu); };
      t.closed_form["alpha"] = [](const In &q) { return q.medium().alpha(); };
      t.closed_form["kappa"] = [](const In &q) { return kappa(q.n(), q.body().k); };
      return t;
    }

    // The Maugis-Dugdale adhesion of a rigid paraboloid (Maugis, J. Colloid Interface Sci. 150 (1992) 243-269;
    // analytic/maugis_dugdale.h): not the chapter's (JKR), the reference of the cohesive-zone FE; sigma_th is the
    // Dugdale stress sigma_0. At k = 0 Maugis' closed form and Tabor parameter, on the graded medium its MDR
    // solution and the Tabor parameter generalised by the chapter's Delta_l (the same header).
    CaseTable maugis_dugdale_table()
    {
      CaseTable  t;
      const auto homogeneous = [](const In &q) {
        const GradedHalfSpace b = q.body();
        validate("maugis_dugdale", b);
        return b.k == 0;
      };
      const auto E_star = [](const In &q) {
        const GradedHalfSpace b = q.body();
        return b.E0 / (1 - b.nu * b.nu);
      };
      // The law and the sphere: sigma_th, dgamma and geometry.R, each > 0.
      const auto law = [](const In &q) {
        check::positive("maugis_dugdale", "sigma_th", q.sigma_th());
        check::positive("maugis_dugdale", "dgamma", q.dgamma());
        check::positive("maugis_dugdale", "geometry.R", q.R());
        return maugis_dugdale::Dugdale{q.sigma_th(), q.dgamma()};
      };
      const auto lambda = [E_star, law](const In &q) {
        law(q);
        return maugis_dugdale::tabor_parameter(q.sigma_th(), q.dgamma(), q.R(), E_star(q));
      };
      const auto no_jump = [](const In &q, const std::string &where) {
        return DomainError("maugis_dugdale: control = displacement has no jump " + where + " (sigma_th = " +
                           check::format(q.sigma_th()) + "): the contact shrinks to nothing; valid: a larger sigma_th");
      };
      // The pull-off in SI units: radius, depth, force.
      const auto critical = [=](const In &q) -> std::array<double, 3> {
        if (!homogeneous(q))
          {
            const auto p = maugis_dugdale::pull_off(q.medium(), Paraboloid{q.R()}, law(q), q.control());
            if (!p.exists)
              throw no_jump(q, "on this graded medium");
            return {p.state.radius, p.state.depth, p.state.force};
          }
        const double l = lambda(q);
        if (!(l >= 1e-3 && l <= 1e3))
          throw DomainError("maugis_dugdale: sigma_th = " + check::format(q.sigma_th()) + " gives the Tabor parameter " +
                            check::format(l) + "; valid: a sigma_th with the Tabor parameter in [1e-3, 1e3]");
        const maugis_dugdale::PullOff p = maugis_dugdale::pull_off(l, q.control());
        if (!p.exists)
          throw no_jump(q, "at the Tabor parameter " + check::format(l));
        const auto scale = maugis_dugdale::scales(q.dgamma(), q.R(), E_star(q));
        return {p.state.A * scale.length, p.state.Delta * scale.depth, p.state.P * scale.force};
      };
      t.closed_form["tabor_parameter"] = [=](const In &q) {
        if (!homogeneous(q))
          {
            return maugis_dugdale::tabor_parameter(q.medium(), Paraboloid{q.R()}, law(q));
          }
        return lambda(q);
      };
      t.closed_form["critical_radius"] = [critical](const In &q) { return critical(q)[0]; };
      t.closed_form["critical_depth"]  = [critical](const In &q) { return critical(q)[1]; };
      t.closed_form["critical_force"]  = [critical](const In &q) { return critical(q)[2]; };
      return t;
    }

    // --- dispatch -------------------------------------------------------------------------------

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
        t["maugis_dugdale"] = maugis_dugdale_table();
        return t;
      }();
      return all;
    }


    const Evaluator &find_evaluator(const Request &q)
    {
      const auto &all = tables();
      const auto c = all.find(q.case_name);
      if (c == all.end())
        throw DomainError("case = '" + q.case_name + "' is unknown (valid: " + check::keys(all) + ")");
      const QuantityTable &table = q.method == Method::numerical_mdr ? c->second.numerical_mdr : c->second.closed_form;
      const auto f = table.find(q.quantity);
      if (f == table.end())
        throw DomainError("quantity = '" + q.quantity + "' is not available for case '" + q.case_name +
                          "' with method '" + method_name(q.method) + "' (valid: " + check::keys(table) + ")");
      return f->second;
    }

    /// The value, or a DomainError naming the request when it is not finite (an overflow past the
    /// range of double, or an expression undefined at these inputs).
    double checked(const double value, const Request &q)
    {
      if (!std::isfinite(value))
        {
          json inputs = to_json(q);
          inputs.erase("case");
          inputs.erase("quantity");
          inputs.erase("method");
          throw DomainError("case '" + q.case_name + "', quantity '" + q.quantity + "' (" + method_name(q.method) +
                            "): non-finite result " + check::format(value) + " for the inputs " + inputs.dump() +
                            " (outside the range of double precision, or undefined there)");
        }
      return value;
    }

  } // namespace

  double evaluate(const Request &request)
  {
    const In in(request);
    return checked(find_evaluator(request)(in), request);
  }

  struct Prepared::Impl
  {
    explicit Impl(const Request &request) : in(request), f(find_evaluator(request)) {}
    In in;
    const Evaluator &f;
  };

  double Prepared::operator()() const { return checked(impl_->f(impl_->in), impl_->in.q); }

  Prepared prepare(const Request &request)
  {
    Prepared p;
    p.impl_ = std::make_shared<const Prepared::Impl>(request);
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
        answer.value = evaluate(parse(j));
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
