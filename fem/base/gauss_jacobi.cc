#include <numerics/gauss_jacobi.h>
#include <fem/base/gauss_jacobi.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  Quadrature<1> gauss_jacobi(const unsigned int n_points, const double s)
  {
    if (n_points == 0)
      throw std::invalid_argument("gauss_jacobi: n_points = 0, need n_points >= 1");
    if (!(s > -1.0))
      {
        std::ostringstream msg;
        msg << "gauss_jacobi: exponent s = " << s << " outside (-1, inf)";
        throw std::invalid_argument(msg.str());
      }

    // The shared rule on [0, 1] with weight x^s (1 - x)^0 (numerics/gauss_jacobi.h: Golub-Welsch
    // nodes polished by Newton's method, Christoffel weights, in long double; header only, no link to the
    // analytic library).
    const detail::GaussJacobiRule rule = detail::gauss_jacobi_rule(n_points, 1.0 + s, 1.0);
    std::vector<Point<1>> points(n_points);
    std::vector<double>   weights(rule.weight);
    for (unsigned int q = 0; q < n_points; ++q)
      points[q][0] = rule.node[q];
    return Quadrature<1>(points, weights);
  }



  template <int dim>
  Quadrature<dim> surface_cell_quadrature(const unsigned int n_points, const double s,
                                          const unsigned int singular_face, std::vector<double> &distance)
  {
    AssertThrow(singular_face < 2 * dim, ExcIndexRange(singular_face, 0, 2 * dim));
    const Quadrature<1> across = gauss_jacobi(n_points, s);
    const QGauss<1>     along(n_points);
    // Across the face (reference axis singular_face / 2) the distance is x for even faces, 1 - x for odd.
    const unsigned int axis     = singular_face / 2;
    const bool         mirrored = (singular_face % 2 == 1);

    std::vector<Point<dim>> points;
    std::vector<double>     weights;
    distance.clear();
    const unsigned int n_along = Utilities::pow(n_points, dim - 1);
    for (unsigned int i = 0; i < n_points; ++i) // across
      for (unsigned int j = 0; j < n_along; ++j) // along: the other axes, lexicographic
        {
          const double xi = across.point(i)[0];
          Point<dim>   p;
          double       w = across.weight(i);
          unsigned int rest = j;
          for (unsigned int d = 0; d < dim; ++d)
            if (d == axis)
              p[d] = mirrored ? 1.0 - xi : xi;
            else
              {
                p[d] = along.point(rest % n_points)[0];
                w *= along.weight(rest % n_points);
                rest /= n_points;
              }
          points.push_back(p);
          weights.push_back(w);
          distance.push_back(xi);
        }
    return Quadrature<dim>(points, weights);
  }

  template Quadrature<2> surface_cell_quadrature<2>(unsigned int, double, unsigned int, std::vector<double> &);
  template Quadrature<3> surface_cell_quadrature<3>(unsigned int, double, unsigned int, std::vector<double> &);



  Quadrature<2> surface_corner_quadrature(const unsigned int n_points, const double s,
                                          const unsigned int singular_vertex)
  {
    if (singular_vertex > 3)
      throw std::invalid_argument("surface_corner_quadrature: singular_vertex = " + std::to_string(singular_vertex) +
                                  " outside [0, 3]");
    // Exponent 1 + s of the ray coordinate u (Duffy's Jacobian u times u^s) must exceed -1; gauss_jacobi checks it.
    const Quadrature<1> ray = gauss_jacobi(2 * n_points, 1 + s);
    const QGauss<1>     across(2 * n_points);
    // Vertex v of the reference square sits at (v % 2, v / 2); a and b are the distances from it along the axes.
    const bool              flip_x = singular_vertex % 2 == 1, flip_y = singular_vertex / 2 == 1;
    std::vector<Point<2>>   points;
    std::vector<double>     weights;
    for (unsigned int triangle = 0; triangle < 2; ++triangle) // b <= a, then a <= b
      for (unsigned int i = 0; i < ray.size(); ++i)
        for (unsigned int j = 0; j < across.size(); ++j)
          {
            const double u = ray.point(i)[0], t = across.point(j)[0];
            const double a = triangle == 0 ? u : u * t, b = triangle == 0 ? u * t : u;
            points.emplace_back(flip_x ? 1 - a : a, flip_y ? 1 - b : b);
            weights.push_back(ray.weight(i) * across.weight(j) * std::pow(u, -s));
          }
    return Quadrature<2>(points, weights);
  }
} // namespace gradcontact::fem
