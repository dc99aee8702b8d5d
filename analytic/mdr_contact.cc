#include <analytic/detail/quadrature.h>
#include <analytic/detail/roots.h>
#include <analytic/errors.h>
#include <analytic/mdr_contact.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace gradcontact::mdr
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    double depth_at(const Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return depth(indentation(f, m, a, dgamma));
    }

    double force_at(const Profile &f, const Medium &m, const double a, const double dgamma = 0.)
    {
      return force(indentation(f, m, a, dgamma), m);
    }

    const char *target_name(const Control given) { return given == Control::displacement ? "d" : "F"; }

    /// FA/(mu F_N) up to which PartialSlip's loop_* forms give the middle of an oscillation loop.
    constexpr double small_loop = 0.25;

    /// The N-point Gauss-Legendre rule on [-1, 1] (nodes ascending).
    struct GaussLegendre
    {
      static constexpr int N = 40;
      double t[N], w[N];

      /// P_0 ... P_N at x by the three-term recurrence.
      static void legendre(const double x, double *P)
      {
        P[0] = 1.;
        P[1] = x;
        for (int n = 1; n < N; ++n)
          P[n + 1] = ((2. * n + 1.) * x * P[n] - n * P[n - 1]) / (n + 1.);
      }

      GaussLegendre()
      {
        double P[N + 1];
        for (int i = 0; i < N; ++i)
          {
            double x = -std::cos(pi * (i + 0.75) / (N + 0.5)); // Newton's method on P_N from this estimate
            for (int it = 0; it < 100; ++it)
              {
                legendre(x, P);
                const double dx = P[N] * (x * x - 1.) / (N * (x * P[N] - P[N - 1]));
                x -= dx;
                if (std::abs(dx) <= 1e-17)
                  break;
              }
            legendre(x, P);
            const double dP = N * (x * P[N] - P[N - 1]) / (x * x - 1.);
            t[i] = x;
            w[i] = 2. / ((1. - x * x) * dP * dP);
          }
      }
    };

    const GaussLegendre &gauss_legendre()
    {
      static const GaussLegendre rule;
      return rule;
    }

    /// int_lo^(lo + length) f(x) dx by the Gauss-Legendre rule (signed for length < 0). The length is given,
    /// not formed as hi - lo: a short interval next to a large lo would lose eps lo / length.
    template <class F>
    double gauss_integral(const F &f, const double lo, const double length)
    {
      const GaussLegendre &rule = gauss_legendre();
      const double half = 0.5 * length;
      double sum = 0.;
      for (int i = 0; i < GaussLegendre::N; ++i)
        sum += rule.w[i] * f(lo + half * (1. + rule.t[i]));
      return half * sum;
    }

    /// A function on [lo, lo + X] as the Legendre series through its samples at the Gauss nodes, with its
    /// integral from lo (the series of the antiderivative). For a function analytic in an ellipse around the
    /// interval both are exact to eps of the largest value times a small constant (absolute, not relative to
    /// small values).
    struct LegendreSeries
    {
      static constexpr int N = GaussLegendre::N;
      double lo = 0., half = 0., c[N] = {};

      template <class F>
      LegendreSeries(const F &fun, const double lo_, const double X) : lo(lo_), half(0.5 * X)
      {
        const GaussLegendre &rule = gauss_legendre();
        double P[N + 1];
        for (int j = 0; j < N; ++j)
          {
            GaussLegendre::legendre(rule.t[j], P);
            const double f = fun(lo + half * (1. + rule.t[j]));
            for (int n = 0; n < N; ++n)
              c[n] += (2. * n + 1.) / 2. * rule.w[j] * P[n] * f;
          }
      }

      double value(const double x) const
      {
        double P[N + 1], sum = 0.;
        GaussLegendre::legendre((x - lo) / half - 1., P);
        for (int n = 0; n < N; ++n)
          sum += c[n] * P[n];
        return sum;
      }

      /// int_lo^x, from int_-1^t P_0 = t + 1 and int_-1^t P_n = (P_(n+1) - P_(n-1)) / (2n + 1)
      double integral(const double x) const
      {
        double P[N + 1];
        const double t = (x - lo) / half - 1.;
        GaussLegendre::legendre(t, P);
        double sum = c[0] * (t + 1.);
        for (int n = 1; n < N; ++n)
          sum += c[n] * (P[n + 1] - P[n - 1]) / (2. * n + 1.);
        return half * sum;
      }
    };
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
    force_a_ = force_at(profile_, m_, a_);
    depth_a_ = depth_at(profile_, m_, a_);
  }

  double PartialSlip::normal_force(const double b) const { return b > 0. ? force_at(profile_, m_, b) : 0.; }

  double PartialSlip::depth(const double b) const { return b > 0. ? depth_at(profile_, m_, b) : 0.; }

  double PartialSlip::pressure(const double b, const double r) const
  {
    return b > 0. ? mdr::pressure(indentation(profile_, m_, b), m_, r) : 0.;
  }

  // --- differences between the indentations to a and to b = a - h ------------------------------------
  // For b <= a/2 the plain difference keeps its digits (F_N and d grow like powers of the radius); above,
  // the integrals over [b, a] of the derivatives in the radius, on tau = a - x in [0, h] so that the
  // interval is h itself (b = a - h would round).

  double PartialSlip::slope_at_gap(const double h) const
  {
    const double b = a_ - h;
    return b > 0. ? equivalent_profile_slope(profile_, m_.k, b) : 0.;
  }

  double PartialSlip::force_drop_slope(const double h) const
  {
    // dF_N/db = 2 cN0 b^(k+1) g'(b) / (c0^k (k+1)), the derivative of 9.11 with w1D = g(b) - g(x)
    const double k = m_.k, b = a_ - h;
    return b > 0. ? 2. * m_.cN0 / (std::pow(m_.c0, k) * (k + 1.)) * std::pow(b, k + 1.) * slope_at_gap(h) : 0.;
  }

  double PartialSlip::force_drop(const double h) const
  {
    if (!(h > 0.))
      return 0.;
    const double b = a_ - h;
    if (!(b > 0.5 * a_) || !profile_.d2f)
      return force_a_ - normal_force(b);
    const auto integrand = [&](const double tau, double, double) { return force_drop_slope(tau); };
    return detail::integrate_analytic_with_distances(integrand, 0., h);
  }

  double PartialSlip::depth_drop(const double h) const
  {
    if (!(h > 0.))
      return 0.;
    const double b = a_ - h;
    if (!(b > 0.5 * a_) || !profile_.d2f)
      return depth_a_ - depth(b);
    const auto integrand = [&](const double tau, double, double) { return slope_at_gap(tau); }; // 9.10: d = g(a)
    return detail::integrate_analytic_with_distances(integrand, 0., h);
  }

  double PartialSlip::pressure_drop(const double h, const double r) const
  {
    if (!(h > 0.))
      return 0.;
    const double b = a_ - h;
    if (!(r < b) || !profile_.d2f)
      return pressure(a_, r) - pressure(b, r); // p(r; b) = 0 for r >= b
    // 9.12 with w1D = g(radius) - g(x): p(r; a) - p(r; b) = cN0/(pi c0^k) int_b^a g'(x) (x^2 - r^2)^((k-1)/2) dx.
    const double k = m_.k, e = (k - 1.) / 2., b_minus_r = (a_ - r) - h;
    const double factor = m_.cN0 / (pi * std::pow(m_.c0, k));
    if (b_minus_r >= h)
      {
        // the singular point x = r lies at least the interval's length below it: a smooth integrand
        const auto integrand = [&](const double tau, double, const double to_h) {
          const double x = a_ - tau;
          return slope_at_gap(tau) * std::pow((b_minus_r + to_h) * (x + r), e);
        };
        return factor * detail::integrate_analytic_with_distances(integrand, 0., h);
      }
    // r close below b: v = (x - r)^((1+k)/2) removes the near-singular factor (x - r)^e; the v-interval
    // (a - r)^q - (b - r)^q is formed as (b - r)^q expm1(q log1p(h / (b - r))).
    const double q = (1. + k) / 2.;
    const double v_lo = std::pow(b_minus_r, q);
    const double span = v_lo * std::expm1(q * std::log1p(h / b_minus_r));
    const auto integrand = [&](double, const double to_lo, double) {
      const double x_minus_r = std::pow(v_lo + to_lo, 1. / q);
      const double tau = h - (x_minus_r - b_minus_r); // a - x
      return equivalent_profile_slope(profile_, k, a_ - tau) * std::pow(2. * r + x_minus_r, e);
    };
    return factor / q * detail::integrate_analytic_with_distances(integrand, 0., span);
  }

  double PartialSlip::gap_for(const double dF) const
  {
    const double target = dF / mu_;
    if (!(target >= 0. && target <= force_a_))
      check::fail("tangential", "Fx", dF, "gives gross slip (|dF| must stay below mu F_N)");
    if (target == force_a_)
      return a_;
    return detail::solve_from_zero([&](const double h) { return force_drop(h); },
                                   [&](const double h) { return force_drop_slope(h); }, target, a_);
  }

  double PartialSlip::gap_for_depth(const double dd) const
  {
    if (!(dd < depth_a_))
      return a_;
    return detail::solve_from_zero([&](const double h) { return depth_drop(h); },
                                   [&](const double h) { return slope_at_gap(h); }, dd, a_);
  }

  double PartialSlip::radius_for(const double dF) const { return a_ - gap_for(dF); }

  double PartialSlip::traction(const double c, const double r) const
  {
    return mu_ * pressure_drop(a_ - c, r); // 9.77
  }

  double PartialSlip::normal_force_slope(const double b) const { return force_drop_slope(a_ - b); }

  double PartialSlip::tangential_force(const double c) const { return mu_ * force_drop(a_ - c); }

  double PartialSlip::tangential_displacement(const double c) const
  {
    return mu_ * m_.alpha() * depth_drop(a_ - c);
  }

  double PartialSlip::stick_radius(const double Fx) const
  {
    check::non_negative("tangential_sphere", "Fx", Fx);
    return radius_for(Fx);
  }

  double PartialSlip::traction_at_force(const double Fx, const double r) const
  {
    check::non_negative("tangential_sphere", "Fx", Fx);
    return mu_ * pressure_drop(gap_for(Fx), r);
  }

  double PartialSlip::tangential_force_at_force(const double Fx) const
  {
    check::non_negative("tangential_sphere", "Fx", Fx);
    return mu_ * force_drop(gap_for(Fx));
  }

  double PartialSlip::tangential_displacement_at_force(const double Fx) const
  {
    check::non_negative("tangential_sphere", "Fx", Fx);
    return mu_ * m_.alpha() * depth_drop(gap_for(Fx));
  }

  void PartialSlip::check_amplitude(const double FA) const
  {
    const double limit = mu_ * force_a_;
    if (!(FA > 0. && FA < limit))
      check::fail("oscillating_sphere", "FA", FA,
                  "is outside (0, mu F_N) = (0, " + check::format(limit) + "): gross slip");
  }

  double PartialSlip::traction(const double FA, const Branch branch, const double Fx, const double r) const
  {
    check_amplitude(FA);
    if (branch == Branch::loading)
      return mu_ * pressure_drop(gap_for(Fx), r);
    check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
    const double hc = gap_for(FA);
    if (FA <= small_loop * mu_ * force_a_ && profile_.d2f && a_ - r > hc) // inside the stick zone of A
      return branch == Branch::unloading ? loop_traction(FA, Fx, r) : -loop_traction(FA, -Fx, r);
    const double dF = branch == Branch::unloading ? FA - Fx : Fx + FA;
    const double tau_A = mu_ * pressure_drop(hc, r);
    const double change = 2. * mu_ * pressure_drop(gap_for(dF / 2.), r); // 9.81
    return branch == Branch::unloading ? tau_A - change : -tau_A + change;
  }

  double PartialSlip::tangential_displacement(const double FA, const Branch branch, const double Fx) const
  {
    check_amplitude(FA);
    if (branch == Branch::loading)
      return mu_ * m_.alpha() * depth_drop(gap_for(Fx));
    check::closed_interval("oscillating_sphere", "Fx", Fx, -FA, FA);
    if (FA <= small_loop * mu_ * force_a_ && profile_.d2f)
      return branch == Branch::unloading ? loop_displacement(FA, Fx) : -loop_displacement(FA, -Fx);
    const double uA = mu_ * m_.alpha() * depth_drop(gap_for(FA));
    const double dF = branch == Branch::unloading ? FA - Fx : Fx + FA;
    const double change = 2. * mu_ * m_.alpha() * depth_drop(gap_for(dF / 2.));
    return branch == Branch::unloading ? uA - change : -uA + change;
  }

  double PartialSlip::hysteresis_force(const double FA, const Branch branch, const double u0) const
  {
    check_amplitude(FA);
    const double uA = mu_ * m_.alpha() * depth_drop(gap_for(FA));
    const double span = branch == Branch::loading ? u0 : (branch == Branch::unloading ? uA - u0 : u0 + uA);
    const double factor = branch == Branch::loading ? 1. : 2.;
    const double lo = branch == Branch::loading ? 0. : -uA;
    check::closed_interval("oscillating_sphere", "u0", u0, lo, uA);
    if (branch != Branch::loading && FA <= small_loop * mu_ * force_a_ && profile_.d2f)
      return branch == Branch::unloading ? loop_force(FA, u0) : -loop_force(FA, -u0);
    // span = factor mu alpha (d(a) - d(b)): the gap of b, then the force change.
    const double h = gap_for_depth(span / (factor * mu_ * m_.alpha()));
    const double change = factor * mu_ * force_drop(h);
    if (branch == Branch::loading)
      return change;
    return branch == Branch::unloading ? FA - change : -FA + change;
  }

  // --- the middle of a small loop ---------------------------------------------------------------------
  // On the unloading branch after A (force FA, s = FA/2, t = (FA - Fx)/2; F(b) the loading curve's force at the
  // slip radius b, Y any quantity of the loading curve as a function of its force, Y(0) at b = a):
  //   u0(Fx)     = delta(FA) - 2 delta(t)                  = D2 delta(s) - 2 [delta(t) - delta(s)]
  //   tau(Fx, r) = mu [2 P(t) - P(0) - P(FA)]               = mu { -D2 P(s) + 2 [P(t) - P(s)] }
  // with D2 Y(s) = Y(2s) - 2 Y(s) + Y(0) = int_0^s [Y'(x + s) - Y'(x)] dx, the second difference that is
  // O(phi^2) while its terms are O(phi): as two separate quadratures of the MDR integrals (and two root
  // searches for the slip radii) it loses eps/phi. Here the densities in the force depend on b(F) alone:
  //   delta'(F) = alpha / (K b^(k+1)),  P'(F) = -C (b^2 - r^2)^((k-1)/2) / (mu K b^(k+1))   (r < b),
  //   K = 2 cN0 / (c0^k (k+1)), C = cN0 / (pi c0^k)          (9.10-9.12 differentiated in the radius),
  // and Y'(x + s) - Y'(x) = Y'(x) expm1(log of their ratio), the ratio formed from the gap difference
  // h(x + s) - h(x): every term keeps its digits. h(F) = a - b(F) on [0, FA] inverts the force drop, whose
  // slope is a Legendre series there (analytic for FA <= mu F_N / 4: the singularity b = 0 is 6 h_c away).

  std::function<double(double)> PartialSlip::loading_gaps(const double FA) const
  {
    // F_N(a) - F_N(a - h) = int_0^h of its slope, as the Legendre series of the slope at the Gauss nodes of
    // [0, h_c] (one g' each), inverted by Newton's method: no root search of the MDR integrals per value.
    const double hc = gap_for(FA);
    const LegendreSeries drop([&](const double h) { return force_drop_slope(h); }, 0., hc);
    return [drop, hc, mu = mu_](const double F) {
      const double target = F / mu;
      if (!(target > 0.))
        return 0.;
      double h = std::min(target / drop.value(0.), hc);
      for (int i = 0; i < 60; ++i)
        {
          const double step = (drop.integral(h) - target) / drop.value(h);
          h = std::clamp(h - step, 0., 2. * hc);
          if (std::abs(step) <= 2. * std::numeric_limits<double>::epsilon() * h)
            break;
        }
      return h;
    };
  }

  PartialSlip::LoopIntegrands PartialSlip::loop_integrands(const double FA) const
  {
    const double k = m_.k, K = 2. * m_.cN0 / (std::pow(m_.c0, k) * (k + 1.)), s = FA / 2.;
    const auto   h = loading_gaps(FA);
    const double c = m_.alpha() / K;
    LoopIntegrands loop;
    loop.density = [=](const double F) { return c * std::pow(a_ - h(F), -(k + 1.)); };
    loop.second  = [=, density = loop.density](const double x) {
      const double h0 = h(x), b0 = a_ - h0;
      return density(x) * std::expm1(-(k + 1.) * std::log1p(-(h(x + s) - h0) / b0));
    };
    return loop;
  }

  double PartialSlip::loop_displacement(const double FA, const double Fx) const
  {
    const double         s = FA / 2.;
    const LoopIntegrands loop = loop_integrands(FA);
    return gauss_integral(loop.second, 0., s) - 2. * gauss_integral(loop.density, s, -Fx / 2.); // t - s = -Fx/2
  }

  double PartialSlip::loop_force(const double FA, const double u0) const
  {
    const double         s    = FA / 2.;
    const LoopIntegrands loop = loop_integrands(FA);
    const auto          &density = loop.density;
    const auto          &second  = loop.second;
    // The force T of the loading curve with delta(T) = (uA - u0)/2 is s + e/2 with
    // 2 [delta(s + e/2) - delta(s)] = D2 delta(s) - u0; then F_x = FA - 2T = -e.
    const double rhs = gauss_integral(second, 0., s) - u0;
    const auto lhs = [&](const double e) { return 2. * gauss_integral(density, s, e / 2.); };
    double lo = -FA, hi = FA, e = rhs / density(s);
    for (int i = 0; i < 100; ++i)
      {
        if (!(e > lo && e < hi))
          e = 0.5 * (lo + hi);
        const double value = lhs(e) - rhs;
        if (value == 0.)
          break;
        (value < 0. ? lo : hi) = e;
        const double next = e - value / density(s + e / 2.);
        const bool done = std::abs(next - e) <= 4. * std::numeric_limits<double>::epsilon() * std::abs(e);
        e = next;
        if (done || hi - lo <= 4. * std::numeric_limits<double>::epsilon() * FA)
          break;
      }
    return -e;
  }

  double PartialSlip::loop_traction(const double FA, const double Fx, const double r) const
  {
    const double k = m_.k, K = 2. * m_.cN0 / (std::pow(m_.c0, k) * (k + 1.)), s = FA / 2.;
    const double e = (k - 1.) / 2., a_minus_r = a_ - r;
    const auto h = loading_gaps(FA);
    const double c = -m_.cN0 / (pi * std::pow(m_.c0, k)) / (mu_ * K);
    // P'(F) at the gap h0 of F: b^2 - r^2 = (a - r - h0)(b + r)
    const auto density_at = [&](const double h0) {
      const double b = a_ - h0;
      return c * std::pow((a_minus_r - h0) * (b + r), e) * std::pow(b, -(k + 1.));
    };
    const auto density = [&](const double F) { return density_at(h(F)); };
    const auto second = [&](const double x) {
      const double h0 = h(x), h1 = h(x + s), b0 = a_ - h0, b1 = a_ - h1;
      const double log_ratio = e * std::log1p(-(h1 - h0) * (b1 + b0) / ((a_minus_r - h0) * (b0 + r))) -
                               (k + 1.) * std::log1p(-(h1 - h0) / b0);
      return density_at(h0) * std::expm1(log_ratio);
    };
    return mu_ * (-gauss_integral(second, 0., s) + 2. * gauss_integral(density, s, -Fx / 2.)); // t - s = -Fx/2
  }

  double PartialSlip::dissipated_energy(const double FA) const
  {
    // The loop area of the Masing loop (9.81): with the loading curve F0(u) (slip radius b, u = mu alpha
    // [d(a) - d(b)], F0 = mu [F_N(a) - F_N(b)]) the branches are F = +-FA -+ 2 F0((uA -+ u)/2), and
    //   int (F_rel - F_unl) du = 8 int_0^uA F0 du - 4 uA FA = 4 int_0^uA u (uA - u) (-dk/du) du,
    // k = dF0/du = 2 cN0 b^(k+1) / (c0^k (k+1) alpha) the tangential stiffness at b (integrations by
    // parts). In b, -dk = 2 cN0/(c0^k alpha) b^k (-db): the integrand is positive and O(phi^3) itself.
    // d(a) - d(b) = int g' is accumulated over panels of tau = a - b in [0, h_c] (widths at most the distance to
    // b = 0, where g' and b^k may be singular), inside a panel as the Legendre series of g' at its Gauss nodes
    // (one g' per node), and the outer integral takes the same nodes. The errors are eps of the largest drop,
    // harmless in the product with d(b) - d(c).
    check_amplitude(FA);
    const double k = m_.k, hc = gap_for(FA);
    if (!profile_.d2f)
      throw DomainError("oscillating_sphere dissipated_energy: the profile needs f'' (numerical MDR)");
    const GaussLegendre &rule = gauss_legendre();
    struct Node
    {
      double drop, weight; // d(a) - d(b) and the quadrature weight times b^k
    };
    std::vector<Node> nodes;
    double lo = 0., accumulated = 0.;
    while (lo < hc)
      {
        const double width = std::min(hc - lo, 0.5 * (a_ - lo));
        const LegendreSeries slope([&](const double tau) { return slope_at_gap(tau); }, lo, width);
        for (int i = 0; i < GaussLegendre::N; ++i)
          {
            const double tau = lo + 0.5 * width * (1. + rule.t[i]);
            nodes.push_back({accumulated + slope.integral(tau), 0.5 * width * rule.w[i] * std::pow(a_ - tau, k)});
          }
        accumulated += slope.integral(lo + width);
        lo += width;
      }
    const double dc = accumulated; // d(a) - d(c)
    double sum = 0.;
    for (const Node &n : nodes)
      sum += n.weight * n.drop * (dc - n.drop);
    return 8. * mu_ * mu_ * m_.alpha() * m_.cN0 / std::pow(m_.c0, k) * sum;
  }
} // namespace gradcontact::mdr
