// gradcontact/analytic: special functions the chapter needs beyond Boost 1.74.
//
// - incomplete_beta(z, x, y) = B(z; x, y) = int_0^z t^(x-1) (1-t)^(y-1) dt (9.17), continued to
//   non-positive, non-integer x through B(z; x, y) = z^x / x 2F1(x, 1-y; 1+x; z) (9.21).
// - beta_upper(z, x, y) = int_z^1 t^(x-1) (1-t)^(y-1) dt for every real x. For x > 0 it equals
//   B(x, y) - B(z; x, y); for x <= 0 it is the finite combination B(x, y) - B(z; x, y) of the
//   continued functions that 9.20, 9.30 and 9.59 need, and it stays finite where Gamma(x) has a
//   pole (x = 0, -1, ...: k = 0 with n = 1 or 3 in 9.30), see ERRATA.md.
// - hyp2f1(a, b, c, z), the Gauss hypergeometric function for 0 <= z <= 1 and c - a - b > 0,
//   accurate up to z = 1 (connection formula to 1 - z; where that formula is degenerate, i.e.
//   c - a - b near an integer, Taylor steps of the hypergeometric equation towards z = 1).
#ifndef GRADCONTACT_ANALYTIC_SPECIAL_FUNCTIONS_H
#define GRADCONTACT_ANALYTIC_SPECIAL_FUNCTIONS_H

namespace gradcontact
{
  /// B(z; x, y) for 0 <= z <= 1, y > 0, and x > 0 or x < 0 not an integer (9.17, 9.21).
  /// one_minus_z, when given (>= 0), is 1 - z formed by the caller without cancellation (e.g.
  /// (r-a)(r+a)/r^2 for z = a^2/r^2): above z = 1/2 only it is used.
  double incomplete_beta(double z, double x, double y, double one_minus_z = -1.);

  /// int_z^1 t^(x-1) (1-t)^(y-1) dt for 0 < z <= 1 (z = 0 allowed when x > 0), y > 0, any real x.
  /// one_minus_z, when given (>= 0), is 1 - z formed by the caller without cancellation (e.g.
  /// (a-r)(a+r)/a^2 for z = r^2/a^2): near z = 1 the integral is ~ (1-z)^y / y, and 1 - z formed from a
  /// rounded z would carry its rounding error eps/(1-z) into the result.
  double beta_upper(double z, double x, double y, double one_minus_z = -1.);

  /// 2F1(a, b; c; z) for 0 <= z <= 1, c not 0, -1, -2, ...; at z = 1 also c - a - b > 0.
  /// one_minus_z, when given (>= 0), is 1 - z formed by the caller without cancellation (e.g.
  /// (a-r)(a+r)/a^2 for z = r^2/a^2): near z = 1, where 2F1 varies like (1-z)^(c-a-b), it is used
  /// instead of 1 - z.
  double hyp2f1(double a, double b, double c, double z, double one_minus_z = -1.);

  /// 2F1(a, b; c; z) - 1 without the cancellation of the difference: the Taylor series without its first
  /// term for z <= 1/2; above, the difference where it loses at most one bit, else the Taylor steps of
  /// the hypergeometric equation for F - 1 (or expm1 of Gauss's sum at z = 1). Same arguments as hyp2f1.
  double hyp2f1_minus_one(double a, double b, double c, double z, double one_minus_z = -1.);

  /// 1 / Gamma(x), zero at the poles x = 0, -1, -2, ...
  double rgamma(double x);
} // namespace gradcontact

#endif
