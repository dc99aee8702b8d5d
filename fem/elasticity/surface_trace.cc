#include <fem/base/boundary_ids.h>
#include <fem/grid/discretization.h>
#include <fem/base/errors.h>
#include <fem/elasticity/surface_trace.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace gradcontact::fem
{
  using namespace dealii;

  double lagrange(const std::vector<double> &x, const std::vector<double> &y, const double r)
  {
    double sum = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        double l = 1;
        for (unsigned int j = 0; j < x.size(); ++j)
          if (j != i)
            l *= (r - x[j]) / (x[i] - x[j]);
        sum += l * y[i];
      }
    return sum;
  }



  std::vector<SurfaceFace> collect_surface_faces(const DoFHandler<2> &dof_handler,
                                                 const std::vector<double> &support_r,
                                                 const unsigned int n_components)
  {
    const FiniteElement<2>              &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<SurfaceFace>             faces;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
          {
            cell->face(f)->get_dof_indices(face_dofs);
            SurfaceFace face;
            face.contact = (cell->face(f)->boundary_id() == boundary_id::contact);
            face.dofs.resize(n_components);
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              {
                const unsigned int c = fe.face_system_to_component_index(i, f).first;
                if (c < n_components)
                  face.dofs[c].push_back(face_dofs[i]);
              }
            for (auto &list : face.dofs)
              std::sort(list.begin(), list.end(),
                        [&](const auto x, const auto y) { return support_r[x] < support_r[y]; });
            for (const auto d : face.dofs[0])
              face.r.push_back(support_r[d]);
            face.r0 = face.r.front();
            face.r1 = face.r.back();
            faces.push_back(std::move(face));
          }
    std::sort(faces.begin(), faces.end(), [](const SurfaceFace &x, const SurfaceFace &y) { return x.r0 < y.r0; });
    return faces;
  }



  const SurfaceFace *find_face(const std::vector<SurfaceFace> &faces, const double r, const double limit)
  {
    const double end = (limit == std::numeric_limits<double>::max()) ? limit : limit * (1 + node_tolerance);
    for (const SurfaceFace &face : faces)
      if (r >= face.r0 && r <= face.r1 && face.r1 <= end)
        return &face;
    return nullptr;
  }



  void add_graded_interval(const double x0, const double x1, const bool graded_left, const bool graded_right,
                           const GradedRule &rule, std::vector<std::pair<double, double>> &points)
  {
    const QGauss<1> gauss(rule.n_points);
    auto add = [&](const double y0, const double y1) {
      for (unsigned int q = 0; q < gauss.size(); ++q)
        points.emplace_back(y0 + (y1 - y0) * gauss.point(q)[0], (y1 - y0) * gauss.weight(q));
    };
    if (!graded_left && !graded_right)
      return add(x0, x1);
    // Split at the middle if both ends are graded; grade each half toward its end.
    const double mid = graded_left && graded_right ? 0.5 * (x0 + x1) : (graded_left ? x1 : x0);
    if (graded_left)
      {
        double hi = mid, length = mid - x0;
        for (unsigned int j = 0; j < rule.pieces; ++j)
          {
            const double lo = (j + 1 == rule.pieces) ? x0 : x0 + length * rule.ratio;
            add(lo, hi);
            hi = lo;
            length *= rule.ratio;
          }
      }
    if (graded_right)
      {
        double lo = mid, length = x1 - mid;
        for (unsigned int j = 0; j < rule.pieces; ++j)
          {
            const double hi = (j + 1 == rule.pieces) ? x1 : x1 - length * rule.ratio;
            add(lo, hi);
            lo = hi;
            length *= rule.ratio;
          }
      }
  }



  std::vector<std::vector<double>> traction_integrals(const std::vector<SurfaceFace> &faces,
                                                      const std::function<double(double)> &t, const double radius,
                                                      std::vector<double> cuts, const GradedRule &rule,
                                                      const char *where)
  {
    cuts.push_back(radius);
    std::sort(cuts.begin(), cuts.end());
    // A piece end is graded when a cut lies at it or within `near_cut_reach` piece lengths beyond it. A
    // kink or branch point at distance d outside a piece of length L is the nearest singularity of the
    // integrand: n-point Gauss then converges only like rho^{-2n}, rho = x + sqrt(x^2 - 1), x = 1 + 2 d / L
    // (the Bernstein ellipse through it). At d = 2 L, rho = 9.9 and 8 points reach 1e-16; closer, the
    // geometric pieces toward the end keep every piece at least a third of its length away from the
    // singularity, as at a cut. The case that needs it: the unloading traction (9.82), whose reversal radius b
    // can lie a small fraction of a face length beyond a face end, where one rule on that face is far from its
    // integral (rho near 1 above); graded, F_x is at the graded rule's own error at a kink.
    constexpr double near_cut_reach = 2.;
    auto             graded_end     = [&](const double x, const double length, const int outward) {
      return std::any_of(cuts.begin(), cuts.end(), [&](const double c) {
        const double beyond = outward * (c - x); // distance of the cut beyond the end, outward from the piece
        return std::abs(x - c) <= node_tolerance * c || (beyond > 0 && beyond <= near_cut_reach * length);
      });
    };
    std::vector<std::vector<double>> integrals(faces.size());
    for (unsigned int k = 0; k < faces.size(); ++k)
      {
        const SurfaceFace &face = faces[k];
        const unsigned int n    = face.r.size();
        integrals[k].assign(n, 0.0);
        if (face.r0 >= radius * (1 - node_tolerance))
          continue;
        // Pieces of [r0, min(r1, radius)] between the cuts; grade toward a cut at an end or just beyond it.
        std::vector<double> ends{face.r0};
        for (const double c : cuts)
          if (c > face.r0 * (1 + node_tolerance) && c < face.r1 * (1 - node_tolerance))
            ends.push_back(c);
        ends.push_back(std::min(face.r1, radius));
        std::vector<std::pair<double, double>> points;
        for (unsigned int j = 0; j + 1 < ends.size(); ++j)
          {
            const double length = ends[j + 1] - ends[j];
            add_graded_interval(ends[j], ends[j + 1], graded_end(ends[j], length, -1),
                                graded_end(ends[j + 1], length, +1), rule, points);
          }
        std::vector<double> unit(n, 0.0);
        for (const auto &[r, w] : points)
          {
            const double value = t(r);
            if (!std::isfinite(value))
              fail(where, "tau(r) at r = " + std::to_string(r), value, "finite values");
            for (unsigned int i = 0; i < n; ++i)
              {
                std::fill(unit.begin(), unit.end(), 0.0);
                unit[i] = 1;
                integrals[k][i] += value * lagrange(face.r, unit, r) * r * w;
              }
          }
      }
    return integrals;
  }



  std::vector<double> support_radii(const Mapping<2> &mapping, const DoFHandler<2> &dof_handler)
  {
    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    std::vector<double> r(support.size());
    for (unsigned int i = 0; i < support.size(); ++i)
      r[i] = support[i][0];
    return r;
  }

  LineMass line_mass_matrix(const std::vector<SurfaceFace> &faces, const unsigned int c, const double limit,
                            const unsigned int n_gauss)
  {
    const double                                    end = limit * (1 + node_tolerance);
    std::map<types::global_dof_index, unsigned int> index;
    LineMass                                        mass;
    for (const SurfaceFace &face : faces)
      if (face.r1 <= end)
        for (const auto d : face.dofs[c])
          if (index.emplace(d, index.size()).second)
            mass.dofs.push_back(d);
    const unsigned int m = index.size();
    mass.matrix.reinit(m, m);
    const QGauss<1> quadrature(n_gauss);
    for (const SurfaceFace &face : faces)
      if (face.r1 <= end)
        {
          const auto &dofs = face.dofs[c];
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double        r = face.r0 + (face.r1 - face.r0) * quadrature.point(q)[0];
              const double        w = quadrature.weight(q) * (face.r1 - face.r0) * r;
              std::vector<double> phi(dofs.size());
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  std::vector<double> unit(dofs.size(), 0.0);
                  unit[i] = 1;
                  phi[i]  = lagrange(face.r, unit, r);
                }
              for (unsigned int i = 0; i < dofs.size(); ++i)
                for (unsigned int j = 0; j < dofs.size(); ++j)
                  mass.matrix(index[dofs[i]], index[dofs[j]]) += phi[i] * phi[j] * w;
            }
        }
    return mass;
  }

  SurfaceCoupling linear_density_coupling(const std::vector<SurfaceFace> &faces, const unsigned int c,
                                          const double limit, const unsigned int n_gauss)
  {
    const double                                    end = limit * (1 + node_tolerance);
    std::map<types::global_dof_index, unsigned int> index;
    SurfaceCoupling                                 coupling;
    for (const SurfaceFace &face : faces)
      if (face.r1 <= end)
        {
          for (const auto d : face.dofs[c])
            if (index.emplace(d, index.size()).second)
              coupling.dofs.push_back(d);
          if (coupling.vertex_r.empty())
            coupling.vertex_r.push_back(face.r0);
          coupling.vertex_r.push_back(face.r1);
        }
    coupling.matrix.reinit(coupling.dofs.size(), coupling.vertex_r.size());
    coupling.vertex_mass.reinit(coupling.vertex_r.size(), coupling.vertex_r.size());
    const QGauss<1> quadrature(n_gauss);
    unsigned int    k = 0; // the face's left vertex
    for (const SurfaceFace &face : faces)
      if (face.r1 <= end)
        {
          const auto &dofs = face.dofs[c];
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const double x = quadrature.point(q)[0];
              const double r = face.r0 + (face.r1 - face.r0) * x;
              const double w = quadrature.weight(q) * (face.r1 - face.r0) * r;
              for (unsigned int i = 0; i < dofs.size(); ++i)
                {
                  std::vector<double> unit(dofs.size(), 0.0);
                  unit[i]          = 1;
                  const double phi = lagrange(face.r, unit, r);
                  coupling.matrix(index[dofs[i]], k) += phi * (1 - x) * w;
                  coupling.matrix(index[dofs[i]], k + 1) += phi * x * w;
                }
              const double psi[2] = {1 - x, x};
              for (unsigned int a = 0; a < 2; ++a)
                for (unsigned int b = 0; b < 2; ++b)
                  coupling.vertex_mass(k + a, k + b) += psi[a] * psi[b] * w;
            }
          ++k;
        }
    return coupling;
  }

  SurfaceCoupling hat_coupling(const std::vector<SurfaceFace> &faces, const unsigned int c,
                               const std::vector<double> &vertex_r, const unsigned int n_gauss)
  {
    const unsigned int m = vertex_r.size();
    if (m < 2)
      fail("hat_coupling", "number of vertices", m, "at least 2");
    for (unsigned int k = 1; k < m; ++k)
      if (!(vertex_r[k] > vertex_r[k - 1]))
        fail("hat_coupling", "vertex radius", vertex_r[k], "ascending");
    const double begin = vertex_r.front(), end = vertex_r.back();
    // psi_k at r in [vertex_r[j], vertex_r[j + 1]]: the two hats of that interval.
    const auto interval = [&](const double r) {
      const auto it = std::upper_bound(vertex_r.begin(), vertex_r.end(), r);
      return std::min<std::size_t>(std::max<std::ptrdiff_t>(it - vertex_r.begin(), 1), m - 1) - 1;
    };
    SurfaceCoupling                                 coupling;
    std::map<types::global_dof_index, unsigned int> index;
    coupling.vertex_r = vertex_r;
    std::vector<const SurfaceFace *> overlapping;
    for (const SurfaceFace &face : faces)
      if (face.r1 > begin && face.r0 < end)
        {
          overlapping.push_back(&face);
          for (const auto d : face.dofs[c])
            if (index.emplace(d, index.size()).second)
              coupling.dofs.push_back(d);
        }
    coupling.matrix.reinit(coupling.dofs.size(), m);
    const QGauss<1> quadrature(n_gauss);
    for (const SurfaceFace *face : overlapping)
      {
        // The face within [begin, end], split at the vertices inside it.
        std::vector<double> cuts{std::max(face->r0, begin)};
        for (const double v : vertex_r)
          if (v > cuts.front() && v < std::min(face->r1, end))
            cuts.push_back(v);
        cuts.push_back(std::min(face->r1, end));
        const auto &dofs = face->dofs[c];
        for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece)
          {
            const double x0 = cuts[piece], x1 = cuts[piece + 1];
            const std::size_t j = interval(0.5 * (x0 + x1));
            const double      v0 = vertex_r[j], v1 = vertex_r[j + 1];
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double r = x0 + (x1 - x0) * quadrature.point(q)[0];
                const double w = quadrature.weight(q) * (x1 - x0) * r;
                const double t = (r - v0) / (v1 - v0);
                for (unsigned int i = 0; i < dofs.size(); ++i)
                  {
                    std::vector<double> unit(dofs.size(), 0.0);
                    unit[i]          = 1;
                    const double phi = lagrange(face->r, unit, r);
                    coupling.matrix(index[dofs[i]], j) += phi * (1 - t) * w;
                    coupling.matrix(index[dofs[i]], j + 1) += phi * t * w;
                  }
              }
          }
      }
    return coupling;
  }

  std::vector<double> recover_line_density(const std::vector<SurfaceFace> &faces, const unsigned int c,
                                           const Vector<double> &forces, const double edge,
                                           const unsigned int n_gauss, const std::size_t n_dofs)
  {
    const LineMass           mass = line_mass_matrix(faces, c, edge, n_gauss);
    const unsigned int       m    = mass.dofs.size();
    LAPACKFullMatrix<double> M(m, m);
    M = mass.matrix;
    Vector<double> p(m);
    for (unsigned int i = 0; i < m; ++i)
      p[i] = forces[mass.dofs[i]];
    M.compute_lu_factorization();
    M.solve(p);
    std::vector<double> nodal(n_dofs, 0.0);
    for (unsigned int i = 0; i < m; ++i)
      nodal[mass.dofs[i]] = p[i];
    return nodal;
  }
} // namespace gradcontact::fem
