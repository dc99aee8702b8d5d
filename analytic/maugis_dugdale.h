// gradcontact/analytic: the Maugis-Dugdale adhesive contact of a rigid sphere (paraboloid f = r^2/(2R)) with
// a homogeneous elastic half-space (k = 0): the classical reference of the cohesive-zone FE
// (fem/cohesive_zone.h). Not part of the chapter, which assumes JKR.
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
} // namespace gradcontact::maugis_dugdale

#endif
