// The loads of the axisymmetric models: rigid axisymmetric indenter profiles f(r) and the normal load
// cases (flat punch, curved indenters under radius, depth or force control, the concave punch,
// constant pressure), and what a run is asked to sample.
//
// Conventions: z points into the material, f(0) = 0, the depth d and the force F_N are positive in
// compression; the equation numbers are the chapter's (9.x).
#ifndef GRADCONTACT_FEM_LOADS_H
#define GRADCONTACT_FEM_LOADS_H

#include <functional>
#include <string>
#include <vector>

namespace gradcontact::fem
{
  /// A rigid axisymmetric indenter profile f(r), f(0) = 0, z into the material.
  struct Profile
  {
    enum class Shape
    {
      paraboloid,        ///< f = r^2 / (2 R)                (9.24)
      cone,              ///< f = r tan(theta)               (9.18)
      power_law,          ///< f = A r^n                      (9.27)
      concave_paraboloid, ///< f = -h0 r^2 / a^2, r <= a      (9.31)
      custom              ///< any convex f(r) given as a function (a user's candidate profile)
    };
    Shape  shape     = Shape::paraboloid;
    double R         = 1.0;
    double tan_theta = 0.0;
    double n         = 2.0;
    double A         = 0.0;
    double h0        = 0.0;

    static Profile paraboloid(double R);
    static Profile cone(double tan_theta);
    static Profile power_law(double n, double A);
    static Profile concave_paraboloid(double h0);
    /// Any convex profile with f(0) = 0; `growth_exponent` (f ~ r^n) only seeds the depth and force
    /// searches of indenter_depth and indenter_force.
    static Profile custom(std::function<double(double)> f, double growth_exponent);
    std::function<double(double)> function; ///< custom: f(r)
    double growth_exponent = 2.0;           ///< custom

    /// f(r); `a` is the punch radius (used by the concave paraboloid only).
    double operator()(double r, double a) const;
    /// The power n of f ~ r^n (2, 1, n; 2 for the concave paraboloid).
    double exponent() const;
    void   validate() const;
  };

  enum class LoadType
  {
    flat_punch,       ///< prescribed depth d on r <= a
    indenter,         ///< curved indenter, contact radius a (mesh), depth found
    indenter_depth,   ///< curved indenter at a given depth, contact radius found on the same mesh
    indenter_force,   ///< curved indenter at a given force, depth and contact radius found
    concave_punch,    ///< concave paraboloid, centre displacement d0, complete contact checked
    constant_pressure ///< p0 on r <= a
  };

  /// A uniform adhesive tension on the surface r <= radius (the cohesive zone of the Dugdale law,
  /// fem/adhesion/cohesive_zone.h), added to the load of LoadType::indenter (radius >= the contact radius a; on the
  /// contact it only lowers the contact pressure, which then is p + stress) or LoadType::constant_pressure
  /// (a separated surface: no contact). stress = 0: none.
  struct Cohesion
  {
    double stress = 0.0; ///< sigma_0 >= 0, tensile
    double radius = 0.0; ///< c > 0 when stress > 0
    bool   active() const { return stress > 0; }
  };

  struct LoadCase
  {
    LoadType type     = LoadType::flat_punch;
    double   depth    = 0.0; ///< d (flat punch, indenter_depth) or d0 (concave punch)
    double   force    = 0.0; ///< F_N (indenter_force)
    Profile  profile;        ///< indenter and concave punch
    double   pressure = 0.0; ///< p0 (constant pressure; may be 0 with a cohesion)
    Cohesion cohesion;       ///< indenter and constant pressure only

    void validate() const;
  };

  /// A point of the meridian plane, z into the material.
  struct StressPoint
  {
    double r = 0, z = 0;
  };

  /// Only what is asked for is computed.
  struct OutputRequest
  {
    std::vector<double> pressure_radii;     ///< sample p(r) here (r <= a)
    std::vector<double> displacement_radii; ///< sample w(r) = u_z(r, 0) here (any r <= L)
    /// Sample the recovered stresses (fem/elasticity/stress_recovery.h) at these physical points, z >= 0.
    std::vector<StressPoint> stress_points;
    std::string         vtu_file;           ///< write the fields here when not empty
  };

  struct Sample
  {
    double r;
    double value;
  };

} // namespace gradcontact::fem

#endif
