#include <fem/base/boundary_ids.h>
#include <fem/base/errors.h>
#include <fem/grid/mesh_3d.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>
#include <cstdio>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    [[noreturn]] void fail(const std::string &what, const double value, const std::string &range)
    {
      fem::fail("HalfSpaceMesh3DParameters", what, value, range);
    }

    /// Relative tolerance (of a) for "this face centre lies on a plane".
    constexpr double on_plane = 1e-10;

    /// The distance of x from the contact circle r = a, z = 0.
    double distance_to_circle(const Point<3> &x, const double a)
    {
      const double rho = std::hypot(x[0], x[1]);
      return std::hypot(rho - a, x[2]);
    }

    MPI_Comm communicator_of(const Triangulation<3> &tria)
    {
      const auto *parallel = dynamic_cast<const parallel::TriangulationBase<3> *>(&tria);
      return parallel ? parallel->get_communicator() : MPI_COMM_SELF;
    }

    /// origin + t_j, t_j = first (1 + q + ... + q^(j-1)), while the step is below (g - 1) of the distance from 0,
    /// then growth by g to end (units of a); the number of those rings and their g into `info`.
    std::vector<double> graded_then_rings(const HalfSpaceMesh3DParameters &p, const double origin, const double first,
                                          const double end, HalfSpaceMesh3DInfo &info)
    {
      const double        q = p.edge_ratio;
      std::vector<double> x;
      double t = first, step = first;
      for (; origin + t < end && step < (p.ring_growth - 1) * (origin + t); step *= q, t += step)
        x.push_back(origin + t);
      const double last = x.empty() ? origin + first : x.back();
      if (x.empty())
        x.push_back(last);
      const unsigned int n =
        std::max(1, static_cast<int>(std::ceil(std::log(end / last) / std::log(p.ring_growth))));
      info.n_rings     = n;
      info.ring_growth = std::pow(end / last, 1.0 / n);
      for (unsigned int j = 1; j <= n; ++j)
        x.push_back(j == n ? end : last * std::pow(info.ring_growth, j));
      return x;
    }

    /// Radii of the rings in units of a: R0, the graded ones inside 1 (distances from the contact edge
    /// t_0 = 0, t_{j+1} = t_j + h_edge q^j), 1, the graded ones outside, then rings growing by g out to L.
    std::vector<double> ring_radii(const HalfSpaceMesh3DParameters &p, HalfSpaceMesh3DInfo &info)
    {
      const double        h = p.h_edge, q = p.edge_ratio;
      std::vector<double> inside; // 1 - t_j > R0, from the core outward
      // (with inner_ring_width: the steps stop growing at it, rings of that width down to the core)
      const auto next_step = [&](const double step) {
        return p.inner_ring_width > 0 ? std::min(step * q, std::max(p.inner_ring_width, h)) : step * q;
      };
      for (double t = h, step = h; 1 - t > p.core_radius + 0.5 * step; step = next_step(step), t += step)
        inside.push_back(1 - t);
      std::reverse(inside.begin(), inside.end());
      std::vector<double> radii{p.core_radius};
      radii.insert(radii.end(), inside.begin(), inside.end());
      radii.push_back(1.0);
      const std::vector<double> outside = graded_then_rings(p, 1.0, h, p.far_field_size, info);
      radii.insert(radii.end(), outside.begin(), outside.end());
      return radii;
    }

    /// Step 1 into `plane` (units of a). The core: the half square |x| <= s, 0 <= y <= s as an (n/2) x (n/4) grid
    /// of squares, n the number of sectors, and n cells between its perimeter and the arc at R0 (the layout of a
    /// hyper ball: no cell has a straight angle where an arc meets a straight edge). Then the rings:
    /// V(j, m) = R_j (cos m pi/n, sin m pi/n), m = 0..n, j = 0 the arc at R0.
    void half_disc(const HalfSpaceMesh3DParameters &p, const std::vector<double> &radii, Triangulation<2> &plane)
    {
      const unsigned int     n = p.sectors, nx = n / 2, ny = n / 4;
      const double           s_core = 0.45 * p.core_radius;
      std::vector<Point<2>>  vertices;
      const auto G = [&](const unsigned int i, const unsigned int j) { return j * (nx + 1) + i; };
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          vertices.emplace_back(-s_core + 2 * s_core * i / nx, s_core * j / ny);
      const unsigned int first_ring = vertices.size();
      for (const double R : radii)
        for (unsigned int m = 0; m <= n; ++m)
          {
            const double t = m * numbers::PI / n;
            // exact zeros on the axes, so that the boundary faces lie on the planes to round-off
            vertices.emplace_back(2 * m == n ? 0.0 : (m == n ? -R : R * std::cos(t)),
                                  (m == 0 || m == n) ? 0.0 : R * std::sin(t));
          }
      const auto V = [&](const unsigned int j, const unsigned int m) { return first_ring + j * (n + 1) + m; };
      // The perimeter of the half square, counter-clockwise from (s, 0): right side, top, left side.
      const auto P = [&](const unsigned int m) {
        if (m <= ny)
          return G(nx, m);
        if (m <= 3 * ny)
          return G(nx - (m - ny), ny);
        return G(0, ny - (m - 3 * ny));
      };

      std::vector<CellData<2>> cells;
      // In deal.II's vertex order (0,0), (1,0), (0,1), (1,1), every cell counter-clockwise.
      const auto add = [&](const unsigned int v0, const unsigned int v1, const unsigned int v2, const unsigned int v3,
                           const types::manifold_id id) {
        CellData<2> c;
        c.vertices    = {v0, v1, v2, v3};
        c.manifold_id = id;
        cells.push_back(c);
      };
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          add(G(i, j), G(i + 1, j), G(i, j + 1), G(i + 1, j + 1), numbers::flat_manifold_id);
      for (unsigned int m = 0; m < n; ++m)
        add(P(m), V(0, m), P(m + 1), V(0, m + 1), numbers::flat_manifold_id);
      for (unsigned int j = 1; j < radii.size(); ++j)
        for (unsigned int m = 0; m < n; ++m)
          add(V(j - 1, m), V(j, m), V(j - 1, m + 1), V(j, m + 1), cylindrical_manifold_id);
      plane.create_triangulation(vertices, cells, SubCellData());
      // The core's arcs at R0 lie on the cylinder: set on the faces shared with the first ring.
      for (const auto &cell : plane.active_cell_iterators())
        if (cell->manifold_id() == cylindrical_manifold_id)
          for (const unsigned int f : cell->face_indices())
            cell->face(f)->set_manifold_id(cylindrical_manifold_id);
    }

    /// Boundary ids from the face centres (the coarse faces lie exactly on their planes or cylinders): the contact
    /// disc and the free surface on z = 0, the symmetry plane y = 0, the far field (bottom and cylinder).
    void name_boundaries(const HalfSpaceMesh3DParameters &p, Triangulation<3> &coarse)
    {
      const double a = p.contact_radius;
      const double L = p.far_field_size * a;
      for (const auto &cell : coarse.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<3> c = cell->face(f)->center();
              if (std::abs(c[2]) < on_plane * a)
                {
                  // On the disc when every vertex is (the vertex average of a 45 degree face lies inside
                  // the circle through its vertices).
                  double outermost = 0;
                  for (const unsigned int v : cell->face(f)->vertex_indices())
                    outermost =
                      std::max(outermost, std::hypot(cell->face(f)->vertex(v)[0], cell->face(f)->vertex(v)[1]));
                  cell->face(f)->set_boundary_id(outermost <= (1 + on_plane) * a ? boundary_id::contact :
                                                                                   boundary_id::free_surface);
                }
              else if (std::abs(c[1]) < on_plane * a)
                cell->face(f)->set_boundary_id(boundary_id::symmetry_plane);
              else if (std::abs(c[2] - L) < on_plane * L ||
                       std::hypot(c[0], c[1]) > (1 - 1e-3) * L * std::cos(numbers::PI / (2 * p.sectors)))
                cell->face(f)->set_boundary_id(boundary_id::far_field);
              else
                AssertThrow(false, ExcMessage("make_coarse_mesh_3d: a boundary face at (" + std::to_string(c[0]) +
                                              ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
                                              ") lies on no named boundary"));
            }
    }
  } // namespace



  void HalfSpaceMesh3DParameters::validate() const
  {
    if (!(contact_radius > 0 && std::isfinite(contact_radius)))
      fail("contact_radius", contact_radius, "(0, inf)");
    if (!(core_radius > 0.1 && core_radius < 0.9))
      fail("core_radius", core_radius, "(0.1, 0.9) (R0 / a)");
    if (!(far_field_size >= 2 && far_field_size <= 1e8))
      fail("far_field_size", far_field_size, "[2, 1e8] (L / a)");
    if (!(ring_growth >= 1.1 && ring_growth <= 4))
      fail("ring_growth", ring_growth, "[1.1, 4]");
    if (!(h_edge >= 1e-8 && h_edge <= 0.25))
      fail("h_edge", h_edge, "[1e-8, 0.25] (/ a)");
    if (!(surface_layer_thickness == 0 || (surface_layer_thickness >= 1e-12 && surface_layer_thickness <= 0.25)))
      fail("surface_layer_thickness", surface_layer_thickness, "0 or [1e-12, 0.25] (/ a)");
    if (!(edge_ratio >= 1.2 && edge_ratio <= 4))
      fail("edge_ratio", edge_ratio, "[1.2, 4]");
    if (!(inner_ring_width == 0 || (inner_ring_width >= h_edge && inner_ring_width <= 0.25)))
      fail("inner_ring_width", inner_ring_width, "0 or [h_edge, 0.25] (/ a)");
    if (edge_refinements > 12)
      fail("edge_refinements", edge_refinements, "[0, 12]");
    if (!(edge_grading >= 0 && edge_grading <= 4))
      fail("edge_grading", edge_grading, "[0, 4]");
    if (sectors != 4 && sectors != 8 && sectors != 16 && sectors != 32)
      fail("sectors", sectors, "{4, 8, 16, 32}");
    if (contact_refinements > 6)
      fail("contact_refinements", contact_refinements, "[0, 6]");
    if (global_refinements > 3)
      fail("global_refinements", global_refinements, "[0, 3]");
  }



  HalfSpaceMesh3DInfo make_coarse_mesh_3d(const HalfSpaceMesh3DParameters &p, Triangulation<3> &tria)
  {
    p.validate();
    const double        a = p.contact_radius;
    HalfSpaceMesh3DInfo info;

    // The radii of the rings, then the depths of the slices: the graded ones from 0, then the same growth
    // (whose rings `info` reports).
    const std::vector<double> radii       = ring_radii(p, info);
    const double              first_slice = p.surface_layer_thickness > 0 ? p.surface_layer_thickness : p.h_edge;
    const std::vector<double> depths      = graded_then_rings(p, 0.0, first_slice, p.far_field_size, info);

    // Step 1: the half disc of the core and the rings.
    Triangulation<2> plane;
    half_disc(p, radii, plane);

    // Step 2: extrusion in z through the graded slices.
    std::vector<double> slices{0.0};
    for (const double z : depths)
      slices.push_back(z * a);
    // The plane is scaled by a before extrusion.
    GridTools::scale(a, plane);
    Triangulation<3> coarse;
    GridGenerator::extrude_triangulation(plane, slices, coarse, true);
    name_boundaries(p, coarse);

    // Step 3, on the caller's triangulation (a distributed one takes the serial coarse mesh by copy).
    tria.copy_triangulation(coarse);
    tria.set_manifold(cylindrical_manifold_id, CylindricalManifold<3>(2));
    info.coarse_cells = coarse.n_active_cells();
    return info;
  }



  void refine_mesh_3d(const HalfSpaceMesh3DParameters &p, Triangulation<3> &tria, HalfSpaceMesh3DInfo &info)
  {
    p.validate();
    const double a = p.contact_radius;
    const auto   refine_where = [&](const auto &rule) {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && rule(cell))
          cell->set_refine_flag();
      tria.execute_coarsening_and_refinement();
    };
    for (unsigned int i = 0; i < p.global_refinements; ++i)
      refine_where([](const auto &) { return true; });
    for (unsigned int i = 0; i < p.edge_refinements; ++i)
      refine_where([&](const auto &cell) {
        return distance_to_circle(cell->center(), a) <= (p.edge_grading + 0.5) * cell->diameter();
      });
    for (unsigned int i = 0; i < p.contact_refinements; ++i)
      refine_where([&](const auto &cell) {
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::contact)
            return true;
        return false;
      });

    double smallest = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && distance_to_circle(cell->center(), a) <= cell->diameter())
        smallest = std::min(smallest, cell->diameter() / a);
    info.min_edge_cell = Utilities::MPI::min(smallest, communicator_of(tria));
  }
} // namespace gradcontact::fem
