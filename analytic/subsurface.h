// gradcontact/analytic: the stresses below an axisymmetric normal contact of the power-law graded half-space, by
// superposing the graded Boussinesq field (point_load.h) over the contact's pressure:
//   sigma(r, z) = int_0^a p(rho) rho drho int_0^2pi G(r', z; phi) dphi,   r'^2 = r^2 + rho^2 - 2 r rho cos(phi),
// G the unit point-force field in the frame of the source, turned into the field point's cylindrical frame.
//
// The pressure is given as p(rho) = smooth(rho) (1 - rho^2/a^2)^e: the edge exponent e is (k - 1)/2 for a flat punch
// (9.16), (1 + k)/2 for a smooth indenter (9.20, 9.26, 9.30), 0 for a uniform pressure (9.38). The radial integral
// takes e into a Gauss-Jacobi rule on its last panel; both integrals are composite Gauss-Legendre elsewhere, graded
// geometrically toward rho = r (where the kernel peaks over a width of order z) and toward the edge, and the angle
// toward phi = 0. The cost grows like log(a / z) in each direction. Within about 1e-6 a of the surface the kernel is a
// near-delta of width z, and its sum loses digits (1e-8 relative at z = 1e-10 a).
#ifndef GRADCONTACT_ANALYTIC_SUBSURFACE_H
#define GRADCONTACT_ANALYTIC_SUBSURFACE_H

#include <analytic/normal.h>
#include <analytic/point_load.h>

#include <functional>
#include <string>

namespace gradcontact
{
  /// An axisymmetric pressure (positive: pushing into the half-space) p(rho) = smooth(rho) (1 - rho^2/a^2)^e on
  /// rho < a [Pa].
  struct AxisymmetricPressure
  {
    double                        a = 0;
    double                        edge_exponent = 0; ///< e > -1
    std::function<double(double)> smooth;
  };

  /// The chapter's contact pressures as such loads (the closed forms of normal.h divided by their edge factor).
  AxisymmetricPressure contact_pressure(const Medium &m, const FlatPunch &punch, double d);
  AxisymmetricPressure contact_pressure(const Medium &m, const Paraboloid &paraboloid, double a);
  AxisymmetricPressure contact_pressure(const Medium &m, const PowerLaw &profile, double a);
  AxisymmetricPressure contact_pressure(const UniformPressure &load);
  /// Any pressure p(rho) on rho < a with edge exponent e (p / (1 - rho^2/a^2)^e smooth), e.g. a JKR state (9.53,
  /// 9.58: the flat punch's (k - 1)/2 from the adhesive term).
  AxisymmetricPressure contact_pressure(double a, double edge_exponent, std::function<double(double)> pressure);

  /// Points per panel of the composite rules: the integrands are smooth on every panel, so a panel's error falls
  /// geometrically with its points.
  struct SuperpositionRule
  {
    unsigned int points = 12;
  };

  /// The stress at (r >= 0, z > 0) under `load` on the half-space of `field` [Pa].
  AxisymmetricStress subsurface_stress(const PointLoadField &field, const AxisymmetricPressure &load, double r,
                                       double z, const SuperpositionRule &rule = {});

  /// Scalar measures of a stress: von Mises' equivalent stress, and the largest shear (largest - smallest principal
  /// stress) / 2, the hoop stress being the third principal stress.
  enum class StressMeasure
  {
    von_mises,
    max_shear
  };
  double measure(const AxisymmetricStress &s, StressMeasure m);
  /// The component `name` of a stress: rr, zz, tt (hoop), rz, principal_max, principal_min (of the meridian pair and
  /// the hoop stress), von_mises or max_shear. A DomainError naming the valid ones when it is none of them.
  double stress_component(const AxisymmetricStress &s, const std::string &name);

  /// Where a measure is largest below a contact, and its value.
  struct StressMaximum
  {
    double value = 0, r = 0, z = 0;
  };

  /// The largest `m` below `load` over 0 <= r <= 2a, 0 < z <= 2a: a grid of r (steps of a/20) and z (geometric from
  /// 1e-3 a), then a pattern search that halves its steps down to 1e-5 a. It asks a bounded field: a load with
  /// e >= 0 (no pressure singularity at the edge) on a medium with k >= 0. On k < 0 the surface layer's radial and hoop
  /// stresses grow like (z/r)^k as z -> 0 (the stiff skin carries them), so the supremum is at the surface and
  /// unbounded; a flat punch's or a JKR state's edge (e < 0) is singular for every k. Both are DomainErrors.
  StressMaximum largest_stress(const PointLoadField &field, const AxisymmetricPressure &load, StressMeasure m);
} // namespace gradcontact

#endif
