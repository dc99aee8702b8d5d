#include <fem/bodies/axisymmetric_solver.h>
#include <fem/io/vtu_output.h>
#include <fem/base/boundary_ids.h>
#include <fem/base/contact_check.h>
#include <fem/base/errors.h>
#include <fem/elasticity/graded_elasticity.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    // Depth and force control: at most this many trial contact sets, and at most this many surface
    // DoFs whose state differs from the mesh's contact zone (one back-substitution and two vectors
    // each). A search that needs more stops with a message: the mesh's contact radius is too far from
    // the answer (remesh at the reported radius).
    constexpr unsigned int max_control_iterations = 60;
    constexpr unsigned int max_modified_dofs      = 200;
  } // namespace






  AxisymmetricSolver::AxisymmetricSolver(const Material &material_,
                                         const MeshParameters &mesh_,
                                         const DiscretizationParameters &discretization_,
                                         const SurfaceRefinement        &refinement_)
    : material((checked_formulation(material_, discretization_), material_))
    , mesh_parameters((mesh_.validate(), mesh_))
    , discretization(discretization_)
    , refinement(refinement_)
    , used_formulation(resolve_formulation(discretization_, material_.nu))
    , fe(axisymmetric_element(discretization_.degree, used_formulation))
    , dof_handler(triangulation)
  {
    make_grid();
    setup_system();
    assemble_system();
  }

  AxisymmetricSolver::~AxisymmetricSolver()
  {
    dof_handler.clear();
  }



  void AxisymmetricSolver::make_grid()
  {
    const auto start = std::chrono::steady_clock::now();
    mesh_info        = make_mesh(mesh_parameters, triangulation);
    refine_toward_surface_points(refinement, triangulation);
    setup_time.mesh  = seconds_since(start);
  }



  void AxisymmetricSolver::setup_system()
  {
    const auto start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);

    // Homogeneous constraints shared by every load: hanging nodes (z-only halvings, edge refinement),
    // u_r = 0 on the axis, u = 0 on the truncation boundary unless the far field is condensed onto it.
    const bool condensed = discretization.far_field == FarField::condensed;
    constraints.clear();
    make_homogeneous_constraints(dof_handler, mapping, fe, constraints, !condensed);
    // The mixed formulation's pressure is component 2 (u_r, u_z, q).
    const unsigned int pressure =
      used_formulation == Formulation::mixed ? 2u : dealii::numbers::invalid_unsigned_int;
    system.reinit(dof_handler, constraints,
                  condensed ? std::make_unique<FarFieldRings>(dof_handler, mapping, constraints, mesh_parameters,
                                                              mesh_info, pressure) :
                              nullptr);

    dof_r = support_radii(mapping, dof_handler);

    // The surface faces with their z-DoFs, and the contact DoFs (on faces with id `contact`, hence
    // r <= a). In 2D a boundary face is never the refined side of a hanging node, so no contact DoF
    // is constrained (only the free-surface node at r = L is, by the far-field condition).
    const double a = mesh_parameters.contact_radius;
    surface_faces  = collect_surface_faces(dof_handler, dof_r, 2);
    contact_dofs.clear();
    for (const SurfaceFace &face : surface_faces)
      if (face.contact)
        for (const auto d : face.dofs[1])
          {
            AssertThrow(!constraints.is_constrained(d),
                        ExcMessage("surface DoF at r = " + std::to_string(dof_r[d]) +
                                   " is constrained; the contact set assumes it is not"));
            contact_dofs.push_back(d);
          }
    std::sort(contact_dofs.begin(), contact_dofs.end());
    contact_dofs.erase(std::unique(contact_dofs.begin(), contact_dofs.end()), contact_dofs.end());
    std::sort(contact_dofs.begin(), contact_dofs.end(),
              [&](const auto x, const auto y) { return dof_r[x] < dof_r[y]; });
    contact_r.clear();
    for (const auto d : contact_dofs)
      contact_r.push_back(dof_r[d]);
    AssertThrow(!contact_dofs.empty() && std::abs(contact_r.back() - a) < node_tolerance * a,
                ExcMessage("the contact zone must end in a node at r = a"));

    // All surface z-DoFs and vertices, ascending r: the candidates of depth and force control.
    surface_dofs.clear();
    surface_vertex_r.clear();
    for (const SurfaceFace &face : surface_faces)
      {
        surface_dofs.insert(surface_dofs.end(), face.dofs[1].begin(), face.dofs[1].end());
        surface_vertex_r.push_back(face.r0);
        surface_vertex_r.push_back(face.r1);
      }
    std::sort(surface_dofs.begin(), surface_dofs.end());
    surface_dofs.erase(std::unique(surface_dofs.begin(), surface_dofs.end()), surface_dofs.end());
    std::sort(surface_dofs.begin(), surface_dofs.end(),
              [&](const auto x, const auto y) { return dof_r[x] < dof_r[y]; });
    std::sort(surface_vertex_r.begin(), surface_vertex_r.end());
    surface_vertex_r.erase(std::unique(surface_vertex_r.begin(), surface_vertex_r.end(),
                                       [&](const double x, const double y) {
                                         return std::abs(x - y) <= node_tolerance * a;
                                       }),
                           surface_vertex_r.end());

    setup_time.setup = seconds_since(start);
  }



  void AxisymmetricSolver::assemble_system()
  {
    const auto start = std::chrono::steady_clock::now();
    CellStiffness cell_stiffness(material, fe, mapping, discretization, mesh_parameters.contact_radius,
                                mesh_parameters.h_edge);
    // P: the contact z-DoFs of every rigid-contact load
    system.assemble(dof_handler, cell_stiffness, contact_dofs);
    // u_z = 1 is rigid: the reactions of the surface rows are summed from displacement differences (DirectSystem).
    Vector<double>    translation(dof_handler.n_dofs());
    std::vector<bool> u_z(fe.n_components(), false);
    u_z[1] = true;
    for (const auto d : DoFTools::extract_dofs(dof_handler, ComponentMask(u_z)))
      translation[d] = 1.0;
    system.set_translation(translation);
    setup_time.assemble = seconds_since(start);
  }



  Vector<double> AxisymmetricSolver::pressure_load(const double p0) const
  {
    // l(v) = \int_{contact} p0 v_z r dr (fem/elasticity/graded_elasticity.h).
    Vector<double>                       b(dof_handler.n_dofs());
    CellPressureLoad                     cell_load(fe, mapping, discretization);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    bool                                 loaded = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Vector<double> &cell_rhs = cell_load.vector(cell, p0, loaded);
        if (!loaded)
          continue;
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_rhs, local_dof_indices, b);
      }
    return b;
  }



  Vector<double> AxisymmetricSolver::cohesion_load(const Cohesion &cohesion) const
  {
    // b_i = -\int_{r <= c} sigma_0 phi_i r dr on the z-DoFs: the tension pulls the surface out (-z).
    Vector<double> b(dof_handler.n_dofs());
    if (!cohesion.active())
      return b;
    if (cohesion.radius >= surface_faces.back().r1)
      fail("AxisymmetricSolver::run (cohesion)", "radius", cohesion.radius,
           "(0, " + std::to_string(surface_faces.back().r1) + ") (inside the truncation radius)");
    const double   stress    = cohesion.stress;
    const auto     integrals = traction_integrals(surface_faces, [stress](double) { return -stress; }, cohesion.radius,
                                                  {}, GradedRule{}, "LoadCase (cohesion)");
    for (unsigned int k = 0; k < surface_faces.size(); ++k)
      for (unsigned int i = 0; i < surface_faces[k].r.size(); ++i)
        b[surface_faces[k].dofs[1][i]] += integrals[k][i];
    return b;
  }



  double AxisymmetricSolver::evaluate_on_surface(const std::vector<double> &nodal, const double r,
                                                 const double contact_edge) const
  {
    // `nodal` is indexed by global DoF; with contact_edge >= 0 only faces on r <= contact_edge count.
    const bool         contact_only = contact_edge >= 0;
    const SurfaceFace *face =
      find_face(surface_faces, r, contact_only ? contact_edge : std::numeric_limits<double>::max());
    if (face)
      return face_value(*face, 1, nodal, r);
    std::ostringstream msg;
    msg << "sample radius r = " << r << " outside the " << (contact_only ? "contact zone" : "surface")
        << " [0, " << (contact_only ? contact_edge : surface_faces.back().r1) << "]";
    throw std::invalid_argument(msg.str());
  }



  const std::pair<Vector<double>, Vector<double>> &
  AxisymmetricSolver::column(const types::global_dof_index dof)
  {
    auto it = columns.find(dof);
    if (it != columns.end())
      return it->second;
    if (columns.size() >= max_modified_dofs)
      {
        std::ostringstream msg;
        msg << "depth/force control: more than " << max_modified_dofs
            << " surface DoFs differ from the mesh's contact zone r <= " << mesh_parameters.contact_radius
            << " (next at r = " << dof_r[dof]
            << "); build the mesh with a contact radius closer to the answer";
        throw std::runtime_error(msg.str());
      }
    const unsigned int   m = contact_dofs.size();
    std::vector<double>  g(m, 0.0);
    Vector<double>       b(dof_handler.n_dofs()), reaction;
    const auto           in_contact = std::find(contact_dofs.begin(), contact_dofs.end(), dof);
    if (in_contact != contact_dofs.end())
      g[in_contact - contact_dofs.begin()] = 1.0; // prescribed value 1 at dof
    else
      b[dof] = 1.0;                               // unit point load at dof
    double         unused;
    Vector<double> c = system.solve(true, g, b, reaction, unused);
    reaction += b; // A c
    return columns.emplace(dof, std::make_pair(std::move(c), std::move(reaction))).first->second;
  }



  AxisymmetricSolver::TrialSet
  AxisymmetricSolver::trial_set(const unsigned int vertex, const Profile &profile,
                                const Vector<double> &u1, const Vector<double> &u2,
                                const Vector<double> &Au1, const Vector<double> &Au2)
  {
    // The radius-controlled state of the contact set C = {surface z-DoFs with r <= r_e}, from the
    // factorisation of the mesh's contact zone C_a = {r <= a}: u = d U1 + U2 with
    //   U_i = u_i + sum_{m in Delta} gamma_{i,m} c_m,    Delta = C xor C_a,
    // c_m = column(m). For m in C \ C_a (r_e > a) c_m carries a unit point load at m and the condition
    // is the prescribed value, U1_l = 1, U2_l = -f(r_l); gamma is then the contact force at l. For
    // m in C_a \ C (r_e < a) c_m carries a unit prescribed value at m and the condition is a free node,
    // (A U)_l = 0. Both give a dense |Delta| x |Delta| system. The depth is the one at which the edge
    // node carries no force, d = -(A U2)_e / (A U1)_e, as for LoadType::indenter.
    const double a     = mesh_parameters.contact_radius;
    const double r_e   = surface_vertex_r[vertex];
    const double limit = r_e * (1 + node_tolerance) + node_tolerance * a;
    TrialSet     t;
    t.vertex = vertex;
    std::vector<types::global_dof_index> delta;
    types::global_dof_index              edge = numbers::invalid_dof_index;
    for (const auto d : surface_dofs)
      if (dof_r[d] <= limit)
        {
          t.active.push_back(d);
          edge = d; // ascending r: the last is the edge node
          if (dof_r[d] > a * (1 + node_tolerance))
            delta.push_back(d);
        }
      else if (dof_r[d] <= a * (1 + node_tolerance))
        delta.push_back(d);
    const bool grow = r_e > a * (1 + node_tolerance);

    t.U1  = u1;
    t.U2  = u2;
    t.AU1 = Au1;
    t.AU2 = Au2;
    const unsigned int n = delta.size();
    if (n > 0)
      {
        LAPACKFullMatrix<double> M(n, n);
        Vector<double>           rhs1(n), rhs2(n);
        for (unsigned int l = 0; l < n; ++l)
          {
            const auto dl = delta[l];
            for (unsigned int m = 0; m < n; ++m)
              {
                const auto &c = column(delta[m]);
                M(l, m)       = grow ? c.first[dl] : c.second[dl];
              }
            rhs1[l] = grow ? 1.0 - u1[dl] : -Au1[dl];
            rhs2[l] = grow ? -profile(dof_r[dl], a) - u2[dl] : -Au2[dl];
          }
        M.compute_lu_factorization();
        M.solve(rhs1);
        M.solve(rhs2);
        for (unsigned int m = 0; m < n; ++m)
          {
            const auto &c = column(delta[m]);
            t.U1.add(rhs1[m], c.first);
            t.U2.add(rhs2[m], c.first);
            t.AU1.add(rhs1[m], c.second);
            t.AU2.add(rhs2[m], c.second);
          }
      }
    t.depth = -t.AU2[edge] / t.AU1[edge];
    for (const auto d : t.active)
      {
        t.F1 += t.AU1[d];
        t.F2 += t.AU2[d];
      }
    return t;
  }



  /// The bracketing search of depth and force control over the surface vertices j: the value of
  /// trial j is the radius-controlled depth d_j (depth control) or force F(d_j) / (2 pi) (force
  /// control) of the contact set {r <= r_j}, which grows with j. Trials are computed on first use and
  /// kept; their count is bounded (max_control_iterations) and every failure names it.
  class AxisymmetricSolver::ContactSetSearch
  {
  public:
    ContactSetSearch(AxisymmetricSolver &solver, const LoadCase &load, const Vector<double> &u1,
                     const Vector<double> &u2, const Vector<double> &Au1, const Vector<double> &Au2)
      : solver(solver), load(load), by_depth(load.type == LoadType::indenter_depth)
      , target(by_depth ? load.depth : load.force / (2 * numbers::PI)), u1(u1), u2(u2), Au1(Au1), Au2(Au2)
    {}

    /// d_j or F(d_j) / (2 pi).
    double value(const unsigned int j)
    {
      const TrialSet &t = trial(j);
      return by_depth ? t.depth : t.depth * t.F1 + t.F2;
    }

    const TrialSet &trial(const unsigned int j)
    {
      auto it = trials.find(j);
      if (it != trials.end())
        return it->second;
      if (trials.size() >= max_control_iterations)
        {
          std::ostringstream msg;
          msg << "depth/force control did not converge: " << trials.size() << " trial contact sets, the last with "
              << trials.rbegin()->second.active.size() << " contact DoFs (edge r = "
              << solver.surface_vertex_r[trials.rbegin()->first] << ")";
          throw std::runtime_error(msg.str());
        }
      try
        {
          return trials.emplace(j, solver.trial_set(j, load.profile, u1, u2, Au1, Au2)).first->second;
        }
      catch (const std::runtime_error &e)
        {
          std::ostringstream msg;
          msg << "depth/force control stopped after " << trials.size() << " trial contact sets (last set: "
              << last_set_size() << " contact DoFs): " << e.what();
          throw std::runtime_error(msg.str());
        }
    }

    [[noreturn]] void fail(const std::string &why) const
    {
      std::ostringstream msg;
      msg << "depth/force control: " << why << " (" << (by_depth ? "depth " : "force ")
          << (by_depth ? load.depth : load.force) << ", " << trials.size() << " trial contact sets, the last with "
          << last_set_size() << " contact DoFs)";
      throw std::runtime_error(msg.str());
    }

    /// The vertices lo < hi = lo + 1 with value(lo) <= target < value(hi): from a start vertex, steps
    /// doubling outward or inward until bracketed, then bisection.
    std::pair<unsigned int, unsigned int> bracket(const unsigned int start_vertex, const unsigned int j_max)
    {
      const std::string near_field = std::to_string(solver.mesh_parameters.near_field_size);
      unsigned int      lo, hi, step = 1;
      if (value(start_vertex) <= target)
        for (lo = start_vertex;; lo = hi, step *= 2)
          {
            if (lo == j_max)
              fail("the contact would leave the near field r <= " + near_field + " a");
            hi = std::min(lo + step, j_max);
            if (value(hi) > target)
              break;
          }
      else
        for (hi = start_vertex;; hi = lo, step *= 2)
          {
            if (hi <= 1)
              fail("no contact beyond the axis node: the load is too small for this mesh");
            lo = (hi > step + 1) ? hi - step : 1;
            if (value(lo) <= target)
              break;
          }
      while (hi - lo > 1)
        {
          const unsigned int mid = (lo + hi) / 2;
          (value(mid) <= target ? lo : hi) = mid;
        }
      return {lo, hi};
    }

    unsigned int n_trials() const { return trials.size(); }

    AxisymmetricSolver &solver;
    const LoadCase     &load;
    const bool          by_depth;
    const double        target; ///< d, or F / (2 pi)

  private:
    std::size_t last_set_size() const { return trials.empty() ? 0 : trials.rbegin()->second.active.size(); }

    const Vector<double>            &u1, &u2, &Au1, &Au2;
    std::map<unsigned int, TrialSet> trials;
  };



  SurfaceFlexibility AxisymmetricSolver::surface_flexibility()
  {
    const auto         start = std::chrono::steady_clock::now();
    SurfaceFlexibility flexibility;
    flexibility.faces = surface_faces;
    for (const auto d : surface_dofs)
      {
        if (!constraints.is_constrained(d))
          {
            flexibility.dofs.push_back(d);
            flexibility.r.push_back(dof_r[d]);
          }
        else if (constraints.get_constraint_entries(d) && !constraints.get_constraint_entries(d)->empty())
          throw std::logic_error("AxisymmetricSolver::surface_flexibility: the surface z-DoF at r = " +
                                 std::to_string(dof_r[d]) + " is constrained to other DoFs (a hanging node)");
      }
    flexibility.matrix  = system.inverse_block(flexibility.dofs);
    flexibility.seconds = seconds_since(start);
    return flexibility;
  }



  Result AxisymmetricSolver::run(const LoadCase &load, const OutputRequest &outputs)
  {
    load.validate();
    Result result;
    result.start(setup_time, dof_handler.n_dofs(), triangulation.n_active_cells(), mesh_info);
    record_far_field(system.far_field_exterior(), result);
    result.formulation      = used_formulation;
    result.contact_radius   = mesh_parameters.contact_radius;
    result.edge_node_radius = mesh_parameters.contact_radius;

    const auto  start = std::chrono::steady_clock::now();
    const State state = (load.type == LoadType::constant_pressure) ? solve_pressure(load, result) :
                        (load.type == LoadType::indenter_depth || load.type == LoadType::indenter_force) ?
                                                                     solve_depth_or_force_controlled(load, result) :
                                                                     solve_radius_controlled(load, result);
    result.active_set_size = state.constrained ? state.active.size() : 0;
    check(load, state, result);
    result.time.solve = seconds_since(start) - result.time.factorize;

    const auto post = std::chrono::steady_clock::now();
    sample(load, state, outputs, result);
    result.time.postprocess = seconds_since(post);
    return result;
  }



  AxisymmetricSolver::State AxisymmetricSolver::solve_radius_controlled(const LoadCase &load, Result &result)
  {
    const double         a = mesh_parameters.contact_radius;
    const unsigned int   m = contact_dofs.size();
    const Vector<double> no_load(dof_handler.n_dofs());
    State                state;
    state.active       = contact_dofs;
    state.contact_edge = a;
    state.g.resize(m);
    switch (load.type)
      {
        case LoadType::flat_punch:
          std::fill(state.g.begin(), state.g.end(), load.depth);
          state.u      = system.solve(true, state.g, no_load, state.reaction, result.time.factorize);
          result.depth = load.depth;
          break;
        case LoadType::concave_punch:
          for (unsigned int i = 0; i < m; ++i)
            state.g[i] = load.depth - load.profile(contact_r[i], a);
          state.u      = system.solve(true, state.g, no_load, state.reaction, result.time.factorize);
          result.depth = load.depth;
          break;
        case LoadType::indenter:
          {
            // u = d u1 + u2 with u1: u_z = 1 on the contact, u2: u_z = -f(r) there; d from R_edge = 0.
            // A cohesion loads u2 (its tension on the contact only shifts the reactions there).
            if (load.cohesion.active() && load.cohesion.radius < a * (1 - node_tolerance))
              fail("AxisymmetricSolver::run (cohesion)", "radius", load.cohesion.radius,
                   "[a, L) with a = " + std::to_string(a) + " (the cohesive zone starts at the contact edge)");
            // u1 and the profile's part are kept (indenter_basis); a cohesion adds u_t: u_z = 0 on the contact
            // under its tension, so u2 = u_f + u_t (linear: the same as one solve with both, to round-off).
            std::vector<double> g2(m);
            for (unsigned int i = 0; i < m; ++i)
              g2[i] = -load.profile(contact_r[i], a);
            if (!indenter_basis || indenter_basis->profile_values != g2)
              {
                auto basis = std::make_unique<IndenterBasis>();
                basis->profile_values = g2;
                basis->u1  = system.solve(true, std::vector<double>(m, 1.0), no_load, basis->reaction1,
                                          result.time.factorize);
                double unused;
                basis->u_f = system.solve(true, g2, no_load, basis->reaction_f, unused);
                indenter_basis = std::move(basis);
              }
            const IndenterBasis &basis = *indenter_basis;
            Vector<double> u2 = basis.u_f, reaction2 = basis.reaction_f;
            const Vector<double> b2 = cohesion_load(load.cohesion);
            if (load.cohesion.active())
              {
                Vector<double> reaction_t;
                double         unused;
                u2 += system.solve(true, std::vector<double>(m, 0.0), b2, reaction_t, unused);
                reaction2 += reaction_t;
              }
            const auto   edge = contact_dofs.back();
            const double d    = -reaction2[edge] / basis.reaction1[edge];
            state.u = u2;
            state.u.add(d, basis.u1);
            state.reaction = reaction2;
            state.reaction.add(d, basis.reaction1);
            for (unsigned int i = 0; i < m; ++i)
              state.g[i] = d - load.profile(contact_r[i], a);
            state.work   = b2 * state.u;
            result.depth = d;
            break;
          }
        default:
          Assert(false, ExcInternalError());
      }
    return state;
  }



  AxisymmetricSolver::State AxisymmetricSolver::solve_pressure(const LoadCase &load, Result &result)
  {
    State state;
    state.constrained        = false;
    state.contact_edge       = mesh_parameters.contact_radius;
    Vector<double> b = pressure_load(load.pressure);
    b += cohesion_load(load.cohesion);
    state.u                  = system.solve(false, {}, b, state.reaction, result.time.factorize);
    result.depth             = state.u[contact_dofs.front()]; // w_c = u_z(0, 0)
    state.work               = b * state.u;
    return state;
  }



  AxisymmetricSolver::State AxisymmetricSolver::solve_depth_or_force_controlled(const LoadCase &load,
                                                                                Result         &result)
  {
    // The discrete contact set is {r <= r_j}, r_j a surface vertex; its radius-controlled depth d_j and
    // force F_j* = F(d_j) grow with j. Find the last j with d_j <= d (depth control) or F_j* <= F (force
    // control). The state is that set at the given d (or at the d that gives F): its edge node is in
    // compression, the next vertex is not in contact.
    const double         a = mesh_parameters.contact_radius;
    const unsigned int   m = contact_dofs.size();
    const Vector<double> no_load(dof_handler.n_dofs());
    std::vector<double>  g1(m, 1.0), g2(m);
    for (unsigned int i = 0; i < m; ++i)
      g2[i] = -load.profile(contact_r[i], a);
    Vector<double>       Au1, Au2;
    const Vector<double> u1 = system.solve(true, g1, no_load, Au1, result.time.factorize);
    double               unused;
    const Vector<double> u2 = system.solve(true, g2, no_load, Au2, unused);
    ContactSetSearch     search(*this, load, u1, u2, Au1, Au2);

    const unsigned int j_a =
      std::lower_bound(surface_vertex_r.begin(), surface_vertex_r.end(), a * (1 - node_tolerance)) -
      surface_vertex_r.begin();
    // Largest index a contact can reach: the vertices inside the near field.
    const unsigned int j_max = std::upper_bound(surface_vertex_r.begin(), surface_vertex_r.end(),
                                                mesh_parameters.near_field_size * a) -
                               surface_vertex_r.begin() - 1;
    // First guess from the scaling of the mesh's own radius-controlled state: d ~ a^n and
    // F ~ a^{n+1+s} (s the surface exponent of E; exact for the power-law half-space, a guess
    // otherwise). Only the start of the search: the bracket decides.
    const double exponent =
      load.profile.exponent() + (search.by_depth ? 0.0 : 1.0 + material.modulus->surface_exponent());
    const double r_guess = a * std::pow(search.target / search.value(j_a), 1.0 / exponent);
    if (r_guess > mesh_parameters.near_field_size * a)
      search.fail("the contact radius, estimated " + std::to_string(r_guess / a) +
                  " a, would leave the near field r <= " + std::to_string(mesh_parameters.near_field_size) + " a");
    const unsigned int start_vertex = std::clamp<unsigned int>(
      std::lower_bound(surface_vertex_r.begin(), surface_vertex_r.end(), r_guess) - surface_vertex_r.begin(), 1u,
      j_max);
    const auto [lo, hi] = search.bracket(start_vertex, j_max);

    const TrialSet &t = search.trial(lo);
    const double    d = search.by_depth ? load.depth : (search.target - t.F2) / t.F1;
    State           state;
    state.u = t.U2;
    state.u.add(d, t.U1);
    state.reaction = t.AU2;
    state.reaction.add(d, t.AU1);
    state.active = t.active;
    state.g.resize(state.active.size());
    for (unsigned int i = 0; i < state.active.size(); ++i)
      state.g[i] = d - load.profile(dof_r[state.active[i]], a);
    result.depth = d;
    // The transition radius between the vertex in contact and the next one out.
    const double value_lo = search.value(lo), value_hi = search.value(hi);
    const double value    = search.by_depth ? d : search.target;
    state.contact_edge      = surface_vertex_r[lo];
    result.edge_node_radius = state.contact_edge;
    result.contact_radius   = surface_vertex_r[lo] + (surface_vertex_r[hi] - surface_vertex_r[lo]) *
                                                       (value - value_lo) / (value_hi - value_lo);
    result.iterations = search.n_trials();
    return state;
  }



  void AxisymmetricSolver::check(const LoadCase &load, const State &state, Result &result) const
  {
    // Force from the reaction (prescribed displacement) or from the load (pressure); the work of both.
    const double a     = mesh_parameters.contact_radius;
    double       force = 0, work = state.work;
    if (state.constrained)
      for (unsigned int i = 0; i < state.active.size(); ++i)
        {
          force += state.reaction[state.active[i]];
          work += state.reaction[state.active[i]] * state.g[i];
        }
    else
      force = load.pressure * a * a / 2; // \int_0^a p0 r dr
    if (load.cohesion.active())
      force -= load.cohesion.stress * load.cohesion.radius * load.cohesion.radius / 2;
    result.force = 2 * numbers::PI * force;

    result.record(check_energy(system.energy(state.u), work, mesh_info.min_surface_cell, "",
                               system.energy_magnitude(state.u)));
    if (!state.constrained)
      return;

    // Consistency of the contact: no tensile zone in the contact (fem/base/contact_check.h: a negative nodal
    // force counts only when a partial sum of the contact forces is tensile too), gap >= 0 outside.
    // `active` is ordered by radius.
    std::vector<double> forces;
    for (const auto d : state.active)
      forces.push_back(state.reaction[d]);
    result.min_relative_contact_force = min_relative_contact_force(forces);
    double min_gap = std::numeric_limits<double>::max();
    if (load.type == LoadType::indenter || load.type == LoadType::indenter_depth ||
        load.type == LoadType::indenter_force)
      for (const auto d : surface_dofs)
        if (dof_r[d] > state.contact_edge * (1 + node_tolerance))
          min_gap = std::min(min_gap, (state.u[d] - (result.depth - load.profile(dof_r[d], a))) /
                                        std::abs(result.depth));
    result.min_relative_gap = (min_gap == std::numeric_limits<double>::max()) ? 0 : min_gap;
    std::ostringstream msg;
    if (result.min_relative_contact_force < -consistency_tolerance)
      msg << (load.type == LoadType::concave_punch ? "contact is not complete: " : "")
          << "tensile nodal contact force (min/max = " << result.min_relative_contact_force << "); ";
    if (result.min_relative_gap < -consistency_tolerance)
      msg << "penetration outside r = " << state.contact_edge << " (min gap / d = " << result.min_relative_gap
          << "); ";
    result.consistent_contact = msg.str().empty();
    result.message += msg.str();
  }



  void AxisymmetricSolver::sample(const LoadCase &load, const State &state, const OutputRequest &outputs,
                                  Result &result) const
  {
    const double a = mesh_parameters.contact_radius;
    if (!outputs.pressure_radii.empty())
      {
        // p(r) recovered consistently from the nodal reactions of the contact (header).
        std::vector<double> p;
        if (state.constrained)
          p = recover_line_density(surface_faces, 1, state.reaction, state.contact_edge, discretization.degree + 2,
                                   dof_handler.n_dofs());
        const auto tension = [&](const double r) {
          return (load.cohesion.active() && r <= load.cohesion.radius) ? load.cohesion.stress : 0.0;
        };
        for (const double r : outputs.pressure_radii)
          result.pressure.push_back({r, (state.constrained ? evaluate_on_surface(p, r, state.contact_edge) :
                                                              (r <= a ? load.pressure : 0.0)) -
                                          tension(r)});
      }
    if (!outputs.displacement_radii.empty())
      {
        const std::vector<double> nodal(state.u.begin(), state.u.end());
        for (const double r : outputs.displacement_radii)
          result.displacement.push_back({r, evaluate_on_surface(nodal, r)});
      }
    std::unique_ptr<StressRecovery> stresses;
    if (!outputs.stress_points.empty() || !outputs.vtu_file.empty())
      {
        if (!stress_fit)
          stress_fit = std::make_unique<StressFit>(
            dof_handler, mapping, material,
            SurfaceMap<2>(discretization.surface_map, *material.modulus, a, mesh_parameters.h_edge), a);
        stresses = std::make_unique<StressRecovery>(*stress_fit, state.u);
      }
    for (const StressPoint &x : outputs.stress_points)
      result.stress.push_back(stresses->at(x.r, x.z));
    if (!outputs.vtu_file.empty())
      output_results(state.u, stresses.get(), outputs.vtu_file);
  }



  void AxisymmetricSolver::output_results(const Vector<double> &u, const StressRecovery *stresses,
                                          const std::string &filename) const
  {
    MeridianDataOut data_out;
    data_out.surface_map =
      SurfaceMap<2>(discretization.surface_map, *material.modulus, mesh_parameters.contact_radius, mesh_parameters.h_edge);
    data_out.attach_dof_handler(dof_handler);
    std::vector<std::string> names{"u_r", "u_z"};
    if (used_formulation == Formulation::mixed)
      names.push_back(mixed_pressure_name(material)); // lambda div u, or (lambda / E) div u on a stiff surface
    const Vector<double> fields = with_physical_pressure(u, dof_handler, fe, material, mesh_parameters.contact_radius);
    data_out.add_data_vector(fields, names);
    if (stresses)
      for (unsigned int c = 0; c < 4; ++c)
        data_out.add_data_vector(stresses->dofs(), stresses->field(c), stresses->name(c));
    Vector<float> modulus(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      modulus[cell->active_cell_index()] =
        material.modulus->value(data_out.surface_map.physical(cell->center())[1]);
    data_out.add_data_vector(modulus, "E");
    write_vtu(data_out, mapping, discretization.degree, filename, "AxisymmetricSolver::output_results");
  }
} // namespace gradcontact::fem
