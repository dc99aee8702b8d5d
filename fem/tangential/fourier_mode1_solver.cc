#include <fem/base/boundary_ids.h>
#include <fem/base/errors.h>
#include <fem/tangential/fourier_mode1_solver.h>
#include <fem/io/vtu_output.h>
#include <fem/elasticity/graded_elasticity.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
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
    // Traction quadrature: every face piece next to a breakpoint (the load radius, a kink of tau) is
    // cut into 16 geometrically shrinking sub-intervals (ratio 0.25 toward the breakpoint) with 8 Gauss
    // points each. A kink like (c - r)^{1/4} (k = -0.5) then costs a relative error of the order of the
    // innermost piece, 0.25^16 ~ 2e-10 of the face.
    const GradedRule traction_rule{8, 16, 0.25};

    /// The discretisation, validated for the displacement formulation (mode 1 has no mixed one).
    const DiscretizationParameters &checked(const DiscretizationParameters &discretization, const double nu)
    {
      discretization.validate();
      require_displacement_formulation(discretization, nu, "FourierMode1Solver");
      return discretization;
    }
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






  FourierMode1Solver::FourierMode1Solver(const Material &material_, const MeshParameters &mesh,
                                         const DiscretizationParameters &discretization_,
                                         const SurfaceRefinement &refinement)
    : material((material_.validate(), material_))
    , discretization(checked(discretization_, material_.nu))
    , fe(FE_Q<2>(discretization_.degree), 3)
    , dof_handler(triangulation)
  {
    mesh.validate();
    make_grid(mesh, refinement);
    setup_system(&mesh);
    assemble_system();
  }

  FourierMode1Solver::FourierMode1Solver(const Material &material_, const Triangulation<2> &mesh,
                                         const DiscretizationParameters &discretization_)
    : material((material_.validate(), material_))
    , discretization(checked(discretization_, material_.nu))
    , fe(FE_Q<2>(discretization_.degree), 3)
    , dof_handler(triangulation)
  {
    require_clamped_far_field(discretization, "FourierMode1Solver (a given triangulation, no rings of fem/grid/mesh.h)");
    const auto start = std::chrono::steady_clock::now();
    triangulation.copy_triangulation(mesh);
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::unassigned)
          throw std::invalid_argument("FourierMode1Solver: the mesh has a boundary face without an id "
                                      "(fem/base/boundary_ids.h) at (" +
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



  void FourierMode1Solver::setup_system(const MeshParameters *mesh)
  {
    const bool condensed = mesh && discretization.far_field == FarField::condensed;
    const auto start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);

    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);

    // Constraints: hanging nodes; far field u = 0 unless condensed (fem/elasticity/far_field.h); on the axis W = 0 and
    // V = U (header). The far field comes first so that a corner node on both keeps u = 0.
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (!condensed)
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

    system.reinit(dof_handler, constraints,
                  condensed ? std::make_unique<FarFieldRings>(dof_handler, mapping, constraints, *mesh, mesh_info) :
                              nullptr);

    // Surface faces with their U, V, W DoFs sorted by r; the contact radius a; the punch DoFs.
    std::vector<double> support_r(support.size());
    for (unsigned int i = 0; i < support.size(); ++i)
      support_r[i] = support[i][0];
    surface_faces = collect_surface_faces(dof_handler, support_r, 3);
    a             = 0;
    punch_dofs.clear();
    for (const SurfaceFace &face : surface_faces)
      if (face.contact)
        {
          a = std::max(a, face.r1);
          for (unsigned int c = 0; c < 2; ++c)
            for (const auto d : face.dofs[c])
              {
                // In 2D a boundary face is never the refined side of a hanging node; the only
                // constrained contact DoF is the axis V (= U).
                AssertThrow(!constraints.is_constrained(d) || (c == 1 && support_r[d] < node_tolerance * face.r1),
                            ExcMessage("contact DoF at r = " + std::to_string(support_r[d]) + " is constrained"));
                if (!constraints.is_constrained(d))
                  punch_dofs.push_back(d);
              }
        }
    std::sort(punch_dofs.begin(), punch_dofs.end());
    punch_dofs.erase(std::unique(punch_dofs.begin(), punch_dofs.end()), punch_dofs.end());
    setup_time.setup = seconds_since(start);
  }



  double FourierMode1Solver::edge_cell() const
  {
    double h_edge = 1.0;
    for (const SurfaceFace &face : surface_faces)
      if (face.contact && std::abs(face.r1 - a) <= node_tolerance * a)
        h_edge = std::min(h_edge, (face.r1 - face.r0) / a);
    return h_edge;
  }



  void FourierMode1Solver::assemble_system()
  {
    const auto                           start = std::chrono::steady_clock::now();
    Mode1CellStiffness cell_stiffness(material, fe, mapping, discretization, a, edge_cell());
    // P: U, V on r <= a of the tangential flat punch
    system.assemble(dof_handler, cell_stiffness, punch_dofs);
    setup_time.assemble = seconds_since(start);
  }



  Vector<double> FourierMode1Solver::traction_load(const TangentialLoad &load) const
  {
    // b_i = \int_{z=0, r <= radius} tau(r) phi_i(r) r dr for the U- and V-DoFs (header).
    Vector<double> b(dof_handler.n_dofs());
    const auto     integrals = traction_integrals(surface_faces, load.traction, load.radius, load.breakpoints,
                                                  traction_rule, "TangentialLoad (traction)");
    for (unsigned int k = 0; k < surface_faces.size(); ++k)
      for (unsigned int i = 0; i < surface_faces[k].r.size(); ++i)
        {
          b[surface_faces[k].dofs[0][i]] += integrals[k][i];
          b[surface_faces[k].dofs[1][i]] += integrals[k][i];
        }
    return b;
  }



  double FourierMode1Solver::surface_value(const Vector<double> &u, const unsigned int component,
                                           const double r) const
  {
    if (const SurfaceFace *face = find_face(surface_faces, r))
      return face_value(*face, component, u, r);
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



  double FourierMode1Solver::solve_punch(const TangentialLoad &load, Vector<double> &u, TangentialResult &result)
  {
    if (punch_dofs.empty())
      throw std::invalid_argument("FourierMode1Solver::run: flat punch on a mesh without contact faces");
    // U = V = delta on the punch DoFs; the reactions there are the nodal forces.
    const std::vector<double> g(punch_dofs.size(), load.displacement);
    Vector<double>            b(dof_handler.n_dofs()), reaction;
    u          = system.solve(true, g, b, reaction, result.time.factorize);
    double sum = 0;
    for (const auto i : punch_dofs)
      sum += reaction[i];
    result.force        = pi * sum;
    result.displacement = load.displacement;
    result.stiffness    = result.force / load.displacement;
    return sum * load.displacement;
  }

  double FourierMode1Solver::solve_traction(const TangentialLoad &load, Vector<double> &u, TangentialResult &result)
  {
    const Vector<double> b   = traction_load(load);
    Vector<double>       rhs = b, reaction;
    constraints.condense(rhs); // the axis V-load joins its U (V = U)
    u = system.solve(false, {}, rhs, reaction, result.time.factorize);
    // F_x = pi \int (tau + tau) r dr = pi sum_i b_i over the U and V DoFs (partition of unity).
    double sum = 0;
    for (unsigned int i = 0; i < b.size(); ++i)
      sum += b[i];
    result.force = pi * sum;
    return b * u;
  }

  void FourierMode1Solver::sample(const TangentialLoad &load, const Vector<double> &u,
                                  const TangentialOutputRequest &outputs, TangentialResult &result) const
  {
    if (load.type != TangentialLoadType::flat_punch && load.stick_radius > 0)
      {
        result.stick        = stick_zone(u, load.stick_radius);
        result.displacement = result.stick.mean_ux;
      }
    for (const double r : outputs.displacement_radii)
      result.surface.push_back({r, surface_value(u, 0, r), surface_value(u, 1, r), surface_value(u, 2, r)});
    if (!outputs.vtu_file.empty())
      output_results(u, outputs.vtu_file);
  }

  TangentialResult FourierMode1Solver::run(const TangentialLoad &load, const TangentialOutputRequest &outputs)
  {
    load.validate();
    TangentialResult result;
    result.start(setup_time, dof_handler.n_dofs(), triangulation.n_active_cells(), mesh_info);
    record_far_field(system.far_field_exterior(), result);

    const auto     start = std::chrono::steady_clock::now();
    Vector<double> u;
    // the work of the loads, per pi
    const double work = load.type == TangentialLoadType::flat_punch ? solve_punch(load, u, result) :
                                                                       solve_traction(load, u, result);
    result.record(check_energy(system.energy(u), work, mesh_info.min_surface_cell, "", system.energy_magnitude(u)));
    result.time.solve = seconds_since(start) - result.time.factorize;

    const auto post = std::chrono::steady_clock::now();
    sample(load, u, outputs, result);
    result.time.postprocess = seconds_since(post);
    return result;
  }



  void FourierMode1Solver::output_results(const Vector<double> &u, const std::string &filename) const
  {
    MeridianDataOut data_out;
    data_out.surface_map = SurfaceMap<2>(discretization.surface_map, *material.modulus, a, edge_cell());
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(u, std::vector<std::string>{"U", "V", "W"});
    write_vtu(data_out, mapping, discretization.degree, filename, "FourierMode1Solver::output_results");
  }
} // namespace gradcontact::fem
