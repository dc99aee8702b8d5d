#include <fem/base/errors.h>
#include <fem/base/boundary_ids.h>
#include <fem/base/contact_check.h>
#include <fem/bodies/distributed_solver.h>
#include <fem/elasticity/graded_elasticity.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    // The z-DoF at the centre (0, 0): its support point is exact, this only absorbs round-off.
    constexpr double centre_tolerance = 1e-12;
  } // namespace






  DistributedSolver::DistributedSolver(const MPI_Comm communicator_, const Material &material_,
                                       const MeshParameters &mesh_,
                                       const DiscretizationParameters &discretization_,
                                       const DistributedSolverParameters &solver_)
    : communicator(require_mpi(communicator_, "DistributedSolver"))
    , material((material_.validate(), material_))
    , mesh_parameters((mesh_.validate(), mesh_))
    , discretization((discretization_.validate(),
                      require_displacement_formulation(discretization_, material_.nu, "DistributedSolver"),
                      require_clamped_far_field(discretization_, "DistributedSolver"),
                      discretization_))
    , solver_parameters((solver_.validate(), solver_))
    , triangulation(communicator)
    , fe(FE_Q<2>(discretization_.degree), 2)
    , dof_handler(triangulation)
    , punch_solver(solver_parameters, dof_handler, discretization_.degree)
    , free_solver(solver_parameters, dof_handler, discretization_.degree)
  {
    make_grid();
    setup_system();
    assemble_system();
  }

  DistributedSolver::~DistributedSolver()
  {
    dof_handler.clear();
  }



  double DistributedSolver::elapsed_max(const std::chrono::steady_clock::time_point &start) const
  {
    const double local = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return Utilities::MPI::max(local, communicator);
  }



  void DistributedSolver::make_grid()
  {
    const auto start = std::chrono::steady_clock::now();
    // The coarse mesh of the serial solver. Process 0 makes it first, so that only one process runs
    // gmsh and the others read the cached .msh.
    Triangulation<2> coarse;
    const unsigned int rank = Utilities::MPI::this_mpi_process(communicator);
    if (rank == 0)
      mesh_info = make_coarse_mesh(mesh_parameters, coarse);
    MPI_Barrier(communicator);
    if (rank != 0)
      mesh_info = make_coarse_mesh(mesh_parameters, coarse);
    triangulation.copy_triangulation(coarse);
    refine_mesh(mesh_parameters, triangulation, mesh_info);
    setup_time.mesh = elapsed_max(start);
  }



  void DistributedSolver::setup_system()
  {
    const auto start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);
    owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    constraints.clear();
    constraints.reinit(relevant);
    make_homogeneous_constraints(dof_handler, mapping, fe, constraints);

    // The unit punch: the homogeneous constraints plus u_z = 1 on the z-DoFs of the contact faces
    // (every locally relevant one, i.e. on owned and ghost cells). As in the serial solver no contact
    // DoF is constrained otherwise (a boundary face is never the refined side of a hanging node in 2D).
    punch_constraints.clear();
    punch_constraints.reinit(relevant);
    punch_constraints.merge(constraints);
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    owned_contact_dofs.clear();
    centre_dof = numbers::invalid_dof_index;
    std::vector<Point<2>> unit_support = fe.get_unit_support_points();
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::contact)
            {
              cell->face(f)->get_dof_indices(face_dofs);
              for (unsigned int i = 0; i < face_dofs.size(); ++i)
                if (fe.face_system_to_component_index(i, f).first == 1)
                  {
                    const auto d = face_dofs[i];
                    if (constraints.is_constrained(d))
                      throw std::runtime_error("DistributedSolver: a contact z-DoF is constrained; the "
                                               "flat punch assumes it is not");
                    if (!punch_constraints.is_constrained(d))
                      {
                        punch_constraints.add_line(d);
                        punch_constraints.set_inhomogeneity(d, 1.0);
                        if (owned.is_element(d))
                          owned_contact_dofs.push_back(d);
                      }
                  }
            }
    punch_constraints.close();

    // The radii of the owned contact z-DoFs (the indenter's prescribed u_z = -f(r)) and the edge DoF.
    {
      std::map<types::global_dof_index, Point<2>> support;
      DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
      owned_contact_r.clear();
      edge_dof = numbers::invalid_dof_index;
      for (const auto d : owned_contact_dofs)
        {
          const double r = support.at(d)[0];
          owned_contact_r.push_back(r);
          if (std::abs(r - mesh_parameters.contact_radius) < 1e-9 * mesh_parameters.contact_radius)
            edge_dof = d;
        }
      const int edges = Utilities::MPI::sum(edge_dof != numbers::invalid_dof_index ? 1 : 0, communicator);
      if (edges != 1)
        throw std::runtime_error("DistributedSolver: found " + std::to_string(edges) +
                                 " contact z-DoFs at the contact edge r = a; expected one");
    }

    // The centre z-DoF, on the owner of a cell with the vertex (0, 0): its value is w_c.
    const double a = mesh_parameters.contact_radius;
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() < centre_tolerance * a)
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                if (fe.system_to_component_index(i).first == 1 && owned.is_element(cell_dofs[i]) &&
                    unit_support[i].distance(GeometryInfo<2>::unit_cell_vertex(v)) < 1e-12)
                  centre_dof = cell_dofs[i];
            }

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, communicator, relevant);
    stiffness.reinit(owned, owned, dsp, communicator);
    punch_matrix.reinit(owned, owned, dsp, communicator);
    unit_punch_rhs.reinit(owned, communicator);
    setup_time.setup = elapsed_max(start);
  }



  void DistributedSolver::assemble_system()
  {
    const auto start = std::chrono::steady_clock::now();
    // K_cell: fem/elasticity/graded_elasticity.h (shared with the serial solver). The unit punch right-hand
    // side is -A g_1 on the free DoFs, g_1 the unit prescribed values (deal.II's elimination of
    // inhomogeneous constraints, with the constrained rows carrying a diagonal entry only).
    CellStiffness                        cell_stiffness(material, fe, mapping, discretization,
                                                         mesh_parameters.contact_radius, mesh_parameters.h_edge);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    dealii::Vector<double>               cell_rhs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FullMatrix<double> &cell_matrix = cell_stiffness.matrix(cell);
          cell->get_dof_indices(local_dof_indices);
          constraints.distribute_local_to_global(cell_matrix, local_dof_indices, stiffness);
          cell_rhs = 0;
          punch_constraints.distribute_local_to_global(cell_matrix, cell_rhs, local_dof_indices, punch_matrix,
                                                       unit_punch_rhs, true);
        }
    stiffness.compress(VectorOperation::add);
    punch_matrix.compress(VectorOperation::add);
    unit_punch_rhs.compress(VectorOperation::add);
    setup_time.assemble = elapsed_max(start);
  }



  void DistributedSolver::solve(const bool contact_constrained, const Vector &b, Vector &u,
                                DistributedResult &result)
  {
    const LinearSolveReport report =
      (contact_constrained ? punch_solver : free_solver).solve(contact_constrained ? punch_matrix : stiffness, b, u);
    result.solver         = report.solver;
    result.iterations     = report.iterations;
    result.residual       = report.residual;
    result.time.factorize = report.factorize;
  }



  double DistributedSolver::solve_flat_punch(const LoadCase &load, Vector &u, DistributedResult &result)
  {
    double work = 0;
    // u = d u1: the unit punch scaled, exact by linearity (the constraints carry u_z = 1).
    solve(true, unit_punch_rhs, u, result);
    punch_constraints.distribute(u);
    u *= load.depth;
    Vector reaction(owned, communicator);
    stiffness.vmult(reaction, u);
    double force = 0;
    for (const auto d : owned_contact_dofs)
      force += reaction[d];
    force        = Utilities::MPI::sum(force, communicator);
    work         = force * load.depth;
    result.force = 2 * numbers::PI * force;
    result.depth = load.depth;
    return work;
  }



  double DistributedSolver::solve_indenter(const LoadCase &load, Vector &u, DistributedResult &result)
  {
    const double a = mesh_parameters.contact_radius;
    double       work = 0;
    // u = d u1 + u2 (axisymmetric_solver.cc, LoadType::indenter): u1 the unit punch, u2 with
    // u_z = g2 = -f(r) on the contact z-DoFs. Its right-hand side is -A g2 on the free rows; A was
    // assembled with the homogeneous constraints only, so (A g2)_i is the coupling of row i to the
    // contact DoFs, and zero on rows constrained by `constraints`. The contact rows of the
    // contact-constrained matrix are decoupled (diagonal only) and overwritten after the solve.
    Vector u1, u2, g2(owned, communicator), b2(owned, communicator);
    solve(true, unit_punch_rhs, u1, result);
    const double factorize = result.time.factorize;
    punch_constraints.distribute(u1);
    for (std::size_t i = 0; i < owned_contact_dofs.size(); ++i)
      g2[owned_contact_dofs[i]] = -load.profile(owned_contact_r[i], a);
    g2.compress(VectorOperation::insert);
    stiffness.vmult(b2, g2);
    b2 *= -1.0;
    for (const auto d : owned_contact_dofs)
      b2[d] = 0;
    b2.compress(VectorOperation::insert);
    solve(true, b2, u2, result);
    result.time.factorize = factorize;
    for (const auto d : owned_contact_dofs)
      u2[d] = g2[d];
    u2.compress(VectorOperation::insert);
    constraints.distribute(u2);
    Vector reaction1(owned, communicator), reaction2(owned, communicator);
    stiffness.vmult(reaction1, u1);
    stiffness.vmult(reaction2, u2);
    const bool   owner = edge_dof != numbers::invalid_dof_index;
    const double r1 = Utilities::MPI::sum(owner ? reaction1[edge_dof] : 0.0, communicator);
    const double r2 = Utilities::MPI::sum(owner ? reaction2[edge_dof] : 0.0, communicator);
    const double d  = -r2 / r1;
    u = u2;
    u.add(d, u1);
    double force = 0, work_local = 0;
    std::vector<std::pair<double, double>> local_forces; // (r, R) of the owned contact DoFs
    for (std::size_t k = 0; k < owned_contact_dofs.size(); ++k)
      {
        const auto   i = owned_contact_dofs[k];
        const double R = d * reaction1[i] + reaction2[i];
        force += R;
        work_local += R * u[i];
        local_forces.emplace_back(owned_contact_r[k], R);
      }
    force = Utilities::MPI::sum(force, communicator);
    work  = Utilities::MPI::sum(work_local, communicator);
    result.force = 2 * numbers::PI * force;
    result.depth = d;
    // The sign check of fem/base/contact_check.h on all contact forces ordered by radius (a few hundred).
    std::vector<std::pair<double, double>> all_forces;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local_forces))
      all_forces.insert(all_forces.end(), part.begin(), part.end());
    std::sort(all_forces.begin(), all_forces.end());
    std::vector<double> forces;
    for (const auto &[r, R] : all_forces)
      forces.push_back(R);
    result.min_relative_contact_force = min_relative_contact_force(forces);
    if (result.min_relative_contact_force < -consistency_tolerance)
      {
        result.consistent_contact = false;
        std::ostringstream msg;
        msg << "tensile nodal contact force (min/max = " << result.min_relative_contact_force << "); ";
        result.message += msg.str();
      }
    return work;
  }



  double DistributedSolver::solve_pressure(const LoadCase &load, Vector &u, DistributedResult &result)
  {
    const double a = mesh_parameters.contact_radius;
    Vector       b;
    double       work = 0;
    // l(v) = \int_{contact} p0 v_z r dr (fem/elasticity/graded_elasticity.h).
    b.reinit(owned, communicator);
    CellPressureLoad                     cell_load(fe, mapping, discretization);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    bool                                 loaded = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const dealii::Vector<double> &cell_rhs = cell_load.vector(cell, load.pressure, loaded);
          if (!loaded)
            continue;
          cell->get_dof_indices(local_dof_indices);
          constraints.distribute_local_to_global(cell_rhs, local_dof_indices, b);
        }
    b.compress(VectorOperation::add);
    solve(false, b, u, result);
    constraints.distribute(u);
    work         = b * u;
    result.force = numbers::PI * load.pressure * a * a; // 2 pi \int_0^a p0 r dr
    const double centre =
      (centre_dof != numbers::invalid_dof_index) ? u[centre_dof] : 0.0;
    // Exactly one process owns the centre z-DoF.
    result.depth = Utilities::MPI::sum(centre, communicator);
    return work;
  }



  DistributedResult DistributedSolver::run(const LoadCase &load)
  {
    load.validate();
    if (load.type != LoadType::flat_punch && load.type != LoadType::constant_pressure &&
        load.type != LoadType::indenter)
      throw std::invalid_argument("DistributedSolver::run: LoadCase::type = " +
                                  std::to_string(static_cast<int>(load.type)) +
                                  " is not supported; valid: flat_punch, constant_pressure, indenter "
                                  "(contact-radius control)");
    const double      a = mesh_parameters.contact_radius;
    DistributedResult result;
    result.start(setup_time, dof_handler.n_dofs(), triangulation.n_global_active_cells(), mesh_info);
    result.n_processes = Utilities::MPI::n_mpi_processes(communicator);
    result.contact_radius = a;

    MPI_Barrier(communicator);
    const auto start = std::chrono::steady_clock::now();
    double work = 0; // work of the loads, per 2 pi
    Vector u;
    switch (load.type)
      {
        case LoadType::flat_punch:
          work = solve_flat_punch(load, u, result);
          break;
        case LoadType::indenter:
          work = solve_indenter(load, u, result);
          break;
        default:
          work = solve_pressure(load, u, result);
      }

    // Energy on the unconstrained DoFs (the constrained rows of A carry a diagonal entry only).
    Vector u_free(u), Au(owned, communicator);
    constraints.set_zero(u_free);
    stiffness.vmult(Au, u_free);
    const double       energy = u_free * Au;
    std::ostringstream residual;
    residual << "linear residual " << result.residual;
    result.record(check_energy(energy, work, mesh_info.min_surface_cell, residual.str()));
    result.time.solve = elapsed_max(start) - result.time.factorize;
    return result;
  }
  DistributedResult solve_controlled(MPI_Comm communicator, const Material &material, const LoadCase &load,
                                     const SettingsAtRadius &settings, const double a0, const double tolerance,
                                     const unsigned int max_trials, const DistributedSolverParameters &solver)
  {
    const char *where = "solve_controlled";
    load.validate();
    const bool by_depth = load.type == LoadType::indenter_depth;
    if (!by_depth && load.type != LoadType::indenter_force)
      throw std::invalid_argument(std::string(where) + ": LoadCase::type = " + std::to_string(static_cast<int>(load.type)) +
                                  " is not indenter_depth or indenter_force");
    if (!(a0 > 0) || !std::isfinite(a0))
      fail(where, "a0 (first contact radius)", a0, "(0, inf)");
    if (!(tolerance >= 1e-14 && tolerance < 1))
      fail(where, "tolerance", tolerance, "[1e-14, 1)");
    if (max_trials < 3 || max_trials > 100)
      fail(where, "max_trials", max_trials, "[3, 100]");
    if (!settings)
      throw std::invalid_argument(std::string(where) + ": the settings function is empty");
    const double target = by_depth ? load.depth : load.force;

    LoadCase radius_controlled = load;
    radius_controlled.type     = LoadType::indenter;
    // log(value(a) / target) of a radius-controlled state at a (every process solves the same state).
    DistributedResult last;
    const auto        trial = [&](const double a) {
      Settings st            = settings(a);
      st.mesh.contact_radius = a;
      DistributedSolver s(communicator, material, st.mesh, st.discretization, solver);
      const unsigned int trials = last.control_trials;
      last                      = s.run(radius_controlled);
      last.control_trials       = trials + 1;
      const double value        = by_depth ? last.depth : last.force;
      if (!(value > 0) || !last.reliable)
        {
          std::ostringstream msg;
          msg << where << ": the radius-controlled state at a = " << a << " has " << (by_depth ? "depth " : "force ")
              << value << (last.reliable ? "" : " and is unreliable: " + last.message);
          throw std::runtime_error(msg.str());
        }
      return std::log(value / target);
    };
    double x0 = std::log(a0), y0 = trial(a0);
    if (std::abs(y0) <= tolerance)
      return last;
    // First step toward the target: d and F grow with a.
    double x1 = x0 + (y0 < 0 ? 1 : -1) * std::log(1.05), y1 = trial(std::exp(x1));
    while (std::abs(y1) > tolerance)
      {
        if (std::abs(x1 - x0) <= 1e-9)
          {
            // a no longer moves: the value's round-off (an ill-conditioned system) is above the tolerance.
            std::ostringstream msg;
            msg << " " << where << ": stopped at the round-off of " << (by_depth ? "d(a)" : "F(a)") << ", relative "
                << std::expm1(y1) << " off the target (tolerance " << tolerance << ", " << last.control_trials
                << " trials);";
            last.message += msg.str();
            return last;
          }
        if (!((y1 - y0) * (x1 - x0) > 0))
          {
            std::ostringstream msg;
            msg << where << ": " << (by_depth ? "d(a)" : "F(a)") << " does not grow with a between a = " << std::exp(x0)
                << " and " << std::exp(x1) << " (" << last.control_trials << " trials)";
            throw std::runtime_error(msg.str());
          }
        if (last.control_trials >= max_trials)
          {
            std::ostringstream msg;
            msg.precision(10);
            msg << where << ": no contact radius after " << last.control_trials << " radius-controlled states: the last, a = "
                << std::exp(x1) << ", has " << (by_depth ? "d = " : "F = ") << target * std::exp(y1) << " for "
                << target << " (relative " << std::expm1(y1) << ", tolerance " << tolerance << ")";
            throw std::runtime_error(msg.str());
          }
        const double step = std::clamp(-y1 * (x1 - x0) / (y1 - y0), -std::log(2.0), std::log(2.0));
        x0                = x1;
        y0                = y1;
        x1                = x1 + step;
        y1                = trial(std::exp(x1));
      }
    return last;
  }

} // namespace gradcontact::fem
