#include <analytic/detail/gauss_jacobi.h>
#include <fem/gauss_jacobi.h>

#include <deal.II/base/quadrature_lib.h>

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

    // The shared rule on [0, 1] with weight x^s (1 - x)^0 (analytic/detail/gauss_jacobi.h: Golub-Welsch
    // nodes polished by Newton's method, Christoffel weights, in long double; header only, no link to the
    // analytic library).
    const detail::GaussJacobiRule rule = detail::gauss_jacobi_rule(n_points, 1.0 + s, 1.0);
    std::vector<Point<1>> points(n_points);
    std::vector<double>   weights(rule.weight);
    for (unsigned int q = 0; q < n_points; ++q)
      points[q][0] = rule.node[q];
    return Quadrature<1>(points, weights);
  }



  Quadrature<2> surface_cell_quadrature(const unsigned int n_points, const double s,
                                        const unsigned int singular_face,
                                        std::vector<double> &distance)
  {
    AssertThrow(singular_face < 4, ExcIndexRange(singular_face, 0, 4));
    const Quadrature<1> across = gauss_jacobi(n_points, s);
    const QGauss<1>     along(n_points);
    // Across the face the distance is x for faces 0 and 2, 1 - x for faces 1 and 3.
    const bool mirrored  = (singular_face % 2 == 1);
    const bool across_is_x = (singular_face < 2);

    std::vector<Point<2>> points;
    std::vector<double>   weights;
    distance.clear();
    for (unsigned int i = 0; i < n_points; ++i)     // across
      for (unsigned int j = 0; j < n_points; ++j)   // along
        {
          const double xi = across.point(i)[0];
          const double t  = mirrored ? 1.0 - xi : xi;
          points.push_back(across_is_x ? Point<2>(t, along.point(j)[0]) :
                                         Point<2>(along.point(j)[0], t));
          weights.push_back(across.weight(i) * along.weight(j));
          distance.push_back(xi);
        }
    return Quadrature<2>(points, weights);
  }
} // namespace gradcontact::fem
