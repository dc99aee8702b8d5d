// The chapter's coefficient h_N written out for the FE tests, so that they check the FE against formulas
// typed from the text rather than against the analytic library.
#ifndef GRADCONTACT_TESTS_FEM_WRITTEN_OUT_H
#define GRADCONTACT_TESTS_FEM_WRITTEN_OUT_H

#include <cmath>

namespace gradcontact::fem::testing
{
  /// h_N(k, nu) of (9.5)-(9.7).
  inline double h_N(const double k, const double v)
  {
    constexpr double pi   = 3.14159265358979323846;
    const double     beta = std::sqrt((1 + k) * (1 - k * v / (1 - v)));                          // (9.7)
    const double     C    = std::pow(2.0, 1 + k) * std::tgamma((3 + k + beta) / 2) *
                     std::tgamma((3 + k - beta) / 2) / (pi * std::tgamma(2 + k));             // (9.6)
    return 2 * (1 + k) * std::cos(k * pi / 2) * std::tgamma(1 + k / 2) /
           (std::sqrt(pi) * C * beta * std::sin(beta * pi / 2) * std::tgamma((1 + k) / 2)); // (9.5)
  }

  /// The flat punch's force (9.16): F = 2 h_N E0 d a^{1+k} / ((1 - nu^2)(1 + k) c0^k).
  inline double flat_punch_force(const double k, const double v, const double E0, const double c0, const double a,
                                 const double d)
  {
    return 2 * h_N(k, v) * E0 * d * std::pow(a, 1 + k) / ((1 - v * v) * (1 + k) * std::pow(c0, k));
  }

  /// The paraboloid's force at contact radius a (9.26): F = 4 h_N E0 a^{k+3} / ((1 - nu^2) c0^k (1 + k)^2 (k + 3) R).
  inline double paraboloid_force(const double k, const double v, const double E0, const double c0, const double a,
                                 const double R)
  {
    return 4 * h_N(k, v) * E0 * std::pow(a, k + 3) / ((1 - v * v) * std::pow(c0, k) * (1 + k) * (1 + k) * (k + 3) * R);
  }
} // namespace gradcontact::fem::testing

#endif
