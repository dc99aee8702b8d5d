#include <analytic/errors.h>
#include <analytic/material.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/math/special_functions/sin_pi.hpp>
#include <boost/math/special_functions/cos_pi.hpp>

#include <cmath>

namespace gradcontact
{
  namespace
  {
    constexpr double pi = boost::math::constants::pi<double>();
    constexpr double root_pi = boost::math::constants::root_pi<double>();

    // 1 - k nu/(1 - nu), written as (1 - nu (1 + k)) / (1 - nu): no cancellation as k -> -1,
    // and 1 + k is exact in floating point for k in (-1, -1/2] (Sterbenz).
    double beta_factor(const double k, const double nu) { return (1. - nu * (1. + k)) / (1. - nu); }
  } // namespace

  void validate(const char *function, const GradedHalfSpace &body)
  {
    check::positive(function, "E0", body.E0);
    check::positive(function, "c0", body.c0);
    check::open_interval(function, "k", body.k, -1., 1.);
    check::closed_interval(function, "nu", body.nu, 0., 0.5);
  }

  double beta(const double k, const double nu)
  {
    check::open_interval("beta", "k", k, -1., 1.);
    check::closed_interval("beta", "nu", nu, 0., 0.5);
    return std::sqrt((1. + k) * beta_factor(k, nu));
  }

  double C(const double k, const double nu)
  {
    const double b = beta(k, nu);
    using boost::math::tgamma;
    return std::pow(2., 1. + k) * tgamma((3. + k + b) / 2.) * tgamma((3. + k - b) / 2.) /
           (pi * tgamma(2. + k));
  }

  namespace
  {
    // The factors h_N (9.5) and h_T (9.79) share: beta, C, cos(k pi/2), sin(beta pi/2) and Gamma(1 + k/2),
    // formed once when a medium needs both. cos(k pi/2) and sin(beta pi/2) through cos_pi/sin_pi, which
    // keep their relative accuracy where they vanish (k -> -1 makes both factors small,
    // h_N ~ pi (1-nu) (1+k)^2).
    struct SharedFactors
    {
      double b, C, cos_k, sin_b, gamma_k;
    };

    SharedFactors shared_factors(const double k, const double nu)
    {
      const double b = beta(k, nu);
      return {b, C(k, nu), boost::math::cos_pi(k / 2.), boost::math::sin_pi(b / 2.),
              boost::math::tgamma(1. + k / 2.)};
    }

    double h_N(const double k, const SharedFactors &f)
    {
      return 2. * (1. + k) * f.cos_k * f.gamma_k /
             (root_pi * f.C * f.b * f.sin_b * boost::math::tgamma((1. + k) / 2.)); // 9.5
    }

    double h_T(const double k, const double nu, const SharedFactors &f)
    {
      return 2. * f.b * f.cos_k * f.gamma_k /
             ((1. - nu * nu) * root_pi * f.C * f.sin_b * boost::math::tgamma((3. + k) / 2.) +
              f.b * (1. + nu) * f.gamma_k); // 9.79
    }
  } // namespace

  double h_N(const double k, const double nu) { return h_N(k, shared_factors(k, nu)); }

  double h_T(const double k, const double nu) { return h_T(k, nu, shared_factors(k, nu)); }

  Medium medium(const GradedHalfSpace &body)
  {
    validate("medium", body);
    const double k = body.k, nu = body.nu;
    const SharedFactors f = shared_factors(k, nu);
    return {k, body.c0, h_N(k, f) * body.E0 / (1. - nu * nu), h_T(k, nu, f) * body.E0};
  }

  Medium medium(const GradedHalfSpace &body1, const GradedHalfSpace &body2)
  {
    validate("medium (body 1)", body1);
    validate("medium (body 2)", body2);
    // 9.4 holds only for equal exponents and characteristic depths.
    if (body2.k != body1.k)
      check::fail("medium", "k of body 2", body2.k,
                  "must equal k of body 1 (" + check::format(body1.k) + ")");
    if (body2.c0 != body1.c0)
      check::fail("medium", "c0 of body 2", body2.c0,
                  "must equal c0 of body 1 (" + check::format(body1.c0) + ")");
    const double k = body1.k;
    const SharedFactors f1 = shared_factors(k, body1.nu), f2 = shared_factors(k, body2.nu);
    const auto compliance_N = [k](const GradedHalfSpace &b, const SharedFactors &f) {
      return (1. - b.nu * b.nu) / (h_N(k, f) * b.E0);
    };
    const auto compliance_T = [k](const GradedHalfSpace &b, const SharedFactors &f) {
      return 1. / (h_T(k, b.nu, f) * b.E0);
    };
    return {k, body1.c0, 1. / (compliance_N(body1, f1) + compliance_N(body2, f2)),
            1. / (compliance_T(body1, f1) + compliance_T(body2, f2))};
  }

  void validate(const char *function, const Medium &m)
  {
    check::open_interval(function, "k", m.k, -1., 1.);
    check::positive(function, "c0", m.c0);
    check::positive(function, "cN0", m.cN0);
    check::positive(function, "cT0", m.cT0);
  }
} // namespace gradcontact
