// gradcontact/analytic: frictionless normal contact of a rigid axisymmetric indenter (or two graded
// bodies, through Medium) with the power-law graded half-space, chapter 9.1 (eqs. 9.14-9.44).
//
// Conventions (analytic/README.md): d, d0 and w positive into the material, p and F positive in
// compression. Every function takes the equivalent Medium (material.h), so the same formula serves a
// rigid indenter (cN0 = h_N E0/(1-nu^2), written h_N E* in the chapter) and two graded bodies (9.4).
// Radii, depths and forces are in consistent units.
#ifndef GRADCONTACT_ANALYTIC_NORMAL_H
#define GRADCONTACT_ANALYTIC_NORMAL_H

#include <analytic/material.h>

namespace gradcontact
{
  // Profiles, measured from the indenter tip (f(0) = 0).

  /// Cylindrical flat punch of radius a (9.14).
  struct FlatPunch
  {
    double a;
  };

  /// Cone f(r) = r tan(theta) (9.18).
  struct Cone
  {
    double tan_theta;
  };

  /// Paraboloid f(r) = r^2/(2R) (9.24); for two spheres R = R1 R2/(R1 + R2).
  struct Paraboloid
  {
    double R;
  };

  /// Power law f(r) = A r^n, n > 0 (9.27).
  struct PowerLaw
  {
    double n;
    double A;
  };

  /// Cylindrical punch of radius a with the concave face f(r) = -h0 r^2/a^2 (9.31), in complete
  /// contact; loaded by the centre displacement d0 (9.32).
  struct ConcavePunch
  {
    double a;
    double h0;
  };

  /// Constant pressure p0 on r < a (9.37).
  struct UniformPressure
  {
    double a;
    double p0;
  };

  /// Stretch factor kappa(n, k) = n/2 B(n/2, (1+k)/2) of the equivalent profile g = kappa f (9.28-9.29).
  double kappa(double n, double k);

  // --- flat punch, 9.16 ---------------------------------------------------------------------
  /// F_N(d) = 2 cN0 d a^(1+k) / ((1+k) c0^k)
  double force(const Medium &m, const FlatPunch &punch, double d);
  /// p(r; d) = cN0 d / (pi c0^k (a^2 - r^2)^((1-k)/2)) for r < a, 0 for r > a; unbounded at r = a.
  double pressure(const Medium &m, const FlatPunch &punch, double d, double r);
  /// w = d for r <= a, cos(k pi/2) d / pi B(a^2/r^2; (1+k)/2, (1-k)/2) for r > a.
  double displacement(const Medium &m, const FlatPunch &punch, double d, double r);

  // --- curved convex indenters as functions of the contact radius a, 9.19-9.30 -----------------
  // Cone (9.19-9.20, with the corrected second beta parameter (2+k)/2 in w, ERRATA.md),
  // paraboloid (9.25-9.26), power law (9.28-9.30; the pressure through beta_upper, finite at the
  // Gamma poles of the printed form).
  double depth(const Medium &m, const Cone &cone, double a);
  double depth(const Medium &m, const Paraboloid &paraboloid, double a);
  double depth(const Medium &m, const PowerLaw &profile, double a);
  double force(const Medium &m, const Cone &cone, double a);
  double force(const Medium &m, const Paraboloid &paraboloid, double a);
  double force(const Medium &m, const PowerLaw &profile, double a);
  double pressure(const Medium &m, const Cone &cone, double a, double r);
  double pressure(const Medium &m, const Paraboloid &paraboloid, double a, double r);
  double pressure(const Medium &m, const PowerLaw &profile, double a, double r);
  /// w(r; a): d(a) - f(r) inside, the beta-function form outside.
  double displacement(const Medium &m, const Cone &cone, double a, double r);
  double displacement(const Medium &m, const Paraboloid &paraboloid, double a, double r);
  double displacement(const Medium &m, const PowerLaw &profile, double a, double r);
  /// a from the depth d > 0 or from the force F > 0 (inverting 9.30).
  double contact_radius_from_depth(const Medium &m, const PowerLaw &profile, double d);
  double contact_radius_from_force(const Medium &m, const PowerLaw &profile, double F);
  PowerLaw as_power_law(const Cone &cone);
  PowerLaw as_power_law(const Paraboloid &paraboloid);

  // --- concave punch in complete contact, 9.34-9.36 ----------------------------------------------
  /// The smallest centre displacement with complete contact, 2 (1-k) h0 / (1+k)^2 (9.35).
  double minimum_centre_displacement(const Medium &m, const ConcavePunch &punch);
  /// F_N(d0) (9.34); throws DomainError when d0 does not give complete contact (9.35).
  double force(const Medium &m, const ConcavePunch &punch, double d0);
  double pressure(const Medium &m, const ConcavePunch &punch, double d0, double r);
  double displacement(const Medium &m, const ConcavePunch &punch, double d0, double r);

  // --- constant pressure, 9.38-9.40 ------------------------------------------------------------
  /// w_c = 2 c0^k cos(k pi/2) p0 a^(1-k) / (cN0 (1-k)) (9.39 with F = p0 pi a^2).
  double centre_displacement(const Medium &m, const UniformPressure &load);
  /// w(r) = w_c 2F1((k-1)/2, (1+k)/2; 1; r^2/a^2) inside,
  ///        w_c (1-k)/2 (a/r)^(1+k) 2F1((1+k)/2, (1+k)/2; 2; a^2/r^2) outside (9.40).
  double displacement(const Medium &m, const UniformPressure &load, double r);
  /// F = p0 pi a^2
  double force(const UniformPressure &load);

  // --- Gibson medium, 9.42-9.44 ------------------------------------------------------------------
  /// The Winkler modulus p/w = 2 E0 / (3 c0) of the incompressible linearly graded half-space, the
  /// limit k -> 1 with nu = 1/2 (9.44); at k < 1 it holds only to O(1-k) (ERRATA.md).
  double gibson_winkler_modulus(double E0, double c0);
} // namespace gradcontact

#endif
