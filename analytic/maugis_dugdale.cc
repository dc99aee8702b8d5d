#include <analytic/adhesion.h>
#include <analytic/errors.h>
#include <analytic/maugis_dugdale.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

namespace gradcontact::maugis_dugdale
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    /// The closing condition of the header, minus 1, in t = sqrt(m^2 - 1).
    double closing(const double lambda, const double A, const double t)
    {
      const double at = std::atan(t);
      const double m1 = t * t / (std::sqrt(1 + t * t) + 1); // m - 1
      return lambda * A * A / 2 * ((t * t - 1) * at + t) + 4 * lambda * lambda * A / 3 * (t * at - m1) - 1;
    }

    void check_lambda(const char *function, const double lambda)
    {
      check::positive(function, "lambda", lambda);
      if (lambda < 1e-3 || lambda > 1e3)
        check::fail(function, "lambda", lambda, "is outside [1e-3, 1e3]");
    }

    /// Where value(t) is smallest over t in [lo, hi]: a scan of `samples` steps, then Brent around the smallest
    /// sample. `first` / `last`: the smallest sample is an end (the caller reads what that means; `t` is then that
    /// end).
    struct ScanMinimum
    {
      double t     = 0;
      bool   first = false, last = false;
    };
    ScanMinimum scan_minimum(const std::function<double(double)> &value, const double lo, const double hi,
                             const int samples)
    {
      int    best       = 0;
      double best_value = std::numeric_limits<double>::max();
      for (int i = 0; i <= samples; ++i)
        {
          const double v = value(lo + (hi - lo) * i / samples);
          if (v < best_value)
            best_value = v, best = i;
        }
      if (best == 0 || best == samples)
        return {best == 0 ? lo : hi, best == 0, best == samples};
      const double   step       = (hi - lo) / samples;
      std::uintmax_t iterations = 200;
      return {boost::math::tools::brent_find_minima(value, lo + step * (best - 1), lo + step * (best + 1), 40, iterations)
                .first,
              false, false};
    }

    /// The pull-off from scan_minimum's result: the vanishing contact `end` where the scan's smallest sample is the
    /// first (force control: its pull-off; displacement control: no jump), else the state at the minimum, replaced by
    /// `end` under force control when F is lower there. `force` reads a state's force; `at` builds the state at t;
    /// `beyond` throws where the smallest sample is the last.
    template <class PullOffType, class StateType, class Force, class At, class Beyond>
    PullOffType finish_pull_off(const ScanMinimum &minimum, const StateType &end, const Control control, Force force,
                                At at, Beyond beyond)
    {
      PullOffType p;
      if (minimum.first)
        {
          p.state                = end;
          p.at_vanishing_contact = true;
          p.exists               = control == Control::force;
          return p;
        }
      if (minimum.last)
        beyond();
      p.state = at(minimum.t);
      if (control == Control::force && force(end) < force(p.state))
        {
          p.state                = end;
          p.at_vanishing_contact = true;
        }
      return p;
    }
  } // namespace

  double tabor_parameter(const double sigma0, const double dgamma, const double R, const double E_star)
  {
    check::positive("maugis_dugdale::tabor_parameter", "sigma0", sigma0);
    check::positive("maugis_dugdale::tabor_parameter", "dgamma", dgamma);
    check::positive("maugis_dugdale::tabor_parameter", "R", R);
    check::positive("maugis_dugdale::tabor_parameter", "E_star", E_star);
    return sigma0 * std::cbrt(9 * R / (2 * pi * dgamma * E_star * E_star));
  }

  Scales scales(const double dgamma, const double R, const double E_star)
  {
    const double K = 4 * E_star / 3;
    return {std::cbrt(pi * dgamma * R * R / K), pi * dgamma * R, std::cbrt(pi * pi * dgamma * dgamma * R / (K * K))};
  }

  State state(const double lambda, const double A)
  {
    check::positive("maugis_dugdale::state", "lambda", lambda);
    check::positive("maugis_dugdale::state", "A", A);
    // The closing function grows with t from -1 at t = 0.
    double hi = 1;
    while (closing(lambda, A, hi) < 0)
      {
        hi *= 2;
        if (hi > 1e150)
          check::fail("maugis_dugdale::state", "A", A, "gives no closing cohesive zone");
      }
    std::uintmax_t iterations = 200;
    const auto     bracket    = boost::math::tools::toms748_solve(
      [&](const double t) { return closing(lambda, A, t); }, 0.0, hi, -1.0, closing(lambda, A, hi),
      boost::math::tools::eps_tolerance<double>(52), iterations);
    const double t = (bracket.first + bracket.second) / 2;
    State        s;
    s.A     = A;
    s.m     = std::sqrt(1 + t * t);
    s.zone  = A * s.m;
    s.P     = A * A * A - lambda * A * A * (t + (1 + t * t) * std::atan(t));
    s.Delta = A * A - 4 * lambda * A * t / 3;
    return s;
  }

  State vanishing_contact(const double lambda)
  {
    check::positive("maugis_dugdale::vanishing_contact", "lambda", lambda);
    // lambda pi C^2 / 4 + 4 lambda^2 (pi/2 - 1) C / 3 = 1, the positive root.
    const double a2 = lambda * pi / 4, a1 = 4 * lambda * lambda * (pi / 2 - 1) / 3;
    const double C  = 2 / (a1 + std::sqrt(a1 * a1 + 4 * a2)); // = (-a1 + sqrt(a1^2 + 4 a2)) / (2 a2)
    State        s;
    s.A     = 0;
    s.m     = std::numeric_limits<double>::infinity();
    s.zone  = C;
    s.P     = -lambda * pi * C * C / 2;
    s.Delta = -4 * lambda * C / 3; // A^2 - 4 lambda A t / 3 with A t -> C
    return s;
  }

  PullOff pull_off(const double lambda, const Control control)
  {
    check_lambda("maugis_dugdale::pull_off", lambda);
    const auto value = [&](const double lnA) {
      const State s = state(lambda, std::exp(lnA));
      return control == Control::force ? s.P : s.Delta;
    };
    // A scan in ln A, then Brent around the smallest sample.
    // The minimum at the A -> 0 end: the pull-off there (force control) or none inside (displacement control).
    return finish_pull_off<PullOff>(
      scan_minimum(value, std::log(1e-6), std::log(1e2), 400), vanishing_contact(lambda), control,
      [](const State &s) { return s.P; }, [&](const double t) { return state(lambda, std::exp(t)); },
      [&] { check::fail("maugis_dugdale::pull_off", "lambda", lambda, "has no pull-off with A <= 100"); });
  }
  namespace
  {
    /// The pieces of the graded state (header) that do not depend on a or c.
    struct GradedTerms
    {
      double k, n, A, kappa, Q, cosk, K, sigma0, h0;

      GradedTerms(const Medium &m, const PowerLaw &p, const Dugdale &law)
        : k(m.k)
        , n(p.n)
        , A(p.A)
        , kappa(gradcontact::kappa(p.n, m.k))
        , Q(m.cN0 / std::pow(m.c0, m.k))
        , cosk(std::cos(m.k * pi / 2))
        , K(2 * cosk / ((1 - m.k) * Q))
        , sigma0(law.sigma0)
        , h0(law.dgamma / law.sigma0)
      {}

      /// B_v(p, q), the incomplete beta function (not normalised), given v and u = 1 - v each without
      /// cancellation: near v = 1 (a << c) as B(p, q) - B_u(q, p).
      static double B(const double p, const double q, const double v, const double u)
      {
        return v <= 0.5 ? boost::math::beta(p, q, v) : boost::math::beta(p, q) - boost::math::beta(q, p, u);
      }

      /// d, F and h(c) - h_0 for a > 0 and c = a (1 + t), t > 0.
      GradedState at(const double a, const double t, double &excess) const
      {
        const double c = a * (1 + t);
        const double u = 1 / ((1 + t) * (1 + t)); // a^2 / c^2
        const double v = t * (2 + t) * u;         // 1 - a^2 / c^2 without cancellation
        const double zone = sigma0 * K * std::pow(a * a * t * (2 + t), (1 - k) / 2); // sigma_0 K (c^2 - a^2)^{(1-k)/2}
        GradedState  s;
        s.radius      = a;
        s.zone_radius = c;
        s.depth       = kappa * A * std::pow(a, n) - zone;
        s.force       = 2 * Q * (s.depth * std::pow(a, 1 + k) / (1 + k) - kappa * A * std::pow(a, 1 + k + n) / (1 + k + n)) -
                  2 * cosk * sigma0 * c * c * B((3 - k) / 2, (1 + k) / 2, v, u) / (1 - k);
        const double h = cosk / pi *
                         (kappa * A * std::pow(c, n) * B((1 - k) / 2, (1 + k + n) / 2, v, u) -
                          s.depth * B((1 - k) / 2, (1 + k) / 2, v, u) - sigma0 * K * std::pow(c, 1 - k) * B(1 - k, (1 + k) / 2, v, u));
        excess = h - h0;
        return s;
      }
    };

    void check_graded(const char *function, const Medium &m, const PowerLaw &p, const Dugdale &law)
    {
      validate(function, m);
      check::positive(function, "n", p.n);
      check::positive(function, "A", p.A);
      check::positive(function, "sigma0", law.sigma0);
      check::positive(function, "dgamma", law.dgamma);
    }

    /// The root of `excess` (< 0 at lo, growing) on (lo, inf) by doubling and TOMS 748.
    double grow_root(const char *function, const char *name, const double value,
                     const std::function<double(double)> &excess, const double lo, double hi)
    {
      double f_hi = excess(hi);
      while (!(f_hi >= 0))
        {
          hi *= 2;
          if (hi > 1e150 || !std::isfinite(f_hi))
            check::fail(function, name, value, "gives no closing cohesive zone");
          f_hi = excess(hi);
        }
      std::uintmax_t iterations = 200;
      const auto     bracket    = boost::math::tools::toms748_solve(excess, lo, hi, excess(lo), f_hi,
                                                                    boost::math::tools::eps_tolerance<double>(52), iterations);
      return (bracket.first + bracket.second) / 2;
    }
  } // namespace

  GradedState state(const Medium &m, const PowerLaw &profile, const Dugdale &law, const double a)
  {
    check_graded("maugis_dugdale::state", m, profile, law);
    check::positive("maugis_dugdale::state", "a", a);
    const GradedTerms terms(m, profile, law);
    const auto        excess = [&](const double t) {
      if (t == 0)
        return -terms.h0; // h(a) = 0 on the contact edge
      double e = 0;
      terms.at(a, t, e);
      return e;
    };
    const double t = grow_root("maugis_dugdale::state", "a", a, excess, 0.0, 1.0);
    double       e = 0;
    return terms.at(a, t, e);
  }

  GradedState state(const Medium &m, const Paraboloid &profile, const Dugdale &law, const double a)
  {
    return state(m, as_power_law(profile), law, a);
  }

  GradedState vanishing_contact(const Medium &m, const PowerLaw &profile, const Dugdale &law)
  {
    check_graded("maugis_dugdale::vanishing_contact", m, profile, law);
    const GradedTerms t(m, profile, law);
    const double      open = 1 - t.cosk * boost::math::beta(1 - t.k, (1 + t.k) / 2) / pi;
    const auto        excess = [&](const double c) {
      return t.A * std::pow(c, t.n) + t.sigma0 * t.K * std::pow(c, 1 - t.k) * open - t.h0;
    };
    // The scale of c: where either term alone reaches h_0.
    const double c_scale = std::min(std::pow(t.h0 / t.A, 1 / t.n), std::pow(t.h0 / (t.sigma0 * t.K * open), 1 / (1 - t.k)));
    const double c       = grow_root("maugis_dugdale::vanishing_contact", "sigma0", law.sigma0, excess, 0.0, c_scale);
    GradedState  s;
    s.zone_radius = c;
    s.depth       = -t.sigma0 * t.K * std::pow(c, 1 - t.k);
    s.force       = -pi * c * c * t.sigma0;
    return s;
  }

  namespace
  {
    /// C Delta_l(a_c) of tabor_parameter: lambda h_0.
    double tabor_length(const char *function, const Medium &m, const PowerLaw &profile, const double dgamma)
    {
      validate(function, m);
      check::positive(function, "dgamma", dgamma);
      if (!(2 * profile.n + m.k - 1 > 0))
        check::fail(function, "n", profile.n, "has no JKR pull-off to define the Tabor parameter (2n + k - 1 <= 0)");
      const double C   = std::cbrt((9 / (2 * pi)) / (std::pow(2 * pi, 1.5) * std::sqrt(9 * pi / 8)));
      const double a_c = jkr::critical_state(m, profile, dgamma, Control::force).radius;
      return C * jkr::delta_ell(m, dgamma, a_c);
    }
  } // namespace

  double tabor_parameter(const Medium &m, const PowerLaw &profile, const Dugdale &law)
  {
    check::positive("maugis_dugdale::tabor_parameter", "sigma0", law.sigma0);
    return tabor_length("maugis_dugdale::tabor_parameter", m, profile, law.dgamma) * law.sigma0 / law.dgamma;
  }

  double tabor_parameter(const Medium &m, const Paraboloid &profile, const Dugdale &law)
  {
    return tabor_parameter(m, as_power_law(profile), law);
  }

  double strength(const Medium &m, const PowerLaw &profile, const double dgamma, const double lambda)
  {
    check::positive("maugis_dugdale::strength", "lambda", lambda);
    return dgamma * lambda / tabor_length("maugis_dugdale::strength", m, profile, dgamma);
  }

  double strength(const Medium &m, const Paraboloid &profile, const double dgamma, const double lambda)
  {
    return strength(m, as_power_law(profile), dgamma, lambda);
  }

  GradedState vanishing_contact(const Medium &m, const Paraboloid &profile, const Dugdale &law)
  {
    return vanishing_contact(m, as_power_law(profile), law);
  }

  GradedPullOff pull_off(const Medium &m, const PowerLaw &profile, const Dugdale &law, const Control control)
  {
    check_graded("maugis_dugdale::pull_off", m, profile, law);
    if (!(2 * profile.n + m.k - 1 > 0))
      check::fail("maugis_dugdale::pull_off", "n", profile.n, "gives no JKR pull-off to scale the search (2n + k - 1 <= 0)");
    const double a_jkr = jkr::critical_state(m, profile, law.dgamma, Control::force).radius;
    const auto   value = [&](const double ln_a) {
      const GradedState s = state(m, profile, law, a_jkr * std::exp(ln_a));
      return control == Control::force ? s.force : s.depth;
    };
    // A scan in ln a (25 samples per decade), then Brent around the smallest sample.
    return finish_pull_off<GradedPullOff>(
      scan_minimum(value, std::log(1e-6), std::log(1e2), 200), vanishing_contact(m, profile, law), control,
      [](const GradedState &s) { return s.force; },
      [&](const double t) { return state(m, profile, law, a_jkr * std::exp(t)); },
      [&] { check::fail("maugis_dugdale::pull_off", "sigma0", law.sigma0, "has no pull-off with a <= 100 a_JKR"); });
  }

  GradedPullOff pull_off(const Medium &m, const Paraboloid &profile, const Dugdale &law, const Control control)
  {
    return pull_off(m, as_power_law(profile), law, control);
  }
} // namespace gradcontact::maugis_dugdale
