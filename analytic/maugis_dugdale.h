// gradcontact/analytic: the Maugis-Dugdale adhesive contact of a rigid sphere (paraboloid f = r^2/(2R)) with
// a homogeneous elastic half-space (k = 0), and of a power-law tip with the graded half-space (below, by the
// MDR): the references of the cohesive-zone FE (fem/adhesion/cohesive_zone.h). Not part of the chapter, which assumes JKR.
//
// Maugis, J. Colloid Interface Sci. 150 (1992) 243-269, in the notation of Johnson and Greenwood,
// J. Colloid Interface Sci. 192 (1997) 326-333. The Dugdale law: a tension sigma_0 acts where the gap is
// below h_0 = dgamma / sigma_0, on a < r < c (a the contact radius, c the end of the cohesive zone). With
// K = 4 E* / 3, the Tabor-Maugis parameter lambda = 2 sigma_0 / (pi dgamma K^2 / R)^{1/3} and
//   A = a (K / (pi dgamma R^2))^{1/3},  P = F / (pi dgamma R),  Delta = d (K^2 / (pi^2 dgamma^2 R))^{1/3},
// m = c / a, the zone closes with the gap h_0 at c when
//   (lambda A^2 / 2) [(m^2 - 2) arcsec m + sqrt(m^2 - 1)]
//     + (4 lambda^2 A / 3) [sqrt(m^2 - 1) arcsec m - m + 1] = 1,
// and then P = A^3 - lambda A^2 [sqrt(m^2 - 1) + m^2 arcsec m],  Delta = A^2 - (4/3) lambda A sqrt(m^2 - 1).
// Written in t = sqrt(m^2 - 1) (arcsec m = atan t) so that m -> 1 (lambda -> inf, JKR: P = A^3 - sqrt(6 A^3))
// loses no digits. lambda -> 0 is DMT: P -> -2 at pull-off.
//
// Force control: pull-off at the minimum of P(A) over the contact branch A > 0, or its limit A -> 0 (the
// contact vanishes with c finite: A m -> C with lambda C^2 pi / 4 + 4 lambda^2 C (pi/2 - 1) / 3 = 1,
// P -> -lambda pi C^2 / 2). Displacement control: the minimum of Delta(A) when the contact branch has one
// inside A > 0 (else the contact shrinks to nothing without a jump: `exists` is false).
#ifndef GRADCONTACT_ANALYTIC_MAUGIS_DUGDALE_H
#define GRADCONTACT_ANALYTIC_MAUGIS_DUGDALE_H

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/states.h>

namespace gradcontact::maugis_dugdale
{
  /// lambda = sigma_0 (9 R / (2 pi dgamma E*^2))^{1/3} (the same as 2 sigma_0 / (pi dgamma K^2 / R)^{1/3}).
  double tabor_parameter(double sigma0, double dgamma, double R, double E_star);

  /// A state of the contact branch in the dimensionless variables of the header.
  struct State
  {
    double A     = 0; ///< contact radius
    double m     = 1; ///< c / a (infinite at A = 0)
    double zone  = 0; ///< c in the units of A: A m
    double P     = 0; ///< force (tensile negative)
    double Delta = 0; ///< depth (approach)
  };

  /// The state of contact radius A > 0 for lambda > 0.
  State state(double lambda, double A);

  /// The A -> 0 end of the contact branch (no contact, zone C).
  State vanishing_contact(double lambda);

  struct PullOff
  {
    State state;
    bool  exists = true; ///< displacement control: the contact branch has an interior minimum of Delta
    bool  at_vanishing_contact = false; ///< force control: the minimum is the A -> 0 end
  };

  /// The pull-off of `control` for lambda in [1e-3, 1e3].
  PullOff pull_off(double lambda, Control control);

  /// Dimensional helpers: the scales of the header (K = 4 E*/3).
  struct Scales
  {
    double length = 0; ///< a = A * length: (pi dgamma R^2 / K)^{1/3}
    double force  = 0; ///< F = P * force: pi dgamma R
    double depth  = 0; ///< d = Delta * depth: (pi^2 dgamma^2 R / K^2)^{1/3}
  };
  Scales scales(double dgamma, double R, double E_star);

