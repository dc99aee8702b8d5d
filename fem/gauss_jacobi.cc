#include <fem/gauss_jacobi.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <limits>
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

    // Recurrence of the monic Jacobi polynomials P^{(alpha, beta)} on [-1, 1], weight
    // (1 - t)^alpha (1 + t)^beta, here alpha = 0 and beta = s so that (1 + t)^s = (2x)^s:
    //   a_0 = (beta - alpha) / (alpha + beta + 2),
    //   a_j = (beta^2 - alpha^2) / ((2j + alpha + beta)(2j + alpha + beta + 2)),               j >= 1,
    //   b_j^2 = 4 j (j + alpha)(j + beta)(j + alpha + beta)
    //           / ((2j + alpha + beta)^2 (2j + alpha + beta + 1)(2j + alpha + beta - 1)),     j >= 1.
    const double alpha = 0.0, beta = s;
    LAPACKFullMatrix<double> J(n_points, n_points);
    for (unsigned int j = 0; j < n_points; ++j)
      {
        const double sum = 2.0 * j + alpha + beta;
        const double a   = (j == 0) ? (beta - alpha) / (alpha + beta + 2.0) :
                                      (beta * beta - alpha * alpha) / (sum * (sum + 2.0));
        J(j, j) = 0.5 * (1.0 + a); // mapped to x = (1 + t)/2: diagonal (1 + a)/2
        if (j + 1 < n_points)
          {
            const double jj  = j + 1.0;
            const double sj  = 2.0 * jj + alpha + beta;
            const double b2  = 4.0 * jj * (jj + alpha) * (jj + beta) * (jj + alpha + beta) /
                              (sj * sj * (sj + 1.0) * (sj - 1.0));
            const double off = 0.5 * std::sqrt(b2); // off-diagonal scales with the map, too
            J(j, j + 1)      = off;
            J(j + 1, j)      = off;
          }
      }

    Vector<double>     nodes;
    FullMatrix<double> vectors;
    // All eigenvalues lie in (0, 1); ask for a slightly larger interval.
    J.compute_eigenvalues_symmetric(-0.5, 1.5, 2.0 * std::numeric_limits<double>::min(), nodes,
                                    vectors);
    AssertThrow(nodes.size() == n_points,
                ExcMessage("gauss_jacobi: eigen solver returned " + std::to_string(nodes.size()) +
                           " of " + std::to_string(n_points) + " nodes"));

    std::vector<Point<1>> points(n_points);
    std::vector<double>   weights(n_points);
    const double          mu0 = 1.0 / (1.0 + s);
    for (unsigned int q = 0; q < n_points; ++q)
      {
        points[q][0] = nodes[q];
        weights[q]   = mu0 * vectors(0, q) * vectors(0, q);
      }
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
