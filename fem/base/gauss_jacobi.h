// Gauss-Jacobi quadrature for the integrals of the surface cell layer.
//
// The n-point rule on [0, 1] with weight x^s, s > -1,
//     \int_0^1 x^s g(x) dx = \sum_q w_q g(x_q)   exactly for polynomials g of degree <= 2n - 1,
// the rule the numerical MDR uses too (numerics/gauss_jacobi.h, header only and free of deal.II:
// the Golub-Welsch algorithm, nodes polished by Newton's method, Christoffel weights, in long double).
// Sharing a quadrature rule does not steer the FE model by the closed forms: gradcontact_fem still does
// not link the analytic library. s = 0 gives Gauss-Legendre.
//
// deal.II 9.4 has no Gauss-Jacobi rule with a non-integer exponent (its jacobi_polynomial_roots takes
// integer alpha, beta), hence this one.
#ifndef GRADCONTACT_FEM_GAUSS_JACOBI_H
#define GRADCONTACT_FEM_GAUSS_JACOBI_H

#include <deal.II/base/quadrature.h>

namespace gradcontact::fem
{
  /// n-point rule on [0, 1] whose weights contain x^s (so sum_q w_q = 1 / (1 + s)).
  /// Throws std::invalid_argument for n = 0 or s <= -1.
  dealii::Quadrature<1> gauss_jacobi(unsigned int n_points, double s);

  /// The rule for a cell whose face `singular_face` (deal.II numbering: 2 d for x_d = 0, 2 d + 1 for
  /// x_d = 1) lies on the surface z = 0: Gauss-Jacobi with exponent s across that face, Gauss-Legendre
  /// along it (a tensor product, dim = 2 or 3). `distance` receives, per point, the reference-coordinate
  /// distance xi_q from that face (the weights contain xi_q^s, so the integrand must be divided by it).
  template <int dim>
  dealii::Quadrature<dim> surface_cell_quadrature(unsigned int n_points, double s, unsigned int singular_face,
                                                  std::vector<double> &distance);

  /// The rule for a 2D cell that touches the surface z = 0 at its vertex `singular_vertex` (deal.II numbering) only,
  /// for integrands z^s g with g smooth. Near that vertex z vanishes linearly along every reference ray, so the
  /// square is split along its diagonal through the vertex and each triangle is collapsed onto it (Duffy, SIAM J.
  /// Numer. Anal. 19 (1982) 1260): with u the distance along the axis from the vertex and t u across it,
  /// dA = u du dt and z^s = u^s (z/u)^s, (z/u)^s smooth, so Gauss-Jacobi of exponent 1 + s in u times
  /// Gauss-Legendre in t converges like the rules of smooth integrands. The weights are those of plain
  /// integration (the u^(1+s) of the Gauss-Jacobi weight divided out again except for the Duffy Jacobian u):
  /// the integrand is evaluated with its z^s. 2 n_points points in u and in t, per triangle.
  /// Throws std::invalid_argument for n_points = 0, s <= -2 or singular_vertex > 3.
  dealii::Quadrature<2> surface_corner_quadrature(unsigned int n_points, double s, unsigned int singular_vertex);
} // namespace gradcontact::fem

#endif
