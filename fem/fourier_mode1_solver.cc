#include <fem/boundary_ids.h>
#include <fem/errors.h>
#include <fem/fourier_mode1_solver.h>
#include <fem/gauss_jacobi.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    constexpr double pi = numbers::PI;
    // Relative tolerance of "this point sits at r = a" (support points are exact up to round-off).
    constexpr double node_tolerance = 1e-10;
    // |pi u.Au - work| / (pi u.Au) above this marks the result unreliable (the axisymmetric solver's
    // threshold: sound solves measured <= 4e-7 there).
    constexpr double energy_mismatch_tolerance = 1e-6;
    // Traction quadrature: every face piece next to a breakpoint (the load radius, a kink of tau) is
    // cut into this many geometrically shrinking sub-intervals (ratio 0.25 toward the breakpoint) with
    // this many Gauss points each. A kink like (c - r)^{1/4} (k = -0.5) then costs a relative error of
    // the order of the innermost piece, 0.25^16 ~ 2e-10 of the face.
    constexpr unsigned int graded_pieces       = 16;
    constexpr double       grading_ratio       = 0.25;
    constexpr unsigned int traction_gauss_points = 8;

    double seconds_since(const std::chrono::steady_clock::time_point &start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    /// Value at r of the Lagrange interpolant through (x_i, y_i).
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

    /// Gauss points and weights on [x0, x1], refined geometrically toward the ends flagged `graded_*`.
    void add_interval(const double x0, const double x1, const bool graded_left, const bool graded_right,
                      std::vector<std::pair<double, double>> &points)
    {
      static const QGauss<1> gauss(traction_gauss_points);
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
          for (unsigned int j = 0; j < graded_pieces; ++j)
            {
              const double lo = (j + 1 == graded_pieces) ? x0 : x0 + length * grading_ratio;
              add(lo, hi);
              hi = lo;
              length *= grading_ratio;
            }
        }
      if (graded_right)
        {
          double lo = mid, length = x1 - mid;
          for (unsigned int j = 0; j < graded_pieces; ++j)
            {
              const double hi = (j + 1 == graded_pieces) ? x1 : x1 - length * grading_ratio;
              add(lo, hi);
              lo = hi;
              length *= grading_ratio;
            }
        }
    }

    /// The mode-1 cell stiffness a(u, v) (header), with the quadrature rules of elasticity_assembly.h:
    /// QGauss(degree + extra) in the bulk, QIterated where a jump of E crosses the cell, Gauss-Jacobi
    /// across the face on z = 0 when E ~ z^s there.
    class Mode1CellStiffness
    {
    public:
      Mode1CellStiffness(const Material &material_, const FESystem<2> &fe_, const Mapping<2> &mapping,
                         const DiscretizationParameters &d)
        : material(material_)
        , fe(fe_)
        , s(material_.modulus->surface_exponent())
        , jumps(material_.modulus->discontinuities())
        , cell_matrix(fe_.n_dofs_per_cell(), fe_.n_dofs_per_cell())
        , B(fe_.n_dofs_per_cell())
      {
        const UpdateFlags flags = update_values | update_gradients | update_quadrature_points | update_JxW_values;
        const unsigned int n_q = d.degree + d.extra_quadrature_points;
        regular    = std::make_unique<FEValues<2>>(mapping, fe, QGauss<2>(n_q), flags);
        subdivided = std::make_unique<FEValues<2>>(
          mapping, fe, QIterated<2>(QGauss<1>(n_q), d.discontinuity_subdivisions), flags);
        for (unsigned int f = 0; f < 4; ++f)
          surface[f] =
            std::make_unique<FEValues<2>>(mapping, fe, surface_cell_quadrature(n_q, s, f, distance[f]), flags);
      }

      const FullMatrix<double> &matrix(const DoFHandler<2>::active_cell_iterator &cell)
      {
        const double nu       = material.nu;
        const double c_lambda = nu / ((1 + nu) * (1 - 2 * nu));
        const double c_mu     = 1 / (2 * (1 + nu));

        unsigned int surface_face = numbers::invalid_unsigned_int;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
            surface_face = f;
        double z_min = std::numeric_limits<double>::max(), z_max = -z_min;
        for (const unsigned int v : cell->vertex_indices())
          {
            z_min = std::min(z_min, cell->vertex(v)[1]);
            z_max = std::max(z_max, cell->vertex(v)[1]);
          }
        const bool straddles =
          std::any_of(jumps.begin(), jumps.end(), [&](const double z) { return z > z_min && z < z_max; });
        FEValues<2>               *fv = regular.get();
        const std::vector<double> *xi = nullptr;
        if (straddles)
          fv = subdivided.get();
        else if (surface_face != numbers::invalid_unsigned_int && s != 0.0)
          {
            fv = surface[surface_face].get();
            xi = &distance[surface_face];
          }
        fv->reinit(cell);

        const unsigned int n = fe.n_dofs_per_cell();
        cell_matrix          = 0;
        for (const unsigned int q : fv->quadrature_point_indices())
          {
            const Point<2> &x = fv->quadrature_point(q);
            const double    r = x[0];
            // The Gauss-Jacobi weights contain xi^s: E / xi^s is the regular factor.
            const double E      = xi ? material.modulus->value(x[1]) / std::pow((*xi)[q], s) :
                                       material.modulus->value(x[1]);
            const double lambda = c_lambda * E, mu = c_mu * E;
            const double weight = r * fv->JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              {
                const double        phi = fv->shape_value(i, q);
                const Tensor<1, 2> &g   = fv->shape_grad(i, q);
                // B = (eps_rr, eps_zz, eps_tt, gamma_rz, gamma_rt, gamma_tz) of the header, per field:
                //   U: (U_r, 0, U/r, U_z, U/r, 0)
                //   V: (0, 0, -V/r, 0, V_r - V/r, V_z)
                //   W: (0, W_z, 0, W_r, 0, W/r)
                switch (fe.system_to_component_index(i).first)
                  {
                    case 0:
                      B[i] = {{g[0], 0.0, phi / r, g[1], phi / r, 0.0}};
                      break;
                    case 1:
                      B[i] = {{0.0, 0.0, -phi / r, 0.0, g[0] - phi / r, g[1]}};
                      break;
                    default:
                      B[i] = {{0.0, g[1], 0.0, g[0], 0.0, phi / r}};
                  }
              }
            for (unsigned int i = 0; i < n; ++i)
              {
                const auto  &Bi   = B[i];
                const double tr_i = Bi[0] + Bi[1] + Bi[2];
                for (unsigned int j = 0; j <= i; ++j)
                  {
                    const auto  &Bj   = B[j];
                    const double tr_j = Bj[0] + Bj[1] + Bj[2];
                    cell_matrix(i, j) +=
                      (lambda * tr_i * tr_j + 2 * mu * (Bi[0] * Bj[0] + Bi[1] * Bj[1] + Bi[2] * Bj[2]) +
                       mu * (Bi[3] * Bj[3] + Bi[4] * Bj[4] + Bi[5] * Bj[5])) *
                      weight;
                  }
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i + 1; j < n; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
        return cell_matrix;
      }

    private:
      const Material                                     material;
      const FESystem<2>                                 &fe;
      const double                                       s;
      const std::vector<double>                          jumps;
      std::unique_ptr<FEValues<2>>                       regular, subdivided;
      std::array<std::unique_ptr<FEValues<2>>, 4>        surface;
      std::array<std::vector<double>, 4>                 distance;
      FullMatrix<double>                                 cell_matrix;
      std::vector<std::array<double, 6>>                 B;
    };
  } // namespace



  TangentialLoad TangentialLoad::flat_punch(const double delta)
  {
    TangentialLoad l;
    l.type         = TangentialLoadType::flat_punch;
    l.displacement = delta;
    l.validate();
    return l;
  }

  TangentialLoad TangentialLoad::profile(std::function<double(double)> tau, const double radius,
                                         const double stick_radius, std::vector<double> breakpoints)
  {
    TangentialLoad l;
    l.type         = TangentialLoadType::traction;
    l.traction     = std::move(tau);
    l.radius       = radius;
    l.stick_radius = stick_radius;
    l.breakpoints  = std::move(breakpoints);
    l.validate();
    return l;
  }

  TangentialLoad TangentialLoad::partial_slip(std::function<double(double, double)> pressure, const double mu,
                                              const double a, const double c)
  {
    const char *where = "TangentialLoad::partial_slip";
    if (!pressure)
      throw std::invalid_argument(std::string(where) + ": the pressure function is empty");
    if (!(mu > 0) || !std::isfinite(mu))
      fail(where, "mu (friction coefficient)", mu, "(0, inf)");
    if (!(a > 0) || !std::isfinite(a))
      fail(where, "a (contact radius)", a, "(0, inf)");
    if (!(c > 0 && c <= a))
      fail(where, "c (stick radius)", c, "(0, a] = (0, " + std::to_string(a) + "]");
    auto tau = [pressure, mu, a, c](const double r) {
      return mu * ((r < a ? pressure(r, a) : 0.0) - (r < c ? pressure(r, c) : 0.0));
    };
    return profile(tau, a, c, c < a ? std::vector<double>{c} : std::vector<double>{});
  }

  void TangentialLoad::validate() const
  {
    switch (type)
      {
        case TangentialLoadType::flat_punch:
          if (!std::isfinite(displacement) || displacement == 0)
            fail("TangentialLoad (flat punch)", "displacement (delta)", displacement, "finite, non-zero");
          break;
        case TangentialLoadType::traction:
          if (!traction)
            throw std::invalid_argument("TangentialLoad (traction): the traction function is empty");
          if (!(radius > 0) || !std::isfinite(radius))
            fail("TangentialLoad (traction)", "radius", radius, "(0, inf)");
          if (!(stick_radius >= 0 && stick_radius <= radius))
            fail("TangentialLoad (traction)", "stick_radius", stick_radius,
                 "[0, radius] = [0, " + std::to_string(radius) + "] (0: no stick-zone statistics)");
          for (const double b : breakpoints)
            if (!(b > 0 && b < radius))
              fail("TangentialLoad (traction)", "breakpoint", b,
                   "(0, radius) = (0, " + std::to_string(radius) + ")");
          break;
      }
  }



  void refine_toward_surface_points(const SurfaceRefinement &refinement, Triangulation<2> &tria)
  {
    if (refinement.levels > 30)
      fail("SurfaceRefinement", "levels", refinement.levels, "[0, 30]");
    for (const double c : refinement.radii)
      if (!(c > 0) || !std::isfinite(c))
        fail("SurfaceRefinement", "radius", c, "(0, inf)");
    for (unsigned int level = 0; level < refinement.levels; ++level)
      {
        for (const auto &cell : tria.active_cell_iterators())
          {
            double r0 = std::numeric_limits<double>::max(), r1 = -r0, z0 = r0, z1 = -r0;
            for (const unsigned int v : cell->vertex_indices())
              {
                r0 = std::min(r0, cell->vertex(v)[0]);
                r1 = std::max(r1, cell->vertex(v)[0]);
                z0 = std::min(z0, cell->vertex(v)[1]);
                z1 = std::max(z1, cell->vertex(v)[1]);
              }
            const double width = r1 - r0;
            for (const double c : refinement.radii)
              if (std::max({0.0, r0 - c, c - r1}) <= width && z0 <= width)
                {
                  // A thin cell (the surface layer) is split along its long side only: isotropic
                  // splits would double the layers of its column at every level. The refinement case
                  // is in the cell's own coordinates (gmsh cells are not aligned with r, z).
                  const double e0 = cell->extent_in_direction(0), e1 = cell->extent_in_direction(1);
                  if (std::min(e0, e1) < 0.5 * std::max(e0, e1))
                    cell->set_refine_flag(e0 > e1 ? RefinementCase<2>::cut_x : RefinementCase<2>::cut_y);
                  else
                    cell->set_refine_flag(RefinementCase<2>::isotropic_refinement);
                  break;
                }
          }
        tria.execute_coarsening_and_refinement();
      }
  }



  FourierMode1Solver::FourierMode1Solver(const Material &material_, const MeshParameters &mesh,
                                         const DiscretizationParameters &discretization_,
                                         const SurfaceRefinement &refinement)
    : material((material_.validate(), material_))
    , discretization((discretization_.validate(),
                      require_displacement_formulation(discretization_, material_.nu, "FourierMode1Solver"),
                      discretization_))
    , fe(FE_Q<2>(discretization_.degree), 3)
    , dof_handler(triangulation)
  {
    mesh.validate();
    make_grid(mesh, refinement);
    setup_system();
    assemble_system();
  }

  FourierMode1Solver::FourierMode1Solver(const Material &material_, const Triangulation<2> &mesh,
                                         const DiscretizationParameters &discretization_)
    : material((material_.validate(), material_))
    , discretization((discretization_.validate(),
                      require_displacement_formulation(discretization_, material_.nu, "FourierMode1Solver"),
                      discretization_))
    , fe(FE_Q<2>(discretization_.degree), 3)
    , dof_handler(triangulation)
  {
    const auto start = std::chrono::steady_clock::now();
    triangulation.copy_triangulation(mesh);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::unassigned)
          throw std::invalid_argument("FourierMode1Solver: the mesh has a boundary face without an id "
                                      "(fem/boundary_ids.h) at (" +
                                      std::to_string(cell->face(f)->center()[0]) + ", " +
                                      std::to_string(cell->face(f)->center()[1]) + ")");
    mesh_info.near_field_source = "user mesh";
    setup_time.mesh             = seconds_since(start);
    setup_system();
    assemble_system();
  }

  FourierMode1Solver::~FourierMode1Solver()
  {
    dof_handler.clear();
  }



  void FourierMode1Solver::make_grid(const MeshParameters &mesh, const SurfaceRefinement &refinement)
  {
    const auto start = std::chrono::steady_clock::now();
    mesh_info        = make_mesh(mesh, triangulation);
    refine_toward_surface_points(refinement, triangulation);
    setup_time.mesh  = seconds_since(start);
  }



  void FourierMode1Solver::setup_system()
  {
    const auto start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);

    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);

    // Constraints: hanging nodes; far field u = 0; on the axis W = 0 and V = U (header). The far
    // field comes first so that a corner node on both keeps u = 0.
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::far_field,
                                             Functions::ZeroFunction<2>(3), constraints);
    const FEValuesExtractors::Scalar W(2);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::axis,
                                             Functions::ZeroFunction<2>(3), constraints, fe.component_mask(W));
    {
      // Pair the U- and V-DoFs of each axis support point (by z) and add V_i = U_i.
      std::map<double, std::array<types::global_dof_index, 2>> pairs;
      std::vector<types::global_dof_index>                     face_dofs(fe.n_dofs_per_face());
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::axis)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const unsigned int c = fe.face_system_to_component_index(i, f).first;
                  if (c < 2)
                    {
                      auto it = pairs.emplace(support[face_dofs[i]][1],
                                              std::array<types::global_dof_index, 2>{
                                                {numbers::invalid_dof_index, numbers::invalid_dof_index}})
                                  .first;
                      it->second[c] = face_dofs[i];
                    }
                }
            }
      for (const auto &[z, uv] : pairs)
        {
          AssertThrow(uv[0] != numbers::invalid_dof_index && uv[1] != numbers::invalid_dof_index,
                      ExcMessage("axis node at z = " + std::to_string(z) + " lacks its U or V DoF"));
          // Hanging or far-field nodes are already constrained (U and V alike).
          if (!constraints.is_constrained(uv[1]) && !constraints.is_constrained(uv[0]))
            {
              constraints.add_line(uv[1]);
              constraints.add_entry(uv[1], uv[0], 1.0);
            }
        }
    }
    constraints.close();

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity_pattern.copy_from(dsp);
    stiffness.reinit(sparsity_pattern);

    // Surface faces with their U, V, W DoFs sorted by r; the contact radius a; the punch DoFs.
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    surface_faces.clear();
    a = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
          {
            cell->face(f)->get_dof_indices(face_dofs);
            SurfaceFace face;
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              face.dofs[fe.face_system_to_component_index(i, f).first].push_back(face_dofs[i]);
            for (auto &list : face.dofs)
              std::sort(list.begin(), list.end(),
                        [&](const auto x, const auto y) { return support[x][0] < support[y][0]; });
            for (const auto d : face.dofs[0])
              face.r.push_back(support[d][0]);
            face.r0 = face.r.front();
            face.r1 = face.r.back();
            if (cell->face(f)->boundary_id() == boundary_id::contact)
              {
                a = std::max(a, face.r1);
                for (unsigned int c = 0; c < 2; ++c)
                  for (const auto d : face.dofs[c])
                    {
                      // In 2D a boundary face is never the refined side of a hanging node; the only
                      // constrained contact DoF is the axis V (= U).
                      AssertThrow(!constraints.is_constrained(d) ||
                                    (c == 1 && support[d][0] < node_tolerance * face.r1),
                                  ExcMessage("contact DoF at r = " + std::to_string(support[d][0]) +
                                             " is constrained"));
                      if (!constraints.is_constrained(d))
                        punch_dofs.push_back(d);
                    }
              }
            surface_faces.push_back(std::move(face));
          }
    std::sort(surface_faces.begin(), surface_faces.end(),
              [](const SurfaceFace &x, const SurfaceFace &y) { return x.r0 < y.r0; });
    std::sort(punch_dofs.begin(), punch_dofs.end());
    punch_dofs.erase(std::unique(punch_dofs.begin(), punch_dofs.end()), punch_dofs.end());
    setup_time.setup = seconds_since(start);
  }



  void FourierMode1Solver::assemble_system()
  {
    const auto                           start = std::chrono::steady_clock::now();
    Mode1CellStiffness                   cell_stiffness(material, fe, mapping, discretization);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_stiffness.matrix(cell), local_dof_indices, stiffness);
      }
    // The punch matrix: rows and columns of the prescribed U, V DoFs zeroed, diagonal kept (symmetric);
    // the prescribed values enter through the right-hand side (as in AxisymmetricSolver).
    punch_stiffness.reinit(sparsity_pattern);
    punch_stiffness.copy_from(stiffness);
    for (const auto i : punch_dofs)
      for (auto entry = punch_stiffness.begin(i); entry != punch_stiffness.end(i); ++entry)
        if (entry->column() != i)
          {
            punch_stiffness.set(entry->column(), i, 0.0);
            entry->value() = 0.0;
          }
    setup_time.assemble = seconds_since(start);
  }



  const SparseDirectUMFPACK &FourierMode1Solver::factorization(const bool punch, double &seconds)
  {
    std::unique_ptr<SparseDirectUMFPACK> &solver = punch ? punch_solver : free_solver;
    seconds                                      = 0;
    if (!solver)
      {
        const auto start = std::chrono::steady_clock::now();
        solver           = std::make_unique<SparseDirectUMFPACK>();
        solver->initialize(punch ? punch_stiffness : stiffness);
        seconds = seconds_since(start);
      }
    return *solver;
  }



  Vector<double> FourierMode1Solver::traction_load(const TangentialLoad &load) const
  {
    // b_i = \int_{z=0, r <= radius} tau(r) phi_i(r) r dr for the U- and V-DoFs (header); the trace of
    // FE_Q on a face is the 1D Lagrange polynomial through the face's support points.
    Vector<double> b(dof_handler.n_dofs());
    std::vector<double> cuts = load.breakpoints;
    cuts.push_back(load.radius);
    std::sort(cuts.begin(), cuts.end());
    for (const SurfaceFace &face : surface_faces)
      {
        if (face.r0 >= load.radius * (1 - node_tolerance))
          continue;
        // Pieces of [r0, min(r1, radius)] between the cuts; grade toward a cut inside or at the end.
        std::vector<double> ends{face.r0};
        for (const double c : cuts)
          if (c > face.r0 * (1 + node_tolerance) && c < face.r1 * (1 - node_tolerance))
            ends.push_back(c);
        ends.push_back(std::min(face.r1, load.radius));
        auto is_cut = [&](const double x) {
          return std::any_of(cuts.begin(), cuts.end(),
                             [&](const double c) { return std::abs(x - c) <= node_tolerance * c; });
        };
        std::vector<std::pair<double, double>> points;
        for (unsigned int j = 0; j + 1 < ends.size(); ++j)
          add_interval(ends[j], ends[j + 1], is_cut(ends[j]), is_cut(ends[j + 1]), points);
        const unsigned int n = face.r.size();
        std::vector<double> unit(n, 0.0), integral(n, 0.0);
        for (const auto &[r, w] : points)
          {
            const double t = load.traction(r);
            if (!std::isfinite(t))
              fail("TangentialLoad (traction)", "tau(r) at r = " + std::to_string(r), t, "finite values");
            for (unsigned int i = 0; i < n; ++i)
              {
                std::fill(unit.begin(), unit.end(), 0.0);
                unit[i] = 1;
                integral[i] += t * lagrange(face.r, unit, r) * r * w;
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            b[face.dofs[0][i]] += integral[i];
            b[face.dofs[1][i]] += integral[i];
          }
      }
    return b;
  }



  double FourierMode1Solver::surface_value(const Vector<double> &u, const unsigned int component,
                                           const double r) const
  {
    for (const SurfaceFace &face : surface_faces)
      if (r >= face.r0 && r <= face.r1)
        {
          std::vector<double> y;
          for (const auto d : face.dofs[component])
            y.push_back(u[d]);
          return lagrange(face.r, y, r);
        }
    fail("FourierMode1Solver::run", "sample radius r", r,
         "[0, " + std::to_string(surface_faces.back().r1) + "] (the surface of the mesh)");
  }



  StickZoneDisplacement FourierMode1Solver::stick_zone(const Vector<double> &u, const double c) const
  {
    StickZoneDisplacement z;
    z.radius = c;
    z.min_U = z.min_V = std::numeric_limits<double>::max();
    z.max_U = z.max_V = -std::numeric_limits<double>::max();
    double             integral = 0, max_uy = 0;
    const QGauss<1>    gauss(discretization.degree + 3);
    constexpr unsigned samples = 16; // equispaced per face for the extrema (plus the nodes)
    for (const SurfaceFace &face : surface_faces)
      {
        if (face.r0 >= c * (1 - node_tolerance))
          break;
        const double        r1 = std::min(face.r1, c);
        std::vector<double> U, V;
        for (const auto d : face.dofs[0])
          U.push_back(u[d]);
        for (const auto d : face.dofs[1])
          V.push_back(u[d]);
        for (unsigned int q = 0; q < gauss.size(); ++q)
          {
            const double r = face.r0 + (r1 - face.r0) * gauss.point(q)[0];
            integral += 0.5 * (lagrange(face.r, U, r) + lagrange(face.r, V, r)) * r * (r1 - face.r0) *
                        gauss.weight(q);
          }
        for (unsigned int j = 0; j <= samples; ++j)
          {
            const double r  = face.r0 + (r1 - face.r0) * j / samples;
            const double Ur = lagrange(face.r, U, r), Vr = lagrange(face.r, V, r);
            z.min_U         = std::min(z.min_U, Ur);
            z.max_U         = std::max(z.max_U, Ur);
            z.min_V         = std::min(z.min_V, Vr);
            z.max_V         = std::max(z.max_V, Vr);
            max_uy          = std::max(max_uy, 0.5 * std::abs(Ur - Vr));
          }
      }
    z.mean_ux         = 2 * integral / (c * c);
    z.relative_spread = (std::max(z.max_U, z.max_V) - std::min(z.min_U, z.min_V)) / std::abs(z.mean_ux);
    z.relative_max_uy = max_uy / std::abs(z.mean_ux);
    return z;
  }



  TangentialResult FourierMode1Solver::run(const TangentialLoad &load, const TangentialOutputRequest &outputs)
  {
    load.validate();
    const bool punch = load.type == TangentialLoadType::flat_punch;
    if (punch && punch_dofs.empty())
      throw std::invalid_argument("FourierMode1Solver::run: flat punch on a mesh without contact faces");
    TangentialResult result;
    result.time    = setup_time;
    result.n_dofs  = dof_handler.n_dofs();
    result.n_cells = triangulation.n_active_cells();
    result.mesh    = mesh_info;

    const SparseDirectUMFPACK &direct = factorization(punch, result.time.factorize);
    const auto                 solve_start = std::chrono::steady_clock::now();
    Vector<double>             u(dof_handler.n_dofs()), b(dof_handler.n_dofs()), rhs;
    double                     work = 0; // work of the loads, per pi
    if (punch)
      {
        // rhs = -A g on the free DoFs, A_ii g_i on the prescribed ones (g = delta on U, V of r <= a).
        Vector<double> g(dof_handler.n_dofs());
        for (const auto i : punch_dofs)
          g[i] = load.displacement;
        rhs.reinit(dof_handler.n_dofs());
        stiffness.vmult(rhs, g);
        rhs *= -1;
        for (const auto i : punch_dofs)
          rhs[i] = punch_stiffness.diag_element(i) * load.displacement;
      }
    else
      {
        b   = traction_load(load);
        rhs = b;
        constraints.condense(rhs); // the axis V-load joins its U (V = U)
      }
    u = rhs;
    direct.solve(u);
    constraints.distribute(u);

    // Reactions R = A u - b (condensed A: the rows of unconstrained DoFs are the equations).
    Vector<double> reaction(dof_handler.n_dofs());
    Vector<double> u_free(u);
    constraints.set_zero(u_free);
    stiffness.vmult(reaction, u_free);
    const double energy = u_free * reaction; // u.Au per pi, unconstrained DoFs only
    if (punch)
      {
        double sum = 0;
        for (const auto i : punch_dofs)
          sum += reaction[i];
        work                = sum * load.displacement;
        result.force        = pi * sum;
        result.displacement = load.displacement;
        result.stiffness    = result.force / load.displacement;
      }
    else
      {
        work = b * u;
        // F_x = pi \int (tau + tau) r dr = pi sum_i b_i over the U and V DoFs (partition of unity).
        double sum = 0;
        for (unsigned int i = 0; i < b.size(); ++i)
          sum += b[i];
        result.force = pi * sum;
      }
    result.energy_mismatch = std::abs(energy - work) / std::abs(energy);
    if (!(result.energy_mismatch <= energy_mismatch_tolerance))
      {
        std::ostringstream msg;
        msg << "unreliable solve: energy mismatch " << result.energy_mismatch << " > " << energy_mismatch_tolerance
            << " (ill-conditioned: surface cells " << mesh_info.min_surface_cell << " a thin); ";
        result.reliable = false;
        result.message += msg.str();
      }
    result.time.solve = seconds_since(solve_start);

    const auto post = std::chrono::steady_clock::now();
    if (!punch && load.stick_radius > 0)
      {
        result.stick        = stick_zone(u, load.stick_radius);
        result.displacement = result.stick.mean_ux;
      }
    for (const double r : outputs.displacement_radii)
      result.surface.push_back({r, surface_value(u, 0, r), surface_value(u, 1, r), surface_value(u, 2, r)});
    if (!outputs.vtu_file.empty())
      output_results(u, outputs.vtu_file);
    result.time.postprocess = seconds_since(post);
    return result;
  }



  void FourierMode1Solver::output_results(const Vector<double> &u, const std::string &filename) const
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(u, std::vector<std::string>{"U", "V", "W"});
    data_out.build_patches(mapping, discretization.degree);
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error("FourierMode1Solver::output_results: cannot write " + filename);
    data_out.write_vtu(out);
  }
} // namespace gradcontact::fem
