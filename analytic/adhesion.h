// gradcontact/analytic: JKR adhesion of the power-law graded half-space, chapter 9.2 (eqs. 9.45-9.74).
//
// The adhesive solution is the non-adhesive one superposed with a flat-punch translation -Delta_l(a)
// (9.45-9.49). Pull-off forces are negative (tensile). Control::force: the critical state is the
// minimum of F_N(a); Control::displacement: the minimum of d(a) (9.48 with C~ = 2/(3+k) or 2/(1-k)).
#ifndef GRADCONTACT_ANALYTIC_ADHESION_H
#define GRADCONTACT_ANALYTIC_ADHESION_H

#include <analytic/material.h>
#include <analytic/normal.h>
#include <analytic/states.h>

namespace gradcontact::jkr
{
  using gradcontact::Control;

  /// C~(k) of 9.48: 2/(3+k) under force control, 2/(1-k) under displacement control.
  double C_tilde(double k, Control control);

  /// Delta_l(a) = sqrt(2 pi dgamma c0^k a^(1-k) / cN0) (9.45), the spring elongation at separation.
  double delta_ell(const Medium &m, double dgamma, double a);

  /// A critical (pull-off) state: contact radius, depth, force.
  struct CriticalState
  {
    double radius;
    double depth;
    double force;
  };

  // --- flat punch, 9.50-9.52 -------------------------------------------------------------------
  /// d_c = -Delta_l(a) (9.51) and F_c = -sqrt(8 pi dgamma cN0 a^(3+k) / ((1+k)^2 c0^k)) (9.52);
  /// the same under both controls (the radius is fixed).
  CriticalState critical_state(const Medium &m, const FlatPunch &punch, double dgamma);

  // --- paraboloid, 9.53-9.57 --------------------------------------------------------------------
  double depth(const Medium &m, const Paraboloid &p, double dgamma, double a);
  double force(const Medium &m, const Paraboloid &p, double dgamma, double a);
  double pressure(const Medium &m, const Paraboloid &p, double dgamma, double a, double r);
  double displacement(const Medium &m, const Paraboloid &p, double dgamma, double a, double r);
  /// a_c (9.55), d_c and F_c (9.56).
  CriticalState critical_state(const Medium &m, const Paraboloid &p, double dgamma, Control control);
  /// The normalised curves (9.57): d/d_c and F/F_c against a/a_c.
  double normalised_depth(double k, Control control, double a_over_ac);
  double normalised_force(double k, Control control, double a_over_ac);

  // --- power law, 9.58-9.63 ---------------------------------------------------------------------
  double depth(const Medium &m, const PowerLaw &p, double dgamma, double a);
  double force(const Medium &m, const PowerLaw &p, double dgamma, double a);
  double pressure(const Medium &m, const PowerLaw &p, double dgamma, double a, double r);
  double displacement(const Medium &m, const PowerLaw &p, double dgamma, double a, double r);
  /// a_c (9.60), d_c and F_c (9.61). A critical state exists only for 2n + k - 1 > 0; otherwise
  /// DomainError ("no critical state").
  CriticalState critical_state(const Medium &m, const PowerLaw &p, double dgamma, Control control);
  /// Jin et al.'s normalisation (9.62): F_c / (1.5 pi dgamma R) for f = r^n / (n R^(n-1)), force
  /// control, one graded body (E0, nu) on a rigid indenter.
  double jin_pulloff_ratio(const GradedHalfSpace &body, double n, double R, double dgamma);
  /// The normalised curves (9.63).
  double normalised_depth(double k, double n, Control control, double a_over_ac);
  double normalised_force(double k, double n, Control control, double a_over_ac);

  // --- concave punch, 9.64-9.68 -----------------------------------------------------------------
  using gradcontact::Mechanism;
  /// Critical state of the concave punch; depth is the rim depth d (d0 = d - h0, 9.65).
  CriticalState critical_state(const Medium &m, const ConcavePunch &punch, double dgamma,
                               double sigma_th, Mechanism mechanism);
  /// The pressure in that critical state (9.66 or 9.68).
  double critical_pressure(const Medium &m, const ConcavePunch &punch, double dgamma,
                           double sigma_th, Mechanism mechanism, double r);
  /// Which mechanism governs (Mechanism::periphery or Mechanism::centre).
  Mechanism governing_mechanism(const Medium &m, const ConcavePunch &punch, double dgamma,
                                double sigma_th);
  /// The h0 at which the two critical depths coincide:
  /// h0* = (1+k)^2/4 (pi c0^k a^(1-k) sigma_th / cN0 - Delta_l(a)); DomainError if it is not positive
  /// (the centre then always separates first).
  double transition_h0(const Medium &m, double a, double dgamma, double sigma_th);

  // --- profile of constant tensile stress, 9.69-9.74 ---------------------------------------------
  struct OptimalProfile
  {
    double a;        ///< contact radius
    double sigma_th; ///< theoretical strength > 0
  };
  /// F_opt = -sigma_th pi a^2 (9.70)
  double force(const OptimalProfile &p);
  /// w_c,opt (9.72), negative (the surface is pulled up)
  double centre_displacement(const Medium &m, const OptimalProfile &p);
  /// w_opt(r) (9.71)
  double displacement(const Medium &m, const OptimalProfile &p, double r);
  /// f_opt(r) = w_c,opt [1 - 2F1((k-1)/2, (1+k)/2; 1; r^2/a^2)] for r <= a (9.73)
  double profile(const Medium &m, const OptimalProfile &p, double r);
  /// f~_opt(r) = f_opt(r) - f_opt(a) (9.74)
  double shifted_profile(const Medium &m, const OptimalProfile &p, double r);
} // namespace gradcontact::jkr

#endif
