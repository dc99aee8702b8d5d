// A singular change of the depth coordinate near the surface of a modulus E ~ z^s, 0 < s < 1.
//
// Under a surface traction the displacement of such a body behaves like u_z ~ d - c z^{1-s} (the strain
// p / E(z) ~ z^{-s} integrates to z^{1-s}): no polynomial in z resolves it, which z-halvings of the surface
// cells (fem/grid/mesh.h) answer with cells down to 1e-10 a. The map below is a global change of coordinates
// (x_t, zeta) -> (x_t, z) in which z^{1-s} is an analytic function of zeta, so the FE space of polynomials in
// the mesh coordinates holds it without any thin cell:
//     z = Phi(x_t, zeta) = zeta^beta (zeta + T)^{1 - beta},  beta = 1 / (1 - s),
//     z^{1-s} = zeta (zeta + T)^{-s}                        (analytic at zeta = 0 for T > 0),
// with the length T(x_t, zeta) below. Phi ~ zeta^beta T^{1-beta} at the surface; since T grows like the
// distance from the contact edge, Phi is homogeneous of degree 1 about that point, and deep below the surface
// a uniform contraction, Phi = zeta (zeta / (zeta + T))^{beta-1} >= zeta (1 + 1.25 alpha)^{1-beta}. Being one
// map of the whole body (the mesh is a mesh of (x_t, zeta), the FE functions are polynomials of the mesh
// coordinates there), it is conforming on any mesh, hanging nodes included.
//
// The length T sets where the map acts. Near the contact edge (a, 0) the field is self-similar about the
// edge point, so T is proportional to the distance from it, and so is the surface cell size of the meshes
// graded toward it; far away T grows like the distance from the origin, as the far-field rings do:
//     T = alpha sqrt(u(r)^2 + zeta^2 + tau^2),   u = (r^2 - a^2) / sqrt(2 (r^2 + a^2)),
// with alpha = SurfaceMapParameters::scale and tau = floor a (the smallest length the map resolves, of the
// order of the edge cell). u ~ r - a at the edge and is a smooth function of r^2, so the map is smooth
// across the axis of the 3D model too. T must depend on zeta as well: with T = alpha |r - a| alone, Phi
// would have a crease above the edge (Phi_r jumps by 2 (beta - 1) alpha across r = a for zeta >> tau),
// which no mesh follows, so that refinement would hardly reduce the error. With zeta in T,
// Phi = rho psi(theta) about the edge point, psi smooth for theta > 0.
//
// Derivatives (q = zeta / (zeta + T)):
//     Phi = zeta q^{beta-1},  dPhi/dT = (1 - beta) q^beta,
//     Phi_zeta = q^{beta-1} (zeta + beta T) / (zeta + T) + (1 - beta) q^beta T_zeta ~ zeta^{beta-1},
//     Phi_t = (1 - beta) q^beta T_t;
// Phi_zeta > 0 for every alpha (Phi / |x| is increasing in zeta / |x|), so the map is one to one. A gradient
// in the mesh coordinates (g_t, g_zeta) is, in the physical ones,
//     du/dz = g_zeta / Phi_zeta,   du/dx_t = g_t - shift_t g_zeta,  shift_t = Phi_t / Phi_zeta ~ zeta.
// The cell integrals then split by their powers of zeta (fem/elasticity/graded_elasticity.h): with gamma = s / (1 - s)
// and E(Phi) ~ zeta^gamma, Phi_zeta ~ zeta^gamma, the zz part E (du/dz)(dv/dz) dz ~ zeta^0, the mixed part
// ~ zeta^gamma and the in-plane part ~ zeta^{2 gamma}, each integrated by its own Gauss-Jacobi rule.
// The map is for 0 < s <= 0.95 only (SurfaceMap's constructor says why not s < 0; above 0.95 q^{beta-1}
// underflows at the quadrature points nearest the surface).
//
// The mesh is a mesh of (x_t, zeta); the physical body is its image. T grows like the distance, so the image of
// the truncation boundary max(r, zeta) = L lies closer, its top at depth >= L (1 + 1.25 alpha)^{1-beta} (a
// factor 1.6 at k = 0.5): use_surface_map (fem/grid/discretization.h) widens the mesh's L by far_field_contraction,
// which costs a few rings (the truncation error falls like (a/L)^{1+k}). A map set by hand
// (DiscretizationParameters::surface_map) leaves L as given.
#ifndef GRADCONTACT_FEM_SURFACE_MAP_H
#define GRADCONTACT_FEM_SURFACE_MAP_H

