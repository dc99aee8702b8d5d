// gradcontact/analytic: the stress and displacement field of a normal point force on the surface of the power-law
// graded half-space E(z) = E0 (z / c0)^k (9.1), -1 < k < 1, constant nu: the graded Boussinesq problem.
//
// Self-similarity. The force P pushes into the half-space (z > 0 is depth) at the origin. No length enters the
// problem but R (E0 c0^-k only scales the displacements), so in spherical coordinates (R, theta from the z-axis,
// x = cos theta = z / R) the field separates:
//   u = P c0^k / E0 * R^-(1+k) (U(x) e_R + V e_theta),   V = sin(theta) W(x),
//   sigma = P / R^2 * x^k * (lambda' tr eps + 2 mu' eps)(U, V),   lambda' = nu / ((1+nu)(1-2nu)), mu' = 1/(2(1+nu)),
// with R^(2+k) eps_RR = -(1+k) U, eps_tt = V_theta + U, eps_pp = U + V cot(theta), 2 eps_Rt = U_theta - (2+k) V.
// Equilibrium (div sigma = 0) is then a fourth-order linear ODE system in x whose coefficients are polynomials in
// x (derived here, not taken from a paper). With delta = x d/dx and Wt = x W it reads
//   [P0(delta) + x^2 P2(delta)] (U, Wt) = 0,
// P0, P2 2x2 matrices of polynomials of degree two in delta (point_load.cc lists them). Its singular points are
// the surface x = 0, the axis x = 1 and x = -1, infinity.
//
// The solution. At the surface the Frobenius exponents are 0, 1 - k, 1 and 2 - k; the first and third give zero
// traction (sigma_tt, sigma_Rt -> 0 as x -> 0, r > 0), the others carry a surface traction (u ~ z^(1-k)): two
// series in x^2 from the surface. At the axis two solutions are regular (U and Wt analytic in 1 - x): two series
// in 1 - x. The field regular at the axis and free of traction on the surface is the one combination of the four
// that matches at an inner angle (a one-dimensional null space: the point force is an eigensolution of the
// self-similar problem), scaled so that the stresses on a hemisphere carry P. Both series converge geometrically
// on their side of the matching angle, so the field is exact to rounding; every evaluation costs a few dozen terms.
//
// Known limits that check it (tests/analytic/test_point_load.cc): Boussinesq's field at k = 0; at Holl's ratio
// nu = 1/(2 + k) the field is purely radial, sigma_RR = -(3 + k) P cos^(1+k)(theta) / (2 pi R^2) (Froehlich's
// distribution with concentration factor 3 + k; Holl 1940); the force through a plane z = const is P; the surface
// displacement is the MDR's uniform pressure over a vanishing circle (9.39).
//
// Surface behaviour: the stresses carry x^k, so on the surface (r > 0) they vanish for k > 0 (E -> 0) and grow
// without bound for k < 0 (E -> infinity) except where their factor vanishes; stress() therefore asks z > 0.
// nu = 1/2 is excluded: the displacement form of the ODE loses its order there (an incompressible medium needs a
// pressure unknown); approaching it, lambda' tr(eps) is the product of a large and a small factor, and the field
// loses digits like (1 - 2 nu)^-2.
#ifndef GRADCONTACT_ANALYTIC_POINT_LOAD_H
#define GRADCONTACT_ANALYTIC_POINT_LOAD_H

#include <analytic/material.h>

#include <array>
#include <vector>

namespace gradcontact
{
  /// Stresses of an axisymmetric field in cylindrical components (r radial, z depth, t hoop) [Pa].
  /// Tension positive.
  struct AxisymmetricStress
  {
    double rr = 0, zz = 0, tt = 0, rz = 0;
  };

  /// Stresses in spherical components about the load point, times R^2 / P (dimensionless functions of the angle).
  struct SphericalStress
  {
    double RR = 0, thth = 0, phph = 0, Rth = 0;
  };

  /// The graded Boussinesq field of a unit normal force (see the file's header). Immutable once built; building
  /// sums the series and matches them (microseconds), every evaluation a few dozen terms.
  class PointLoadField
  {
  public:
    /// -1 < k < 1, 0 <= nu < 1/2. Throws DomainError naming the argument, its value and the range.
    PointLoadField(double k, double nu);

    double k() const { return k_; }
    double nu() const { return nu_; }

    /// R^2 / P times the spherical stresses at angle theta from the axis, 0 <= theta < pi/2.
    SphericalStress angular(double theta) const;

    /// The stresses at radius r >= 0 and depth z > 0 under a force P [N] pushing into the half-space [Pa].
    AxisymmetricStress stress(double P, double r, double z) const;

    /// The displacement (u_r, u_z) at r >= 0, z >= 0, (r, z) != 0, of `body` under a force P [m]; u_z > 0 into
    /// the half-space.
    std::array<double, 2> displacement(const GradedHalfSpace &body, double P, double r, double z) const;

    /// The angular functions U(x) and W(x) of the displacement at x = cos(theta) in [0, 1], scaled to P c0^k / E0 = 1,
    /// with their x-derivatives: {U, dU/dx, W, dW/dx}.
    std::array<double, 4> modes(double x) const;

  private:
    /// R^2 / P times the spherical stresses at x = cos(theta).
    SphericalStress spherical(double x) const;

    double k_, nu_;
    /// Series coefficients of (U, Wt), already combined and scaled: from the surface in powers of x (even and odd
    /// parts interleaved: entry m is the coefficient of x^m), from the axis in powers of t = 1 - x.
    std::vector<std::array<double, 2>> surface_, axis_;
    /// The stresses' series from the surface (point_load.cc, surface_brackets).
    std::vector<std::array<double, 4>> surface_stress_;
  };
} // namespace gradcontact

#endif