  // --- the graded half-space, by the MDR ------------------------------------------------------------------------
  //
  // The same Dugdale law on E0 (z/c0)^k, for a power-law indenter f = A r^n (a paraboloid is n = 2, A = 1/(2R)),
  // solved with the MDR relations of the chapter (9.11-9.13; notation of mdr.h: c_N(x) = cN0 (|x|/c0)^k,
  // Q = cN0 / c0^k, g(x) = kappa(n, k) A |x|^n, 9.2 and 9.28). The same problem was solved in closed form by
  // Willert, Facta Universitatis Ser. Mech. Eng. 16 (2018) 9-18; this is our own derivation, written out here.
  //
  // The foundation w1D(x) on 0 <= x <= c. The tension sigma_0 on a < r < c and nothing beyond c determine w1D on
  // x > a by 9.13 alone (it integrates the pressure outward from x):
  //   w1D(x) = -sigma_0 K (c^2 - x^2)^{(1-k)/2},  a < x < c,  K = 2 cos(k pi/2) / ((1 - k) Q),
  // and 9.12 gives back p = -sigma_0 there (the integral is B((1-k)/2, (1+k)/2) / 2). On the contact w1D = d - g(x).
  // A finite stress at the contact edge (Maugis' condition) makes w1D continuous at a:
  //   d = g(a) - sigma_0 K (c^2 - a^2)^{(1-k)/2}.
  // The force, 9.11, with v = 1 - a^2 / c^2 and B_v the incomplete beta function:
  //   F = 2 Q [d a^{1+k} / (1+k) - kappa A a^{1+k+n} / (1+k+n)] - 2 cos(k pi/2) sigma_0 c^2 B_v((3-k)/2, (1+k)/2) / (1-k).
  // The zone ends where the gap h(c) = f(c) - d + w(c) reaches h_0 = dgamma / sigma_0. With w(c) from 9.12 and
  // the identity kappa B((1+k+n)/2, (1-k)/2) cos(k pi/2) = pi (so that h(a) = 0 on a contact edge), every term is
  // an integral over [a, c] and no digits are lost as c -> a (large lambda):
  //   h(c) = cos(k pi/2) / pi [kappa A c^n B_v((1-k)/2, (1+k+n)/2) - d B_v((1-k)/2, (1+k)/2)
  //                            - sigma_0 K c^{1-k} B_v(1-k, (1+k)/2)].
  // As a -> 0 (the contact vanishes, the zone remains): d = -sigma_0 K c^{1-k}, F = -pi c^2 sigma_0, and
  //   A c^n + sigma_0 K c^{1-k} [1 - cos(k pi/2) B(1-k, (1+k)/2) / pi] = h_0.
  // At k = 0 and n = 2 these are Maugis' equations above, and as sigma_0 -> inf with dgamma fixed the zone's jump
  // sigma_0 K (c^2 - a^2)^{1/2 - k/2} tends to JKR's Delta_l(a) (9.46).

  /// The Dugdale law: the tension sigma0 up to the separation h_0 = dgamma / sigma0.
  struct Dugdale
  {
    double sigma0 = 0; ///< [Pa]
    double dgamma = 0; ///< work of adhesion [J/m^2]
  };

  /// A dimensional state: contact radius a, zone end c, depth d, force F (tensile negative).
  struct GradedState
  {
    double radius = 0, zone_radius = 0, depth = 0, force = 0;
  };

  /// The state of contact radius a > 0 (the zone's end c from h(c) = h_0 by TOMS 748 in c / a - 1).
  GradedState state(const Medium &m, const PowerLaw &profile, const Dugdale &law, double a);
  GradedState state(const Medium &m, const Paraboloid &profile, const Dugdale &law, double a);

  /// The a -> 0 end of the contact branch (radius 0, the zone c remaining).
  GradedState vanishing_contact(const Medium &m, const PowerLaw &profile, const Dugdale &law);
  GradedState vanishing_contact(const Medium &m, const Paraboloid &profile, const Dugdale &law);

  struct GradedPullOff
  {
    GradedState state;
    bool        exists               = true;  ///< displacement control: d(a)'s smallest value lies at a > 0 (not at the vanishing contact)
    bool        at_vanishing_contact = false; ///< force control: the minimum of F is the a -> 0 end
  };

  /// The Tabor parameter of the graded medium. Maugis' lambda (k = 0, paraboloid) is the ratio of the elastic
  /// separation at the JKR contact edge to the range h_0. Written with the chapter's flat-punch pull-back at the
  /// force-controlled JKR pull-off, Delta_l(a_c) (9.45; a_c of 9.55 or 9.60), which at k = 0 is sqrt(2 pi dgamma a_c /
  /// E*) with a_c = (9 pi dgamma R^2 / (8 E*))^{1/3}, it is
  ///   lambda = C Delta_l(a_c) / h_0,   C^3 = (9 / (2 pi)) / ((2 pi)^{3/2} (9 pi / 8)^{1/2})   (C = 0.3644),
  /// and this defines lambda for every k and profile: the same physical ratio, Maugis' value at k = 0.
  double tabor_parameter(const Medium &m, const PowerLaw &profile, const Dugdale &law);
  double tabor_parameter(const Medium &m, const Paraboloid &profile, const Dugdale &law);
  /// sigma_0 = dgamma / h_0 of the Tabor parameter lambda > 0 (the inverse of tabor_parameter).
  double strength(const Medium &m, const PowerLaw &profile, double dgamma, double lambda);
  double strength(const Medium &m, const Paraboloid &profile, double dgamma, double lambda);

  /// The pull-off of `control`: the minimum of F(a) or d(a) over a in 1e-6..1e2 times the chapter's
  /// force-controlled JKR radius (9.60; it needs 2n + k - 1 > 0), by a scan in ln a and Brent's method.
  GradedPullOff pull_off(const Medium &m, const PowerLaw &profile, const Dugdale &law, Control control);
  GradedPullOff pull_off(const Medium &m, const Paraboloid &profile, const Dugdale &law, Control control);
} // namespace gradcontact::maugis_dugdale

#endif