#include <fem/modulus/modulus.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace gradcontact::fem
{
  /// The map of the header, as a discretisation choice.
  struct SurfaceMapParameters
  {
    bool   enabled = false;
    /// alpha; 0: alpha = 0.5 sqrt((1 - s) / s), else [0.02, 20]. The formula follows the optimum of the
    /// flat-punch force at degree 4 (h_edge = 1e-7 a) over s, which falls as s -> 1; away from it the error
    /// grows fast for s -> 1, so a hand-set alpha there wants a scan (`fem_study load=punch k=0.9 p=4
    /// h_edge=1e-7 map=<alpha>`).
    double scale = 0;
    /// tau / a; 0: the mesh's cell size at the contact edge (h_edge), else [1e-12, 1].
    double floor = 0;

    /// Throws std::invalid_argument naming the member, its value and the valid range.
    void validate() const;
  };

  /// The map for one body: modulus surface exponent s, contact radius a (physical units).
  template <int dim>
  class SurfaceMap
  {
  public:
    /// The map at one point of the mesh coordinates.
    struct Value
    {
      double              z;        ///< Phi, the physical depth
      double              dz;       ///< dPhi / dzeta (> 0 for zeta > 0)
      dealii::Tensor<1, dim> shift; ///< Phi_t / Phi_zeta for the tangential axes, 0 in the depth axis
    };

    /// The identity (no map).
    SurfaceMap() = default;

    /// The map of `parameters` for `modulus` (surface exponent s), contact radius a (physical units) and
    /// the mesh's edge cell size h_edge (/ a, the floor tau when parameters.floor = 0); the identity when
    /// the parameters disable it or s = 0. Throws std::invalid_argument when enabled for a modulus with
    /// jumps (their depths would be mesh coordinates) or with s outside (0, 0.95]: s = 1 (the Gibson medium)
    /// has no singular layer, s -> 1 underflows (beta - 1 = 19 at 0.95), and for s < 0 the map makes the
    /// regular field outside the contact ~ zeta^beta, beta < 1 (the flat punch at k = -0.5 loses orders of
    /// magnitude of its force accuracy).
    SurfaceMap(const SurfaceMapParameters &parameters, const ModulusField &modulus, double contact_radius,
               double h_edge);

    /// The automatic alpha, 0.5 sqrt((1 - s) / s) (SurfaceMapParameters::scale).
    static double automatic_scale(double s) { return 0.5 * std::sqrt((1 - s) / s); }
    /// How much the map pulls the truncation boundary max(r, zeta) = L toward the contact at most: the image of
    /// its top zeta = L lies at depth >= L / this (T <= 1.25 alpha L there, Phi = zeta (zeta / (zeta + T))^{beta-1}).
    static double far_field_contraction(double s, double alpha)
    {
      return std::pow(1 + 1.25 * alpha, s / (1 - s));
    }

    bool active() const { return beta != 1.0; }
    /// beta = 1 / (1 - s).
    double exponent() const { return beta; }
    /// gamma = beta - 1 = s / (1 - s): E(Phi) and Phi_zeta both ~ zeta^gamma at the surface.
    double gamma() const { return beta - 1.0; }

    /// Phi, Phi_zeta and the shift at mesh point x, zeta = x[dim - 1] > 0 (quadrature points); zeta <= 0 (the
    /// surface) gives Phi = 0, Phi_zeta = 0 (the map is singular there) and no shift.
    Value at(const dealii::Point<dim> &x) const;
    /// The physical point of mesh point x (for output).
    dealii::Point<dim> physical(const dealii::Point<dim> &x) const;
    /// The mesh point whose image is the physical point p (the inverse of physical(): Phi is increasing in zeta,
    /// so zeta solves Phi(x_t, zeta) = z by bracketing and Newton steps kept inside the bracket).
    dealii::Point<dim> mesh_point(const dealii::Point<dim> &p) const;
    /// T at mesh point x.
    double length(const dealii::Point<dim> &x) const;

  private:
    double beta = 1.0, alpha = 0.0, a = 1.0, tau = 0.0;
    /// T and its gradient in the mesh coordinates.
    double length_and_gradient(const dealii::Point<dim> &x, dealii::Tensor<1, dim> &gradient) const;
  };

  extern template class SurfaceMap<2>;
  extern template class SurfaceMap<3>;
} // namespace gradcontact::fem

#endif
