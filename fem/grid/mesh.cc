#include <fem/base/errors.h>
#include <fem/base/boundary_ids.h>
#include <fem/grid/mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#ifndef GRADCONTACT_MESH_DIR
#  define GRADCONTACT_MESH_DIR "meshes"
#endif
#ifndef GRADCONTACT_DEFAULT_MESH_CACHE
#  define GRADCONTACT_DEFAULT_MESH_CACHE "mesh-cache"
#endif

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    // Relative tolerance for "this vertex is on z = 0 / at the contact edge". Vertices there are exact
    // (gmsh writes the geometry points, refinement takes midpoints), so this only absorbs round-off.
    constexpr double on_line_tolerance = 1e-12;
    // Largest ratio of neighbouring cell sizes in the deal.II near field.
    constexpr double max_growth = 1.5;
    // Safety stop of the halving loop: 2^-200 is far below any sensible surface_layer_thickness.
    constexpr unsigned int max_halving_sweeps = 200;

    [[noreturn]] void fail(const std::string &what, const double value, const std::string &range)
    {
      fem::fail("MeshParameters", what, value, range);
    }

    std::string read_file(const std::string &path)
    {
      std::ifstream in(path);
      if (!in)
        throw std::runtime_error("make_mesh: cannot read " + path);
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }

    /// Steps covering [0, length] that grow geometrically (<= max_growth) from h_fine at the start to
    /// at most h_coarse, scaled to sum exactly to length.
    std::vector<double> graded_steps(const double length, const double h_fine, const double h_coarse)
    {
      std::vector<double> steps;
      double              h = h_fine, sum = 0.0;
      while (sum < length)
        {
          steps.push_back(h);
          sum += h;
          h = std::min(h * max_growth, h_coarse);
        }
      for (double &s : steps)
        s *= length / sum;
      return steps;
    }

    /// The gmsh cell size at (R1 a, 0) / a.
    double outer_size(const MeshParameters &p)
    {
      return p.h_surface_outer > 0 ? p.h_surface_outer : p.h_surface;
    }

    /// Step 1 with deal.II: tensor-product grid, r graded toward 1 from both sides, z toward 0.
    void deal_ii_near_field(const MeshParameters &p, Triangulation<2> &tria)
    {
      const double R1 = p.near_field_size;
      std::vector<double> inside = graded_steps(1.0, p.h_edge, p.h_surface); // from r = 1 toward 0
      std::reverse(inside.begin(), inside.end());
      const std::vector<double> outside = graded_steps(R1 - 1.0, p.h_edge, p.h_far);
      std::vector<std::vector<double>> steps(2);
      steps[0] = inside;
      steps[0].insert(steps[0].end(), outside.begin(), outside.end());
      steps[1] = graded_steps(R1, p.h_edge, p.h_far);
      GridGenerator::subdivided_hyper_rectangle(tria, steps, Point<2>(0, 0), Point<2>(R1, R1));

      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const Point<2> c = cell->face(f)->center();
              if (std::abs(c[1]) < on_line_tolerance)
                cell->face(f)->set_boundary_id(c[0] < 1.0 ? boundary_id::contact :
                                                            boundary_id::free_surface);
              else if (std::abs(c[0]) < on_line_tolerance)
                cell->face(f)->set_boundary_id(boundary_id::axis);
              else
                cell->face(f)->set_boundary_id(boundary_id::far_field);
            }
    }

    /// gmsh returns collapsed quads where the grading is too steep: h_edge = 1e-6 with h_surface = 0.5
    /// yields cells of zero area at (a, 0) and a singular matrix in UMFPACK (h_edge = 1e-6 with
    /// h_surface = 0.25, and 1e-7 with 0.25, are fine; test_contact.cc, "A near-field mesh that gmsh
    /// collapses ..."). Such a mesh is refused here: a cell whose
    /// bilinear map has a corner Jacobian <= 1e-12 of its largest is degenerate or inverted.
    void check_cells(const Triangulation<2> &tria, const MeshParameters &p)
    {
      unsigned int bad = 0;
      Point<2>     first;
      for (const auto &cell : tria.active_cell_iterators())
        {
          // deal.II's vertex order: 0 (0,0), 1 (1,0), 2 (0,1), 3 (1,1); at each corner the cross product
          // of the two edges leaving it, counter-clockwise.
          const auto cross = [&](const unsigned int o, const unsigned int a, const unsigned int b) {
            const Tensor<1, 2> u = cell->vertex(a) - cell->vertex(o), v = cell->vertex(b) - cell->vertex(o);
            return u[0] * v[1] - u[1] * v[0];
          };
          const double j[4] = {cross(0, 1, 2), cross(1, 3, 0), cross(3, 2, 1), cross(2, 0, 3)};
          const double largest = std::max({std::abs(j[0]), std::abs(j[1]), std::abs(j[2]), std::abs(j[3])});
          if (!(std::min({j[0], j[1], j[2], j[3]}) > 1e-12 * largest))
            if (bad++ == 0)
              first = cell->center();
        }
      if (bad > 0)
        {
          std::ostringstream msg;
          msg << "make_mesh: gmsh made " << bad << " degenerate or inverted cells (the first at (r, z) / a = ("
              << first[0] << ", " << first[1] << ")) from h_edge = " << p.h_edge << " and h_surface = "
              << p.h_surface << " (ratio " << p.h_surface / p.h_edge
              << "): this grading is too steep for gmsh; raise h_edge or lower h_surface (h_surface = 0.25 "
                 "works with h_edge down to 1e-7), or use NearFieldMesher::deal_ii";
          throw std::invalid_argument(msg.str());
        }
    }

    /// Step 1 with gmsh, cached by the .geo text and its parameters.
    MeshInfo gmsh_near_field(const MeshParameters &p, Triangulation<2> &tria)
    {
      namespace fs = std::filesystem;
      const std::string geo = p.geo_file.empty() ? std::string(GRADCONTACT_MESH_DIR) + "/near_field.geo" :
                                                   p.geo_file;
      std::string cache = p.cache_directory;
      if (cache.empty())
        {
          const char *env = std::getenv("GRADCONTACT_MESH_CACHE");
          cache           = env ? env : GRADCONTACT_DEFAULT_MESH_CACHE;
        }
      fs::create_directories(cache);

      std::ostringstream key;
      key.precision(17);
      key << "geo=" << std::hash<std::string>{}(read_file(geo)) << " R1=" << p.near_field_size
          << " h_edge=" << p.h_edge << " h_surface=" << p.h_surface << " h_far=" << p.h_far
          << " h_outer=" << outer_size(p) << '\n';
      std::ostringstream name;
      name << "near_field_" << std::hex << std::hash<std::string>{}(key.str());
      const fs::path msh     = fs::path(cache) / (name.str() + ".msh");
      const fs::path keyfile = fs::path(cache) / (name.str() + ".key");

      // The key file holds the key and the size and hash of the .msh it was written with: a cached mesh
      // that was truncated (a full disk) or changed after (a copy) fails the check and is made again.
      const auto checksum = [](const std::string &text) {
        std::ostringstream c;
        c << "msh_bytes=" << text.size() << " msh_hash=" << std::hex << std::hash<std::string>{}(text) << '\n';
        return c.str();
      };
      MeshInfo info;
      info.near_field_source = msh.string();
      info.cache_hit = fs::exists(msh) && fs::exists(keyfile) &&
                       read_file(keyfile.string()) == key.str() + checksum(read_file(msh.string()));
      if (!info.cache_hit)
        {
          // Write to a private name and rename: a concurrent or interrupted run never sees half a file.
          const std::string tmp = msh.string() + ".tmp" + std::to_string(::getpid());
          const std::string log = tmp + ".log";
          std::ostringstream cmd;
          cmd.precision(17);
          cmd << p.gmsh_executable << " -2 -v 2 -format msh22"
              << " -setnumber R1 " << p.near_field_size << " -setnumber h_edge " << p.h_edge
              << " -setnumber h_surface " << p.h_surface << " -setnumber h_far " << p.h_far
              << " -setnumber h_outer " << outer_size(p) << " '"
              << geo << "' -o '" << tmp << "' > '" << log << "' 2>&1";
          const int rc = std::system(cmd.str().c_str());
          if (rc != 0 || !fs::exists(tmp))
            {
              std::string out = fs::exists(log) ? read_file(log) : std::string("(no log)");
              if (out.size() > 2000)
                out = out.substr(out.size() - 2000);
              fs::remove(tmp);
              throw std::runtime_error("make_mesh: gmsh could not mesh " + geo + " (exit code " +
                                       std::to_string(rc) + ", command: " + cmd.str() + "):\n" + out);
            }
          fs::remove(log);
          const std::string key_tmp = keyfile.string() + ".tmp" + std::to_string(::getpid());
          std::ofstream(key_tmp) << key.str() << checksum(read_file(tmp));
          fs::rename(tmp, msh);
          fs::rename(key_tmp, keyfile);
        }

      GridIn<2> grid_in;
      grid_in.attach_triangulation(tria);
      std::ifstream in(msh);
      grid_in.read_msh(in);
      check_cells(tria, p);
      return info;
    }

    /// The cells of the near field `near` into `cells` and its boundary lines into `boundary` (the far-field ones
    /// too), with the adjacency of the far-field lines' vertices; std::runtime_error for a boundary face without a
    /// physical group.
    void copy_near_field(const Triangulation<2> &near, std::vector<CellData<2>> &cells, SubCellData &boundary,
                         std::map<unsigned int, std::vector<unsigned int>> &far_neighbours)
    {
      for (const auto &cell : near.active_cell_iterators())
        {
          CellData<2> c;
          for (const unsigned int v : cell->vertex_indices())
            c.vertices[v] = cell->vertex_index(v);
          c.material_id = 0;
          cells.push_back(c);
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const unsigned int v0 = cell->face(f)->vertex_index(0),
                                   v1 = cell->face(f)->vertex_index(1);
                const types::boundary_id id = cell->face(f)->boundary_id();
                if (id == boundary_id::unassigned)
                  throw std::runtime_error("make_mesh: near-field boundary face at " +
                                           std::to_string(cell->face(f)->center()[0]) + ", " +
                                           std::to_string(cell->face(f)->center()[1]) +
                                           " carries no physical group");
                if (id == boundary_id::far_field)
                  {
                    far_neighbours[v0].push_back(v1);
                    far_neighbours[v1].push_back(v0);
                  }
                CellData<1> line;
                line.vertices[0] = v0;
                line.vertices[1] = v1;
                line.boundary_id = id;
                boundary.boundary_lines.push_back(line);
              }
        }
    }

    /// The far-field chain of the near field (radius R1 / a) ordered from its end on the surface (z = 0) to its
    /// end on the axis.
    std::vector<unsigned int> far_field_chain(std::map<unsigned int, std::vector<unsigned int>> &far_neighbours,
                                              const std::vector<Point<2>> &vertices, const double R1)
    {
      unsigned int start = numbers::invalid_unsigned_int;
      for (const auto &[v, nb] : far_neighbours)
        if (nb.size() == 1 && std::abs(vertices[v][1]) < on_line_tolerance * R1)
          start = v;
      AssertThrow(start != numbers::invalid_unsigned_int,
                  ExcMessage("make_mesh: far-field boundary of the near field has no end on z = 0"));
      std::vector<unsigned int> chain{start};
      while (true)
        {
          const auto &nb   = far_neighbours[chain.back()];
          unsigned int next = numbers::invalid_unsigned_int;
          for (const unsigned int v : nb)
            if (chain.size() < 2 || v != chain[chain.size() - 2])
              next = v;
          if (next == numbers::invalid_unsigned_int)
            break;
          chain.push_back(next);
        }
      AssertThrow(std::abs(vertices[chain.back()][0]) < on_line_tolerance * R1,
                  ExcMessage("make_mesh: far-field chain does not end on the axis"));
      return chain;
    }

    /// One ring of quads between the vertices `inner` and `outer` of the chain, in deal.II's lexicographic order
    /// 0 = (inner i), 1 = (inner i+1), 2 = (outer i), 3 = (outer i+1), flipped along the chain where that gives a
    /// negative Jacobian; and the ring's boundary lines on z = 0 (first chain vertex) and on the axis (last one).
    void add_ring(const std::vector<unsigned int> &inner, const std::vector<unsigned int> &outer,
                  const std::vector<Point<2>> &vertices, std::vector<CellData<2>> &cells, SubCellData &boundary)
    {
      for (unsigned int i = 0; i + 1 < inner.size(); ++i)
        {
          CellData<2> c;
          unsigned int a0 = inner[i], a1 = inner[i + 1], b0 = outer[i], b1 = outer[i + 1];
          const Tensor<1, 2> e1 = vertices[a1] - vertices[a0], e2 = vertices[b0] - vertices[a0];
          if (e1[0] * e2[1] - e1[1] * e2[0] < 0)
            {
              std::swap(a0, a1);
              std::swap(b0, b1);
            }
          c.vertices[0] = a0;
          c.vertices[1] = a1;
          c.vertices[2] = b0;
          c.vertices[3] = b1;
          c.material_id = 0;
          cells.push_back(c);
        }
      CellData<1> surface, axis;
      surface.vertices[0] = inner.front();
      surface.vertices[1] = outer.front();
      surface.boundary_id = boundary_id::free_surface;
      axis.vertices[0]    = inner.back();
      axis.vertices[1]    = outer.back();
      axis.boundary_id    = boundary_id::axis;
      boundary.boundary_lines.push_back(surface);
      boundary.boundary_lines.push_back(axis);
    }

    /// The n rings out to L / a scaled from the far-field chain of the near field (radius R1 / a, ring j at
    /// growth^j, the last at L / R1 exactly), whose lines become interior; the outermost chain is the far field.
    void add_rings(const std::vector<unsigned int> &chain, const unsigned int n, const double growth, const double R1,
                   const double L, std::vector<Point<2>> &vertices, std::vector<CellData<2>> &cells,
                   SubCellData &boundary)
    {
      // Drop the near field's far-field lines: they are interior now.
      boundary.boundary_lines.erase(
        std::remove_if(boundary.boundary_lines.begin(), boundary.boundary_lines.end(),
                       [](const CellData<1> &l) { return l.boundary_id == boundary_id::far_field; }),
        boundary.boundary_lines.end());

      std::vector<unsigned int> inner = chain;
      for (unsigned int j = 1; j <= n; ++j)
        {
          const double scale = (j == n) ? L / R1 : std::pow(growth, j);
          std::vector<unsigned int> outer;
          for (const unsigned int v : chain)
            {
              outer.push_back(vertices.size());
              vertices.push_back(Point<2>(vertices[v][0] * scale, vertices[v][1] * scale));
            }
          add_ring(inner, outer, vertices, cells, boundary);
          inner = outer;
        }
      for (unsigned int i = 0; i + 1 < inner.size(); ++i)
        {
          CellData<1> far;
          far.vertices[0] = inner[i];
          far.vertices[1] = inner[i + 1];
          far.boundary_id = boundary_id::far_field;
          boundary.boundary_lines.push_back(far);
        }
    }

    /// Step 2: the near field (units of a) plus n rings of quads out to L / a, into `tria`.
    void attach_far_field(const Triangulation<2> &near, const MeshParameters &p, MeshInfo &info,
                          Triangulation<2> &tria)
    {
      std::vector<Point<2>>       vertices = near.get_vertices();
      std::vector<CellData<2>>    cells;
      SubCellData                 boundary;
      std::map<unsigned int, std::vector<unsigned int>> far_neighbours; // far-field chain adjacency
      copy_near_field(near, cells, boundary, far_neighbours);

      const double R1       = p.near_field_size;
      const double L        = p.far_field_size;
      const unsigned int n  = (L > R1 * (1 + on_line_tolerance)) ?
                                static_cast<unsigned int>(std::ceil(std::log(L / R1) / std::log(p.ring_growth))) :
                                0;
      info.n_rings     = n;
      info.ring_growth = n > 0 ? std::pow(L / R1, 1.0 / n) : 1.0;
      if (n > 0)
        add_rings(far_field_chain(far_neighbours, vertices, R1), n, info.ring_growth, R1, L, vertices, cells,
                  boundary);

      GridTools::consistently_order_cells(cells);
      tria.create_triangulation(vertices, cells, boundary);

      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary() && face->boundary_id() == boundary_id::unassigned)
          throw std::runtime_error("make_mesh: boundary face at r = " + std::to_string(face->center()[0]) +
                                   ", z = " + std::to_string(face->center()[1]) + " has no boundary id");
    }
  } // namespace



  void MeshParameters::validate() const
  {
    if (!(contact_radius > 0) || !std::isfinite(contact_radius))
      fail("contact_radius", contact_radius, "(0, inf)");
    if (!(near_field_size >= 1.5))
      fail("near_field_size", near_field_size, "[1.5, inf) (R1 / a)");
    if (!(h_edge > 0 && h_edge <= h_surface))
      fail("h_edge", h_edge, "(0, h_surface]");
    if (axis_refinements > 40)
      fail("axis_refinements", axis_refinements, "[0, 40]");
    if (!(axis_grading >= 0 && axis_grading <= 10))
      fail("axis_grading", axis_grading, "[0, 10]");
    if (!(h_surface > 0 && h_surface <= 1.0))
      fail("h_surface", h_surface, "(0, 1]");
    if (!(h_far >= h_surface && h_far <= near_field_size))
      fail("h_far", h_far, "[h_surface, near_field_size]");
    if (!(h_surface_outer == 0 || (h_surface_outer >= h_surface && h_surface_outer <= h_far)))
      fail("h_surface_outer", h_surface_outer, "0 (= h_surface) or [h_surface, h_far]");
    if (!(far_field_size >= near_field_size && far_field_size <= 1e16))
      fail("far_field_size", far_field_size, "[near_field_size, 1e16] (L / a)");
    if (!(ring_growth > 1.05 && ring_growth <= 4.0))
      fail("ring_growth", ring_growth, "(1.05, 4]");
    if (!(surface_layer_thickness >= 1e-12 && surface_layer_thickness <= 1.0))
      fail("surface_layer_thickness", surface_layer_thickness, "[1e-12, 1] (/ a)");
    if (!(halving_radius >= 0 && halving_radius <= near_field_size))
      fail("halving_radius", halving_radius, "[0, near_field_size]");
    if (edge_refinements > 40)
      fail("edge_refinements", edge_refinements, "[0, 40]");
    if (global_refinements > 6)
      fail("global_refinements", global_refinements, "[0, 6]");
  }



  MeshParameters recommended_mesh_parameters(const double contact_radius, const double s,
                                             const double truncation_tolerance)
  {
    // The truncation constant C of the flat-punch force error C (a/L)^{1+k}, fitted per k from two L
    // (`build/cases/tools/studies/fem_study load=punch L=...`); it falls as k grows, and its largest, at k = -0.5,
    // is used for any s.
    constexpr double truncation_constant = 1.1;
    constexpr double min_far_field = 1e4, max_far_field = 1e16;
    // Thinnest surface layer for s > 0: the error of u_z ~ z^{1-s} falls like t^{1-s}.
    constexpr double singular_surface_layer = 1e-10;
    // For s < 0 the stresses sigma_rr ~ E eps_rr blow up at the surface: a graded layer to 1e-4 a
    // resolves the pressure near the axis; thinner than 1e-7 a the solve becomes garbage (the
    // energy-mismatch check, energy_mismatch_tolerance, flags it, and the mismatch grows as the layer thins).
    constexpr double stiff_surface_layer = 1e-4;
    // s = 1: the Gibson medium (9.42), solved by the mixed formulation only (Material::validate).
    if (!(s > -1 && s <= 1))
      fail("surface_exponent", s, "(-1, 1]");
    if (!(truncation_tolerance > 0 && truncation_tolerance < 1))
      fail("truncation_tolerance", truncation_tolerance, "(0, 1)");
    MeshParameters p;
    p.contact_radius = contact_radius;
    p.far_field_size = std::clamp(std::pow(truncation_constant / truncation_tolerance, 1 / (1 + s)),
                                  min_far_field, max_far_field);
    // s = 1 (Gibson, nu = 1/2): the displacement is regular at z = 0 (w = p / k_W), so a thin surface layer
    // does not improve the constant-pressure w (test_mixed.cc, the Winkler response of the Gibson medium;
    // `fem_study load=pressure k=1 nu=0.5 formulation=mixed layer=...` compares).
    p.surface_layer_thickness =
      (s >= 1) ? 1.0 : (s > 0) ? singular_surface_layer : (s < 0) ? stiff_surface_layer : 1.0;
    p.validate();
    return p;
  }



  MeshInfo make_near_field(const MeshParameters &p, Triangulation<2> &near)
  {
    p.validate();
    if (p.mesher == NearFieldMesher::gmsh)
      return gmsh_near_field(p, near);
    deal_ii_near_field(p, near);
    MeshInfo info;
    info.near_field_source = "deal.II";
    return info;
  }



  MeshInfo make_coarse_mesh(const MeshParameters &p, Triangulation<2> &tria)
  {
    AssertThrow(tria.n_cells() == 0, ExcMessage("make_coarse_mesh: the triangulation must be empty"));
    Triangulation<2> near;
    MeshInfo         info = make_near_field(p, near);
    attach_far_field(near, p, info, tria);
    GridTools::scale(p.contact_radius, tria);
    return info;
  }



  MeshInfo make_mesh(const MeshParameters &p, Triangulation<2> &tria)
  {
    MeshInfo info = make_coarse_mesh(p, tria);
    refine_mesh(p, tria, info);
    return info;
  }



  void refine_mesh(const MeshParameters &p, Triangulation<2> &tria, MeshInfo &info)
  {
    // On a distributed triangulation every process flags its own cells by the same geometric rule,
    // so the refined mesh does not depend on the partition; the flags of other cells are ignored.
    const auto *distributed = dynamic_cast<const parallel::distributed::Triangulation<2> *>(&tria);
    auto       global_or    = [&](const bool local) {
      return distributed ? Utilities::MPI::max(static_cast<int>(local), tria.get_communicator()) != 0 :
                                    local;
    };
    const double a = p.contact_radius;

    // Step 3a: isotropic refinement of the cells at the contact edge (a, 0).
    const Point<2> edge(a, 0.0);
    for (unsigned int cycle = 0; cycle < p.edge_refinements; ++cycle)
      {
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->is_locally_owned() && cell->vertex(v).distance(edge) < on_line_tolerance * a)
              cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }

    // Step 3a': the same at the surface point of the axis (0, 0), where the pressure of a cone (and of
    // f ~ r^n, n < 2) is singular.
    const Point<2> centre(0.0, 0.0);
    for (unsigned int cycle = 0; cycle < p.axis_refinements; ++cycle)
      {
        // A cell is refined when its centre lies within axis_grading diameters of (0, 0): the cells
        // end up about 1 / axis_grading of their distance from the singular point (a geometric mesh
        // toward it), not only the one corner cell (which leaves the cone's pressure, singular at the
        // apex, far less accurate than elsewhere).
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (cell->center().norm() < p.axis_grading * cell->diameter() ||
               std::any_of(cell->vertex_indices().begin(), cell->vertex_indices().end(),
                           [&](const unsigned int v) {
                             return cell->vertex(v).distance(centre) < on_line_tolerance * a;
                           })))
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }

    // Uniform refinements (h-studies) after the local ones, so that the meshes of a study are nested
    // and keep the edge and axis grading of level 0 (refined before them, the axis grading of a cone
    // covered 3 coarse cell diameters at level 0 but 1.5 at level 1, and the depth error of the cone
    // was not monotone over the levels).
    tria.refine_global(p.global_refinements);

    // Step 3b: halve the surface cells under r <= halving_radius a parallel to the surface until they
    // are at most surface_layer_thickness a thick. The refinement case that halves the distance to
    // face f is cut_x for faces 0, 1 and cut_y for faces 2, 3.
    const double r_max = p.halving_radius * a * (1 + on_line_tolerance);
    const double t_max = p.surface_layer_thickness * a * (1 + on_line_tolerance);
    for (unsigned int sweep = 0; sweep < max_halving_sweeps; ++sweep)
      {
        bool flagged = false;
        double thickest = 0;
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()) &&
                  cell->face(f)->center()[0] <= r_max && cell->extent_in_direction(f / 2) > t_max)
                {
                  thickest = std::max(thickest, cell->extent_in_direction(f / 2) / a);
                  if (!distributed)
                    cell->set_refine_flag(f < 2 ? RefinementCase<2>::cut_x : RefinementCase<2>::cut_y);
                  flagged = true;
                }
        if (!global_or(flagged))
          break;
        // p4est refines isotropically only; isotropic halvings down to 1e-10 a would multiply the
        // cells along the surface by 2^33. Every process throws (the decision above is collective).
        if (distributed)
          fail("surface_layer_thickness (distributed triangulation: z-only halvings are anisotropic "
               "refinement, which p4est does not support; the surface cells are up to " +
                 std::to_string(Utilities::MPI::max(thickest, tria.get_communicator())) +
                 " a thick)",
               p.surface_layer_thickness, "[that thickness, 1] (no halvings)");
        tria.execute_coarsening_and_refinement();
        ++info.n_halvings;
      }

    info.min_surface_cell = std::numeric_limits<double>::max();
    info.min_edge_cell    = std::numeric_limits<double>::max();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
              info.min_surface_cell =
                std::min(info.min_surface_cell, cell->extent_in_direction(f / 2) / a);
            if (cell->vertex(f).distance(edge) < on_line_tolerance * a)
              info.min_edge_cell = std::min(info.min_edge_cell, cell->minimum_vertex_distance() / a);
          }
    if (distributed)
      {
        info.min_surface_cell = Utilities::MPI::min(info.min_surface_cell, tria.get_communicator());
        info.min_edge_cell    = Utilities::MPI::min(info.min_edge_cell, tria.get_communicator());
      }
  }


  namespace
  {
    /// The bounding box of a cell in (r, z).
    struct Box
    {
      double r0, r1, z0;
      double width() const { return r1 - r0; }
    };

    Box bounding_box(const Triangulation<2>::active_cell_iterator &cell)
    {
      Box b{std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
      for (const unsigned int v : cell->vertex_indices())
        {
          b.r0 = std::min(b.r0, cell->vertex(v)[0]);
          b.r1 = std::max(b.r1, cell->vertex(v)[0]);
          b.z0 = std::min(b.z0, cell->vertex(v)[1]);
        }
      return b;
    }

    /// A thin cell (the surface layer) is split along its long side only: isotropic splits would double the layers
    /// of its column at every level. The refinement case is in the cell's own coordinates (gmsh cells are not
    /// aligned with r, z).
    void flag_for_surface_refinement(const Triangulation<2>::active_cell_iterator &cell)
    {
      const double e0 = cell->extent_in_direction(0), e1 = cell->extent_in_direction(1);
      if (std::min(e0, e1) < 0.5 * std::max(e0, e1))
        cell->set_refine_flag(e0 > e1 ? RefinementCase<2>::cut_x : RefinementCase<2>::cut_y);
      else
        cell->set_refine_flag(RefinementCase<2>::isotropic_refinement);
    }
  } // namespace


  void refine_toward_surface_points(const SurfaceRefinement &refinement, Triangulation<2> &tria)
  {
    if (refinement.levels > 30)
      fail("SurfaceRefinement", "levels", refinement.levels, "[0, 30]");
    for (const double c : refinement.radii)
      if (!(c > 0) || !std::isfinite(c))
        fail("SurfaceRefinement", "radius", c, "(0, inf)");
    for (const SurfaceInterval &interval : refinement.intervals)
      {
        if (!(interval.r0 >= 0) || !std::isfinite(interval.r0))
          fail("SurfaceRefinement", "interval start r0", interval.r0, "[0, inf)");
        if (!(interval.r1 > interval.r0) || !std::isfinite(interval.r1))
          fail("SurfaceRefinement", "interval end r1", interval.r1, "(r0, inf) with r0 = " + std::to_string(interval.r0));
        if (interval.cells < 1 || interval.cells > 1024)
          fail("SurfaceRefinement", "interval cells", interval.cells, "[1, 1024]");
      }
    // The intervals: every surface cell (and the cells of its column within one width of the surface) that overlaps
    // one is split until it is at most (r1 - r0) / cells wide. Each round halves them; 40 rounds span 1e12.
    for (unsigned int round = 0; round < 40 && !refinement.intervals.empty(); ++round)
      {
        bool flagged = false;
        for (const auto &cell : tria.active_cell_iterators())
          {
            const Box b = bounding_box(cell);
            for (const SurfaceInterval &interval : refinement.intervals)
              if (b.r1 > interval.r0 && b.r0 < interval.r1 && b.z0 <= b.width() &&
                  b.width() > (interval.r1 - interval.r0) / interval.cells)
                {
                  flag_for_surface_refinement(cell);
                  flagged = true;
                  break;
                }
          }
        if (!flagged)
          break;
        tria.execute_coarsening_and_refinement();
      }
    // The points: each level splits the cells within one cell width of one.
    for (unsigned int level = 0; level < refinement.levels; ++level)
      {
        for (const auto &cell : tria.active_cell_iterators())
          {
            const Box b = bounding_box(cell);
            for (const double c : refinement.radii)
              if (std::max({0.0, b.r0 - c, c - b.r1}) <= b.width() && b.z0 <= b.width())
                {
                  flag_for_surface_refinement(cell);
                  break;
                }
          }
        tria.execute_coarsening_and_refinement();
      }
  }
} // namespace gradcontact::fem
