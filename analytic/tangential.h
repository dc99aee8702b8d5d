// gradcontact/analytic: tangential contact with partial slip, chapter 9.3 (eqs. 9.75-9.87).
//
// Valid for the decoupled pairings of 9.3.1 (equal materials; a rigid body on a graded body with the
// Holl ratio nu = 1/(2+k); both with the Holl ratio). The generalised Ciavarella-Jaeger theorem
// (9.77): tau(r) = mu [p(r; a) - p(r; c)], F_x = mu [F_N(a) - F_N(c)], u0 = mu alpha [d(a) - d(c)],
// alpha = cN0 / cT0 (9.78). Spheres: Paraboloid{R} with the effective radius R.
#ifndef GRADCONTACT_ANALYTIC_TANGENTIAL_H
#define GRADCONTACT_ANALYTIC_TANGENTIAL_H

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/states.h>

namespace gradcontact::tangential
{
  /// Checks the Holl ratio condition of pairings 2 and 3 (9.3.1): nu = 1/(2+k) needs k > 0
  /// (nu <= 1/2). Throws DomainError for k <= 0.
  double holl_ratio(double k);

  /// Partial slip of spheres under a monotonically rising tangential force (9.80).
  struct SphereSlip
  {
    double R;  ///< effective radius of curvature
    double mu; ///< friction coefficient > 0
  };

  /// tau(r; a, c) (9.80); c in [0, a] the stick radius.
  double traction(const Medium &m, const SphereSlip &s, double a, double c, double r);
  /// F_x(c, a) = mu F_N(a) [1 - (c/a)^(k+3)] (9.80)
  double tangential_force(const Medium &m, const SphereSlip &s, double a, double c);
  /// u0(c, a) = mu alpha d(a) [1 - (c/a)^2] (9.80)
  double tangential_displacement(const Medium &m, const SphereSlip &s, double a, double c);
  /// c from F_x, 0 <= F_x < mu F_N (gross slip otherwise: DomainError).
  double stick_radius(const Medium &m, const SphereSlip &s, double a, double Fx);
  /// tau(r), u0 and F_x (9.80) under the tangential force Fx instead of at the stick radius c: every
  /// difference 1 - (c/a)^e is formed from the force fraction s = Fx/(mu F_N) as -expm1(e/(k+3)
  /// log1p(-s)), not from a rounded c (which loses eps/s at small Fx). Same checks as stick_radius.
  double traction_at_force(const Medium &m, const SphereSlip &s, double a, double Fx, double r);
  double tangential_displacement_at_force(const Medium &m, const SphereSlip &s, double a, double Fx);
  double tangential_force_at_force(const Medium &m, const SphereSlip &s, double a, double Fx);

  /// Oscillation between +-F_A after the initial loading to A (9.81-9.86).
  using gradcontact::Branch;

  /// The tangential traction at force Fx on a branch (9.82, with the factor mu, ERRATA.md).
  double traction(const Medium &m, const SphereSlip &s, double a, double FA, Branch branch, double Fx,
                  double r);
  /// u0 at force Fx on a branch (9.83).
  double tangential_displacement(const Medium &m, const SphereSlip &s, double a, double FA,
                                 Branch branch, double Fx);
  /// F_x(u0) on a branch: the hysteresis loop (9.84); u_A from 9.85.
  double hysteresis_force(const Medium &m, const SphereSlip &s, double a, double FA, Branch branch,
                          double u0);
  /// The radius b of the annulus b < r <= a whose slip has reversed at the force Fx on the unloading or
  /// reloading branch: |F_A -+ Fx| = 2 mu F_N(a) [1 - (b/a)^(k+3)] (9.81). Inside b the state of A holds.
  double reversal_radius(const Medium &m, const SphereSlip &s, double a, double FA, Branch branch, double Fx);
  /// u_A (9.85)
  double displacement_at_A(const Medium &m, const SphereSlip &s, double a, double FA);
  /// Energy dissipated per cycle, the loop area of 9.84:
  /// 2 (k+3)^2 (k+1) mu^2 F_N^2 c0^k / ((k+5) cT0 a^(k+1)) [1 - (1-phi)^((k+5)/(k+3))
  ///   - (k+5)/(2(k+3)) phi (1 + (1-phi)^(2/(k+3)))], phi = F_A/(mu F_N).
  /// With cT0 of the pairing this is 9.86 for two equal bodies (cT0 = h_T E0 / 2) and half of 9.86
  /// for a rigid sphere on one graded body (ERRATA.md); at k = 0 it is Mindlin-Deresiewicz (9.87).
  double dissipated_energy(const Medium &m, const SphereSlip &s, double a, double FA);
} // namespace gradcontact::tangential

#endif
