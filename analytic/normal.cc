#include <analytic/errors.h>
#include <analytic/normal.h>
#include <analytic/special_functions.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/math/special_functions/cos_pi.hpp>

#include <cmath>
#include <limits>

namespace gradcontact
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    // a^2 - r^2 without cancellation near the contact edge.
    double difference_of_squares(const double a, const double r) { return (a - r) * (a + r); }

    // n + k - 1, the exponent of p(r) ~ r^(n+k-1) of a power-law tip (9.30), without cancellation
    // for n + k near 1.
    double power_law_exponent(const double n, const double k) { return (n - 1.) + k; }

    // cos(k pi/2) / pi, the prefactor of every surface displacement outside the contact (9.12).
    double outer_factor(const double k) { return boost::math::cos_pi(k / 2.) / pi; }

    // B(a^2/r^2; x, y) for r > a, the incomplete beta of every displacement outside the contact, with
    // w = 1 - z = (r-a)(r+a)/r^2 formed without cancellation: near the edge (z > 1/2) only w enters.
    double outer_beta(const double x, const double y, const double a, const double r)
    {
      return incomplete_beta((a / r) * (a / r), x, y, (r - a) * (r + a) / (r * r));
    }

    // B(a^2/r^2; (1+k)/2, (1-k)/2): w outside a flat punch of unit depth, times pi / cos(k pi/2).
    double flat_punch_outer_beta(const double k, const double a, const double r)
    {
      return outer_beta((1. + k) / 2., (1. - k) / 2., a, r);
    }

    void check_medium(const char *fn, const Medium &m) { validate(fn, m); }

    void check_power_law(const char *fn, const PowerLaw &p)
    {
      check::positive(fn, "n", p.n);
      check::positive(fn, "A", p.A);
    }
  } // namespace

  double kappa(const double n, const double k)
  {
    check::positive("kappa", "n", n);
    check::open_interval("kappa", "k", k, -1., 1.);
    // kappa = n/2 B(n/2, (1+k)/2) = Gamma(n/2 + 1) Gamma((1+k)/2) / Gamma((1+k+n)/2) (9.29), in long double:
    // in double, kappa, whose difference from 1 the displacement near the edge takes as k -> 1, loses up to
    // 1e-13 (against the references). For n <= 200 from three log-gammas (glibc's reentrant lgammal_r, all
    // arguments positive; the cheaper path): their sum keeps about 1e-18 absolute while the log-gammas stay below
    // a few hundred, and kappa is within 1.3e-16 (about one ulp) of 50 digits for n in [0.05, 300], k in
    // (-1, 1). Above, the log-gammas grow like n log n and so would the error of their difference (5e-14 at
    // n = 1e5): Boost's beta promoted to long double (slower) keeps it. n and k stay the same over the
    // calls of a prepared request or of a root search for the contact radius: the last value is kept, per
    // thread.
    static_assert(std::numeric_limits<long double>::digits >= 64,
                  "kappa needs the 64-bit mantissa of x87 long double (or wider)");
    struct Last
    {
      double n, k, kappa;
    };
    thread_local Last last{std::nan(""), std::nan(""), 0.};
    if (n == last.n && k == last.k)
      return last.kappa;
    const long double x = n / 2.L, y = (1.L + k) / 2.L;
    constexpr double  log_gamma_limit = 200.;
    if (n <= log_gamma_limit)
      {
        int sign = 0; // every argument is positive: the sign is +1
        last     = {n, k,
                    static_cast<double>(
                      std::exp(lgammal_r(x + 1.L, &sign) + lgammal_r(y, &sign) - lgammal_r(x + y, &sign)))};
      }
    else
      {
        using promoted = boost::math::policies::policy<boost::math::policies::promote_double<true>>;
        last           = {n, k, static_cast<double>(x * boost::math::beta(x, y, promoted()))};
      }
    return last.kappa;
  }

  PowerLaw as_power_law(const Cone &cone)
  {
    check::positive("cone", "tan_theta", cone.tan_theta);
    return {1., cone.tan_theta};
  }

  PowerLaw as_power_law(const Paraboloid &paraboloid)
  {
    check::positive("paraboloid", "R", paraboloid.R);
    return {2., 1. / (2. * paraboloid.R)};
  }

  // --- flat punch ---------------------------------------------------------------------------
  double force(const Medium &m, const FlatPunch &punch, const double d)
  {
    const char *fn = "flat_punch force";
    check_medium(fn, m);
    check::positive(fn, "a", punch.a);
    check::finite(fn, "d", d);
    return 2. * m.cN0 * d * std::pow(punch.a, 1. + m.k) / ((1. + m.k) * std::pow(m.c0, m.k));
  }

  double pressure(const Medium &m, const FlatPunch &punch, const double d, const double r)
  {
    const char *fn = "flat_punch pressure";
    check_medium(fn, m);
    check::positive(fn, "a", punch.a);
    check::finite(fn, "d", d);
    check::non_negative(fn, "r", r);
    if (r > punch.a)
      return 0.;
    if (r == punch.a)
      check::fail(fn, "r", r, "equals a: the pressure is unbounded at the punch edge (use r != a)");
    return m.cN0 * d /
           (pi * std::pow(m.c0, m.k) * std::pow(difference_of_squares(punch.a, r), (1. - m.k) / 2.));
  }

  double displacement(const Medium &m, const FlatPunch &punch, const double d, const double r)
  {
    const char *fn = "flat_punch displacement";
    check_medium(fn, m);
    check::positive(fn, "a", punch.a);
    check::finite(fn, "d", d);
    check::non_negative(fn, "r", r);
    if (r <= punch.a)
      return d;
    return outer_factor(m.k) * d * flat_punch_outer_beta(m.k, punch.a, r);
  }

  // --- power law, cone, paraboloid ------------------------------------------------------------
  double depth(const Medium &m, const PowerLaw &p, const double a)
  {
    const char *fn = "power_law depth";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "a", a);
    return kappa(p.n, m.k) * p.A * std::pow(a, p.n); // 9.30
  }

  double force(const Medium &m, const PowerLaw &p, const double a)
  {
    const char *fn = "power_law force";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "a", a);
    const double k = m.k, n = p.n;
    return 2. * m.cN0 * kappa(n, k) * n * p.A * std::pow(a, n + k + 1.) /
           (std::pow(m.c0, k) * (k + 1.) * (n + k + 1.)); // 9.30
  }

  double pressure(const Medium &m, const PowerLaw &p, const double a, const double r)
  {
    const char *fn = "power_law pressure";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "a", a);
    check::non_negative(fn, "r", r);
    if (r >= a)
      return 0.;
    const double k = m.k, n = p.n;
    const double prefactor = m.cN0 * kappa(n, k) * n * p.A / (pi * std::pow(m.c0, k));
    // n + k - 1 as (n - 1) + k: exact n - 1 for 1/2 <= n <= 2 (Sterbenz), then one rounding. Formed as
    // (n + k) - 1 it would carry the rounding of n + k, a relative error eps/(n + k - 1): 4e-9 for the
    // cone (n = 1) at k = 2.6e-8, where p(0) ~ 1/k.
    const double e = power_law_exponent(n, k);
    if (r == 0.)
      {
        // p(0) = prefactor int_0^a x^(n+k-2) dx: finite only for n + k > 1.
        if (!(e > 0.))
          check::fail(fn, "n + k", n + k,
                      "must be > 1 for a finite pressure at r = 0 (the tip is too sharp)");
        return prefactor * std::pow(a, e) / e;
      }
    // 9.30: r^(n+k-1)/2 [B((1-k-n)/2, (1+k)/2) - B(r^2/a^2; (1-k-n)/2, (1+k)/2)], the bracket
    // being the upper incomplete integral, finite for every n (ERRATA.md, Gamma poles). Near the edge
    // it is ~ (1 - r^2/a^2)^((1+k)/2): 1 - r^2/a^2 = (a-r)(a+r)/a^2, not 1 minus a rounded (r/a)^2.
    const double z = (r / a) * (r / a);
    return prefactor / 2. * std::pow(r, e) *
           beta_upper(z, -e / 2., (1. + k) / 2., difference_of_squares(a, r) / (a * a));
  }

  double displacement(const Medium &m, const PowerLaw &p, const double a, const double r)
  {
    const char *fn = "power_law displacement";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "a", a);
    check::non_negative(fn, "r", r);
    const double k = m.k, n = p.n;
    const double d = kappa(n, k) * p.A * std::pow(a, n);
    if (r <= a)
      return d - p.A * std::pow(r, n);
    const double y = (1. - k) / 2.;
    return outer_factor(k) * d *
           (outer_beta((1. + k) / 2., y, a, r) - std::pow(r / a, n) * outer_beta((1. + k + n) / 2., y, a, r)); // 9.30
  }

  double contact_radius_from_depth(const Medium &m, const PowerLaw &p, const double d)
  {
    const char *fn = "power_law contact_radius";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "d", d);
    return std::pow(d / (kappa(p.n, m.k) * p.A), 1. / p.n);
  }

  double contact_radius_from_force(const Medium &m, const PowerLaw &p, const double F)
  {
    const char *fn = "power_law contact_radius";
    check_medium(fn, m);
    check_power_law(fn, p);
    check::positive(fn, "F", F);
    const double k = m.k, n = p.n;
    const double unit_force = 2. * m.cN0 * kappa(n, k) * n * p.A /
                              (std::pow(m.c0, k) * (k + 1.) * (n + k + 1.));
    return std::pow(F / unit_force, 1. / (n + k + 1.));
  }

  double depth(const Medium &m, const Cone &c, const double a) { return depth(m, as_power_law(c), a); }
  double force(const Medium &m, const Cone &c, const double a) { return force(m, as_power_law(c), a); }
  double pressure(const Medium &m, const Cone &c, const double a, const double r)
  {
    // 9.20 is 9.30 at n = 1: r^k/2 [B(-k/2, (1+k)/2) - B(r^2/a^2; -k/2, (1+k)/2)].
    return pressure(m, as_power_law(c), a, r);
  }
  double displacement(const Medium &m, const Cone &c, const double a, const double r)
  {
    // 9.20 with the second beta parameter (2+k)/2 (printed: (3+k)/2, ERRATA.md) = 9.30 at n = 1.
    return displacement(m, as_power_law(c), a, r);
  }

  double depth(const Medium &m, const Paraboloid &p, const double a)
  {
    const char *fn = "paraboloid depth";
    check_medium(fn, m);
    check::positive(fn, "R", p.R);
    check::positive(fn, "a", a);
    return a * a / ((m.k + 1.) * p.R); // 9.26
  }

  double force(const Medium &m, const Paraboloid &p, const double a)
  {
    const char *fn = "paraboloid force";
    check_medium(fn, m);
    check::positive(fn, "R", p.R);
    check::positive(fn, "a", a);
    const double k = m.k;
    return 4. * m.cN0 * std::pow(a, k + 3.) /
           (std::pow(m.c0, k) * (k + 1.) * (k + 1.) * (k + 3.) * p.R); // 9.26
  }

  double pressure(const Medium &m, const Paraboloid &p, const double a, const double r)
  {
    const char *fn = "paraboloid pressure";
    check_medium(fn, m);
    check::positive(fn, "R", p.R);
    check::positive(fn, "a", a);
    check::non_negative(fn, "r", r);
    if (r >= a)
      return 0.;
    const double k = m.k;
    const double s = difference_of_squares(a, r) / (a * a); // 1 - r^2/a^2
    return 2. * m.cN0 * std::pow(a, k + 1.) / (pi * std::pow(m.c0, k) * (k + 1.) * (k + 1.) * p.R) *
           std::pow(s, (1. + k) / 2.); // 9.26
  }

  double displacement(const Medium &m, const Paraboloid &p, const double a, const double r)
  {
    const char *fn = "paraboloid displacement";
    check_medium(fn, m);
    check::positive(fn, "R", p.R);
    check::positive(fn, "a", a);
    check::non_negative(fn, "r", r);
    const double k = m.k;
    if (r <= a)
      return a * a / ((k + 1.) * p.R) - r * r / (2. * p.R);
    const double y = (1. - k) / 2.;
    return a * a * outer_factor(k) / ((k + 1.) * p.R) *
           (outer_beta((1. + k) / 2., y, a, r) - (r / a) * (r / a) * outer_beta((3. + k) / 2., y, a, r)); // 9.26
  }

  // --- concave punch ----------------------------------------------------------------------------
  namespace
  {
    void check_concave(const char *fn, const Medium &m, const ConcavePunch &punch, const double d0)
    {
      check_medium(fn, m);
      check::positive(fn, "a", punch.a);
      check::non_negative(fn, "h0", punch.h0);
      check::finite(fn, "d0", d0);
      const double d_min = minimum_centre_displacement(m, punch);
      if (!(d0 > d_min))
        check::fail(fn, "d0", d0,
                    "must exceed 2 (1-k) h0/(1+k)^2 = " + check::format(d_min) +
                      " for complete contact of the concave punch (9.35)");
    }
  } // namespace

  double minimum_centre_displacement(const Medium &m, const ConcavePunch &punch)
  {
    return 2. * (1. - m.k) * punch.h0 / ((1. + m.k) * (1. + m.k));
  }

  double force(const Medium &m, const ConcavePunch &punch, const double d0)
  {
    check_concave("concave_paraboloid force", m, punch, d0);
    const double k = m.k;
    return 2. * m.cN0 * std::pow(punch.a, k + 1.) / ((1. + k) * std::pow(m.c0, k)) *
           (d0 + 2. * punch.h0 / (k + 3.)); // 9.34
  }

  double pressure(const Medium &m, const ConcavePunch &punch, const double d0, const double r)
  {
    const char *fn = "concave_paraboloid pressure";
    check_concave(fn, m, punch, d0);
    check::non_negative(fn, "r", r);
    const double k = m.k, a = punch.a;
    if (r > a)
      return 0.;
    if (r == a)
      check::fail(fn, "r", r, "equals a: the pressure is unbounded at the punch edge (use r != a)");
    // k - 1 + 2 r^2/a^2 = (k + 1) - 2 (1 - r^2/a^2), with 1 - r^2/a^2 = (a-r)(a+r)/a^2.
    const double s = difference_of_squares(a, r) / (a * a);
    return m.cN0 /
           (pi * std::pow(m.c0, k) * std::pow(difference_of_squares(a, r), (1. - k) / 2.)) *
           (d0 + 2. * punch.h0 / ((k + 1.) * (k + 1.)) * ((k + 1.) - 2. * s)); // 9.34
  }

  double displacement(const Medium &m, const ConcavePunch &punch, const double d0, const double r)
  {
    const char *fn = "concave_paraboloid displacement";
    check_concave(fn, m, punch, d0);
    check::non_negative(fn, "r", r);
    const double k = m.k, a = punch.a;
    if (r <= a)
      return d0 + punch.h0 * (r / a) * (r / a); // 9.32: d0 - f(r)
    const double y = (1. - k) / 2.;
    return outer_factor(k) * (d0 * outer_beta((1. + k) / 2., y, a, r) +
                              2. * punch.h0 / (k + 1.) * (r / a) * (r / a) * outer_beta((3. + k) / 2., y, a, r)); // 9.34
  }

  // --- constant pressure ---------------------------------------------------------------------
  double centre_displacement(const Medium &m, const UniformPressure &load)
  {
    const char *fn = "constant_pressure depth";
    check_medium(fn, m);
    check::positive(fn, "a", load.a);
    check::finite(fn, "p0", load.p0);
    const double k = m.k;
    return 2. * std::pow(m.c0, k) * boost::math::cos_pi(k / 2.) * load.p0 *
           std::pow(load.a, 1. - k) / (m.cN0 * (1. - k)); // 9.39
  }

  double displacement(const Medium &m, const UniformPressure &load, const double r)
  {
    const char *fn = "constant_pressure displacement";
    check::non_negative(fn, "r", r);
    const double wc = centre_displacement(m, load);
    const double k = m.k, a = load.a;
    if (r <= a)
      return wc * hyp2f1((k - 1.) / 2., (1. + k) / 2., 1., (r / a) * (r / a), (a - r) * (a + r) / (a * a)); // 9.40
    return wc * (1. - k) / 2. * std::pow(a / r, 1. + k) *
           hyp2f1((1. + k) / 2., (1. + k) / 2., 2., (a / r) * (a / r), (r - a) * (r + a) / (r * r)); // 9.40
  }

  double force(const UniformPressure &load)
  {
    check::positive("constant_pressure force", "a", load.a);
    check::finite("constant_pressure force", "p0", load.p0);
    return load.p0 * pi * load.a * load.a;
  }

  double gibson_winkler_modulus(const double E0, const double c0)
  {
    check::positive("gibson_winkler_modulus", "E0", E0);
    check::positive("gibson_winkler_modulus", "c0", c0);
    return 2. * E0 / (3. * c0); // 9.44
  }
} // namespace gradcontact
