// gradcontact/analytic: contact problems solved with the numerical MDR engine (mdr.h) for any
// axisymmetric profile: the contact radius from a depth or a force (with or without adhesion), the
// adhesive critical states of a concave punch, and Ciavarella-Jaeger partial slip and oscillation.
// Each is the numerical twin of a closed form (normal.h, adhesion.h, tangential.h) and never calls it.
//
//   contact radius:  d(a) = d or F_N(a) = F; with adhesion the root on the stable branch a >= a_c
//   concave punch:   periphery w1D(a) = -Delta_l(a) (9.46); centre p(0) = -sigma_th, p(0) linear in d0
//   partial slip:    tau = mu [p(r; a) - p(r; c)], F_x = mu [F_N(a) - F_N(c)],
//                    u0 = mu alpha [d(a) - d(c)]                                               (9.77)
//   oscillation:     a change |dF| of the force reverses the slip in b < r < a with
//                    |dF| = 2 mu [F_N(a) - F_N(b)]                                             (9.81)
#ifndef GRADCONTACT_ANALYTIC_MDR_CONTACT_H
#define GRADCONTACT_ANALYTIC_MDR_CONTACT_H

#include <analytic/material.h>
#include <analytic/mdr.h>
#include <analytic/states.h>

#include <functional>

namespace gradcontact::mdr
{
  /// The contact radius of a non-adhesive indentation of `profile` to the depth `target`
  /// (Control::displacement) or under the force `target` (Control::force); both rise from 0 with a.
  double contact_radius(const Profile &profile, const Medium &m, Control given, double target);

  /// The same with adhesion dgamma > 0: the root on the stable branch a >= a_c, where `critical` is the
  /// critical state of the same control (critical_state()). DomainError below the critical value.
  double contact_radius(const Profile &profile, const Medium &m, Control given, double target, double dgamma,
                        const CriticalState &critical);

  /// f(r) = -h0 r^2 / a^2, the concave punch of depth h0 at its rim r = a (9.31).
  Profile concave_paraboloid(double a, double h0);

  /// A critical state of the concave punch in complete adhesive contact.
  struct ConcaveState
  {
    double d0;    ///< centre displacement
    double depth; ///< rim depth d = d0 + h0 (9.65)
    double force;
  };

  /// The critical state of a concave punch (radius a, depth h0) under the given mechanism: the periphery
  /// from w1D(a) = -Delta_l(a) (9.46), the centre from p(0) = -sigma_th; `governing` takes the larger rim depth.
  ConcaveState concave_critical_state(const Medium &m, double a, double h0, double dgamma, double sigma_th,
                                      Mechanism mechanism);

  /// The h0 at which both mechanisms give the same rim depth (their difference is linear in h0).
  /// DomainError when it is not positive (the centre then separates first for every h0 >= 0).
  double concave_transition_h0(const Medium &m, double a, double dgamma, double sigma_th);

  /// Ciavarella-Jaeger partial slip and oscillation (9.77, 9.81) of an indentation of `profile` to the
  /// contact radius a, every normal quantity from the MDR integrals. The normal load stays fixed.
  ///
  /// Every tangential quantity is a difference of the normal solution at a and at a slip radius b <= a.
  /// Near b = a (small forces, small amplitudes, stick radii close to a) the two are close, so the
  /// differences are integrals over [b, a] of the derivatives in a (9.11: dF_N/da = 2 cN0 a^(k+1) g'(a) /
  /// (c0^k (k+1)); 9.10: dd/da = g'(a); 9.12: p(r; a) - p(r; b) = cN0/(pi c0^k) int_b^a g'(x)
  /// (x^2 - r^2)^((k-1)/2) dx), and b is carried as its gap h = a - b, found to eps relative to h.
  /// The profile needs f'' for them (otherwise the plain differences are taken).
  class PartialSlip
  {
  public:
    /// mu > 0 and a > 0, else DomainError.
    PartialSlip(Profile profile, const Medium &m, double mu, double a);

