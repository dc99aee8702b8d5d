#include <analytic/adhesion.h>
#include <analytic/errors.h>
#include <analytic/special_functions.h>

#include <boost/math/constants/constants.hpp>

#include <cmath>

namespace gradcontact::jkr
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    void check_adhesion(const char *fn, const Medium &m, const double dgamma)
    {
      validate(fn, m);
      check::positive(fn, "dgamma (work of adhesion)", dgamma);
    }

    // The general superposition (9.49): the non-adhesive solution at the same contact radius plus a
    // flat punch of radius a pulled back by Delta_l(a). One template serves every convex profile.
    template <class Profile>
    double adhesive_depth(const Medium &m, const Profile &p, const double dgamma, const double a)
    {
      return gradcontact::depth(m, p, a) - delta_ell(m, dgamma, a);
    }
    template <class Profile>
    double adhesive_force(const Medium &m, const Profile &p, const double dgamma, const double a)
    {
      return gradcontact::force(m, p, a) + gradcontact::force(m, FlatPunch{a}, -delta_ell(m, dgamma, a));
    }
    template <class Profile>
    double adhesive_pressure(const Medium &m, const Profile &p, const double dgamma, const double a,
                             const double r)
    {
      return gradcontact::pressure(m, p, a, r) +
             gradcontact::pressure(m, FlatPunch{a}, -delta_ell(m, dgamma, a), r);
    }
    template <class Profile>
    double adhesive_displacement(const Medium &m, const Profile &p, const double dgamma, const double a,
                                 const double r)
    {
      return gradcontact::displacement(m, p, a, r) +
             gradcontact::displacement(m, FlatPunch{a}, -delta_ell(m, dgamma, a), r);
    }
  } // namespace

  double C_tilde(const double k, const Control control)
  {
    return control == Control::force ? 2. / (3. + k) : 2. / (1. - k); // 9.48
  }

  double delta_ell(const Medium &m, const double dgamma, const double a)
  {
    const char *fn = "delta_ell";
    check_adhesion(fn, m, dgamma);
    check::positive(fn, "a", a);
    return std::sqrt(2. * pi * dgamma * std::pow(m.c0, m.k) * std::pow(a, 1. - m.k) / m.cN0); // 9.45
  }

  CriticalState critical_state(const Medium &m, const FlatPunch &punch, const double dgamma)
  {
    const char *fn = "jkr_flat_punch critical_state";
    check_adhesion(fn, m, dgamma);
    check::positive(fn, "a", punch.a);
    const double k = m.k, a = punch.a;
    const double Fc = -std::sqrt(8. * pi * dgamma * m.cN0 * std::pow(a, 3. + k) /
                                 ((k + 1.) * (k + 1.) * std::pow(m.c0, k))); // 9.52
    return {a, -delta_ell(m, dgamma, a), Fc};                               // 9.51
  }

  // --- paraboloid --------------------------------------------------------------------------------
  double depth(const Medium &m, const Paraboloid &p, const double dgamma, const double a)
  {
    return adhesive_depth(m, p, dgamma, a); // 9.53
  }
  double force(const Medium &m, const Paraboloid &p, const double dgamma, const double a)
  {
    return adhesive_force(m, p, dgamma, a); // 9.53
  }
  double pressure(const Medium &m, const Paraboloid &p, const double dgamma, const double a,
                  const double r)
  {
    return adhesive_pressure(m, p, dgamma, a, r); // 9.53
  }
  double displacement(const Medium &m, const Paraboloid &p, const double dgamma, const double a,
                      const double r)
  {
    return adhesive_displacement(m, p, dgamma, a, r); // 9.53
  }

  CriticalState critical_state(const Medium &m, const Paraboloid &p, const double dgamma,
                               const Control control)
  {
    const char *fn = "jkr_paraboloid critical_state";
    check_adhesion(fn, m, dgamma);
    check::positive(fn, "R", p.R);
    const double k = m.k, R = p.R, Ct = C_tilde(k, control);
    const double ac = std::pow(pi * (1. + k) * (1. + k) * R * R * dgamma * std::pow(m.c0, k) /
                                 (2. * Ct * Ct * m.cN0),
                               1. / (3. + k));                                   // 9.55
    const double dc = (1. - 2. * Ct) / ((1. + k) * R) * ac * ac;                 // 9.56
    const double Fc = (1. - Ct * (3. + k)) / (Ct * Ct * (3. + k)) * 2. * pi * dgamma * R; // 9.56
    return {ac, dc, Fc};
  }

  double normalised_depth(const double k, const Control control, const double s)
  {
    return normalised_depth(k, 2., control, s); // 9.57 is 9.63 at n = 2
  }
  double normalised_force(const double k, const Control control, const double s)
  {
    return normalised_force(k, 2., control, s);
  }

  // --- power law ------------------------------------------------------------------------------
  double depth(const Medium &m, const PowerLaw &p, const double dgamma, const double a)
  {
    return adhesive_depth(m, p, dgamma, a); // 9.58
  }
  double force(const Medium &m, const PowerLaw &p, const double dgamma, const double a)
  {
    return adhesive_force(m, p, dgamma, a); // 9.58
  }
  double pressure(const Medium &m, const PowerLaw &p, const double dgamma, const double a,
                  const double r)
  {
    return adhesive_pressure(m, p, dgamma, a, r); // 9.59
  }
  double displacement(const Medium &m, const PowerLaw &p, const double dgamma, const double a,
                      const double r)
  {
    return adhesive_displacement(m, p, dgamma, a, r); // 9.59
  }

  namespace
  {
    // 2n + k - 1 as (2n - 1) + k: exact 2n - 1 for 1/4 <= n <= 1 (Sterbenz), then one rounding; formed
    // as (2n + k) - 1 it would carry the rounding of 2n + k, a relative error eps/(2n + k - 1).
    double critical_exponent(const double n, const double k) { return (2. * n - 1.) + k; }

    // The factors 1 - C~ (n + k + 1) of F_c and 1 - C~ n of d_c (9.61, 9.63). Under force control the
    // first is -(2n + k - 1)/(3 + k), under displacement control the second is -(2n + k - 1)/(1 - k):
    // both are formed from critical_exponent, not as 1 minus a rounded product.
    double force_factor(const double k, const double n, const Control control)
    {
      return control == Control::force ? -critical_exponent(n, k) / (3. + k) : 1. - C_tilde(k, control) * (n + k + 1.);
    }
    double depth_factor(const double k, const double n, const Control control)
    {
      return control == Control::displacement ? -critical_exponent(n, k) / (1. - k) : 1. - C_tilde(k, control) * n;
    }

    void check_critical_exists(const char *fn, const double k, const double n)
    {
      // d(a) = kappa A a^n - Delta_l(a) with Delta_l ~ a^((1-k)/2), F(a) ~ P a^(n+k+1) - Q a^((3+k)/2):
      // both have a minimum over a > 0 only if n > (1-k)/2.
      if (!(critical_exponent(n, k) > 0.))
        check::fail(fn, "2n + k - 1", critical_exponent(n, k),
                    "must be > 0: no critical state exists for this profile (d(a) and F_N(a) have "
                    "no minimum)");
    }
  } // namespace

  CriticalState critical_state(const Medium &m, const PowerLaw &p, const double dgamma,
                               const Control control)
  {
    const char *fn = "jkr_power_law critical_state";
    check_adhesion(fn, m, dgamma);
    check::positive(fn, "n", p.n);
    check::positive(fn, "A", p.A);
    const double k = m.k, n = p.n, Ct = C_tilde(k, control);
    check_critical_exists(fn, k, n);
    const double kap = kappa(n, k);
    const double e = 1. / critical_exponent(n, k);
    const double Q = 2. * pi * dgamma * std::pow(m.c0, k) / m.cN0; // = Delta_l(a)^2 / a^(1-k)
    const double G = Ct * n * kap * p.A;                             // C~ g'(a) / a^(n-1)
    const double ac = std::pow(Q / (G * G), e);                      // 9.60
    const double dc = std::pow(std::pow(Q, n) * std::pow(1. / G, 1. - k), e) * depth_factor(k, n, control) / (n * Ct);
    const double Fc = 2. * force_factor(k, n, control) / (Ct * (n + k + 1.) * (k + 1.)) *
                      std::pow(std::pow(2. * pi * dgamma, n + k + 1.) *
                                 std::pow(std::pow(m.c0, k) / m.cN0, 2. - n) *
                                 std::pow(1. / G, k + 3.),
                               e); // 9.61
    return {ac, dc, Fc};
  }

  double jin_pulloff_ratio(const GradedHalfSpace &body, const double n, const double R,
                           const double dgamma)
  {
    const char *fn = "jin_pulloff_ratio";
    validate(fn, body);
    check::positive(fn, "n", n);
    check::positive(fn, "R", R);
    check::positive(fn, "dgamma", dgamma);
    const double k = body.k;
    check_critical_exists(fn, k, n);
    const double hN = h_N(k, body.nu);
    const double bracket = std::pow(2. * pi, n + k + 1.) *
                           std::pow((1. - body.nu * body.nu) / hN, 2. - n) *
                           std::pow((3. + k) / (2. * kappa(n, k)), k + 3.) *
                           std::pow(R / body.c0, k * (n - 2.)) *
                           std::pow(body.E0 * R / dgamma, n - 2.);
    return -2. * critical_exponent(n, k) / (3. * pi * (n + k + 1.) * (k + 1.)) *
           std::pow(bracket, 1. / critical_exponent(n, k)); // 9.62: 1 - k - 2n = -(2n + k - 1)
  }

  double normalised_depth(const double k, const double n, const Control control, const double s)
  {
    const char *fn = "jkr normalised_depth";
    check::open_interval(fn, "k", k, -1., 1.);
    check::positive(fn, "n", n);
    check::non_negative(fn, "a/a_c", s);
    const double Ct = C_tilde(k, control);
    const double denominator = depth_factor(k, n, control);
    if (denominator == 0.)
      check::fail(fn, "n", n, "makes d_c = 0 (n C~ = 1): the depth cannot be normalised by it");
    return (std::pow(s, n) - n * Ct * std::pow(s, (1. - k) / 2.)) / denominator; // 9.63
  }

  double normalised_force(const double k, const double n, const Control control, const double s)
  {
    const char *fn = "jkr normalised_force";
    check::open_interval(fn, "k", k, -1., 1.);
    check::positive(fn, "n", n);
    check::non_negative(fn, "a/a_c", s);
    const double Ct = C_tilde(k, control), m = n + k + 1.;
    const double denominator = force_factor(k, n, control);
    if (denominator == 0.)
      check::fail(fn, "n", n, "makes F_c = 0 (C~ (n+k+1) = 1): the force cannot be normalised by it");
    return (std::pow(s, m) - Ct * m * std::pow(s, (k + 3.) / 2.)) / denominator; // 9.63
  }

  // --- concave punch ------------------------------------------------------------------------------
  namespace
  {
    void check_concave(const char *fn, const Medium &m, const ConcavePunch &punch, const double dgamma,
                       const double sigma_th)
    {
      check_adhesion(fn, m, dgamma);
      check::positive(fn, "a", punch.a);
      check::non_negative(fn, "h0", punch.h0);
      check::positive(fn, "sigma_th", sigma_th);
    }

    CriticalState periphery_state(const Medium &m, const ConcavePunch &punch, const double dgamma)
    {
      const double k = m.k, a = punch.a, h0 = punch.h0;
      const double dl = delta_ell(m, dgamma, a);
      const double dP = -dl - h0 * (1. - k) / (1. + k); // 9.65
      const double FP = -std::sqrt(8. * pi * m.cN0 * dgamma * std::pow(a, 3. + k) /
                                   ((1. + k) * (1. + k) * std::pow(m.c0, k))) -
                        8. * m.cN0 * h0 * std::pow(a, 1. + k) /
                          ((k + 1.) * (k + 1.) * (k + 3.) * std::pow(m.c0, k)); // 9.66
      return {a, dP, FP};
    }

    CriticalState centre_state(const Medium &m, const ConcavePunch &punch, const double sigma_th)
    {
      const double k = m.k, a = punch.a, h0 = punch.h0;
      const double c0k = std::pow(m.c0, k);
      const double dC = -pi * c0k * std::pow(a, 1. - k) * sigma_th / m.cN0 +
                        (3. + k * k) / ((1. + k) * (1. + k)) * h0; // 9.67
      const double FC = -2. * pi * a * a * sigma_th / (1. + k) +
                        16. * m.cN0 * h0 * std::pow(a, k + 1.) /
                          ((k + 1.) * (k + 1.) * (k + 1.) * (k + 3.) * c0k); // 9.68
      return {a, dC, FC};
    }
  } // namespace

  Mechanism governing_mechanism(const Medium &m, const ConcavePunch &punch, const double dgamma,
                                const double sigma_th)
  {
    check_concave("jkr_concave governing_mechanism", m, punch, dgamma, sigma_th);
    // Unloading lowers the rim depth d: the mechanism whose critical depth is larger comes first.
    return periphery_state(m, punch, dgamma).depth >= centre_state(m, punch, sigma_th).depth
             ? Mechanism::periphery
             : Mechanism::centre;
  }

  CriticalState critical_state(const Medium &m, const ConcavePunch &punch, const double dgamma,
                               const double sigma_th, Mechanism mechanism)
  {
    check_concave("jkr_concave critical_state", m, punch, dgamma, sigma_th);
    if (mechanism == Mechanism::governing)
      mechanism = governing_mechanism(m, punch, dgamma, sigma_th);
    return mechanism == Mechanism::periphery ? periphery_state(m, punch, dgamma)
                                             : centre_state(m, punch, sigma_th);
  }

  double critical_pressure(const Medium &m, const ConcavePunch &punch, const double dgamma,
                           const double sigma_th, Mechanism mechanism, const double r)
  {
    const char *fn = "jkr_concave critical_pressure";
    check_concave(fn, m, punch, dgamma, sigma_th);
    check::non_negative(fn, "r", r);
    const double k = m.k, a = punch.a, h0 = punch.h0;
    if (r > a)
      return 0.;
    if (r == a)
      check::fail(fn, "r", r, "equals a: the pressure is unbounded at the punch edge (use r != a)");
    if (mechanism == Mechanism::governing)
      mechanism = governing_mechanism(m, punch, dgamma, sigma_th);
    const double c0k = std::pow(m.c0, k);
    const double rho2 = (r / a) * (r / a);
    const double one_minus_rho2 = (a - r) * (a + r) / (a * a); // not 1 - rho2: rho2 is rounded
    const double edge = std::pow((a - r) * (a + r), (1. - k) / 2.);
    if (mechanism == Mechanism::periphery)
      return m.cN0 / (pi * c0k * edge) *
             (-delta_ell(m, dgamma, a) - 4. * h0 / ((k + 1.) * (k + 1.)) * one_minus_rho2); // 9.66
    return (-std::pow(a, 1. - k) * sigma_th +
            4. * m.cN0 * h0 * rho2 / (pi * (k + 1.) * (k + 1.) * c0k)) /
           edge; // 9.68
  }

  double transition_h0(const Medium &m, const double a, const double dgamma, const double sigma_th)
  {
    const char *fn = "jkr_concave transition_h0";
    check_concave(fn, m, ConcavePunch{a, 0.}, dgamma, sigma_th);
    const double k = m.k;
    // Equal critical depths of 9.65 and 9.67.
    const double h0 = (1. + k) * (1. + k) / 4. *
                      (pi * std::pow(m.c0, k) * std::pow(a, 1. - k) * sigma_th / m.cN0 -
                       delta_ell(m, dgamma, a));
    if (!(h0 > 0.))
      check::fail(fn, "sigma_th", sigma_th,
                  "is too small: the centre separates first for every h0 >= 0 (no transition)");
    return h0;
  }

  // --- optimal profile --------------------------------------------------------------------------
  namespace
  {
    UniformPressure as_load(const char *fn, const OptimalProfile &p)
    {
      check::positive(fn, "a", p.a);
      check::positive(fn, "sigma_th", p.sigma_th);
      return {p.a, -p.sigma_th}; // 9.69: p = -sigma_th on r <= a
    }
  } // namespace

  double force(const OptimalProfile &p)
  {
    return gradcontact::force(as_load("optimal_profile force", p)); // 9.70
  }

  double centre_displacement(const Medium &m, const OptimalProfile &p)
  {
    return gradcontact::centre_displacement(m, as_load("optimal_profile depth", p)); // 9.72
  }

  double displacement(const Medium &m, const OptimalProfile &p, const double r)
  {
    return gradcontact::displacement(m, as_load("optimal_profile displacement", p), r); // 9.71
  }

  double profile(const Medium &m, const OptimalProfile &p, const double r)
  {
    const char *fn = "optimal_profile profile";
    const UniformPressure load = as_load(fn, p);
    check::closed_interval(fn, "r", r, 0., p.a);
    const double k = m.k;
    return gradcontact::centre_displacement(m, load) *
           -hyp2f1_minus_one((k - 1.) / 2., (1. + k) / 2., 1., (r / p.a) * (r / p.a),
                             (p.a - r) * (p.a + r) / (p.a * p.a)); // 9.73: w_c [1 - 2F1(...)]
  }

  double shifted_profile(const Medium &m, const OptimalProfile &p, const double r)
  {
    return profile(m, p, r) - profile(m, p, p.a); // 9.74
  }
} // namespace gradcontact::jkr
