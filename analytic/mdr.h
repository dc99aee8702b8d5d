// gradcontact/analytic: the numerical MDR engine (chapter 9.1.1 and 9.2.1) for any axisymmetric
// profile. It is the independent check of every closed form and the tool a user calls to check a
// closed form of their own.
//
//   g(x)   = |x|^(1-k) int_0^|x| f'(r) (x^2 - r^2)^(-(1-k)/2) dr                          (9.2)
//   d(a)   = g(a) (non-adhesive, 9.10);   w1D(a) = -Delta_l(a) (adhesive, 9.46)
//   F(a)   = int_-a^a c_N(x) w1D(x) dx, c_N(x) = cN0 (|x|/c0)^k                             (9.11)
//   p(r)   = -cN0/(pi c0^k) int_r^inf w1D'(x) (x^2 - r^2)^(-(1-k)/2) dx  (a jump of w1D at a counts) (9.12)
//   w(r)   = 2 cos(k pi/2)/pi int_0^min(r,a) x^k w1D(x) (r^2 - x^2)^(-(1+k)/2) dx           (9.12)
//   w1D(x) = 2 c0^k cos(k pi/2)/cN0 int_x^a r p(r) (r^2 - x^2)^(-(1+k)/2) dr                (9.13)
//
// Every integral is mapped onto int_0^1 u^alpha (1-u)^beta h(u) du with the end-point powers in
// alpha and beta, and integrated by Gauss-Jacobi rules (detail/quadrature.h): the weight carries the
// mass of x^k near 0 for k -> -1 exactly, however small its scale. The variables are chosen so that h is
// analytic for the profiles whose tip power is known (Profile::tip_exponent): r = x v in 9.2 (h is then
// phi(x v), with f'(r) = r^(n-1) phi(r)), x = r v and x = a v in 9.11-9.12 with w1D = d - x^n G(x) split
// into its two terms, and x = r + (a - r) t in the pressure. Where h has a singularity just outside the
// interval (the pressure at r << a: x = 0 at t = -r/(a - r); the displacement at r just above a) the
// panels are graded toward it. Where a rule does not resolve h (its last coefficients, detail/quadrature.h),
// the integral falls back to tanh-sinh, the end-point powers removed by u = v^(1/(alpha+1)) / 2 (and the
// mirror image at u = 1): a plain tanh-sinh loses digits at k -> +-1 (ERRATA.md, quadrature item).
#ifndef GRADCONTACT_ANALYTIC_MDR_H
#define GRADCONTACT_ANALYTIC_MDR_H

#include <analytic/material.h>
#include <analytic/states.h>

#include <functional>
#include <limits>

namespace gradcontact::mdr
{
  /// An axisymmetric profile f(r), f(0) = 0, with its derivatives. f'' is needed only for the
  /// pressure (through g'(x)); leave it empty otherwise.
  struct Profile
  {
    std::function<double(double)> f;
    std::function<double(double)> df;
    std::function<double(double)> d2f;
    /// n where f'(r) = r^(n-1) phi(r) with phi analytic at r = 0 (A r^n: n), so that the quadratures put
    /// r^(n-1) into their weight; NaN when unknown (f' is then taken as analytic itself, and a tip that is
    /// not ends in the tanh-sinh fallback).
    double tip_exponent = std::numeric_limits<double>::quiet_NaN();
  };

  /// f = A r^n with exact derivatives and tip_exponent n.
  Profile power_law(double n, double A);

