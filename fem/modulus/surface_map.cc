#include <fem/base/errors.h>
#include <fem/modulus/surface_map.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace gradcontact::fem
{
  void SurfaceMapParameters::validate() const
  {
    if (scale != 0 && !(scale >= 0.02 && scale <= 20))
      fail("SurfaceMapParameters", "scale", scale, "0 (automatic) or [0.02, 20]");
    if (floor != 0 && !(floor >= 1e-12 && floor <= 1))
      fail("SurfaceMapParameters", "floor", floor, "0 (the mesh's h_edge) or [1e-12, 1] (/ a)");
  }



  template <int dim>
  SurfaceMap<dim>::SurfaceMap(const SurfaceMapParameters &p, const ModulusField &modulus, const double contact_radius,
                              const double h_edge)
  {
    p.validate();
    const double s = modulus.surface_exponent();
    if (!p.enabled || s == 0.0)
      return;
    if (!(contact_radius > 0 && std::isfinite(contact_radius)))
      fail("SurfaceMap", "contact_radius", contact_radius, "(0, inf)");
    if (!(s > 0 && s <= 0.95))
      fail("SurfaceMap (E ~ z^s at the surface; the map is for a vanishing surface modulus)", "surface exponent", s,
           "(0, 0.95]");
    if (!modulus.discontinuities().empty())
      fail("SurfaceMap (not for a modulus with jumps: their depths would be mesh coordinates)", "first jump depth",
           modulus.discontinuities().front(), "none");
    const double floor = (p.floor != 0) ? p.floor : h_edge;
    if (!(floor >= 1e-12 && floor <= 1))
      fail("SurfaceMap (the floor from the mesh)", "h_edge", floor, "[1e-12, 1] (/ a)");
    beta  = 1.0 / (1.0 - s);
    alpha = (p.scale != 0) ? p.scale : automatic_scale(s);
    a     = contact_radius;
    tau   = floor * contact_radius;
  }



  template <int dim>
  double SurfaceMap<dim>::length_and_gradient(const dealii::Point<dim> &x, dealii::Tensor<1, dim> &gradient) const
  {
    // T = alpha sqrt(u^2 + zeta^2 + tau^2), u = (r^2 - a^2) / sqrt(2 (r^2 + a^2)),
    // du/dx_t = 2 (r^2 + 3 a^2) x_t / (2 (r^2 + a^2))^{3/2}.
    double r2 = 0;
    for (int d = 0; d < dim - 1; ++d)
      r2 += x[d] * x[d];
    const double zeta = x[dim - 1];
    const double w    = 2 * (r2 + a * a);
    const double u    = (r2 - a * a) / std::sqrt(w);
    const double du   = 2 * (r2 + 3 * a * a) / (w * std::sqrt(w)); // du/dx_t = du * x_t
    const double S    = std::sqrt(u * u + zeta * zeta + tau * tau);
    for (int d = 0; d < dim - 1; ++d)
      gradient[d] = alpha * u * du * x[d] / S;
    gradient[dim - 1] = alpha * zeta / S;
    return alpha * S;
  }



  template <int dim>
  double SurfaceMap<dim>::length(const dealii::Point<dim> &x) const
  {
    dealii::Tensor<1, dim> unused;
    return length_and_gradient(x, unused);
  }



  template <int dim>
  typename SurfaceMap<dim>::Value SurfaceMap<dim>::at(const dealii::Point<dim> &x) const
  {
    const double zeta = x[dim - 1];
    if (!active())
      return {zeta, 1.0, dealii::Tensor<1, dim>()};
    if (!(zeta > 0))
      return {0.0, 0.0, dealii::Tensor<1, dim>()};
    dealii::Tensor<1, dim> dT;
    const double           T     = length_and_gradient(x, dT);
    const double           q     = zeta / (zeta + T);
    const double           qb    = std::pow(q, beta - 1);
    const double           Phi_T = (1 - beta) * qb * q;
    Value                  v;
    v.z  = zeta * qb;
    v.dz = qb * (zeta + beta * T) / (zeta + T) + Phi_T * dT[dim - 1];
    for (int d = 0; d < dim - 1; ++d)
      v.shift[d] = Phi_T * dT[d] / v.dz;
    return v;
  }



  template <int dim>
  dealii::Point<dim> SurfaceMap<dim>::physical(const dealii::Point<dim> &x) const
  {
    dealii::Point<dim> p = x;
    if (active() && x[dim - 1] > 0)
      p[dim - 1] = at(x).z;
    return p;
  }

  template <int dim>
  dealii::Point<dim> SurfaceMap<dim>::mesh_point(const dealii::Point<dim> &p) const
  {
    const double z = p[dim - 1];
    if (!active() || !(z > 0))
      return p;
    // Phi <= zeta (q < 1, beta > 1), so zeta >= z; widen the upper end until Phi reaches z.
    dealii::Point<dim> x  = p;
    double             lo = z, hi = 2 * z;
    x[dim - 1]            = hi;
    while (at(x).z < z)
      {
        lo = hi;
        hi *= 2;
        x[dim - 1] = hi;
      }
    double zeta = 0.5 * (lo + hi);
    for (unsigned int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i)
      {
        x[dim - 1]    = zeta;
        const Value v = at(x);
        if (std::abs(v.z - z) <= 2 * std::numeric_limits<double>::epsilon() * z)
          break;
        (v.z < z ? lo : hi) = zeta;
        const double newton = zeta - (v.z - z) / v.dz;
        zeta                = (newton > lo && newton < hi) ? newton : 0.5 * (lo + hi);
      }
    x[dim - 1] = zeta;
    return x;
  }

  template class SurfaceMap<2>;
  template class SurfaceMap<3>;
} // namespace gradcontact::fem
