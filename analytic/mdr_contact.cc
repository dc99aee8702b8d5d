#include <analytic/detail/quadrature.h>
#include <analytic/detail/roots.h>
#include <analytic/errors.h>
#include <analytic/mdr_contact.h>

#include <boost/math/tools/toms748_solve.hpp>

#include <cstdint>
#include <utility>

namespace gradcontact::mdr
{
  namespace
  {
    double depth_at(const Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return depth(indentation(f, m, a, dgamma));
    }

    double force_at(const Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return force(indentation(f, m, a, dgamma), m);
    }

    const char *target_name(const Control given) { return given == Control::displacement ? "d" : "F"; }
  } // namespace

  double contact_radius(const Profile &profile, const Medium &m, const Control given, const double target)
  {
    check::positive("contact_radius", target_name(given), target);
    if (given == Control::displacement)
      return detail::solve_increasing([&](double a) { return depth_at(profile, m, a); }, target, m.c0,
                                      "contact_radius");
    return detail::solve_increasing([&](double a) { return force_at(profile, m, a); }, target, m.c0,
                                    "contact_radius");
  }

  double contact_radius(const Profile &profile, const Medium &m, const Control given, const double target,
                        const double dgamma, const CriticalState &critical)
  {
    check::finite("contact_radius", target_name(given), target);
    const bool by_depth = given == Control::displacement;
    const auto value = [&](const double a) {
      return by_depth ? depth_at(profile, m, a, dgamma) : force_at(profile, m, a, dgamma);
    };
    return detail::stable_branch_root(value, target, critical.radius, by_depth ? critical.depth : critical.force,
                                      target_name(given));
  }

  Profile concave_paraboloid(const double a, const double h0)
  {
    const double c = h0 / (a * a); // f = -h0 r^2 / a^2 (9.31)
    return {[c](double r) { return -c * r * r; }, [c](double r) { return -2. * c * r; },
            [c](double) { return -2. * c; }};
  }

  namespace
  {
    // The centre displacements of the two mechanisms: periphery d0 = g(a) - Delta_l(a) (9.46); centre
    // p(0) = -sigma_th with p(0) = p_shape + d0 p_unit (the profile at d0 = 0 plus a unit flat punch).
    double periphery_d0(const Profile &f, const Medium &m, const double a, const double dgamma)
    {
      return depth(indentation(f, m, a, dgamma));
    }

    double centre_d0(const Profile &f, const Medium &m, const double a, const double sigma_th)
    {
      const double p_shape = pressure(indentation_to_depth(f, m.k, a, 0.), m, 0.);
      const double p_unit = pressure(flat(a, 1.), m, 0.);
      return (-sigma_th - p_shape) / p_unit;
    }
  } // namespace

  ConcaveState concave_critical_state(const Medium &m, const double a, const double h0, const double dgamma,
                                      const double sigma_th, const Mechanism mechanism)
  {
    check::positive("jkr_concave", "sigma_th", sigma_th);
    check::non_negative("jkr_concave", "geometry.h0", h0);
    const Profile f = concave_paraboloid(a, h0);
    const auto state = [&](const double d0) {
      return ConcaveState{d0, d0 + h0, force(indentation_to_depth(f, m.k, a, d0), m)};
    };
    if (mechanism == Mechanism::periphery)
      return state(periphery_d0(f, m, a, dgamma));
    if (mechanism == Mechanism::centre)
      return state(centre_d0(f, m, a, sigma_th));
    const ConcaveState P = state(periphery_d0(f, m, a, dgamma)), C = state(centre_d0(f, m, a, sigma_th));
    return P.depth >= C.depth ? P : C;
  }

  double concave_transition_h0(const Medium &m, const double a, const double dgamma, const double sigma_th)
  {
    check::positive("jkr_concave", "sigma_th", sigma_th);
    // rim_P(h0) - rim_C(h0) = d0_P(h0) - d0_C(h0) is linear in h0: two evaluations give its root.
    const auto difference = [&](const double h0) {
      const Profile f = concave_paraboloid(a, h0);
      return periphery_d0(f, m, a, dgamma) - centre_d0(f, m, a, sigma_th);
    };
    const double scale = a; // any non-zero h0 serves a linear function
    const double f0 = difference(0.), f1 = difference(scale);
    const double h0 = -f0 * scale / (f1 - f0);
    if (!(h0 > 0.))
      check::fail("jkr_concave transition_h0", "sigma_th", sigma_th,
                  "is too small: the centre separates first for every h0 >= 0 (no transition)");
    return h0;
  }

  PartialSlip::PartialSlip(Profile profile, const Medium &m, const double mu, const double a)
    : profile_(std::move(profile)), m_(m), mu_(mu), a_(a)
  {
    check::positive("tangential", "mu (friction coefficient)", mu);
    check::positive("tangential", "a", a);
  }

  double PartialSlip::normal_force(const double b) const { return b > 0. ? force_at(profile_, m_, b) : 0.; }

  double PartialSlip::depth(const double b) const { return b > 0. ? depth_at(profile_, m_, b) : 0.; }

  double PartialSlip::pressure(const double b, const double r) const
  {
    return b > 0. ? mdr::pressure(indentation(profile_, m_, b), m_, r) : 0.;
  }

