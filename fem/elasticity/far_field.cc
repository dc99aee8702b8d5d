#include <fem/base/boundary_ids.h>
#include <fem/elasticity/far_field.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    /// The doubling stops when the chain clamped at its far end is this close to the infinite one.
    constexpr double chain_tolerance = 1e-18;
    /// Relative distance of a support point from a polyline g^j P that counts as on it.
    constexpr double on_polyline = 1e-9;

    double polyline_radius(const Point<2> &p) { return std::max(p[0], p[1]); }

    using Dense = LAPACKFullMatrix<double>;

    /// M^{-1} R for a copy of M (LU).
    Dense solve(const Dense &M, const Dense &R)
    {
      Dense lu(M), x(R);
      lu.compute_lu_factorization();
      lu.solve(x);
      return x;
    }
  } // namespace



  FarFieldRings::FarFieldRings(const DoFHandler<2> &dof_handler_, const Mapping<2> &mapping,
                               const AffineConstraints<double> &constraints_, const MeshParameters &mesh,
                               const MeshInfo &info, const unsigned int pressure_component)
    : dof_handler(dof_handler_)
    , constraints(constraints_)
  {
    if (info.n_rings < 2)
      {
        std::ostringstream msg;
        msg << "FarFieldRings: MeshParameters::far_field_size = " << mesh.far_field_size << " gives " << info.n_rings
            << " far-field rings; the condensed far field needs at least 2 (L / a > near_field_size ring_growth = "
            << mesh.near_field_size * mesh.ring_growth << ")";
        throw std::invalid_argument(msg.str());
      }
    const double L = mesh.far_field_size * mesh.contact_radius, g = info.ring_growth;
    const std::array<double, 3> radius{{L / (g * g), L / g, L}};

    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    const FiniteElement<2>              &fe = dof_handler.get_fe();
    std::vector<unsigned int>            component(dof_handler.n_dofs(), 0);
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    std::array<std::set<types::global_dof_index>, 2> ring_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const double c = polyline_radius(cell->center());
        for (unsigned int i = 0; i < 2; ++i)
          if (c > radius[i] && c < radius[i + 1])
            {
              rings[i].cells.push_back(cell);
              cell->get_dof_indices(local);
              for (unsigned int l = 0; l < local.size(); ++l)
                {
                  component[local[l]] = fe.system_to_component_index(l).first;
                  ring_dofs[i].insert(local[l]);
                }
            }
      }

    for (unsigned int i = 0; i < 2; ++i)
      {
        if (rings[i].cells.empty())
          throw std::invalid_argument("FarFieldRings: no cells between max(r, z) = " + std::to_string(radius[i]) +
                                      " and " + std::to_string(radius[i + 1]) + " (not a mesh of fem/grid/mesh.h)");
        for (const auto d : ring_dofs[i])
          {
            if (constraints.is_constrained(d))
              {
                // u_r = 0 (mode 0) or W = 0 and V = U (mode 1) on the axis: the same relation in every ring,
                // applied when its matrix is assembled; a DoF tied to DoFs of another ring (a hanging node) is
                // refused.
                const auto *entries = constraints.get_constraint_entries(d);
                bool        local   = !constraints.is_inhomogeneously_constrained(d);
                if (entries)
                  for (const auto &[master, weight] : *entries)
                    local = local && ring_dofs[i].count(master) && !constraints.is_constrained(master);
                if (!local)
                  throw std::invalid_argument("FarFieldRings: DoF " + std::to_string(d) + " at (" +
                                              std::to_string(support[d][0]) + ", " + std::to_string(support[d][1]) +
                                              ") of a far-field ring is constrained to DoFs outside its ring "
                                              "(a hanging node) or inhomogeneously; the rings must be conforming");
                continue;
              }
            const double R = polyline_radius(support[d]);
            if (std::abs(R - radius[i]) <= on_polyline * radius[i])
              inner_port[i].push_back(d);
            else if (std::abs(R - radius[i + 1]) <= on_polyline * radius[i + 1])
              outer_port[i].push_back(d);
            else
              rings[i].interior.push_back(d);
          }
      }

    // Entry j of every port: the same DoF of the scaled polyline.
    const auto by_component_and_angle = [&](const types::global_dof_index x, const types::global_dof_index y) {
      if (component[x] != component[y])
        return component[x] < component[y];
      return std::atan2(support[x][1], support[x][0]) < std::atan2(support[y][1], support[y][0]);
    };
    for (unsigned int i = 0; i < 2; ++i)
      {
        std::sort(inner_port[i].begin(), inner_port[i].end(), by_component_and_angle);
        std::sort(outer_port[i].begin(), outer_port[i].end(), by_component_and_angle);
      }
    const std::array<const std::vector<types::global_dof_index> *, 4> ports{
      {&inner_port[0], &outer_port[0], &inner_port[1], &outer_port[1]}};
    const std::array<double, 4> port_radius{{radius[0], radius[1], radius[1], radius[2]}};
    for (unsigned int p = 1; p < 4; ++p)
      {
        bool same = ports[p]->size() == ports[0]->size();
        for (unsigned int j = 0; same && j < ports[0]->size(); ++j)
          {
            const auto x = (*ports[0])[j], y = (*ports[p])[j];
            same = component[x] == component[y] &&
                   (support[y] / port_radius[p] - support[x] / port_radius[0]).norm() <= 1e3 * on_polyline;
          }
        if (!same)
          throw std::invalid_argument("FarFieldRings: the DoFs on max(r, z) = " + std::to_string(port_radius[p]) +
                                      " are no scaled copy of those on max(r, z) = " + std::to_string(radius[0]) +
                                      " (the last rings of the mesh are not self-similar)");
      }
    check_truncation_boundary();
    pressure_entry.resize(outer_port[1].size());
    for (std::size_t j = 0; j < outer_port[1].size(); ++j)
      pressure_entry[j] = component[outer_port[1][j]] == pressure_component;
    if (rings[0].interior.size() != rings[1].interior.size())
      throw std::invalid_argument("FarFieldRings: the last two rings differ in their interior DoFs (" +
                                  std::to_string(rings[0].interior.size()) + " and " +
                                  std::to_string(rings[1].interior.size()) + ")");
  }



  void FarFieldRings::check_truncation_boundary() const
  {
    // The outer port found by geometry is the truncation boundary of the mesh (boundary id far_field).
    std::set<types::global_dof_index>    truncation;
    std::vector<types::global_dof_index> face_dofs(dof_handler.get_fe().n_dofs_per_face());
    for (const auto &cell : rings[1].cells)
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::far_field)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (const auto d : face_dofs)
              if (!constraints.is_constrained(d))
                truncation.insert(d);
          }
    if (truncation != std::set<types::global_dof_index>(outer_port[1].begin(), outer_port[1].end()))
      throw std::invalid_argument("FarFieldRings: the " + std::to_string(outer_port[1].size()) +
                                  " DoFs on max(r, z) = L are not the " + std::to_string(truncation.size()) +
                                  " free DoFs of the far_field boundary (not a mesh of fem/grid/mesh.h)");
  }



  FullMatrix<double> FarFieldRings::two_port(const unsigned int i, const CellMatrix &cell_matrix) const
  {
    const unsigned int n = inner_port[i].size(), m = rings[i].interior.size();
    std::map<types::global_dof_index, unsigned int> index;
    for (unsigned int j = 0; j < n; ++j)
      {
        index[inner_port[i][j]] = j;
        index[outer_port[i][j]] = n + j;
      }
    for (unsigned int j = 0; j < m; ++j)
      index[rings[i].interior[j]] = 2 * n + j;

    Dense                                K(2 * n + m, 2 * n + m);
    std::vector<types::global_dof_index> local(dof_handler.get_fe().n_dofs_per_cell());
    // Each cell DoF as a combination of ring unknowns: itself, its masters (constrained), or none (zero).
    std::vector<std::vector<std::pair<unsigned int, double>>> to(local.size());
    for (const auto &cell : rings[i].cells)
      {
        cell->get_dof_indices(local);
        for (unsigned int l = 0; l < local.size(); ++l)
          {
            to[l].clear();
            if (!constraints.is_constrained(local[l]))
              to[l].emplace_back(index.at(local[l]), 1.0);
            else if (const auto *entries = constraints.get_constraint_entries(local[l]))
              for (const auto &[master, weight] : *entries)
                to[l].emplace_back(index.at(master), weight);
          }
        const FullMatrix<double> &Kc = cell_matrix(cell);
        for (unsigned int p = 0; p < local.size(); ++p)
          for (const auto &[P, wp] : to[p])
            for (unsigned int q = 0; q < local.size(); ++q)
              for (const auto &[Q, wq] : to[q])
                K(P, Q) += wp * wq * Kc(p, q);
      }

    // T = K_PP - K_PI K_II^{-1} K_IP over the 2n port DoFs (degree 1: no interior DoFs).
    FullMatrix<double> T(2 * n, 2 * n);
    if (m == 0)
      {
        for (unsigned int r = 0; r < 2 * n; ++r)
          for (unsigned int c = 0; c < 2 * n; ++c)
            T(r, c) = K(r, c);
        return T;
      }
    Dense Kii(m, m), Kip(m, 2 * n);
    for (unsigned int r = 0; r < m; ++r)
      {
        for (unsigned int c = 0; c < m; ++c)
          Kii(r, c) = K(2 * n + r, 2 * n + c);
        for (unsigned int c = 0; c < 2 * n; ++c)
          Kip(r, c) = K(2 * n + r, c);
      }
    const Dense X = solve(Kii, Kip);
    for (unsigned int r = 0; r < 2 * n; ++r)
      for (unsigned int c = 0; c < 2 * n; ++c)
        {
          double t = K(r, c);
          for (unsigned int l = 0; l < m; ++l)
            t -= Kip(l, r) * X(l, c);
          T(r, c) = t;
        }
    return T;
  }



  std::pair<double, double> FarFieldRings::fit_ring_scale(const FullMatrix<double> &T0, const FullMatrix<double> &T1) const
  {
    // sigma: least squares of T1 onto T0 over the displacement entries; mu: of T1 onto sigma T0 over the
    // displacement-pressure entries (mu = g^(1 - s) for q, g for q / E; fem/elasticity/graded_elasticity.h).
    const unsigned int n = T0.m() / 2;
    double             uu01 = 0, uu00 = 0, up01 = 0, up00 = 0;
    for (unsigned int r = 0; r < T0.m(); ++r)
      for (unsigned int c = 0; c < T0.n(); ++c)
        {
          const unsigned int pressures = pressure_entry[r % n] + pressure_entry[c % n];
          if (pressures == 0)
            uu01 += T1(r, c) * T0(r, c), uu00 += T0(r, c) * T0(r, c);
          else if (pressures == 1)
            up01 += T1(r, c) * T0(r, c), up00 += T0(r, c) * T0(r, c);
        }
    const double sigma = uu01 / uu00;
    return {sigma, up00 > 0 ? up01 / (sigma * up00) : 1.0};
  }



  Exterior FarFieldRings::condense(const CellMatrix &cell_matrix) const
  {
    const FullMatrix<double> T0 = two_port(0, cell_matrix), T1 = two_port(1, cell_matrix);
    const unsigned int       n  = T1.m() / 2;
    Exterior                 exterior;
    std::tie(exterior.ring_scale, exterior.pressure_scale) = fit_ring_scale(T0, T1);
    const double sigma = exterior.ring_scale, mu = exterior.pressure_scale;
    // The factor of port entry j when a ring is scaled by one ring (D of the header).
    const auto factor = [&](const unsigned int j, const double pressure_factor) {
      return pressure_entry[j % n] ? pressure_factor : 1.0;
    };
    double deviation = 0, norm = 0;
    for (unsigned int r = 0; r < T0.m(); ++r)
      for (unsigned int c = 0; c < T0.n(); ++c)
        {
          deviation += std::pow(T1(r, c) - sigma * factor(r, mu) * factor(c, mu) * T0(r, c), 2);
          norm += T1(r, c) * T1(r, c);
        }
    exterior.self_similarity = std::sqrt(deviation / norm);
    std::ostringstream why;
    why.precision(3);
    if (!(exterior.self_similarity <= self_similarity_tolerance))
      why << "the last two far-field rings are no scaled copies of each other: relative deviation "
          << exterior.self_similarity << " > " << self_similarity_tolerance
          << " (a modulus that is no power law of depth at max(r, z) = L, or a surface map not yet homogeneous there)";
    else if (!(sigma > 1 + 1e-9))
      why << "the stiffness of consecutive far-field rings grows by " << sigma
          << " <= 1: the exterior of a modulus E ~ z^s with s <= -1 is not bounded";
    if (!why.str().empty())
      throw std::runtime_error("FarFieldRings::condense: " + why.str());

    // The first exterior ring is sigma D T1 D. A chain of N rings is kept with its far port in the units of its
    // last ring (its DoFs times D^N): then the copy of a chain scaled by g^N is `scale` (sigma^N) times the chain,
    // D cancels from the doubling, and no power of mu (g^(1 - s) per ring, thousands of rings near s = -1) is
    // ever formed. The near port stays in the mesh's units, and its block is S.
    Dense A(n, n), B(n, n), C(n, n);
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = 0; c < n; ++c)
        {
          A(r, c) = sigma * factor(r, mu) * factor(c, mu) * T1(r, c);
          B(r, c) = sigma * factor(r, mu) * T1(r, n + c);
          C(r, c) = sigma * T1(n + r, n + c);
        }
    double scale = sigma; // of the next chain against this one: sigma^N
    while (1 / scale > chain_tolerance)
      {
        if (exterior.doublings == 64)
          throw std::runtime_error("FarFieldRings::condense: the chain of 2^64 rings still has a truncation factor " +
                                   std::to_string(1 / scale));
        Dense M(C), R(n, 2 * n);
        M.add(scale, A);
        for (unsigned int r = 0; r < n; ++r)
          for (unsigned int c = 0; c < n; ++c)
            {
              R(r, c)     = B(c, r); // B^T
              R(r, n + c) = B(r, c);
            }
        const Dense X = solve(M, R); // [M^{-1} B^T | M^{-1} B], one factorisation
        Dense       P(n, n), Q(n, n), BP(n, n), BQ(n, n), BtQ(n, n);
        for (unsigned int r = 0; r < n; ++r)
          for (unsigned int c = 0; c < n; ++c)
            {
              P(r, c) = X(r, c);
              Q(r, c) = X(r, n + c);
            }
        B.mmult(BP, P);
        B.mmult(BQ, Q);
        B.Tmmult(BtQ, Q);
        A.add(-1.0, BP);
        B = BQ;
        B *= -scale;
        C *= scale;
        C.add(-scale * scale, BtQ);
        scale *= scale;
        ++exterior.doublings;
      }
    exterior.chain_error = 1 / scale;

    exterior.dofs = outer_port[1];
    exterior.stiffness.reinit(n, n);
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int c = 0; c < n; ++c)
        exterior.stiffness(r, c) = 0.5 * (A(r, c) + A(c, r));
    return exterior;
  }



  void record_far_field(const Exterior &exterior, RunReport &report)
  {
    report.far_field_ring_scale      = exterior.ring_scale;
    report.far_field_self_similarity = exterior.self_similarity;
    report.far_field_doublings       = exterior.doublings;
  }
} // namespace gradcontact::fem