    /// F_N, d and p(r) of the indentation to radius b (0 for b = 0).
    double normal_force(double b) const;
    double depth(double b) const;
    double pressure(double b, double r) const;
    /// dF_N/db at b in [0, a]: 9.11 differentiated, 2 cN0 b^(k+1) g'(b) / (c0^k (k+1)).
    double normal_force_slope(double b) const;
    /// The radius b in [0, a] with mu [F_N(a) - F_N(b)] = dF; DomainError for gross slip.
    double radius_for(double dF) const;
    /// Its gap a - b, accurate relative to itself.
    double gap_for(double dF) const;

    /// Monotonic loading with the stick radius c in [0, a] (9.77).
    double traction(double c, double r) const;
    double tangential_force(double c) const;
    double tangential_displacement(double c) const;
    /// The stick radius under the force Fx >= 0.
    double stick_radius(double Fx) const;
    /// The same three under the force Fx >= 0 instead of at c (the gap of c from gap_for, c never formed).
    double traction_at_force(double Fx, double r) const;
    double tangential_force_at_force(double Fx) const;
    double tangential_displacement_at_force(double Fx) const;

    /// The oscillation between +-FA, 0 < FA < mu F_N(a), after the loading to A.
    double traction(double FA, Branch branch, double Fx, double r) const;
    double tangential_displacement(double FA, Branch branch, double Fx) const;
    /// F_x(u0) on a branch (the hysteresis loop).
    double hysteresis_force(double FA, Branch branch, double u0) const;
    /// The loop area int (F_reloading - F_unloading) du0, computed as an integral with a positive
    /// integrand that is O(phi^3) itself (not as the cancelling integral of the branches, which loses
    /// eps/phi^2), phi = FA/(mu F_N):
    ///   8 mu^2 alpha cN0/c0^k int_c^a b^k [d(a) - d(b)] [d(b) - d(c)] db.
    double dissipated_energy(double FA) const;

  private:
    void check_amplitude(double FA) const;
    /// F_N(a) - F_N(a - h), d(a) - d(a - h) and p(r; a) - p(r; a - h) for 0 <= h <= a.
    double force_drop(double h) const;
    double depth_drop(double h) const;
    double pressure_drop(double h, double r) const;
    /// g'(a - h) and the slope of force_drop.
    double slope_at_gap(double h) const;
    double force_drop_slope(double h) const;
    /// The gap h with depth_drop(h) = dd.
    double gap_for_depth(double dd) const;
    /// The unloading branch of a small loop (FA/(mu F_N) <= 1/4) near its middle, where its value is
    /// a second difference of the loading curve: u0 at Fx, F_x at u0, tau(r) at Fx for r inside the stick
    /// zone of A. As integrals over the force of the loading curve's densities, which depend on the slip
    /// radius b(F) alone (du/dF = alpha c0^k (k+1) / (2 cN0 b^(k+1)), 9.11 and 9.10), with b(F) from a
    /// Legendre series of the gap a - b(F) on [0, FA] (see mdr_contact.cc).
    /// The gap a - b(F) of the loading curve's slip radius as a function of the tangential force F in [0, FA].
    std::function<double(double)> loading_gaps(double FA) const;
    /// The integrands of the loop (FA) in the force F: the density du/dF of the loading curve and the
    /// second difference of the loading curve at x; shared by loop_displacement and loop_force.
    struct LoopIntegrands
    {
      std::function<double(double)> density, second;
    };
    LoopIntegrands loop_integrands(double FA) const;
    double loop_displacement(double FA, double Fx) const;
    double loop_force(double FA, double u0) const;
    double loop_traction(double FA, double Fx, double r) const;

    Profile profile_;
    Medium m_;
    double mu_, a_;
    double force_a_, depth_a_; ///< F_N(a), d(a)
  };
} // namespace gradcontact::mdr

#endif