  /// The 1D displacement of the Winkler foundation on [0, a] (even in x) and its slope.
  /// Outside |x| > a it is zero; a jump at x = a enters the pressure as the edge term.
  struct Foundation
  {
    std::function<double(double)> w;  ///< w1D(x), 0 <= x <= a
    std::function<double(double)> dw; ///< w1D'(x), needed for the pressure only
    double a;                         ///< contact radius
    /// For w1D = d - g(x) of a profile (indentation_to_depth): the profile's f', so that force()
    /// can use the single integral int_0^a x^k g(x) dx = 1/(1+k) int_0^a f'(r) (a^2-r^2)^((1+k)/2) dr
    /// (9.2 in 9.11, integration order exchanged) instead of a nested quadrature.
    std::function<double(double)> profile_slope;
    double d = 0.; ///< the depth of that indentation
    /// w1D(a) where it is known without forming d - g(a): -Delta_l(a) of an adhesive indentation (9.46),
    /// whose d - g(a) would lose eps g(a)/Delta_l(a). NaN: take w(a).
    double edge_value = std::numeric_limits<double>::quiet_NaN();
    /// Where w1D = (a^2 - x^2)^e phi(x) with phi smooth at the edge (foundations of a pressure, 9.13:
    /// e = (1-k)/2), e and phi: the quadratures then treat the factor exactly. For k -> +-1 the
    /// combined end-point exponents approach -1 and part of the mass lies below the smallest double,
    /// which no quadrature of w1D itself can reach.
    double edge_exponent = 0.;
    std::function<double(double)> edge_free;
    /// Where w1D = d - x^n G(x) with G analytic (indentations of a profile with a known tip exponent n):
    /// n, G and G1(x) = -w1D'(x) / x^(n-1) (the latter needs f''). The quadratures of 9.11 and 9.12 then
    /// integrate d and x^n G(x) separately, each with its power in the weight.
    double tip_exponent = std::numeric_limits<double>::quiet_NaN();
    std::function<double(double)> tip_free, tip_free_slope;
    /// false: the quadratures of 9.11-9.13 on this foundation go straight to tanh-sinh, but for the pressure at
    /// r > 0, whose integrand is analytic on [r, a] whatever the tip (set by
    /// indentation_to_depth for a profile of unknown tip power whose f' no Gauss-Jacobi rule resolves: a
    /// tip power other than an integer, a kink, a finite-difference slope).
    bool gauss_jacobi = true;
  };

  /// g(x) (9.2)
  double equivalent_profile(const Profile &profile, double k, double x);
  /// g'(x), from f' and f''.
  double equivalent_profile_slope(const Profile &profile, double k, double x);

  /// The foundation w1D(x) = d - g(x) on |x| <= a for a given depth d (9.9); d is the centre
  /// displacement d0 for a concave punch in complete contact.
  Foundation indentation_to_depth(const Profile &profile, double k, double a, double d);

  /// A rigid flat translation w1D = d on |x| <= a (flat punch, 9.14).
  Foundation flat(double a, double d);

  /// The foundation w1D(x) = d - g(x) of an indentation to contact radius a. Without adhesion
  /// d = g(a) (9.10); with dgamma > 0, d = g(a) - Delta_l(a) (9.46). dgamma = 0 means no adhesion.
  Foundation indentation(const Profile &profile, const Medium &m, double a, double dgamma = 0.);

  /// The foundation (9.13) of a surface pressure p(r) on r < a (p = 0 outside).
  Foundation from_pressure(const std::function<double(double)> &p, const Medium &m, double a);

  /// d = w1D(0) + g(0) = w1D(0) for indentations (the depth at the centre, 9.9).
  double depth(const Foundation &w1d);
  /// F_N (9.11); single quadrature for indentations of a profile, nested otherwise.
  double force(const Foundation &w1d, const Medium &m);
  /// F_N (9.11) by the nested quadrature of w1D, whatever the foundation (for checks of force()).
  double force_nested(const Foundation &w1d, const Medium &m);
  /// p(r) (9.12), zero for r > a.
  double pressure(const Foundation &w1d, const Medium &m, double r);
  /// w(r) (9.12), inside and outside the contact.
  double displacement(const Foundation &w1d, const Medium &m, double r);

  using gradcontact::Control;

  struct CriticalState
  {
    double radius;
    double depth;
    double force;
  };

  /// The critical (pull-off) state of an adhesive indentation, found by minimising F_N(a) (force
  /// control) or d(a) (displacement control) over a in [a_lo, a_hi] (a log-spaced scan, then the root of
  /// the slope from g'(a) where the profile has f''; otherwise Brent's method and the root of a
  /// central-difference derivative), not from 9.48. DomainError when the
  /// minimum lies on the end of the bracket (no critical state inside it). With bracket_shifts > 0 a
  /// minimum on an end first moves the bracket by nine decades toward that end (keeping one decade of
  /// overlap), at most bracket_shifts times.
  CriticalState critical_state(const Profile &profile, const Medium &m, double dgamma, Control control,
                               double a_lo, double a_hi, unsigned int bracket_shifts = 0);
  /// The same in the default bracket: nine decades either side of c0, moved toward a minimum found on
  /// its end up to four times (the critical radius of a tip with n + k -> 0 falls far below c0:
  /// 5.5e-16 m for n = 1, k = -0.9, c0 = 1.2e-4 m).
  CriticalState critical_state(const Profile &profile, const Medium &m, double dgamma, Control control);
} // namespace gradcontact::mdr

#endif
