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
  class PartialSlip
  {
  public:
    /// mu > 0 and a > 0, else DomainError.
    PartialSlip(Profile profile, const Medium &m, double mu, double a);

    /// F_N, d and p(r) of the indentation to radius b (0 for b = 0).
    double normal_force(double b) const;
    double depth(double b) const;
    double pressure(double b, double r) const;
    /// The radius b in [0, a] with mu [F_N(a) - F_N(b)] = dF; DomainError for gross slip.
    double radius_for(double dF) const;

    /// Monotonic loading with the stick radius c in [0, a] (9.77).
    double traction(double c, double r) const;
    double tangential_force(double c) const;
    double tangential_displacement(double c) const;
    /// The stick radius under the force Fx >= 0.
    double stick_radius(double Fx) const;

    /// The oscillation between +-FA, 0 < FA < mu F_N(a), after the loading to A.
    double traction(double FA, Branch branch, double Fx, double r) const;
    double tangential_displacement(double FA, Branch branch, double Fx) const;
    /// F_x(u0) on a branch (the hysteresis loop).
    double hysteresis_force(double FA, Branch branch, double u0) const;
    /// The loop area, -2 int F_unloading du over the unloading branch.
    double dissipated_energy(double FA) const;

  private:
    void check_amplitude(double FA) const;

    Profile profile_;
    Medium m_;
    double mu_, a_;
  };
} // namespace gradcontact::mdr

#endif
