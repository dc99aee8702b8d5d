#include <fem/axisymmetric_solver.h>
#include <fem/boundary_ids.h>
#include <fem/gauss_jacobi.h>

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

    [[noreturn]] void fail(const std::string &where, const std::string &what, const double value,
                           const std::string &range)
    {
      std::ostringstream msg;
      msg.precision(17);
      msg << where << ": " << what << " = " << value << " outside " << range;
      throw std::invalid_argument(msg.str());
    }

    double seconds_since(const std::chrono::steady_clock::time_point &start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    bool is_surface(const types::boundary_id id)
    {
      return id == boundary_id::contact || id == boundary_id::free_surface;
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
        case LoadType::indenter:
          profile.validate();
          if (profile.shape == Profile::Shape::concave_paraboloid)
            throw std::invalid_argument(
              "LoadCase (indenter): profile concave_paraboloid needs LoadType::concave_punch");
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



  AxisymmetricSolver::AxisymmetricSolver(const Material &material_,
                                         const MeshParameters &mesh_,
                                         const DiscretizationParameters &discretization_)
    : material((material_.validate(), material_))
    , mesh_parameters((mesh_.validate(), mesh_))
    , discretization((discretization_.validate(), discretization_))
    , fe(FE_Q<2>(discretization_.degree), 2)
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
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const FEValuesExtractors::Scalar radial(0);
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::axis,
                                             Functions::ZeroFunction<2>(2), constraints,
                                             fe.component_mask(radial));
    VectorTools::interpolate_boundary_values(mapping, dof_handler, boundary_id::far_field,
                                             Functions::ZeroFunction<2>(2), constraints);
    constraints.close();

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
        if (cell->face(f)->at_boundary() && is_surface(cell->face(f)->boundary_id()))
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

    setup_time.setup = seconds_since(start);
  }



  void AxisymmetricSolver::assemble_system()
  {
    const auto   start = std::chrono::steady_clock::now();
    const double nu    = material.nu;
    const ModulusField &E = *material.modulus;
    const double s        = E.surface_exponent();
    // lambda = c_lambda E, mu = c_mu E
    const double c_lambda = nu / ((1 + nu) * (1 - 2 * nu));
    const double c_mu     = 1 / (2 * (1 + nu));

    const unsigned int  n_q   = discretization.degree + discretization.extra_quadrature_points;
    const UpdateFlags   flags = update_values | update_gradients | update_quadrature_points |
                              update_JxW_values;
    const QGauss<2>     regular_quadrature(n_q);
    FEValues<2>         regular(mapping, fe, regular_quadrature, flags);
    const QIterated<2>  subdivided_quadrature(QGauss<1>(n_q), discretization.discontinuity_subdivisions);
    FEValues<2>         subdivided(mapping, fe, subdivided_quadrature, flags);
    // One Gauss-Jacobi rule per reference face that may lie on z = 0; `distance` is the reference
    // distance xi_q from that face, whose power xi_q^s the weights already contain.
    std::vector<std::unique_ptr<FEValues<2>>> surface(4);
    std::vector<std::vector<double>>          distance(4);
    for (unsigned int f = 0; f < 4; ++f)
      surface[f] = std::make_unique<FEValues<2>>(
        mapping, fe, surface_cell_quadrature(n_q, s, f, distance[f]), flags);
    const std::vector<double> jumps = E.discontinuities();

    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    // Per shape function: eps_rr, eps_zz, eps_tt, gamma_rz.
    std::vector<std::array<double, 4>> B(dofs_per_cell);

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        unsigned int surface_face = numbers::invalid_unsigned_int;
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && is_surface(cell->face(f)->boundary_id()))
            surface_face = f;
        double z_min = std::numeric_limits<double>::max(), z_max = 0;
        for (const unsigned int v : cell->vertex_indices())
          {
            z_min = std::min(z_min, cell->vertex(v)[1]);
            z_max = std::max(z_max, cell->vertex(v)[1]);
          }
        const bool straddles = std::any_of(jumps.begin(), jumps.end(),
                                           [&](const double z) { return z > z_min && z < z_max; });

        FEValues<2> *fe_values = &regular;
        const std::vector<double> *xi = nullptr;
        if (straddles)
          fe_values = &subdivided;
        else if (surface_face != numbers::invalid_unsigned_int && s != 0.0)
          {
            fe_values = surface[surface_face].get();
            xi        = &distance[surface_face];
          }
        fe_values->reinit(cell);

        cell_matrix = 0;
        for (const unsigned int q : fe_values->quadrature_point_indices())
          {
            const Point<2> &x = fe_values->quadrature_point(q);
            const double    r = x[0];
            // With the Gauss-Jacobi rule JxW contains xi^s, so E is divided by it: E(z)/xi^s is the
            // regular factor (E0 (h(x)/c0)^k for the power law, h the local cell height).
            const double modulus = (xi ? E.value(x[1]) / std::pow((*xi)[q], s) : E.value(x[1]));
            const double lambda  = c_lambda * modulus;
            const double mu      = c_mu * modulus;
            const double weight  = r * fe_values->JxW(q);

            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const unsigned int  c    = fe.system_to_component_index(i).first;
                const double        phi  = fe_values->shape_value(i, q);
                const Tensor<1, 2> &grad = fe_values->shape_grad(i, q);
                B[i] = (c == 0) ? std::array<double, 4>{{grad[0], 0.0, phi / r, grad[1]}} :
                                  std::array<double, 4>{{0.0, grad[1], 0.0, grad[0]}};
              }
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const double tr_i = B[i][0] + B[i][1] + B[i][2];
                for (unsigned int j = 0; j <= i; ++j)
                  {
                    const double tr_j = B[j][0] + B[j][1] + B[j][2];
                    cell_matrix(i, j) +=
                      (lambda * tr_i * tr_j +
                       2 * mu * (B[i][0] * B[j][0] + B[i][1] * B[j][1] + B[i][2] * B[j][2]) +
                       mu * B[i][3] * B[j][3]) *
                      weight;
                  }
              }
          }
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (unsigned int j = i + 1; j < dofs_per_cell; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);

        cell->get_dof_indices(local_dof_indices);
        constraints.distribute_local_to_global(cell_matrix, local_dof_indices, stiffness);
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
    // l(v) = \int_{contact} p0 v_z r dr: the pressure pushes into the material (+z).
    Vector<double>      b(dof_handler.n_dofs());
    const QGauss<1>     quadrature(discretization.degree + discretization.extra_quadrature_points);
    FEFaceValues<2>     fe_face(mapping, fe, quadrature,
                            update_values | update_quadrature_points | update_JxW_values);
    const unsigned int  dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>      cell_rhs(dofs_per_cell);
    std::vector<types::global_dof_index> local_dof_indices(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == boundary_id::contact)
          {
            fe_face.reinit(cell, f);
            cell_rhs = 0;
            for (const unsigned int q : fe_face.quadrature_point_indices())
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                if (fe.system_to_component_index(i).first == 1)
                  cell_rhs(i) += p0 * fe_face.shape_value(i, q) * fe_face.quadrature_point(q)[0] *
                                 fe_face.JxW(q);
            cell->get_dof_indices(local_dof_indices);
            constraints.distribute_local_to_global(cell_rhs, local_dof_indices, b);
          }
    return b;
  }



  std::vector<double> AxisymmetricSolver::recover_pressure(const Vector<double> &reaction) const
  {
    // Consistent recovery: R_i = \int p phi_i r dr on the contact line, i.e. M p = R with
    // M_ij = \int phi_i phi_j r dr (phi the z-trace of the basis functions, 1D Lagrange on each face).
    const unsigned int m = contact_dofs.size();
    std::map<types::global_dof_index, unsigned int> index;
    for (unsigned int i = 0; i < m; ++i)
      index[contact_dofs[i]] = i;
    LAPACKFullMatrix<double> M(m, m);
    const QGauss<1>          quadrature(discretization.degree + 2);
    for (const SurfaceFace &face : surface_faces)
      if (face.contact)
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
    for (unsigned int i = 0; i < m; ++i)
      p[i] = reaction[contact_dofs[i]];
    M.compute_lu_factorization();
    M.solve(p);
    return std::vector<double>(p.begin(), p.end());
  }



  double AxisymmetricSolver::evaluate_on_surface(const std::vector<double> &nodal, const double r,
                                                 const bool contact_only) const
  {
    // `nodal` is indexed by global DoF (displacement) or, with contact_only, by contact index.
    std::map<types::global_dof_index, unsigned int> index;
    if (contact_only)
      for (unsigned int i = 0; i < contact_dofs.size(); ++i)
        index[contact_dofs[i]] = i;
    for (const SurfaceFace &face : surface_faces)
      if (r >= face.r0 && r <= face.r1 && (!contact_only || face.contact))
        {
          std::vector<double> y;
          for (const auto d : face.dofs)
            y.push_back(contact_only ? nodal[index[d]] : nodal[d]);
          return lagrange(face.r, y, r);
        }
    std::ostringstream msg;
    msg << "sample radius r = " << r << " outside the " << (contact_only ? "contact zone" : "surface")
        << " [0, " << (contact_only ? contact_r.back() : surface_faces.back().r1) << "]";
    throw std::invalid_argument(msg.str());
  }



  Result AxisymmetricSolver::run(const LoadCase &load, const OutputRequest &outputs)
  {
    load.validate();
    const double a = mesh_parameters.contact_radius;
    Result       result;
    result.time           = setup_time;
    result.n_dofs         = dof_handler.n_dofs();
    result.n_cells        = triangulation.n_active_cells();
    result.mesh           = mesh_info;
    result.contact_radius = a;

    const auto     start = std::chrono::steady_clock::now();
    const unsigned m     = contact_dofs.size();
    const Vector<double> no_load(dof_handler.n_dofs());
    Vector<double>       u, reaction;
    std::vector<double>  g(m);
    double               work = 0; // work of the prescribed displacements and loads, per 2 pi
    bool                 constrained = true;

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

    // Force from the reaction (prescribed displacement) or from the load (pressure).
    double force = 0;
    if (constrained)
      for (unsigned int i = 0; i < m; ++i)
        {
          force += reaction[contact_dofs[i]];
          work += reaction[contact_dofs[i]] * g[i];
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
        // Consistency of the contact: nodal forces >= 0 in the contact, gap >= 0 outside.
        double max_force = 0, min_force = std::numeric_limits<double>::max();
        for (const auto d : contact_dofs)
          {
            max_force = std::max(max_force, std::abs(reaction[d]));
            min_force = std::min(min_force, reaction[d]);
          }
        result.min_relative_contact_force = min_force / max_force;
        double min_gap = std::numeric_limits<double>::max();
        if (load.type == LoadType::indenter)
          for (const SurfaceFace &face : surface_faces)
            if (!face.contact)
              for (unsigned int i = 0; i < face.dofs.size(); ++i)
                if (face.r[i] > a * (1 + node_tolerance))
                  min_gap = std::min(min_gap, (u[face.dofs[i]] - (result.depth - load.profile(face.r[i], a))) /
                                                std::abs(result.depth));
        result.min_relative_gap = (min_gap == std::numeric_limits<double>::max()) ? 0 : min_gap;
        std::ostringstream msg;
        if (result.min_relative_contact_force < -consistency_tolerance)
          msg << (load.type == LoadType::concave_punch ? "contact is not complete: " : "")
              << "tensile nodal contact force (min/max = " << result.min_relative_contact_force << "); ";
        if (result.min_relative_gap < -consistency_tolerance)
          msg << "penetration outside r = a (min gap / d = " << result.min_relative_gap << "); ";
        result.consistent_contact = msg.str().empty();
        result.message += msg.str();
      }

    if (!outputs.pressure_radii.empty())
      {
        std::vector<double> p;
        if (constrained)
          p = recover_pressure(reaction);
        for (const double r : outputs.pressure_radii)
          result.pressure.push_back(
            {r, constrained ? evaluate_on_surface(p, r, true) : (r <= a ? load.pressure : 0.0)});
      }
    if (!outputs.displacement_radii.empty())
      {
        const std::vector<double> nodal(u.begin(), u.end());
        for (const double r : outputs.displacement_radii)
          result.displacement.push_back({r, evaluate_on_surface(nodal, r, false)});
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
    const std::vector<std::string> names{"u_r", "u_z"};
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
