#include <fem/errors.h>
#include <fem/axisymmetric_solver.h>
#include <fem/contact_check.h>
#include <fem/boundary_ids.h>
#include <fem/elasticity_assembly.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    constexpr unsigned int max_degree = 4;
    // Relative tolerance of "this DoF sits at r = a" (support points are exact up to round-off).
    constexpr double node_tolerance = 1e-10;
    // A nodal contact force (relative to the largest) or a gap (relative to the depth) below -this is a
    // consistency violation. Not round-off: the nodal forces of Lagrange elements of degree >= 2 are
    // not sign-definite where p vanishes like (a - r)^{(1+k)/2}; consistent states measured down to
    // -3e-5 (p = 3), a violated complete contact of the concave punch is O(1).
    constexpr double consistency_tolerance = 1e-3;
    // |u.Au - work| / u.Au above this means the direct solver returned garbage (measured: <= 4e-9 on
    // sound meshes, 3.7e-7 at k = -0.5 with 1e-5 a surface cells; 2e-4 .. 3e-3 once k < 0 surface
    // cells are thinner than 1e-7 a).
    constexpr double energy_mismatch_tolerance = 1e-6;
    // Depth and force control: at most this many trial contact sets, and at most this many surface
    // DoFs whose state differs from the mesh's contact zone (one back-substitution and two vectors
    // each). A search that needs more stops with a message: the mesh's contact radius is too far from
    // the answer (remesh at the reported radius).
    constexpr unsigned int max_control_iterations = 60;
    constexpr unsigned int max_modified_dofs      = 200;


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
  } // namespace



  void DiscretizationParameters::validate() const
  {
    if (degree < 1 || degree > max_degree)
      fail("DiscretizationParameters", "degree", degree, "[1, 4]");
    if (extra_quadrature_points > 6)
      fail("DiscretizationParameters", "extra_quadrature_points", extra_quadrature_points, "[0, 6]");
    if (discontinuity_subdivisions < 1 || discontinuity_subdivisions > 64)
      fail("DiscretizationParameters", "discontinuity_subdivisions", discontinuity_subdivisions,
           "[1, 64]");
    if (formulation != Formulation::displacement && formulation != Formulation::mixed &&
        formulation != Formulation::automatic)
      fail("DiscretizationParameters", "formulation", static_cast<int>(formulation),
           "{displacement, mixed, automatic}");
    if (formulation == Formulation::mixed && degree < 2)
      fail("DiscretizationParameters (mixed formulation)", "degree", degree,
           "[2, 4] (the pressure space is FE_Q(degree - 1))");
  }



  Formulation resolve_formulation(const DiscretizationParameters &discretization, const double nu)
  {
    Formulation f = discretization.formulation;
    if (f == Formulation::automatic)
      f = (nu >= automatic_mixed_threshold) ? Formulation::mixed : Formulation::displacement;
    if (f == Formulation::mixed && discretization.degree < 2)
      fail("DiscretizationParameters (mixed formulation, nu = " + std::to_string(nu) + ")", "degree",
           discretization.degree, "[2, 4] (the pressure space is FE_Q(degree - 1))");
    return f;
  }



  void require_displacement_formulation(const DiscretizationParameters &discretization, const double nu,
                                        const std::string &where)
  {
    if (resolve_formulation(discretization, nu) == Formulation::mixed)
      {
        std::ostringstream msg;
        msg << where << ": not supported with the mixed formulation (DiscretizationParameters::formulation = "
            << (discretization.formulation == Formulation::mixed ? "mixed" : "automatic") << ", nu = " << nu
            << "); use Formulation::displacement with nu < 0.5";
        throw std::invalid_argument(msg.str());
      }
  }



  Settings recommended_settings(const double contact_radius, const double s, const double force_tolerance)
  {
    if (!(force_tolerance > 0 && force_tolerance < 1))
      fail("recommended_settings", "force_tolerance", force_tolerance, "(0, 1)");
    // The threshold between the two measured settings: degree 3 reaches 3.8e-7..2.1e-6.
    constexpr double degree_3_limit = 1e-6;
    Settings settings;
    settings.mesh = recommended_mesh_parameters(contact_radius, s, std::min(force_tolerance / 10, 1e-8));
    if (force_tolerance < degree_3_limit)
      {
        settings.discretization.degree = 4;
        settings.mesh.h_edge           = 1e-6;
        settings.mesh.h_far            = 4.0;
        settings.mesh.ring_growth      = 1.3;
        // The halvings of the cells just outside the contact doubled the DoFs for k = 0.5 and did not
        // change the error (measured 2.03e-6 vs 2.58e-6 at degree 3).
        settings.mesh.halving_radius = 1.0;
      }
    return settings;
  }



  Profile Profile::paraboloid(const double R)
  {
    Profile p;
    p.shape = Shape::paraboloid;
    p.R     = R;
    p.validate();
    return p;
  }

  Profile Profile::cone(const double tan_theta)
  {
    Profile p;
    p.shape     = Shape::cone;
    p.tan_theta = tan_theta;
    p.validate();
    return p;
  }

  Profile Profile::power_law(const double n, const double A)
  {
    Profile p;
    p.shape = Shape::power_law;
    p.n     = n;
    p.A     = A;
    p.validate();
    return p;
  }

  Profile Profile::concave_paraboloid(const double h0)
  {
    Profile p;
    p.shape = Shape::concave_paraboloid;
    p.h0    = h0;
    p.validate();
    return p;
  }

  Profile Profile::custom(std::function<double(double)> f, const double growth_exponent)
  {
    Profile p;
    p.shape = Shape::custom;
    p.function = std::move(f);
    p.growth_exponent = growth_exponent;
    return p;
  }

  double Profile::operator()(const double r, const double a) const
  {
    switch (shape)
      {
        case Shape::paraboloid:
          return r * r / (2 * R);
        case Shape::cone:
          return r * tan_theta;
        case Shape::power_law:
          return A * std::pow(r, n);
        case Shape::concave_paraboloid:
          return -h0 * (r / a) * (r / a);
        case Shape::custom:
          return function(r);
      }
    return 0; // unreachable
  }

  double Profile::exponent() const
  {
    switch (shape)
      {
        case Shape::paraboloid:
        case Shape::concave_paraboloid:
          return 2.0;
        case Shape::cone:
          return 1.0;
        case Shape::power_law:
          return n;
        case Shape::custom:
          return growth_exponent;
      }
    return 0; // unreachable
  }

  void Profile::validate() const
  {
    switch (shape)
      {
        case Shape::paraboloid:
          if (!(R > 0) || !std::isfinite(R))
            fail("Profile (paraboloid)", "R", R, "(0, inf)");
          break;
        case Shape::cone:
          if (!(tan_theta > 0) || !std::isfinite(tan_theta))
            fail("Profile (cone)", "tan_theta", tan_theta, "(0, inf)");
          break;
        case Shape::power_law:
          if (!(n > 0) || !std::isfinite(n))
            fail("Profile (power law)", "n", n, "(0, inf)");
          if (!(A > 0) || !std::isfinite(A))
            fail("Profile (power law)", "A", A, "(0, inf)");
          break;
        case Shape::concave_paraboloid:
          if (!(h0 >= 0) || !std::isfinite(h0))
            fail("Profile (concave paraboloid)", "h0", h0, "[0, inf)");
          break;
        case Shape::custom:
          if (!function)
            throw std::invalid_argument("Profile (custom): the profile function is empty");
          if (!(growth_exponent > 0) || !std::isfinite(growth_exponent))
            fail("Profile (custom)", "growth_exponent", growth_exponent, "(0, inf)");
          break;
      }
  }

  void LoadCase::validate() const
  {
    switch (type)
      {
        case LoadType::flat_punch:
          if (!std::isfinite(depth) || depth == 0)
            fail("LoadCase (flat punch)", "depth", depth, "finite, non-zero");
          break;
        case LoadType::indenter_depth:
          if (!std::isfinite(depth) || !(depth > 0))
            fail("LoadCase (indenter, depth control)", "depth", depth, "(0, inf)");
          [[fallthrough]];
        case LoadType::indenter_force:
          if (type == LoadType::indenter_force && (!std::isfinite(force) || !(force > 0)))
            fail("LoadCase (indenter, force control)", "force", force, "(0, inf)");
          [[fallthrough]];
        case LoadType::indenter:
          profile.validate();
          // Under contact-radius control the concave paraboloid is allowed: its radius-controlled state
          // (edge force zero, tension inside) is a basis state of the adhesive superposition
          // (fem/adhesion.h); depth and force control assume a convex profile.
          if (profile.shape == Profile::Shape::concave_paraboloid && type != LoadType::indenter)
            throw std::invalid_argument(
              "LoadCase (indenter, depth or force control): profile concave_paraboloid needs "
              "LoadType::concave_punch or LoadType::indenter");
          break;
        case LoadType::concave_punch:
          profile.validate();
          if (profile.shape != Profile::Shape::concave_paraboloid)
            throw std::invalid_argument("LoadCase (concave punch): profile must be concave_paraboloid");
          if (!std::isfinite(depth) || !(depth > 0))
            fail("LoadCase (concave punch)", "depth (d0)", depth, "(0, inf)");
          break;
        case LoadType::constant_pressure:
          if (!std::isfinite(pressure) || pressure == 0)
            fail("LoadCase (constant pressure)", "pressure", pressure, "finite, non-zero");
          break;
      }
  }



  namespace
  {
    /// Validates the discretisation, then the material for the formulation it resolves to.
    Formulation checked_formulation(const Material &material, const DiscretizationParameters &discretization)
    {
      discretization.validate();
      const Formulation f = resolve_formulation(discretization, material.nu);
      material.validate(f == Formulation::mixed);
      return f;
    }

    /// (u_r, u_z) in FE_Q(p), plus q in FE_Q(p - 1) for the mixed formulation (Taylor-Hood).
    FESystem<2> make_fe(const unsigned int degree, const Formulation formulation)
    {
      if (formulation == Formulation::mixed)
        return FESystem<2>(FE_Q<2>(degree), 2, FE_Q<2>(degree - 1), 1);
      return FESystem<2>(FE_Q<2>(degree), 2);
    }
  } // namespace



  AxisymmetricSolver::AxisymmetricSolver(const Material &material_,
                                         const MeshParameters &mesh_,
                                         const DiscretizationParameters &discretization_)
    : material((checked_formulation(material_, discretization_), material_))
    , mesh_parameters((mesh_.validate(), mesh_))
    , discretization(discretization_)
    , used_formulation(resolve_formulation(discretization_, material_.nu))
    , fe(make_fe(discretization_.degree, used_formulation))
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
    setup_time.mesh  = seconds_since(start);
  }



  void AxisymmetricSolver::setup_system()
  {
    const auto start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);

    // Homogeneous constraints shared by every load: hanging nodes (z-only halvings, edge refinement),
    // u_r = 0 on the axis, u = 0 on the truncation boundary.
    constraints.clear();
    make_homogeneous_constraints(dof_handler, mapping, fe, constraints);

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    sparsity_pattern.copy_from(dsp);
    stiffness.reinit(sparsity_pattern);

    std::vector<Point<2>> support(dof_handler.n_dofs());
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    dof_r.resize(support.size());
    for (unsigned int i = 0; i < support.size(); ++i)
      dof_r[i] = support[i][0];

    // The surface faces with their z-DoFs, and the contact DoFs (on faces with id `contact`, hence
    // r <= a). In 2D a boundary face is never the refined side of a hanging node, so no contact DoF
    // is constrained (only the free-surface node at r = L is, by the far-field condition).
    const double a = mesh_parameters.contact_radius;
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    std::vector<types::global_dof_index> contact;
    surface_faces.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && boundary_id::is_surface(cell->face(f)->boundary_id()))
          {
            cell->face(f)->get_dof_indices(face_dofs);
            SurfaceFace face;
            face.contact = (cell->face(f)->boundary_id() == boundary_id::contact);
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              if (fe.face_system_to_component_index(i, f).first == 1)
                face.dofs.push_back(face_dofs[i]);
            std::sort(face.dofs.begin(), face.dofs.end(),
                      [&](const auto x, const auto y) { return dof_r[x] < dof_r[y]; });
            for (const auto d : face.dofs)
              {
                face.r.push_back(dof_r[d]);
                AssertThrow(!face.contact || !constraints.is_constrained(d),
                            ExcMessage("surface DoF at r = " + std::to_string(dof_r[d]) +
                                       " is constrained; the contact set assumes it is not"));
              }
            face.r0 = face.r.front();
            face.r1 = face.r.back();
            if (face.contact)
              contact.insert(contact.end(), face.dofs.begin(), face.dofs.end());
            surface_faces.push_back(face);
          }
    std::sort(surface_faces.begin(), surface_faces.end(),
              [](const SurfaceFace &x, const SurfaceFace &y) { return x.r0 < y.r0; });
    std::sort(contact.begin(), contact.end());
    contact.erase(std::unique(contact.begin(), contact.end()), contact.end());
    std::sort(contact.begin(), contact.end(),
              [&](const auto x, const auto y) { return dof_r[x] < dof_r[y]; });
    contact_dofs = contact;
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
        surface_dofs.insert(surface_dofs.end(), face.dofs.begin(), face.dofs.end());
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
    // K_cell: fem/elasticity_assembly.h (shared with the distributed solver).
    CellStiffness                        cell_stiffness(material, fe, mapping, discretization);
    std::vector<types::global_dof_index> local_dof_indices(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_stiffness.matrix(cell), local_dof_indices, stiffness);
      }

    // The matrix with the contact z-DoFs eliminated (rows and columns zeroed, diagonal kept), so
    // that it stays symmetric; the prescribed values enter through the right-hand side in solve().
    contact_stiffness.reinit(sparsity_pattern);
    contact_stiffness.copy_from(stiffness);
    for (const auto i : contact_dofs)
      for (auto entry = contact_stiffness.begin(i); entry != contact_stiffness.end(i); ++entry)
        if (entry->column() != i)
          {
            contact_stiffness.set(entry->column(), i, 0.0);
            entry->value() = 0.0;
          }

    setup_time.assemble = seconds_since(start);
  }



  const SparseDirectUMFPACK &AxisymmetricSolver::factorization(const bool contact_constrained,
                                                               double &seconds)
  {
    std::unique_ptr<SparseDirectUMFPACK> &solver = contact_constrained ? contact_solver : free_solver;
    seconds                                      = 0;
    if (!solver)
      {
        const auto start = std::chrono::steady_clock::now();
        solver           = std::make_unique<SparseDirectUMFPACK>();
        solver->initialize(contact_constrained ? contact_stiffness : stiffness);
        seconds = seconds_since(start);
      }
    return *solver;
  }



  Vector<double> AxisymmetricSolver::solve(const bool contact_constrained,
                                           const std::vector<double> &g,
                                           const Vector<double> &b, Vector<double> &reaction,
                                           double &factorize_seconds)
  {
    const SparseDirectUMFPACK &direct = factorization(contact_constrained, factorize_seconds);

    // rhs = b - A g_ext on the free DoFs, K_ii g_i on the prescribed ones.
    Vector<double> u(dof_handler.n_dofs()), rhs(b);
    if (contact_constrained)
      {
        Vector<double> g_ext(dof_handler.n_dofs()), Ag(dof_handler.n_dofs());
        for (unsigned int i = 0; i < contact_dofs.size(); ++i)
          g_ext[contact_dofs[i]] = g[i];
        stiffness.vmult(Ag, g_ext);
        rhs -= Ag;
        for (unsigned int i = 0; i < contact_dofs.size(); ++i)
          rhs[contact_dofs[i]] = contact_stiffness.diag_element(contact_dofs[i]) * g[i];
      }
    u = rhs;
    direct.solve(u);
    constraints.distribute(u);

    reaction.reinit(dof_handler.n_dofs());
    stiffness.vmult(reaction, u);
    reaction -= b;
    return u;
  }



  Vector<double> AxisymmetricSolver::pressure_load(const double p0) const
  {
    // l(v) = \int_{contact} p0 v_z r dr (fem/elasticity_assembly.h).
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



  std::vector<double> AxisymmetricSolver::recover_pressure(const Vector<double> &reaction,
                                                           const double edge) const
  {
    // Consistent recovery: R_i = \int p phi_i r dr on the contact line r <= edge, i.e. M p = R with
    // M_ij = \int phi_i phi_j r dr (phi the z-trace of the basis functions, 1D Lagrange on each face).
    const double limit = edge * (1 + node_tolerance);
    std::map<types::global_dof_index, unsigned int> index;
    for (const SurfaceFace &face : surface_faces)
      if (face.r1 <= limit)
        for (const auto d : face.dofs)
          index.emplace(d, index.size());
    const unsigned int       m = index.size();
    LAPACKFullMatrix<double> M(m, m);
    const QGauss<1>          quadrature(discretization.degree + 2);
    for (const SurfaceFace &face : surface_faces)
      if (face.r1 <= limit)
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double r  = face.r0 + (face.r1 - face.r0) * quadrature.point(q)[0];
            const double w  = quadrature.weight(q) * (face.r1 - face.r0) * r;
            std::vector<double> phi(face.dofs.size());
            for (unsigned int i = 0; i < face.dofs.size(); ++i)
              {
                std::vector<double> unit(face.dofs.size(), 0.0);
                unit[i] = 1;
                phi[i]  = lagrange(face.r, unit, r);
              }
            for (unsigned int i = 0; i < face.dofs.size(); ++i)
              for (unsigned int j = 0; j < face.dofs.size(); ++j)
                M(index[face.dofs[i]], index[face.dofs[j]]) += phi[i] * phi[j] * w;
          }
    Vector<double> p(m);
    for (const auto &[dof, i] : index)
      p[i] = reaction[dof];
    M.compute_lu_factorization();
    M.solve(p);
    std::vector<double> nodal(dof_handler.n_dofs(), 0.0);
    for (const auto &[dof, i] : index)
      nodal[dof] = p[i];
    return nodal;
  }



  double AxisymmetricSolver::evaluate_on_surface(const std::vector<double> &nodal, const double r,
                                                 const double contact_edge) const
  {
    // `nodal` is indexed by global DoF; with contact_edge >= 0 only faces on r <= contact_edge count.
    const bool contact_only = contact_edge >= 0;
    for (const SurfaceFace &face : surface_faces)
      if (r >= face.r0 && r <= face.r1 &&
          (!contact_only || face.r1 <= contact_edge * (1 + node_tolerance)))
        {
          std::vector<double> y;
          for (const auto d : face.dofs)
            y.push_back(nodal[d]);
          return lagrange(face.r, y, r);
        }
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
    Vector<double> c = solve(true, g, b, reaction, unused);
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



  Result AxisymmetricSolver::run(const LoadCase &load, const OutputRequest &outputs)
  {
    load.validate();
    const double a = mesh_parameters.contact_radius;
    Result       result;
    result.time           = setup_time;
    result.n_dofs         = dof_handler.n_dofs();
    result.n_cells        = triangulation.n_active_cells();
    result.formulation    = used_formulation;
    result.mesh           = mesh_info;
    result.contact_radius = a;
    result.edge_node_radius = a;

    const auto     start = std::chrono::steady_clock::now();
    const unsigned m     = contact_dofs.size();
    const Vector<double> no_load(dof_handler.n_dofs());
    Vector<double>       u, reaction;
    // The DoFs with prescribed u_z (the contact) and their values g.
    std::vector<types::global_dof_index> active = contact_dofs;
    std::vector<double>  g(m);
    double               work = 0; // work of the prescribed displacements and loads, per 2 pi
    bool                 constrained = true;
    double               contact_edge = a;

    switch (load.type)
      {
        case LoadType::flat_punch:
          std::fill(g.begin(), g.end(), load.depth);
          u            = solve(true, g, no_load, reaction, result.time.factorize);
          result.depth = load.depth;
          break;
        case LoadType::concave_punch:
          for (unsigned int i = 0; i < m; ++i)
            g[i] = load.depth - load.profile(contact_r[i], a);
          u            = solve(true, g, no_load, reaction, result.time.factorize);
          result.depth = load.depth;
          break;
        case LoadType::indenter:
          {
            // u = d u1 + u2 with u1: u_z = 1 on the contact, u2: u_z = -f(r) there; d from R_edge = 0.
            Vector<double> reaction1, reaction2;
            std::vector<double> g1(m, 1.0), g2(m);
            for (unsigned int i = 0; i < m; ++i)
              g2[i] = -load.profile(contact_r[i], a);
            const Vector<double> u1 = solve(true, g1, no_load, reaction1, result.time.factorize);
            double               unused;
            const Vector<double> u2   = solve(true, g2, no_load, reaction2, unused);
            const auto           edge = contact_dofs.back();
            const double         d    = -reaction2[edge] / reaction1[edge];
            u = u2;
            u.add(d, u1);
            reaction = reaction2;
            reaction.add(d, reaction1);
            for (unsigned int i = 0; i < m; ++i)
              g[i] = d - load.profile(contact_r[i], a);
            result.depth = d;
            break;
          }
        case LoadType::indenter_depth:
        case LoadType::indenter_force:
          {
            // The discrete contact set is {r <= r_j}, r_j a surface vertex; its radius-controlled depth
            // d_j and force F_j* = F(d_j) grow with j. Find the last j with d_j <= d (depth control) or
            // F_j* <= F (force control): search outward or inward from the mesh's contact radius with
            // doubling steps until bracketed, then bisect. The state is that set at the given d (or at
            // the d that gives F): its edge node is in compression, the next vertex is not in contact.
            std::vector<double> g1(m, 1.0), g2(m);
            for (unsigned int i = 0; i < m; ++i)
              g2[i] = -load.profile(contact_r[i], a);
            Vector<double> Au1, Au2;
            const Vector<double> u1 = solve(true, g1, no_load, Au1, result.time.factorize);
            double               unused;
            const Vector<double> u2 = solve(true, g2, no_load, Au2, unused);
            const bool   by_depth = load.type == LoadType::indenter_depth;
            const double target   = by_depth ? load.depth : load.force / (2 * numbers::PI);
            std::map<unsigned int, TrialSet> trials;
            auto key = [&](const unsigned int j) {
              auto it = trials.find(j);
              if (it == trials.end())
                {
                  if (trials.size() >= max_control_iterations)
                    {
                      std::ostringstream msg;
                      msg << "depth/force control did not converge: " << trials.size()
                          << " trial contact sets, the last with " << trials.rbegin()->second.active.size()
                          << " contact DoFs (edge r = " << surface_vertex_r[trials.rbegin()->first] << ")";
                      throw std::runtime_error(msg.str());
                    }
                  try
                    {
                      it = trials.emplace(j, trial_set(j, load.profile, u1, u2, Au1, Au2)).first;
                    }
                  catch (const std::runtime_error &e)
                    {
                      std::ostringstream msg;
                      msg << "depth/force control stopped after " << trials.size()
                          << " trial contact sets (last set: "
                          << (trials.empty() ? 0 : trials.rbegin()->second.active.size())
                          << " contact DoFs): " << e.what();
                      throw std::runtime_error(msg.str());
                    }
                }
              const TrialSet &t = it->second;
              return by_depth ? t.depth : t.depth * t.F1 + t.F2;
            };
            const unsigned int j_a =
              std::lower_bound(surface_vertex_r.begin(), surface_vertex_r.end(), a * (1 - node_tolerance)) -
              surface_vertex_r.begin();
            // Largest index a contact can reach: the vertices inside the near field.
            const unsigned int j_max =
              std::upper_bound(surface_vertex_r.begin(), surface_vertex_r.end(),
                               mesh_parameters.near_field_size * a) - surface_vertex_r.begin() - 1;
            unsigned int lo, hi; // key(lo) <= target < key(hi)
            auto fail_bracket = [&](const std::string &why) {
              std::ostringstream msg;
              msg << "depth/force control: " << why << " (" << (by_depth ? "depth " : "force ")
                  << (by_depth ? load.depth : load.force) << ", " << trials.size()
                  << " trial contact sets, the last with "
                  << (trials.empty() ? 0 : trials.rbegin()->second.active.size()) << " contact DoFs)";
              throw std::runtime_error(msg.str());
            };
            // First guess from the scaling of the mesh's own radius-controlled state: d ~ a^n and
            // F ~ a^{n+1+s} (s the surface exponent of E; exact for the power-law half-space, a guess
            // otherwise). Only the start of the search: the bracket below decides.
            const double exponent =
              load.profile.exponent() + (by_depth ? 0.0 : 1.0 + material.modulus->surface_exponent());
            const double r_guess = a * std::pow(target / key(j_a), 1.0 / exponent);
            if (r_guess > mesh_parameters.near_field_size * a)
              fail_bracket("the contact radius, estimated " + std::to_string(r_guess / a) +
                           " a, would leave the near field r <= " +
                           std::to_string(mesh_parameters.near_field_size) + " a");
            unsigned int start_vertex =
              std::lower_bound(surface_vertex_r.begin(), surface_vertex_r.end(), r_guess) -
              surface_vertex_r.begin();
            start_vertex = std::clamp(start_vertex, 1u, j_max);
            if (key(start_vertex) <= target)
              {
                lo = start_vertex;
                unsigned int step = 1;
                while (true)
                  {
                    if (lo == j_max)
                      fail_bracket("the contact would leave the near field r <= " +
                                   std::to_string(mesh_parameters.near_field_size) + " a");
                    hi = std::min(lo + step, j_max);
                    if (key(hi) > target)
                      break;
                    lo = hi;
                    step *= 2;
                  }
              }
            else
              {
                hi = start_vertex;
                unsigned int step = 1;
                while (true)
                  {
                    if (hi <= 1)
                      fail_bracket("no contact beyond the axis node: the load is too small for this mesh");
                    lo = (hi > step + 1) ? hi - step : 1;
                    if (key(lo) <= target)
                      break;
                    hi = lo;
                    step *= 2;
                  }
              }
            while (hi - lo > 1)
              {
                const unsigned int mid = (lo + hi) / 2;
                (key(mid) <= target ? lo : hi) = mid;
              }
            const TrialSet &t = trials.at(lo);
            const double    d = by_depth ? load.depth : (target - t.F2) / t.F1;
            u                 = t.U2;
            u.add(d, t.U1);
            reaction = t.AU2;
            reaction.add(d, t.AU1);
            active = t.active;
            g.resize(active.size());
            for (unsigned int i = 0; i < active.size(); ++i)
              g[i] = d - load.profile(dof_r[active[i]], a);
            result.depth = d;
            // The transition radius between the vertex in contact and the next one out.
            const double key_lo = key(lo), key_hi = key(hi);
            const double value  = by_depth ? d : target;
            contact_edge = surface_vertex_r[lo];
            result.edge_node_radius = contact_edge;
            result.contact_radius =
              surface_vertex_r[lo] + (surface_vertex_r[hi] - surface_vertex_r[lo]) * (value - key_lo) / (key_hi - key_lo);
            result.iterations = trials.size();
            break;
          }
        case LoadType::constant_pressure:
          {
            constrained              = false;
            const Vector<double> b   = pressure_load(load.pressure);
            std::vector<double>  none;
            u            = solve(false, none, b, reaction, result.time.factorize);
            result.depth = u[contact_dofs.front()]; // w_c = u_z(0, 0)
            work         = b * u;
            break;
          }
      }
    result.active_set_size = constrained ? active.size() : 0;

    // Force from the reaction (prescribed displacement) or from the load (pressure).
    double force = 0;
    if (constrained)
      for (unsigned int i = 0; i < active.size(); ++i)
        {
          force += reaction[active[i]];
          work += reaction[active[i]] * g[i];
        }
    else
      force = load.pressure * a * a / 2; // \int_0^a p0 r dr
    result.force = 2 * numbers::PI * force;

    // Energy on the unconstrained DoFs only: A carries dummy diagonal entries in the rows of
    // constrained DoFs (and no coupling to them), so those must not enter u.Au.
    Vector<double> u_free(u), Au(dof_handler.n_dofs());
    constraints.set_zero(u_free);
    stiffness.vmult(Au, u_free);
    const double energy    = u_free * Au;
    result.energy_mismatch = std::abs(energy - work) / std::abs(energy);
    if (!(result.energy_mismatch <= energy_mismatch_tolerance))
      {
        std::ostringstream msg;
        msg << "unreliable solve: energy mismatch " << result.energy_mismatch << " > "
            << energy_mismatch_tolerance << " (ill-conditioned: surface cells " << mesh_info.min_surface_cell
            << " a thin; increase MeshParameters::surface_layer_thickness); ";
        result.reliable = false;
        result.message += msg.str();
      }
    result.time.solve      = seconds_since(start) - result.time.factorize;

    const auto post = std::chrono::steady_clock::now();
    if (constrained)
      {
        // Consistency of the contact: no tensile zone in the contact (fem/contact_check.h: a negative
        // nodal force counts only when a partial sum of the contact forces is tensile too), gap >= 0
        // outside. `active` is ordered by radius.
        std::vector<double> forces;
        for (const auto d : active)
          forces.push_back(reaction[d]);
        result.min_relative_contact_force = min_relative_contact_force(forces);
        double min_gap = std::numeric_limits<double>::max();
        if (load.type == LoadType::indenter || load.type == LoadType::indenter_depth ||
            load.type == LoadType::indenter_force)
          for (const auto d : surface_dofs)
            if (dof_r[d] > contact_edge * (1 + node_tolerance))
              min_gap = std::min(min_gap, (u[d] - (result.depth - load.profile(dof_r[d], a))) /
                                            std::abs(result.depth));
        result.min_relative_gap = (min_gap == std::numeric_limits<double>::max()) ? 0 : min_gap;
        std::ostringstream msg;
        if (result.min_relative_contact_force < -consistency_tolerance)
          msg << (load.type == LoadType::concave_punch ? "contact is not complete: " : "")
              << "tensile nodal contact force (min/max = " << result.min_relative_contact_force << "); ";
        if (result.min_relative_gap < -consistency_tolerance)
          msg << "penetration outside r = " << contact_edge << " (min gap / d = " << result.min_relative_gap
              << "); ";
        result.consistent_contact = msg.str().empty();
        result.message += msg.str();
      }

    if (!outputs.pressure_radii.empty())
      {
        std::vector<double> p;
        if (constrained)
          p = recover_pressure(reaction, contact_edge);
        for (const double r : outputs.pressure_radii)
          result.pressure.push_back(
            {r, constrained ? evaluate_on_surface(p, r, contact_edge) : (r <= a ? load.pressure : 0.0)});
      }
    if (!outputs.displacement_radii.empty())
      {
        const std::vector<double> nodal(u.begin(), u.end());
        for (const double r : outputs.displacement_radii)
          result.displacement.push_back({r, evaluate_on_surface(nodal, r)});
      }
    if (!outputs.vtu_file.empty())
      output_results(u, outputs.vtu_file);
    result.time.postprocess = seconds_since(post);
    return result;
  }



  void AxisymmetricSolver::output_results(const Vector<double> &u, const std::string &filename) const
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(dof_handler);
    std::vector<std::string> names{"u_r", "u_z"};
    if (used_formulation == Formulation::mixed)
      names.push_back("q"); // q = lambda div u (mixed formulation)
    data_out.add_data_vector(u, names);
    Vector<float> modulus(triangulation.n_active_cells());
    for (const auto &cell : triangulation.active_cell_iterators())
      modulus[cell->active_cell_index()] = material.modulus->value(cell->center()[1]);
    data_out.add_data_vector(modulus, "E");
    data_out.build_patches(mapping, discretization.degree);
    std::ofstream out(filename);
    if (!out)
      throw std::runtime_error("output_results: cannot write " + filename);
    data_out.write_vtu(out);
  }
} // namespace gradcontact::fem
