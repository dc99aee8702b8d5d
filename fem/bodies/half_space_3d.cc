#include <fem/base/boundary_ids.h>
#include <fem/base/errors.h>
#include <fem/elasticity/graded_elasticity.h>
#include <fem/bodies/half_space_3d.h>

#include <deal.II/base/function.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    double elapsed_max(const std::chrono::steady_clock::time_point &start, const MPI_Comm communicator)
    {
      return Utilities::MPI::max(seconds_since(start), communicator);
    }

    unsigned int mask_of(const std::array<bool, 3> &prescribed)
    {
      return (prescribed[0] ? 1u : 0u) | (prescribed[1] ? 2u : 0u) | (prescribed[2] ? 4u : 0u);
    }

    /// CG cannot solve the mixed formulation's saddle point (indefinite); MUMPS' LU can.
    void require_direct_when_mixed(const DistributedSolverParameters &solver, const Formulation formulation)
    {
      if (formulation == Formulation::mixed && solver.method != DistributedSolverParameters::Method::direct)
        throw std::invalid_argument("HalfSpace3DSolver: DistributedSolverParameters::method = amg_cg with the mixed "
                                    "formulation (an indefinite saddle point, which CG cannot solve); use method = "
                                    "direct");
    }
  } // namespace



  void FlatPunch3D::validate() const
  {
    if (!(prescribed[0] || prescribed[1] || prescribed[2]))
      throw std::invalid_argument("FlatPunch3D: prescribed = (false, false, false); prescribe at least one "
                                  "displacement component on the contact disc");
    const char *names[3] = {"displacement[0] (u_x)", "displacement[1] (u_y)", "displacement[2] (u_z)"};
    for (unsigned int c = 0; c < 3; ++c)
      if (!std::isfinite(displacement[c]))
        fem::fail("FlatPunch3D", names[c], displacement[c], "(-inf, inf)");
  }



  HalfSpace3DSolver::HalfSpace3DSolver(const MPI_Comm communicator_, const Material &material_,
                                       const HalfSpaceMesh3DParameters &mesh_,
                                       const DiscretizationParameters &discretization_,
                                       const DistributedSolverParameters &solver_)
    : communicator(require_mpi(communicator_, "HalfSpace3DSolver"))
    , material(material_)
    , mesh_parameters((mesh_.validate(), mesh_))
    , formulation(checked_formulation(material_, discretization_))
    , discretization((require_clamped_far_field(discretization_, "HalfSpace3DSolver"), discretization_))
    , solver_parameters((solver_.validate(), require_direct_when_mixed(solver_, formulation), solver_))
    , triangulation(communicator)
    , fe(displacement_pressure_element<3>(discretization_.degree, formulation))
    , dof_handler(triangulation)
    , mapping(discretization_.degree)
  {
    auto start = std::chrono::steady_clock::now();
    mesh_info  = make_coarse_mesh_3d(mesh_parameters, triangulation);
    refine_mesh_3d(mesh_parameters, triangulation, mesh_info);
    setup_time.mesh = elapsed_max(start, communicator);

    start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);
    owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    constraints.clear();
    constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    // (the mixed formulation's pressure, the last component, is free on every boundary)
    const FEValuesExtractors::Vector displacement(0);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::far_field,
                                             Functions::ZeroFunction<3>(fe.n_components()), constraints,
                                             fe.component_mask(displacement));
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::symmetry_plane,
                                             Functions::ZeroFunction<3>(fe.n_components()), constraints,
                                             fe.component_mask(FEValuesExtractors::Scalar(1)));
    constraints.close();

    // The contact DoFs (on faces with id `contact`, i.e. the closure of the disc) that the free constraints
    // leave free; hanging ones follow their parents, which lie on the disc too.
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::array<std::set<types::global_dof_index>, 3> found;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::contact)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const unsigned int c = fe.face_system_to_component_index(i, f).first;
                  if (c < 3 && !constraints.is_constrained(face_dofs[i]))
                    found[c].insert(face_dofs[i]);
                }
            }
    for (unsigned int c = 0; c < 3; ++c)
      contact_dofs[c].assign(found[c].begin(), found[c].end());

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator, relevant);
    stiffness.reinit(owned, owned, dsp, communicator);
    setup_time.setup = elapsed_max(start, communicator);

    start = std::chrono::steady_clock::now();
    assemble(constraints, stiffness);
    setup_time.assemble = elapsed_max(start, communicator);
  }

  HalfSpace3DSolver::~HalfSpace3DSolver()
  {
    by_mask.clear();
    dof_handler.clear();
  }



  void HalfSpace3DSolver::assemble(const AffineConstraints<double> &with, Matrix &matrix)
  {
    CellStiffness3D                      cell_stiffness(material, fe, mapping, discretization,
                                                         mesh_parameters.contact_radius, mesh_parameters.h_edge);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FullMatrix<double> &cell_matrix = cell_stiffness.matrix(cell);
          cell->get_dof_indices(local_dof_indices);
          with.distribute_local_to_global(cell_matrix, local_dof_indices, matrix);
        }
    matrix.compress(VectorOperation::add);
  }



  HalfSpace3DSolver::Constrained &HalfSpace3DSolver::constrained(const std::array<bool, 3> &prescribed)
  {
    const unsigned int mask = mask_of(prescribed);
    if (by_mask.count(mask))
      return *by_mask[mask];
    // One factorisation at a time: a 3D sparse LU takes gigabytes (fem/doc/distributed-and-3d.md, "3D model").
    by_mask.clear();
    std::unique_ptr<Constrained> &slot = by_mask[mask];
    slot = std::make_unique<Constrained>();
    Constrained &c = *slot;
    c.solver = std::make_unique<DistributedLinearSolver<3>>(solver_parameters, dof_handler, discretization.degree);
    if (mask == 0) // nothing prescribed: the free stiffness itself
      {
        c.matrix = &stiffness;
        return c;
      }
    c.constraints.clear();
    c.constraints.reinit(relevant);
    c.constraints.merge(constraints);
    for (unsigned int d = 0; d < 3; ++d)
      if (prescribed[d])
        for (const auto i : contact_dofs[d])
          c.constraints.add_line(i); // homogeneous: the solve is for the correction to the prescribed values
    c.constraints.close();
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, c.constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator, relevant);
    c.own_matrix.reinit(owned, owned, dsp, communicator);
    assemble(c.constraints, c.own_matrix);
    c.matrix = &c.own_matrix;
    return c;
  }



  HalfSpace3DResult HalfSpace3DSolver::run(const FlatPunch3D &punch)
  {
    punch.validate();
    HalfSpace3DResult result;
    result.n_dofs      = dof_handler.n_dofs();
    result.n_cells     = triangulation.n_global_active_cells();
    result.n_processes = Utilities::MPI::n_mpi_processes(communicator);
    result.mesh        = mesh_info;
    result.time        = setup_time;

    MPI_Barrier(communicator);
    const auto   start = std::chrono::steady_clock::now();
    Constrained &c     = constrained(punch.prescribed);

    // u = g + w: g the prescribed values on the free contact DoFs, w = 0 there and A w = -A g on the
    // other free rows (A condensed with the free constraints, so A g is the coupling to the disc).
    Vector g(owned, communicator), b(owned, communicator), w;
    for (unsigned int d = 0; d < 3; ++d)
      if (punch.prescribed[d])
        for (const auto i : contact_dofs[d])
          if (owned.is_element(i))
            g[i] = punch.displacement[d];
    g.compress(VectorOperation::insert);
    stiffness.vmult(b, g);
    b *= -1.0;
    for (unsigned int d = 0; d < 3; ++d)
      if (punch.prescribed[d])
        for (const auto i : contact_dofs[d])
          if (owned.is_element(i))
            b[i] = 0;
    b.compress(VectorOperation::insert);
    result.linear         = c.solver->solve(*c.matrix, b, w);
    result.time.factorize = result.linear.factorize;
    w += g;

    // Reactions and energy with the free constraints (their constrained entries zero: the condensed A).
    Vector reaction(owned, communicator);
    stiffness.vmult(reaction, w);
    const double energy = w * reaction;
    double       work   = 0;
    for (unsigned int d = 0; d < 3; ++d)
      {
        double local = 0;
        for (const auto i : contact_dofs[d])
          if (owned.is_element(i))
            local += reaction[i];
        const double half = Utilities::MPI::sum(local, communicator);
        if (punch.prescribed[d])
          work += half * punch.displacement[d];
        result.force[d] = (d == 1) ? 0.0 : 2 * half;
      }
    result.energy_mismatch = std::abs(energy - work) / std::abs(energy);
    if (!(result.energy_mismatch <= 1e-6))
      {
        std::ostringstream msg;
        msg << "energy check failed: |u.Au - work| / u.Au = " << result.energy_mismatch << " > 1e-6 (linear residual "
            << result.linear.residual << "); ";
        result.message += msg.str();
        result.reliable = false;
      }
    result.time.solve = elapsed_max(start, communicator) - result.time.factorize;

    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    result.memory_mb = Utilities::MPI::max(static_cast<double>(memory.VmHWM) / 1024, communicator);
    return result;
  }



  SurfaceCompliance3D HalfSpace3DSolver::surface_compliance(const double radius)
  {
    const double a = mesh_parameters.contact_radius, L = mesh_parameters.far_field_size * a;
    if (!(radius > 0 && radius < L))
      fem::fail("HalfSpace3DSolver::surface_compliance", "radius", radius, "(0, L)");
    const double tolerance = 1e-10 * a;

    // The surface DoFs within the radius: (x, y, component, dof, constrained) from every process.
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    using Entry = std::tuple<double, double, unsigned int, types::global_dof_index, bool>;
    std::vector<Entry>                   local;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                {
                  const unsigned int c = fe.face_system_to_component_index(i, f).first;
                  if (c >= 3) // the mixed formulation's pressure: eliminated with the interior
                    continue;
                  const Point<3> &x = support.at(face_dofs[i]);
                  if (std::hypot(x[0], x[1]) <= radius + tolerance)
                    local.emplace_back(x[0], x[1], c, face_dofs[i], constraints.is_constrained(face_dofs[i]));
                }
            }
    std::vector<Entry> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const Entry &p, const Entry &q) { return std::get<3>(p) < std::get<3>(q); });
    all.erase(std::unique(all.begin(), all.end(),
                          [](const Entry &p, const Entry &q) { return std::get<3>(p) == std::get<3>(q); }),
              all.end());
    // Nodes: the three components at one support point, ordered by (x, y).
    std::sort(all.begin(), all.end(), [&](const Entry &p, const Entry &q) {
      if (std::abs(std::get<0>(p) - std::get<0>(q)) > tolerance)
        return std::get<0>(p) < std::get<0>(q);
      if (std::abs(std::get<1>(p) - std::get<1>(q)) > tolerance)
        return std::get<1>(p) < std::get<1>(q);
      return std::get<2>(p) < std::get<2>(q);
    });

    SurfaceCompliance3D                  surface;
    std::vector<types::global_dof_index> dofs; // of the unknowns
    std::vector<types::global_dof_index> z_dofs;
    for (std::size_t k = 0; k < all.size(); k += 3)
      {
        std::array<int, 3> unknown{{-1, -1, -1}};
        for (unsigned int c = 0; c < 3; ++c)
          {
            const auto &[x, y, component, dof, is_constrained] = all.at(k + c);
            if (component != c || std::abs(x - std::get<0>(all[k])) > tolerance ||
                std::abs(y - std::get<1>(all[k])) > tolerance)
              throw std::runtime_error("HalfSpace3DSolver::surface_compliance: the surface DoFs do not come in "
                                       "triples per support point");
            if (is_constrained)
              {
                if (c != 1 || std::abs(y) > tolerance)
                  throw std::runtime_error("HalfSpace3DSolver::surface_compliance: a surface DoF within the radius "
                                           "is constrained (a hanging node); use a mesh without refinement cycles "
                                           "under the contact");
                continue; // u_y = 0 on the symmetry plane
              }
            unknown[c] = dofs.size();
            dofs.push_back(dof);
            if (c == 2)
              z_dofs.push_back(dof);
          }
        surface.nodes.emplace_back(std::get<0>(all[k]), std::get<1>(all[k]));
        surface.unknown.push_back(unknown);
      }

    // C: the block of the free body's A^{-1} on the unknowns (the displacements of the unknowns under a unit
    // nodal force on each), from the Schur complement of the assembled free stiffness.
    surface.C = inverse_on_rows(stiffness, dofs);

    // Areas: \int_{z=0} phi_i dA of the z shape functions.
    Vector                  area(owned, communicator);
    FEFaceValues<3>         face_values(mapping, fe, QGauss<2>(discretization.degree + 1),
                                        update_values | update_JxW_values);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
            {
              face_values.reinit(cell, f);
              cell->get_dof_indices(cell_dofs);
              dealii::Vector<double> cell_area(fe.n_dofs_per_cell());
              for (const unsigned int q : face_values.quadrature_point_indices())
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  if (fe.system_to_component_index(i).first == 2)
                    cell_area[i] += face_values.shape_value(i, q) * face_values.JxW(q);
              constraints.distribute_local_to_global(cell_area, cell_dofs, area);
            }
    area.compress(VectorOperation::add);
    std::vector<double> node_area(z_dofs.size(), 0.0);
    for (unsigned int i = 0; i < z_dofs.size(); ++i)
      if (owned.is_element(z_dofs[i]))
        node_area[i] = area[z_dofs[i]];
    MPI_Allreduce(MPI_IN_PLACE, node_area.data(), static_cast<int>(node_area.size()), MPI_DOUBLE, MPI_SUM,
                  communicator);
    surface.area = node_area;
    return surface;
  }
} // namespace gradcontact::fem