  double PartialSlip::radius_for(const double dF) const
  {
    const double FNa = normal_force(a_);
    const double target = FNa - dF / mu_;
    if (!(target >= 0. && target <= FNa))
      check::fail("tangential", "Fx", dF, "gives gross slip (|dF| must stay below mu F_N)");
    if (target == 0.)
      return 0.;
    const double g_lo = -target, g_hi = FNa - target;
    if (g_hi == 0.)
      return a_;
    std::uintmax_t iterations = 200;
    const auto root = boost::math::tools::toms748_solve([&](double b) { return normal_force(b) - target; }, 0., a_,
                                                        g_lo, g_hi, boost::math::tools::eps_tolerance<double>(50),
                                                        iterations);
    return 0.5 * (root.first + root.second);
  }

  double PartialSlip::traction(const double c, const double r) const
  {
    return mu_ * (pressure(a_, r) - pressure(c, r)); // 9.77
  }

  double PartialSlip::tangential_force(const double c) const
  {
    return mu_ * (normal_force(a_) - normal_force(c));
  }

  double PartialSlip::tangential_displacement(const double c) const
  {
    return mu_ * m_.alpha() * (depth(a_) - depth(c));
  }

  double PartialSlip::stick_radius(const double Fx) const
  {
    check::non_negative("tangential_sphere", "Fx", Fx);
    return radius_for(Fx);
  }

  void PartialSlip::check_amplitude(const double FA) const
  {
    const double limit = mu_ * normal_force(a_);
    if (!(FA > 0. && FA < limit))
      check::fail("oscillating_sphere", "FA", FA,
                  "is outside (0, mu F_N) = (0, " + check::format(limit) + "): gross slip");
  }

  double PartialSlip::traction(const double FA, const Branch branch, const double Fx, const double r) const
  {
    check_amplitude(FA);
    const double c = radius_for(FA);
    const auto pair = [&](const double outer, const double inner) { return pressure(outer, r) - pressure(inner, r); };
    if (branch == Branch::loading)
      return mu_ * pair(a_, radius_for(Fx));
    check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
    const double dF = branch == Branch::unloading ? FA - Fx : Fx + FA;
    const double b = radius_for(dF / 2.);
    const double tau_A = mu_ * pair(a_, c);
    const double change = 2. * mu_ * pair(a_, b); // 9.81
    return branch == Branch::unloading ? tau_A - change : -tau_A + change;
  }

  double PartialSlip::tangential_displacement(const double FA, const Branch branch, const double Fx) const
  {
    check_amplitude(FA);
    const double c = radius_for(FA);
    const double uA = mu_ * m_.alpha() * (depth(a_) - depth(c));
    if (branch == Branch::loading)
      return mu_ * m_.alpha() * (depth(a_) - depth(radius_for(Fx)));
    check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
    const double dF = branch == Branch::unloading ? FA - Fx : Fx + FA;
    const double b = radius_for(dF / 2.);
    const double change = 2. * mu_ * m_.alpha() * (depth(a_) - depth(b));
    return branch == Branch::unloading ? uA - change : -uA + change;
  }

  double PartialSlip::hysteresis_force(const double FA, const Branch branch, const double u0) const
  {
    check_amplitude(FA);
    const double c = radius_for(FA);
    const double da = depth(a_);
    const double uA = mu_ * m_.alpha() * (da - depth(c));
    const double span = branch == Branch::loading ? u0 : (branch == Branch::unloading ? uA - u0 : u0 + uA);
    const double factor = branch == Branch::loading ? 1. : 2.;
    const double lo = branch == Branch::loading ? 0. : -uA;
    check::closed_interval("oscillating_sphere", "u0", u0, lo, uA);
    // span = factor mu alpha (d(a) - d(b)): solve d(b) for b, then the force change.
    const double target = da - span / (factor * mu_ * m_.alpha());
    double b = 0.;
    if (target > 0.)
      b = detail::solve_increasing([&](double x) { return depth(x); }, target, a_ / 2., "hysteresis b");
    const double change = factor * mu_ * (normal_force(a_) - normal_force(b));
    if (branch == Branch::loading)
      return change;
    return branch == Branch::unloading ? FA - change : -FA + change;
  }

  double PartialSlip::dissipated_energy(const double FA) const
  {
    // The loop area int (F_reloading - F_unloading) du over [-uA, uA] = -2 int F_unloading(u) du
    // (F_reloading(u) = -F_unloading(-u); the reloading branch lies above), parametrised by the
    // annulus radius b in [c, a]: u(b) = uA - 2 mu alpha (d(a) - d(b)), F(b) = FA - 2 mu (F_N(a) - F_N(b)).
    check_amplitude(FA);
    const double c = radius_for(FA), FNa = normal_force(a_);
    const auto integrand = [&](const double b, double, double) {
      const double F = FA - 2. * mu_ * (FNa - normal_force(b));
      const double du_db = 2. * mu_ * m_.alpha() * equivalent_profile_slope(profile_, m_.k, b);
      return F * du_db;
    };
    return -2. * detail::integrate_with_distances(integrand, c, a_, 1e-12);
  }
} // namespace gradcontact::mdr
