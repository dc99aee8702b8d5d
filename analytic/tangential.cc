#include <analytic/errors.h>
#include <analytic/tangential.h>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <limits>

namespace gradcontact::tangential
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();

    void check_slip(const char *fn, const Medium &m, const SphereSlip &s, const double a)
    {
      validate(fn, m);
      check::positive(fn, "R", s.R);
      check::positive(fn, "mu (friction coefficient)", s.mu);
      check::positive(fn, "a", a);
    }

    // The paraboloid pressure of 9.80 without its factor: P (a^2 - r^2)^((1+k)/2) with
    // P = 2 cN0 / (pi c0^k (k+1)^2 R), zero outside the radius.
    double parabolic_prefactor(const Medium &m, const double R)
    {
      const double k = m.k;
      return 2. * m.cN0 / (pi * std::pow(m.c0, k) * (k + 1.) * (k + 1.) * R);
    }

    // Every tangential closed form is a difference of the normal solution at two radii b <= a (9.77,
    // 9.81), and b enters only through the fractions 1 - (b/a)^e (e = k+3 for forces, 2 for depths and
    // the squared radii of the traction). Near b = a the fraction is small, and 1 minus a rounded power
    // of a rounded ratio would lose eps/fraction: the fractions are formed from what the caller knows
    // exactly, the gap a - b or the force fraction s = 1 - (b/a)^(k+3):
    //   1 - (1 - s)^P = -expm1(P log1p(-s)),   1 - (b/a)^e = -expm1(e log1p(-(a - b)/a)).

    /// 1 - (1 - s)^P for 0 <= s <= 1.
    double one_minus_power(const double s, const double P) { return -std::expm1(P * std::log1p(-s)); }

    /// 1 - (b/a)^e for 0 <= b <= a, from the gap a - b.
    double one_minus_ratio_power(const double a, const double b, const double e)
    {
      return -std::expm1(e * std::log1p(-(a - b) / a));
    }

    /// (1 - (t - delta))^P - (1 - t)^P = m(t) - m(t - delta) for m(s) = 1 - (1 - s)^P, from delta, t < 1:
    /// (1 - t)^P expm1(P log1p(delta / (1 - t))), without the cancellation of the two powers.
    double power_step(const double t, const double delta, const double P)
    {
      const double one_minus_t = 1. - t;
      return std::pow(one_minus_t, P) * std::expm1(P * std::log1p(delta / one_minus_t));
    }

    /// The second difference m(2h) - 2 m(h) = 2 (1-h)^P - (1-2h)^P - 1 of m(s) = 1 - (1 - s)^P for
    /// 0 <= 2h <= 1 and 0 < P < 2. It is O(h^2) (P (1-P) h^2 to leading order): the loop of an oscillation
    /// closes on it (u0 at Fx = 0, F_x at u0 = 0, the traction in the stick zone), and the printed form of
    /// 9.83-9.84 loses eps/h^2 there; it also vanishes like 1 - P as P -> 1 (k -> -1 in 9.81-9.84), where the
    /// printed form loses eps/(1-P) at any h (5e5 eps at P = 1 - 2e-6, h = 0.46). Two regions:
    /// - 2h <= 0.7: the binomial series sum_(j>=2) C(P, j) (-h)^j (2 - 2^j), whose terms have one sign
    ///   (no cancellation), carry the factor P (1-P), and fall at least like 0.7^j;
    /// - 2h > 0.7: (1 - s)^P = (1 - s)^n [1 + expm1((P - n) log1p(-s))] with n = 0 or 1 the integer nearer
    ///   P: the parts (1 - s)^n cancel exactly (2 (1-h)^n - (1-2h)^n - 1 = 0), and the two expm1 terms that
    ///   remain differ by a bounded factor: at most 8 eps lost against 40-digit mpmath over 0 < P < 2 (the
    ///   series would need up to 300 terms near 2h = 0.9 and lose 9 eps, the printed form 500 eps at P = 1e-3).
    double second_difference(const double h, const double P)
    {
      if (2. * h > 0.7)
        {
          if (2. * h >= 1.)
            return std::expm1((1. - P) * std::log(2.)); // m(1) - 2 m(1/2) = 2^(1-P) - 1
          const double n = P < 0.5 ? 0. : 1.;
          return 2. * std::pow(1. - h, n) * std::expm1((P - n) * std::log1p(-h)) -
                 std::pow(1. - 2. * h, n) * std::expm1((P - n) * std::log1p(-2. * h));
        }
      double b = -P;                         // C(P, j) (-1)^j at j = 1
      double hj = h, h2j = 2. * h, sum = 0.; // h^j, (2h)^j
      for (int j = 2; j < 1000; ++j)
        {
          b *= (j - 1. - P) / j;
          hj *= h;
          h2j *= 2. * h;
          const double term = b * (2. * hj - h2j);
          sum += term;
          if (std::abs(term) <= 0.5 * std::numeric_limits<double>::epsilon() * std::abs(sum))
            break;
        }
      return sum;
    }

    /// m(F) - 2 m(G) for m(s) = 1 - (1 - s)^P, F the fraction at the turning point A and G = (F - sigma)/2
    /// the fraction of the annulus at sigma in [-F, F] on the unloading branch: the normalised u0 at a force
    /// (P = 2/(k+3), F = phi = F_A/(mu F_N), sigma = F_x/(mu F_N); 9.83) or the normalised F_x at a displacement
    /// (P = (k+3)/2, F = u_A/(mu alpha d), sigma = u0/(mu alpha d); 9.84). Written as
    /// [m(F) - 2 m(F/2)] - 2 [m(G) - m(F/2)] with G - F/2 = -sigma/2: the first bracket is the second
    /// difference, the second a step of m, neither cancels; the sum cancels only where the branch crosses
    /// zero, which its input sigma decides.
    double branch_value(const double F, const double sigma, const double P)
    {
      const double G = (F - sigma) / 2.;
      return second_difference(F / 2., P) - 2. * power_step(G, -sigma / 2., P);
    }

    // mu [p(r; a) - p(r; b)] / (mu P) for b <= a: with x = a^2 - r^2, gap2 = a^2 - b^2 and
    // y = b^2 - r^2 (both formed by the caller without cancellation), x^q for r >= b (y <= 0) and
    // y^q expm1(q log1p(gap2 / y)) inside: as k -> -1 the exponent q = (1+k)/2 -> 0 and both powers tend
    // to 1, and near b = a the two powers are close.
    double pressure_step(const double x, const double gap2, const double y, const double q)
    {
      if (!(x > 0.))
        return 0.;
      if (!(y > 0.))
        return std::pow(x, q);
      return std::pow(y, q) * std::expm1(q * std::log1p(gap2 / y));
    }

    double normal_force(const Medium &m, const SphereSlip &s, const double a)
    {
      return gradcontact::force(m, Paraboloid{s.R}, a);
    }

    void check_amplitude(const char *fn, const Medium &m, const SphereSlip &s, const double a,
                         const double FA)
    {
      check_slip(fn, m, s, a);
      const double limit = s.mu * normal_force(m, s, a);
      check::finite(fn, "FA", FA);
      if (!(FA > 0. && FA < limit))
        check::fail(fn, "FA", FA,
                    "is outside (0, mu F_N) = (0, " + check::format(limit) + "): gross slip");
    }

    // Radius b of the slip annulus that a change |dF| of the force opens on an unloading or reloading
    // branch: |dF| = 2 mu F_N(a) [1 - (b/a)^(k+3)] (9.81).
    double annulus_radius(const Medium &m, const SphereSlip &s, const double a, const double dF)
    {
      return a * std::exp(std::log1p(-dF / (2. * s.mu * normal_force(m, s, a))) / (m.k + 3.));
    }

    /// The unloading branch at the force fraction sigma = Fx/(mu F_N) in [-phi, phi] after the loading to
    /// phi = F_A/(mu F_N), as a multiple of mu P (the traction, 9.82 with mu) at x = a^2 - r^2:
    ///   tau/(mu P) = [x^q - y_c^q] - 2 [x^q - y_b^q],  y = x - (a^2 - radius^2), q = (1+k)/2,
    /// with a^2 - c^2 = a^2 m(phi), a^2 - b^2 = a^2 m((phi - sigma)/2), m(s) = 1 - (1-s)^(2/(k+3)) (9.81).
    /// Inside the stick zone of A (r < c <= b) it is 2 [y_b^q - y_h^q] + x^q D_q(h/x) with h = (a^2 - c^2)/2,
    /// y_h = x - h and D_q the second difference of 1 - (1-s)^q: y_b - y_h = a^2 [m(phi)/2 - m(b's fraction)]
    /// is branch_value/2, formed without cancellation, so the traction near the middle of a small loop
    /// (O(phi^2)) keeps its digits.
    double unloading_traction(const double k, const double phi, const double sigma, const double a, const double r)
    {
      const double q = (1. + k) / 2., P = 2. / (k + 3.);
      const double x = (a - r) * (a + r);
      if (!(x > 0.))
        return 0.;
      const double a2 = a * a;
      const double gap_c = a2 * one_minus_power(phi, P);
      const double gap_b = a2 * one_minus_power((phi - sigma) / 2., P);
      if (!(x - gap_b > 0.)) // r >= b: the slip has reversed
        return -std::pow(x, q);
      if (!(x - gap_c > 0.)) // c <= r < b
        return 2. * std::pow(x - gap_b, q) - std::pow(x, q);
      const double y_h = x - gap_c / 2.;
      const double step = a2 * branch_value(phi, sigma, P) / 2.; // y_b - y_h
      return 2. * std::pow(y_h, q) * std::expm1(q * std::log1p(step / y_h)) +
             std::pow(x, q) * second_difference(gap_c / (2. * x), q);
    }

    // The bracket of the dissipated energy (9.86),
    //   B(phi) = 1 - (1-phi)^(1+q) - (1+q)/2 phi (1 + (1-phi)^q),  q = 2/(k+3),
    // vanishes like (1+q) q (1-q)/12 phi^3: the printed form loses all digits for small phi. Its Taylor
    // series sum_(j>=3) (-1)^(j+1) [C(1+q, j) - (1+q)/2 C(q, j-1)] phi^j (binomial coefficients C) is
    // used for phi <= 1/2, where it converges at least like 2^-j.
    double dissipation_bracket(const double phi, const double q)
    {
      if (phi > 0.5)
        return 1. - std::pow(1. - phi, 1. + q) - (1. + q) / 2. * phi * (1. + std::pow(1. - phi, q));
      // C(1+q, j) and C(q, j-1) by their recurrences, starting at j = 2.
      double c1 = (1. + q) * q / 2.; // C(1+q, 2)
      double c0 = q;                 // C(q, 1)
      double power = phi * phi, sum = 0.;
      for (int j = 3; j < 400; ++j)
        {
          c1 *= (1. + q - (j - 1.)) / j;
          c0 *= (q - (j - 2.)) / (j - 1.);
          power *= phi;
          const double term = ((j % 2 == 1) ? 1. : -1.) * (c1 - (1. + q) / 2. * c0) * power;
          sum += term;
          if (std::abs(term) <= 1e-17 * std::abs(sum))
            return sum;
        }
      return sum;
    }

    void check_branch_force(const char *fn, const double FA, const double Fx)
    {
      check::closed_interval(fn, "Fx", Fx, -FA, FA);
    }
  } // namespace

  double holl_ratio(const double k)
  {
    check::open_interval("holl_ratio", "k", k, 0., 1.);
    return 1. / (2. + k);
  }

  double traction(const Medium &m, const SphereSlip &s, const double a, const double c, const double r)
  {
    const char *fn = "tangential_sphere traction";
    check_slip(fn, m, s, a);
    check::closed_interval(fn, "c (stick radius)", c, 0., a);
    check::non_negative(fn, "r", r);
    // p(r; a) - p(r; c) from a^2 - c^2 and c^2 - r^2 as differences of the inputs (9.80)
    return s.mu * parabolic_prefactor(m, s.R) *
           pressure_step((a - r) * (a + r), (a - c) * (a + c), (c - r) * (c + r), (1. + m.k) / 2.); // 9.80
  }

  double tangential_force(const Medium &m, const SphereSlip &s, const double a, const double c)
  {
    const char *fn = "tangential_sphere tangential_force";
    check_slip(fn, m, s, a);
    check::closed_interval(fn, "c (stick radius)", c, 0., a);
    return s.mu * normal_force(m, s, a) * one_minus_ratio_power(a, c, m.k + 3.); // 9.80
  }

  double tangential_displacement(const Medium &m, const SphereSlip &s, const double a, const double c)
  {
    const char *fn = "tangential_sphere tangential_displacement";
    check_slip(fn, m, s, a);
    check::closed_interval(fn, "c (stick radius)", c, 0., a);
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    return s.mu * m.alpha() * d * ((a - c) * (a + c) / (a * a)); // 9.80: 1 - c^2/a^2
  }

  double stick_radius(const Medium &m, const SphereSlip &s, const double a, const double Fx)
  {
    const char *fn = "tangential_sphere stick_radius";
    check_slip(fn, m, s, a);
    const double limit = s.mu * normal_force(m, s, a);
    check::finite(fn, "Fx", Fx);
    if (!(Fx >= 0. && Fx < limit))
      check::fail(fn, "Fx", Fx, "is outside [0, mu F_N) = [0, " + check::format(limit) + "): gross slip");
    return a * std::exp(std::log1p(-Fx / limit) / (m.k + 3.));
  }

  namespace
  {
    /// Fx/(mu F_N) after the gross-slip check of stick_radius.
    double force_fraction(const char *fn, const Medium &m, const SphereSlip &s, const double a, const double Fx)
    {
      check_slip(fn, m, s, a);
      const double limit = s.mu * normal_force(m, s, a);
      check::finite(fn, "Fx", Fx);
      if (!(Fx >= 0. && Fx < limit))
        check::fail(fn, "Fx", Fx, "is outside [0, mu F_N) = [0, " + check::format(limit) + "): gross slip");
      return Fx / limit;
    }
  } // namespace

  double traction_at_force(const Medium &m, const SphereSlip &s, const double a, const double Fx, const double r)
  {
    const char *fn = "tangential_sphere traction";
    const double fraction = force_fraction(fn, m, s, a, Fx);
    check::non_negative(fn, "r", r);
    const double x = (a - r) * (a + r);
    const double gap = a * a * one_minus_power(fraction, 2. / (m.k + 3.)); // a^2 - c^2 (9.80)
    return s.mu * parabolic_prefactor(m, s.R) * pressure_step(x, gap, x - gap, (1. + m.k) / 2.); // 9.80
  }

  double tangential_displacement_at_force(const Medium &m, const SphereSlip &s, const double a, const double Fx)
  {
    const char *fn = "tangential_sphere tangential_displacement";
    const double fraction = force_fraction(fn, m, s, a, Fx);
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    return s.mu * m.alpha() * d * one_minus_power(fraction, 2. / (m.k + 3.)); // 9.80 with 1 - c^2/a^2 from Fx
  }

  double tangential_force_at_force(const Medium &m, const SphereSlip &s, const double a, const double Fx)
  {
    force_fraction("tangential_sphere tangential_force", m, s, a, Fx);
    return Fx; // mu F_N [1 - (c/a)^(k+3)] at the stick radius of Fx (9.80)
  }

  double traction(const Medium &m, const SphereSlip &s, const double a, const double FA,
                  const Branch branch, const double Fx, const double r)
  {
    const char *fn = "oscillating_sphere traction";
    check_amplitude(fn, m, s, a, FA);
    check::non_negative(fn, "r", r);
    if (branch == Branch::loading)
      return traction_at_force(m, s, a, Fx, r);
    check_branch_force(fn, FA, Fx);
    const double limit = s.mu * normal_force(m, s, a);
    const double phi = FA / limit, sigma = Fx / limit;
    // The change on the branch, -+2 mu [p(r; a) - p(r; b)] (9.81), added to tau_A; the reloading state is
    // the mirror image of the unloading one, starting from tau_E = -tau_A.
    const double P = s.mu * parabolic_prefactor(m, s.R);
    return branch == Branch::unloading ? P * unloading_traction(m.k, phi, sigma, a, r)
                                       : -P * unloading_traction(m.k, phi, -sigma, a, r); // 9.82 (with mu)
  }

  double reversal_radius(const Medium &m, const SphereSlip &s, const double a, const double FA,
                         const Branch branch, const double Fx)
  {
    const char *fn = "oscillating_sphere reversal_radius";
    check_amplitude(fn, m, s, a, FA);
    if (branch == Branch::loading)
      throw DomainError(std::string(fn) + ": branch = loading has no reversed slip (unloading or reloading only)");
    check_branch_force(fn, FA, Fx);
    return annulus_radius(m, s, a, branch == Branch::unloading ? FA - Fx : Fx + FA);
  }

  double displacement_at_A(const Medium &m, const SphereSlip &s, const double a, const double FA)
  {
    const char *fn = "oscillating_sphere displacement_at_A";
    check_amplitude(fn, m, s, a, FA);
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    return s.mu * m.alpha() * d * one_minus_power(FA / (s.mu * normal_force(m, s, a)), 2. / (m.k + 3.)); // 9.85
  }

  double tangential_displacement(const Medium &m, const SphereSlip &s, const double a, const double FA,
                                 const Branch branch, const double Fx)
  {
    const char *fn = "oscillating_sphere tangential_displacement";
    check_amplitude(fn, m, s, a, FA);
    if (branch == Branch::loading)
      return tangential_displacement_at_force(m, s, a, Fx);
    check_branch_force(fn, FA, Fx);
    const double limit = s.mu * normal_force(m, s, a);
    const double phi = FA / limit, sigma = Fx / limit, P = 2. / (m.k + 3.);
    // u0 = u_A - 2 mu alpha d [1 - (b/a)^2] (9.81, 9.83) = mu alpha d [m(phi) - 2 m((phi - sigma)/2)]
    const double scale = s.mu * m.alpha() * gradcontact::depth(m, Paraboloid{s.R}, a);
    return branch == Branch::unloading ? scale * branch_value(phi, sigma, P)
                                       : -scale * branch_value(phi, -sigma, P); // 9.83
  }

  double hysteresis_force(const Medium &m, const SphereSlip &s, const double a, const double FA,
                          const Branch branch, const double u0)
  {
    const char *fn = "oscillating_sphere hysteresis_force";
    check_amplitude(fn, m, s, a, FA);
    const double uA = displacement_at_A(m, s, a, FA);
    check::finite(fn, "u0", u0);
    const double FN = normal_force(m, s, a);
    const double scale = s.mu * m.alpha() * gradcontact::depth(m, Paraboloid{s.R}, a);
    const double Q = (m.k + 3.) / 2.;
    if (branch == Branch::loading)
      {
        check::closed_interval(fn, "u0", u0, 0., uA);
        // 9.80 with c eliminated: F_x = mu F_N [1 - (1 - u0 / (mu alpha d))^((k+3)/2)]
        return s.mu * FN * one_minus_power(u0 / scale, Q);
      }
    check::closed_interval(fn, "u0", u0, -uA, uA);
    // 9.84: F_x = F_A - 2 mu F_N [1 - (1 - (u_A - u0)/(2 mu alpha d))^((k+3)/2)], with F_A = mu F_N n(u_A/scale)
    // for n(v) = 1 - (1 - v)^((k+3)/2) (9.85): mu F_N [n(v_A) - 2 n((v_A - v)/2)], v = u0/scale.
    const double vA = one_minus_power(FA / (s.mu * FN), 1. / Q);
    return branch == Branch::unloading ? s.mu * FN * branch_value(vA, u0 / scale, Q)
                                       : -s.mu * FN * branch_value(vA, -u0 / scale, Q); // 9.84
  }

  double dissipated_energy(const Medium &m, const SphereSlip &s, const double a, const double FA)
  {
    const char *fn = "oscillating_sphere dissipated_energy";
    check_amplitude(fn, m, s, a, FA);
    const double k = m.k;
    const double FN = normal_force(m, s, a);
    const double phi = FA / (s.mu * FN);
    return 2. * (k + 3.) * (k + 3.) * (k + 1.) * s.mu * s.mu * FN * FN * std::pow(m.c0, k) /
           ((k + 5.) * m.cT0 * std::pow(a, k + 1.)) * dissipation_bracket(phi, 2. / (k + 3.)); // 9.86
  }
} // namespace gradcontact::tangential
