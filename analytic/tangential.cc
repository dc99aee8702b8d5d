#include <analytic/errors.h>
#include <analytic/tangential.h>

#include <boost/math/constants/constants.hpp>

#include <cmath>

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

    // p(r; outer) - p(r; inner) for inner <= outer: as k -> -1 the exponent (1+k)/2 -> 0 and both
    // powers tend to 1, so the difference is formed as y^q expm1(q log(x/y)) without cancellation.
    double parabolic_difference(const Medium &m, const double R, const double outer, const double inner,
                                const double r)
    {
      if (r >= outer)
        return 0.;
      const double q = (1. + m.k) / 2.;
      const double x = (outer - r) * (outer + r);
      if (r >= inner)
        return parabolic_prefactor(m, R) * std::pow(x, q);
      const double y = (inner - r) * (inner + r);
      return parabolic_prefactor(m, R) * std::pow(y, q) * std::expm1(q * std::log(x / y));
    }

    // 1 - (b/a)^2 for b = a (1 - s)^(1/(k+3)): -expm1(2/(k+3) log1p(-s)), exact as s -> 0.
    double one_minus_square_ratio(const double s, const double k)
    {
      return -std::expm1(2. / (k + 3.) * std::log1p(-s));
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
      return a * std::pow(1. - dF / (2. * s.mu * normal_force(m, s, a)), 1. / (m.k + 3.));
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
    return s.mu * parabolic_difference(m, s.R, a, c, r); // 9.80
  }

  double tangential_force(const Medium &m, const SphereSlip &s, const double a, const double c)
  {
    const char *fn = "tangential_sphere tangential_force";
    check_slip(fn, m, s, a);
    check::closed_interval(fn, "c (stick radius)", c, 0., a);
    return s.mu * normal_force(m, s, a) * (1. - std::pow(c / a, m.k + 3.)); // 9.80
  }

  double tangential_displacement(const Medium &m, const SphereSlip &s, const double a, const double c)
  {
    const char *fn = "tangential_sphere tangential_displacement";
    check_slip(fn, m, s, a);
    check::closed_interval(fn, "c (stick radius)", c, 0., a);
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    return s.mu * m.alpha() * d * (1. - (c / a) * (c / a)); // 9.80
  }

  double stick_radius(const Medium &m, const SphereSlip &s, const double a, const double Fx)
  {
    const char *fn = "tangential_sphere stick_radius";
    check_slip(fn, m, s, a);
    const double limit = s.mu * normal_force(m, s, a);
    check::finite(fn, "Fx", Fx);
    if (!(Fx >= 0. && Fx < limit))
      check::fail(fn, "Fx", Fx, "is outside [0, mu F_N) = [0, " + check::format(limit) + "): gross slip");
    return a * std::pow(1. - Fx / limit, 1. / (m.k + 3.));
  }

  double traction(const Medium &m, const SphereSlip &s, const double a, const double FA,
                  const Branch branch, const double Fx, const double r)
  {
    const char *fn = "oscillating_sphere traction";
    check_amplitude(fn, m, s, a, FA);
    check::non_negative(fn, "r", r);
    if (branch == Branch::loading)
      return traction(m, s, a, stick_radius(m, s, a, Fx), r);
    check_branch_force(fn, FA, Fx);
    const double c = stick_radius(m, s, a, FA);
    const double tau_A = traction(m, s, a, c, r);
    const double dF = (branch == Branch::unloading) ? FA - Fx : Fx + FA;
    const double b = annulus_radius(m, s, a, dF);
    // Change on the branch: -+2 mu [p(r; a) - p(r; b)] (9.81); the reloading state is the mirror
    // image of the unloading one, starting from tau_E = -tau_A.
    const double change = 2. * s.mu * parabolic_difference(m, s.R, a, b, r);
    return branch == Branch::unloading ? tau_A - change : -tau_A + change; // 9.82 (with mu)
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
    return s.mu * m.alpha() * d * one_minus_square_ratio(FA / (s.mu * normal_force(m, s, a)), m.k); // 9.85
  }

  double tangential_displacement(const Medium &m, const SphereSlip &s, const double a, const double FA,
                                 const Branch branch, const double Fx)
  {
    const char *fn = "oscillating_sphere tangential_displacement";
    check_amplitude(fn, m, s, a, FA);
    if (branch == Branch::loading)
      return tangential_displacement(m, s, a, stick_radius(m, s, a, Fx));
    check_branch_force(fn, FA, Fx);
    const double uA = displacement_at_A(m, s, a, FA);
    const double dF = (branch == Branch::unloading) ? FA - Fx : Fx + FA;
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    const double change = 2. * s.mu * m.alpha() * d *
                          one_minus_square_ratio(dF / (2. * s.mu * normal_force(m, s, a)), m.k); // 9.81
    return branch == Branch::unloading ? uA - change : -uA + change;           // 9.83
  }

  double hysteresis_force(const Medium &m, const SphereSlip &s, const double a, const double FA,
                          const Branch branch, const double u0)
  {
    const char *fn = "oscillating_sphere hysteresis_force";
    check_amplitude(fn, m, s, a, FA);
    const double uA = displacement_at_A(m, s, a, FA);
    check::finite(fn, "u0", u0);
    const double FN = normal_force(m, s, a);
    const double d = gradcontact::depth(m, Paraboloid{s.R}, a);
    const double q = 2. * m.alpha() * s.mu * d;
    if (branch == Branch::loading)
      {
        check::closed_interval(fn, "u0", u0, 0., uA);
        // 9.80 with c eliminated: F_x = mu F_N [1 - (1 - u0 / (mu alpha d))^((k+3)/2)]
        return s.mu * FN * (1. - std::pow(1. - 2. * u0 / q, (m.k + 3.) / 2.));
      }
    check::closed_interval(fn, "u0", u0, -uA, uA);
    if (branch == Branch::unloading)
      return FA - 2. * s.mu * FN * (1. - std::pow(1. + (u0 - uA) / q, (m.k + 3.) / 2.)); // 9.84
    return -FA + 2. * s.mu * FN * (1. - std::pow(1. - (u0 + uA) / q, (m.k + 3.) / 2.)); // 9.84
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
