#include <fem/base/errors.h>
#include <fem/bodies/loads.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace gradcontact::fem
{
  Profile Profile::paraboloid(const double R)
  {
    Profile p;
    p.shape = Shape::paraboloid;
    p.R     = R;
    p.validate();
    return p;
  }

  Profile Profile::cone(const double tan_theta)
  {
    Profile p;
    p.shape     = Shape::cone;
    p.tan_theta = tan_theta;
    p.validate();
    return p;
  }

  Profile Profile::power_law(const double n, const double A)
  {
    Profile p;
    p.shape = Shape::power_law;
    p.n     = n;
    p.A     = A;
    p.validate();
    return p;
  }

  Profile Profile::concave_paraboloid(const double h0)
  {
    Profile p;
    p.shape = Shape::concave_paraboloid;
    p.h0    = h0;
    p.validate();
    return p;
  }

  Profile Profile::custom(std::function<double(double)> f, const double growth_exponent)
  {
    Profile p;
    p.shape = Shape::custom;
    p.function = std::move(f);
    p.growth_exponent = growth_exponent;
    return p;
  }

  double Profile::operator()(const double r, const double a) const
  {
    switch (shape)
      {
        case Shape::paraboloid:
          return r * r / (2 * R);
        case Shape::cone:
          return r * tan_theta;
        case Shape::power_law:
          return A * std::pow(r, n);
        case Shape::concave_paraboloid:
          return -h0 * (r / a) * (r / a);
        case Shape::custom:
          return function(r);
      }
    return 0; // unreachable
  }

  double Profile::exponent() const
  {
    switch (shape)
      {
        case Shape::paraboloid:
        case Shape::concave_paraboloid:
          return 2.0;
        case Shape::cone:
          return 1.0;
        case Shape::power_law:
          return n;
        case Shape::custom:
          return growth_exponent;
      }
    return 0; // unreachable
  }

  void Profile::validate() const
  {
    switch (shape)
      {
        case Shape::paraboloid:
          if (!(R > 0) || !std::isfinite(R))
            fail("Profile (paraboloid)", "R", R, "(0, inf)");
          break;
        case Shape::cone:
          if (!(tan_theta > 0) || !std::isfinite(tan_theta))
            fail("Profile (cone)", "tan_theta", tan_theta, "(0, inf)");
          break;
        case Shape::power_law:
          if (!(n > 0) || !std::isfinite(n))
            fail("Profile (power law)", "n", n, "(0, inf)");
          if (!(A > 0) || !std::isfinite(A))
            fail("Profile (power law)", "A", A, "(0, inf)");
          break;
        case Shape::concave_paraboloid:
          if (!(h0 >= 0) || !std::isfinite(h0))
            fail("Profile (concave paraboloid)", "h0", h0, "[0, inf)");
          break;
        case Shape::custom:
          if (!function)
            throw std::invalid_argument("Profile (custom): the profile function is empty");
          if (!(growth_exponent > 0) || !std::isfinite(growth_exponent))
            fail("Profile (custom)", "growth_exponent", growth_exponent, "(0, inf)");
          break;
      }
  }

  void LoadCase::validate() const
  {
    switch (type)
      {
        case LoadType::flat_punch:
          if (!std::isfinite(depth) || depth == 0)
            fail("LoadCase (flat punch)", "depth", depth, "finite, non-zero");
          break;
        case LoadType::indenter_depth:
          if (!std::isfinite(depth) || !(depth > 0))
            fail("LoadCase (indenter, depth control)", "depth", depth, "(0, inf)");
          [[fallthrough]];
        case LoadType::indenter_force:
          if (type == LoadType::indenter_force && (!std::isfinite(force) || !(force > 0)))
            fail("LoadCase (indenter, force control)", "force", force, "(0, inf)");
          [[fallthrough]];
        case LoadType::indenter:
          profile.validate();
          // Under contact-radius control the concave paraboloid is allowed: its radius-controlled state
          // (edge force zero, tension inside) is a basis state of the adhesive superposition
          // (fem/adhesion/adhesion.h); depth and force control assume a convex profile.
          if (profile.shape == Profile::Shape::concave_paraboloid && type != LoadType::indenter)
            throw std::invalid_argument(
              "LoadCase (indenter, depth or force control): profile concave_paraboloid needs "
              "LoadType::concave_punch or LoadType::indenter");
          break;
        case LoadType::concave_punch:
          profile.validate();
          if (profile.shape != Profile::Shape::concave_paraboloid)
            throw std::invalid_argument("LoadCase (concave punch): profile must be concave_paraboloid");
          if (!std::isfinite(depth) || !(depth > 0))
            fail("LoadCase (concave punch)", "depth (d0)", depth, "(0, inf)");
          break;
        case LoadType::constant_pressure:
          if (!std::isfinite(pressure) || (pressure == 0 && !cohesion.active()))
            fail("LoadCase (constant pressure)", "pressure", pressure, "finite, non-zero (0 only with a cohesion)");
          break;
      }
    if (!(cohesion.stress >= 0) || !std::isfinite(cohesion.stress))
      fail("LoadCase (cohesion)", "stress", cohesion.stress, "[0, inf)");
    if (cohesion.active())
      {
        if (type != LoadType::indenter && type != LoadType::constant_pressure)
          throw std::invalid_argument("LoadCase (cohesion): a cohesive tension needs LoadType::indenter or "
                                      "LoadType::constant_pressure");
        if (!(cohesion.radius > 0) || !std::isfinite(cohesion.radius))
          fail("LoadCase (cohesion)", "radius", cohesion.radius, "(0, inf)");
      }
  }
} // namespace gradcontact::fem
