#include <fem/base/errors.h>
#include <fem/elasticity/graded_elasticity.h>
#include <fem/base/table_file.h>
#include <fem/contact/unilateral_contact.h>
#include <fem/io/vtu_output.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    /// Relative tolerances of the active-set conditions: a force below this fraction of the largest
    /// nodal force, or a gap below this fraction of the displacement scale, counts as zero (round-off of
    /// the dense solves; the nodes at an edge carry values of that size).
    constexpr double force_zero = 1e-12;
    constexpr double gap_zero   = 1e-12;
    /// Contact zones closer than this fraction of their radius are reported as one (UnilateralResult::zones).
    constexpr double zone_merge_distance = 1e-3;

    /// K = D^T (C D), the weighted gaps of the vertex pressures: symmetric positive definite
    /// (symmetrised against the round-off of the back-substitutions).
    FullMatrix<double> contact_matrix(const FullMatrix<double> &D, const FullMatrix<double> &CD)
    {
      FullMatrix<double> K(D.n(), D.n());
      D.Tmmult(K, CD);
      for (unsigned int i = 0; i < K.m(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          K(i, j) = K(j, i) = 0.5 * (K(i, j) + K(j, i));
      return K;
    }
  } // namespace



  Indenter Indenter::of(const Profile &profile, const double a)
  {
    profile.validate();
    Indenter i;
    i.f      = [profile, a](const double r) { return profile(r, a); };
    i.extent = profile.shape == Profile::Shape::concave_paraboloid ? a : std::numeric_limits<double>::infinity();
    i.name   = profile.shape == Profile::Shape::concave_paraboloid ? "concave punch" : "indenter";
    return i;
  }

  Indenter Indenter::table(std::vector<double> r, std::vector<double> f)
  {
    if (r.size() < 2 || r.size() != f.size())
      fail("Indenter::table", "number of points", r.size(), "at least 2, as many r as f");
    if (r.front() != 0)
      fail("Indenter::table", "first r", r.front(), "0 (the table starts at the axis)");
    for (std::size_t j = 1; j < r.size(); ++j)
      if (!(r[j] > r[j - 1]) || !std::isfinite(r[j]))
        fail("Indenter::table", "r", r[j], "finite and ascending");
    for (const double v : f)
      if (!std::isfinite(v))
        fail("Indenter::table", "f", v, "finite");
    Indenter i;
    i.extent = r.back();
    i.name   = "tabulated indenter";
    i.f      = [r = std::move(r), f = std::move(f)](const double x) {
      const auto   it = std::upper_bound(r.begin(), r.end(), x);
      const auto   j  = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - r.begin(), 1), r.size() - 1);
      const double t  = (x - r[j - 1]) / (r[j] - r[j - 1]);
      return (1 - t) * f[j - 1] + t * f[j];
    };
    return i;
  }

  Indenter Indenter::from_csv(const std::string &file)
  {
    TableFile rows = read_table_file(file, "Indenter::from_csv", "r", "f");
    try
      {
        Indenter i = table(std::move(rows.x), std::move(rows.y));
        i.name     = "indenter of " + file;
        return i;
      }
    catch (const std::invalid_argument &e)
      {
        throw std::invalid_argument("Indenter::from_csv: \"" + file + "\": " + e.what());
      }
  }

  void Indenter::validate() const
  {
    if (!f)
      throw std::invalid_argument("Indenter (" + name + "): the profile function is empty");
    if (!(extent > 0))
      fail("Indenter (" + name + ")", "extent", extent, "(0, inf]");
  }

  void UnilateralLoad::validate() const
  {
    indenter.validate();
    if (control == ContactControl::depth && !std::isfinite(depth))
      fail("UnilateralLoad (depth control)", "depth", depth, "finite");
    if (control == ContactControl::force && !(force > 0 && std::isfinite(force)))
      fail("UnilateralLoad (force control)", "force", force, "(0, inf)");
    if (!(friction.coefficient >= 0))
      fail("UnilateralLoad", "friction coefficient", friction.coefficient, "[0, inf] (inf: full stick)");
    if (friction.enabled() && !(friction.load_steps >= 1 && friction.load_steps <= 10000))
      fail("UnilateralLoad", "friction load steps", friction.load_steps, "[1, 10000]");
  }



  UnilateralContactSolver::Body::Body(const Material &material_, const MeshParameters &mesh,
                                      const DiscretizationParameters &discretization, const double candidate_radius,
                                      const SurfaceRefinement &refinement, const std::string &name_)
    : name(name_)
    , material(material_)
    , contact_radius(mesh.contact_radius)
    , h_edge(mesh.h_edge)
    , used_formulation((require_clamped_far_field(discretization, "UnilateralContactSolver (" + name_ + ")"),
                        checked_formulation(material_, discretization)))
    , fe(axisymmetric_element(discretization.degree, used_formulation))
    , dof_handler(triangulation)
  {
    auto start = std::chrono::steady_clock::now();
    mesh_info  = make_mesh(mesh, triangulation);
    refine_toward_surface_points(refinement, triangulation);
    time.mesh = seconds_since(start);

    start = std::chrono::steady_clock::now();
    dof_handler.distribute_dofs(fe);
    constraints.clear();
    make_homogeneous_constraints(dof_handler, mapping, fe, constraints);
    system.reinit(dof_handler, constraints);
    const std::vector<double> dof_r = support_radii(mapping, dof_handler);
    // The candidates: the surface z-DoFs of the faces with r1 <= the candidate radius and the vertices
    // of those faces, both ascending in r, with the coupling D of the linear pressure.
    surface_faces      = collect_surface_faces(dof_handler, dof_r, 2);
    const double limit = std::min(candidate_radius, surface_faces.back().r1);
    coupling           = linear_density_coupling(surface_faces, 1, limit, discretization.degree + 2);
    if (coupling.dofs.empty())
      fail("UnilateralContactSolver", "candidate_radius", candidate_radius, "at least one surface face wide");
    candidates = coupling.dofs;
    for (const auto d : candidates)
      {
        if (constraints.is_constrained(d))
          fail("UnilateralContactSolver (" + name + ")", "candidate_radius", candidate_radius,
               "inside the truncation radius (the surface DoF at r = " + std::to_string(dof_r[d]) + " is fixed)");
        candidate_r.push_back(dof_r[d]);
      }
    time.setup = seconds_since(start);

    start = std::chrono::steady_clock::now();
    CellStiffness cell_stiffness(material, fe, mapping, discretization, contact_radius, h_edge);
    system.assemble(dof_handler, cell_stiffness, {}); // contact enters as nodal forces: nothing prescribed
    time.assemble = seconds_since(start);
  }

  UnilateralContactSolver::Body::~Body()
  {
    dof_handler.clear();
  }

  Vector<double> UnilateralContactSolver::Body::response(const FullMatrix<double> &D, const unsigned int k,
                                                         double &factorize_seconds)
  {
    Vector<double> b(dof_handler.n_dofs()), reaction;
    for (unsigned int i = 0; i < D.m(); ++i)
      b[candidates[i]] = D(i, k);
    const Vector<double> u = system.solve(false, {}, b, reaction, factorize_seconds);
    Vector<double>       column(D.m());
    for (unsigned int i = 0; i < D.m(); ++i)
      column[i] = u[candidates[i]];
    return column;
  }

  FullMatrix<double> UnilateralContactSolver::Body::compliance(const FullMatrix<double> &D, double &factorize_seconds)
  {
    FullMatrix<double> CD(D.m(), D.n());
    for (unsigned int k = 0; k < D.n(); ++k)
      {
        double               factor = 0;
        const Vector<double> column = response(D, k, factor);
        factorize_seconds += factor;
        for (unsigned int i = 0; i < D.m(); ++i)
          CD(i, k) = column[i];
      }
    return CD;
  }

  UnilateralContactSolver::Body::HatCompliance
  UnilateralContactSolver::Body::hat_compliance(const std::vector<double> &vertex_r, const std::vector<double> &radii,
                                                const unsigned int n_gauss, double &factorize_seconds,
                                                const unsigned int first_column, const HatCompliance *previous)
  {
    HatCompliance      h;
    h.coupling = hat_coupling(surface_faces, 1, vertex_r, n_gauss);
    const FullMatrix<double> &D = h.coupling.matrix;
    const unsigned int m = vertex_r.size(), n = radii.size();
    std::vector<const SurfaceFace *> at;
    for (const double r : radii)
      {
        at.push_back(find_face(surface_faces, r));
        if (!at.back())
          fail("UnilateralContactSolver (" + name + ")", "sample radius", r,
               "on the surface [0, " + std::to_string(surface_faces.back().r1) + "]");
      }
    h.K.reinit(m, m);
    h.at_radii.reinit(n, m);
    for (unsigned int k = 0; k < std::min(first_column, m); ++k)
      {
        for (unsigned int i = 0; i < n; ++i)
          h.at_radii(i, k) = previous->at_radii(i, k);
        for (unsigned int j = 0; j < std::min(first_column, m); ++j)
          h.K(j, k) = previous->K(j, k);
      }
    for (unsigned int k = first_column; k < m; ++k)
      {
        Vector<double> b(dof_handler.n_dofs()), reaction;
        for (unsigned int i = 0; i < D.m(); ++i)
          b[h.coupling.dofs[i]] = D(i, k);
        double               factor = 0;
        const Vector<double> u      = system.solve(false, {}, b, reaction, factor);
        factorize_seconds += factor;
        for (unsigned int i = 0; i < n; ++i)
          h.at_radii(i, k) = face_value(*at[i], 1, u, radii[i]);
        for (unsigned int j = 0; j < m; ++j)
          {
            double weighted = 0; // \int psi_j u r dr
            for (unsigned int i = 0; i < D.m(); ++i)
              weighted += D(i, j) * u[h.coupling.dofs[i]];
            h.K(j, k) = weighted;
            if (j < first_column)
              h.K(k, j) = weighted;
          }
      }
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int k = 0; k < j; ++k)
        h.K(j, k) = h.K(k, j) = 0.5 * (h.K(j, k) + h.K(k, j));
    return h;
  }

  Vector<double> UnilateralContactSolver::Body::field(const std::vector<types::global_dof_index> &dofs,
                                                      const std::vector<double> &values, EnergyCheck &check)
  {
    Vector<double> b(dof_handler.n_dofs()), reaction;
    for (unsigned int i = 0; i < values.size(); ++i)
      b[dofs[i]] = values[i];
    double         unused = 0;
    Vector<double> u      = system.solve(false, {}, b, reaction, unused);
    check = check_energy(system.energy(u), b * u, mesh_info.min_surface_cell, name, system.energy_magnitude(u));
    return u;
  }



  UnilateralContactSolver::UnilateralContactSolver(const Material &material, const MeshParameters &mesh,
                                                   const DiscretizationParameters &discretization_,
                                                   const double candidate_radius_, const SurfaceRefinement &refinement_,
                                                   const std::optional<Material> &indenter_body)
    : discretization(discretization_)
    , mesh_parameters(mesh)
    , candidate_radius(candidate_radius_)
    , refinement(refinement_)
  {
    mesh.validate();
    if (!(candidate_radius > 0) || !std::isfinite(candidate_radius))
      fail("UnilateralContactSolver", "candidate_radius", candidate_radius, "(0, inf)");
    half_space = std::make_unique<Body>(material, mesh, discretization, candidate_radius, refinement, "half-space");
    candidate_limit = std::min(candidate_radius, half_space->surface_faces.back().r1);

    // (C D)_ik = u_i of the nodal forces of the pressure psi_k: one back-substitution per vertex and body.
    // The time counts as setup (the factorisations as this solver's factorize, reported by the first run).
    const auto start = std::chrono::steady_clock::now();
    setup_time       = half_space->time;
    all.D            = half_space->coupling.matrix;
    all.M            = half_space->coupling.vertex_mass;
    all.CD           = half_space->compliance(all.D, setup_time.factorize);
    all.K_half_space = contact_matrix(all.D, all.CD);
    setup_time.setup += seconds_since(start) - setup_time.factorize;
    set_indenter_body(indenter_body);
  }

  void UnilateralContactSolver::set_indenter_body(const std::optional<Material> &indenter_body)
  {
    indenter.reset();
    all.indenter    = Body::HatCompliance();
    indenter_factor = 1;
    if (indenter_body)
      {
        // The indenter's own surface layer (a homogeneous body needs no z-halvings; 1e-10 a thin cells make
        // its solve garbage) and far field (the same truncation error (a/L)^{1+s}, s its deep exponent); the
        // surface vertices stay the half-space's.
        if (!indenter_body->modulus)
          throw std::invalid_argument("UnilateralContactSolver: the elastic indenter's modulus field is empty");
        MeshParameters own = mesh_parameters;
        const double   s1  = half_space->material.modulus->deep_exponent();
        const double   s2  = indenter_body->modulus->deep_exponent();
        own.far_field_size = std::clamp(std::pow(mesh_parameters.far_field_size, (1 + s1) / (1 + s2)), 1e4, 1e16);
        own.surface_layer_thickness =
          std::max(mesh_parameters.surface_layer_thickness,
                   recommended_mesh_parameters(mesh_parameters.contact_radius,
                                               indenter_body->modulus->surface_exponent(), 1e-8)
                     .surface_layer_thickness);
        indenter = std::make_unique<Body>(*indenter_body, own, discretization, candidate_radius, refinement, "indenter");
        const auto   start            = std::chrono::steady_clock::now();
        const double factorize_before = setup_time.factorize;
        all.indenter = indenter->hat_compliance(half_space->coupling.vertex_r, half_space->candidate_r,
                                                discretization.degree + 2, setup_time.factorize);
        setup_time.mesh += indenter->time.mesh;
        setup_time.assemble += indenter->time.assemble;
        setup_time.setup +=
          indenter->time.setup + seconds_since(start) - (setup_time.factorize - factorize_before);
      }
    combine(all);
  }

  UnilateralContactSolver::~UnilateralContactSolver() = default;

  unsigned int UnilateralContactSolver::n_dofs() const
  {
    return half_space->dof_handler.n_dofs() + (indenter ? indenter->dof_handler.n_dofs() : 0);
  }

  void UnilateralContactSolver::set_indenter_modulus_factor(const double factor)
  {
    if (!indenter)
      throw std::invalid_argument("UnilateralContactSolver::set_indenter_modulus_factor: the indenter is rigid");
    if (!(factor > 0))
      fail("UnilateralContactSolver::set_indenter_modulus_factor", "factor", factor, "(0, inf] (inf: rigid)");
    indenter_factor = factor;
    combine(all);
  }

  void UnilateralContactSolver::combine(SurfaceOperator &op) const
  {
    op.K = op.K_half_space;
    if (indenter)
      op.K.add(1 / indenter_factor, op.indenter.K);
  }

  FullMatrix<double> UnilateralContactSolver::gap_compliance(const SurfaceOperator &op) const
  {
    FullMatrix<double> C(op.CD);
    if (indenter)
      C.add(1 / indenter_factor, op.indenter.at_radii);
    return C;
  }



  UnilateralContactSolver::SurfaceOperator UnilateralContactSolver::surface_operator(const Indenter &shape)
  {
    const std::vector<double> &candidate_r = half_space->candidate_r;
    if (candidate_r.back() <= shape.extent * (1 + node_tolerance))
      return all;
    // The faces up to the extent. The pressure of every vertex but the last has the same nodal forces
    // as on all faces (a leading block of C D); the last one's half hat needs one more solve per body.
    SurfaceOperator op;
    SurfaceCoupling coupling =
      linear_density_coupling(half_space->surface_faces, 1, shape.extent, discretization.degree + 2);
    const unsigned int n = coupling.dofs.size(), m = coupling.vertex_r.size();
    if (n == 0)
      fail("UnilateralLoad (" + shape.name + ")", "extent", shape.extent, "at least one surface face wide");
    for (unsigned int i = 0; i < n; ++i)
      AssertThrow(coupling.dofs[i] == half_space->candidates[i], ExcInternalError());
    op.D = std::move(coupling.matrix);
    op.M = std::move(coupling.vertex_mass);
    op.CD.reinit(n, m);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int k = 0; k + 1 < m; ++k)
        op.CD(i, k) = all.CD(i, k);
    double               unused = 0;
    const Vector<double> last   = half_space->response(op.D, m - 1, unused);
    for (unsigned int i = 0; i < n; ++i)
      op.CD(i, m - 1) = last[i];
    op.K_half_space = contact_matrix(op.D, op.CD);
    if (indenter)
      op.indenter = indenter->hat_compliance(coupling.vertex_r,
                                             std::vector<double>(half_space->candidate_r.begin(),
                                                                 half_space->candidate_r.begin() + n),
                                             discretization.degree + 2, unused, m - 1, &all.indenter);
    combine(op);
    return op;
  }



  class UnilateralContactSolver::ActiveSetProblem
  {
  public:
    ActiveSetProblem(const UnilateralContactSolver &solver, const UnilateralLoad &load, const SurfaceOperator &op,
                     const std::vector<double> &f)
      : solver(solver)
      , load(load)
      , op(op)
      , f(f)
      , n(op.D.m())
      , m(op.D.n())
      , by_force(load.control == ContactControl::force)
      , target(load.force / (2 * numbers::PI))
      , C(solver.gap_compliance(op))
      , weighted(solver.weighted_profile(op, load, f))
      , D1(weighted.D1)
      , Df(weighted.Df)
      , f_vertex(weighted.f_vertex)
      , max_steps(50 + 4 * m)
    {}

    // The state of an active set: p on it (0 elsewhere), lambda = D p, u = C lambda, the weighted gaps
    // w = D^T (u - (d - f)); the depth given or found.
    void state(const std::vector<bool> &active, ActiveSetSolution &s) const
    {
      std::vector<unsigned int> I;
      for (unsigned int k = 0; k < m; ++k)
        if (active[k])
          I.push_back(k);
      const unsigned int a_size = I.size();
      s.p.assign(m, 0.0);
      s.depth = by_force ? 0.0 : load.depth;
      if (a_size > 0)
        {
          const unsigned int       size = a_size + (by_force ? 1 : 0);
          LAPACKFullMatrix<double> K(size, size);
          Vector<double>           rhs(size);
          for (unsigned int a = 0; a < a_size; ++a)
            {
              for (unsigned int b = 0; b < a_size; ++b)
                K(a, b) = op.K(I[a], I[b]);
              rhs[a] = by_force ? -Df[I[a]] : load.depth * D1[I[a]] - Df[I[a]];
              if (by_force)
                {
                  K(a, a_size) = -D1[I[a]];
                  K(a_size, a) = D1[I[a]];
                }
            }
          if (by_force)
            rhs[a_size] = target;
          K.compute_lu_factorization();
          K.solve(rhs);
          for (unsigned int a = 0; a < a_size; ++a)
            s.p[I[a]] = rhs[a];
          if (by_force)
            s.depth = rhs[a_size];
        }
      Vector<double> pv(m), lambda(n), u(n), h(n), w(m);
      for (unsigned int k = 0; k < m; ++k)
        pv[k] = s.p[k];
      op.D.vmult(lambda, pv);
      C.vmult(u, pv);
      for (unsigned int i = 0; i < n; ++i)
        h[i] = u[i] - s.depth + f[i];
      op.D.Tvmult(w, h);
      s.lambda.assign(lambda.begin(), lambda.end());
      s.u.assign(u.begin(), u.end());
      s.weighted_gap.assign(w.begin(), w.end());
      s.active = active;
    }

    // After a cycle of PDAS: the primal active-set method of Lawson and Hanson (Solving Least Squares
    // Problems, 1974, ch. 23) for the convex problem min 1/2 p^T K p - b^T p, p >= 0 (with 1^T D p = F/(2 pi)
    // under force control), whose optimality conditions are this LCP: p stays feasible and the energy
    // falls at every step, so no set repeats and it ends for a symmetric positive definite K. It keeps
    // p >= 0 at every vertex (no tensile runs at a corner).
    void monotone(ActiveSetSolution &s) const
    {
      const unsigned int steps_before = s.iterations;
      std::vector<bool>  P(m, false);
      if (by_force)
        P[std::min_element(f_vertex.begin(), f_vertex.end()) - f_vertex.begin()] = true;
      ActiveSetSolution current;
      state(P, current);
      std::vector<bool> blocked(m, false); // added, but not positive when solved (round-off): skipped
      for (unsigned int step = 1;; ++step)
        {
          current.iterations = steps_before + step;
          current.monotone_steps = step;
          if (step > max_steps)
            {
              std::ostringstream msg;
              msg << "unilateral contact (" << load.indenter.name << "): the active set did not settle after "
                  << steps_before << " PDAS steps and " << step - 1 << " steps of the monotone method, "
                  << std::count(P.begin(), P.end(), true) << " of " << m << " candidate vertices in contact";
              throw std::runtime_error(msg.str());
            }
          const double w_scale = solver.gap_scale(op, current, D1);
          unsigned int add = m;
          for (unsigned int k = 0; k < m; ++k)
            if (!P[k] && !blocked[k] && current.weighted_gap[k] < -gap_zero * w_scale &&
                (add == m || current.weighted_gap[k] < current.weighted_gap[add]))
              add = k;
          if (add == m)
            {
              s = current;
              return;
            }
          P[add] = true;
          for (bool first = true;; first = false)
            {
              ActiveSetSolution trial;
              state(P, trial);
              double       alpha = 1;
              unsigned int limit = m;
              for (unsigned int k = 0; k < m; ++k)
                if (P[k] && !(trial.p[k] > 0))
                  {
                    const double step_to_zero = current.p[k] / (current.p[k] - trial.p[k]);
                    if (step_to_zero < alpha)
                      {
                        alpha = step_to_zero;
                        limit = k;
                      }
                  }
              if (limit == m)
                {
                  current = trial;
                  std::fill(blocked.begin(), blocked.end(), false);
                  break;
                }
              if (first && limit == add && !(alpha > 0))
                {
                  P[add]       = false; // the new vertex is not positive even alone: skip it
                  blocked[add] = true;
                  break;
                }
              // Back to the boundary of p >= 0 on the segment from the current p toward the trial one;
              // the vertices that reach zero leave P.
              for (unsigned int k = 0; k < m; ++k)
                if (P[k])
                  {
                    current.p[k] += alpha * (trial.p[k] - current.p[k]);
                    if (k == limit || !(current.p[k] > 0))
                      {
                        P[k]         = false;
                        current.p[k] = 0;
                      }
                  }
            }
        }
    }

    /// The start: the geometric overlap (force control: the lowest vertex of the indenter alone).
    std::vector<bool> start() const
    {
      std::vector<bool> active(m, false);
      if (by_force)
        active[std::min_element(f_vertex.begin(), f_vertex.end()) - f_vertex.begin()] = true;
      else
        for (unsigned int k = 0; k < m; ++k)
          active[k] = load.depth - f_vertex[k] > 0;
      return active;
    }

    double gap_scale(const ActiveSetSolution &s) const { return solver.gap_scale(op, s, D1); }

    const UnilateralContactSolver &solver;
    const UnilateralLoad          &load;
    const SurfaceOperator         &op;
    const std::vector<double>     &f;
    const unsigned int             n;        // displacement nodes
    const unsigned int             m;        // pressure vertices
    const bool                     by_force;
    const double                   target;   // 1^T D p
    const FullMatrix<double>       C;        // the gap's displacements of each vertex pressure
    const WeightedProfile          weighted;
    const Vector<double>          &D1, &Df;
    const std::vector<double>     &f_vertex;
    const unsigned int             max_steps; // per stage
  };



  UnilateralContactSolver::ActiveSetSolution
  UnilateralContactSolver::solve_active_set(const UnilateralLoad &load, const SurfaceOperator &op,
                                            const std::vector<double> &f) const
  {
    const ActiveSetProblem problem(*this, load, op, f);
    const unsigned int     m      = problem.m;
    std::vector<bool>      active = problem.start();
    ActiveSetSolution           s;
    std::set<std::vector<bool>> seen;
    for (unsigned int step = 1;; ++step)
      {
        problem.state(active, s);
        s.iterations = step;
        const std::vector<bool> next = next_contact_set(active, s.p, s.weighted_gap, op.M, problem.gap_scale(s));
        if (next == active)
          return s;
        if (step >= problem.max_steps)
          {
            std::ostringstream msg;
            msg << "unilateral contact (" << load.indenter.name << "): the active set did not settle after " << step
                << " PDAS steps, "
                << std::count(active.begin(), active.end(), true) << " of " << m << " candidate vertices in contact";
            throw std::runtime_error(msg.str());
          }
        seen.insert(active);
        if (seen.count(next))
          {
            problem.monotone(s); // a cycle
            return s;
          }
        active = next;
      }
  }



  UnilateralContactSolver::WeightedProfile
  UnilateralContactSolver::weighted_profile(const SurfaceOperator &op, const UnilateralLoad &load,
                                            const std::vector<double> &f) const
  {
    const unsigned int n = op.D.m(), m = op.D.n();
    WeightedProfile    w;
    Vector<double>     ones(n), fv(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        ones[i] = 1;
        fv[i]   = f[i];
      }
    w.D1.reinit(m);
    w.Df.reinit(m);
    op.D.Tvmult(w.D1, ones);
    op.D.Tvmult(w.Df, fv);
    w.f_vertex.resize(m);
    for (unsigned int k = 0; k < m; ++k)
      w.f_vertex[k] = load.indenter.f(half_space->coupling.vertex_r[k]);
    return w;
  }

  double UnilateralContactSolver::gap_scale(const SurfaceOperator &op, const ActiveSetSolution &s,
                                            const Vector<double> &D1) const
  {
    double w_scale = 0;
    for (unsigned int k = 0; k < D1.size(); ++k)
      w_scale = std::max(w_scale, std::abs(D1[k]) * std::abs(s.depth));
    for (const double u : s.u)
      w_scale = std::max(w_scale, std::abs(u) * op.D.linfty_norm());
    return w_scale;
  }

  std::vector<bool> UnilateralContactSolver::next_contact_set(const std::vector<bool> &active, const std::vector<double> &p,
                                                              const std::vector<double> &weighted_gap,
                                                              const FullMatrix<double> &M, const double w_scale)
  {
    const unsigned int m     = active.size();
    double             p_max = 0;
    for (const double x : p)
      p_max = std::max(p_max, std::abs(x));
    // The vertices that violate their condition: free with a negative weighted gap, or in a run of
    // contact vertices with tensile pressures that ends a contact zone or is tensile as a whole (the
    // forces (M p)_k of its vertices' shares, M >= 0). Next to a singular edge (the corner of a
    // punch) the linear pressure alternates in sign while the force there is compressive: such a
    // run stays in contact. Without such runs this is the PDAS update.
    Vector<double> pv(m), share(m);
    for (unsigned int k = 0; k < m; ++k)
      pv[k] = p[k];
    M.vmult(share, pv);
    const double      share_max = share.linfty_norm();
    std::vector<bool> next      = active;
    for (unsigned int k = 0; k < m; ++k)
      if (!active[k] && weighted_gap[k] < -gap_zero * w_scale)
        next[k] = true;
    for (unsigned int k = 0; k < m;)
      {
        if (!(active[k] && p[k] < -force_zero * p_max))
          {
            ++k;
            continue;
          }
        unsigned int end = k; // the run [k, end)
        double       sum = 0;
        while (end < m && active[end] && p[end] < -force_zero * p_max)
          sum += share[end++];
        const bool zone_end = k == 0 || !active[k - 1] || end == m || !active[end];
        if (zone_end || sum < -force_zero * share_max)
          for (unsigned int j = k; j < end; ++j)
            next[j] = false;
        k = end;
      }
    return next;
  }



  void UnilateralContactSolver::edges(const UnilateralLoad &load, const ActiveSetSolution &s,
                                      const std::vector<double> &f, UnilateralResult &result) const
  {
    const std::vector<double> &vertex_r    = half_space->coupling.vertex_r;
    const std::vector<double> &candidate_r = half_space->candidate_r;
    const unsigned int         m           = s.active.size();
    for (unsigned int k = 0; k < m; ++k)
      if (s.active[k])
        {
          if (k == 0 || !s.active[k - 1])
            result.zones.push_back({vertex_r[k], vertex_r[k]});
          result.zones.back().r_out = vertex_r[k];
          ++result.active_nodes;
        }
    if (result.zones.empty())
      return;
    // Zones less than zone_merge_distance r apart are one: next to a smooth edge, where p -> 0, the linear
    // pressure alternates in sign over a few vertices of the edge grading.
    std::vector<ContactZone> merged{result.zones.front()};
    for (std::size_t z = 1; z < result.zones.size(); ++z)
      if (result.zones[z].r_in - merged.back().r_out <= zone_merge_distance * result.zones[z].r_in)
        merged.back().r_out = result.zones[z].r_out;
      else
        merged.push_back(result.zones[z]);
    result.zones = merged;
    const double r_e = result.zones.back().r_out;
    if (r_e >= vertex_r[m - 1] * (1 - node_tolerance))
      {
        // The contact reaches the last vertex: the indenter's edge, or the candidate radius.
        if (m < vertex_r.size() || r_e >= load.indenter.extent * (1 - node_tolerance))
          {
            result.edge_at_extent = true;
            result.outer_edge     = r_e;
            result.edge_bracket   = {r_e, r_e};
            return;
          }
        std::ostringstream msg;
        msg << "unilateral contact (" << load.indenter.name << "): the contact reaches the candidate radius "
            << candidate_limit << "; solve with a larger one";
        throw std::runtime_error(msg.str());
      }
    const unsigned int e = std::lower_bound(vertex_r.begin(), vertex_r.begin() + m, r_e * (1 - node_tolerance)) -
                           vertex_r.begin();
    result.edge_bracket = {r_e, vertex_r[e + 1]};
    result.outer_edge   = r_e;
    // Sub-node estimates. From the pressure at the last two vertices in contact, p = K (a - r)^alpha,
    // alpha = (1 + s)/2 (9.26; s the surface exponent of E); from the gaps of the next two displacement
    // nodes beyond the bracket, h = K (r - a)^beta, beta = (3 + s)/2. Each is kept only inside the bracket. With an
    // elastic indenter the more compliant surface sets the edge at small scales: the larger exponent.
    const double exponent_s =
      std::max(half_space->material.modulus->surface_exponent(),
               indenter ? indenter->material.modulus->surface_exponent() : -std::numeric_limits<double>::infinity());
    // An estimate a little outside the bracket (the edge on a node, round-off) is clamped into it.
    const double width      = result.edge_bracket.second - result.edge_bracket.first;
    const auto   in_bracket = [&](double &x) {
      if (!std::isfinite(x) || x < result.edge_bracket.first - 0.25 * width ||
          x > result.edge_bracket.second + 0.25 * width)
        return false;
      x = std::clamp(x, result.edge_bracket.first, result.edge_bracket.second);
      return true;
    };
    if (e >= 1 && s.active[e - 1] && s.p[e] > 0 && s.p[e - 1] > s.p[e])
      {
        const double gamma = 2 / (1 + exponent_s);
        const double q1 = std::pow(s.p[e - 1], gamma), q2 = std::pow(s.p[e], gamma);
        double       x  = vertex_r[e] + q2 * (vertex_r[e] - vertex_r[e - 1]) / (q1 - q2);
        if (in_bracket(x))
          result.edge_from_pressure = x;
      }
    const unsigned int n = f.size();
    unsigned int       i = 0;
    // The nodes beyond the bracket: those inside it (a midside node, the next vertex) may still be in contact
    // up to the weak condition's round-off, and a gap of that size breaks the fit.
    while (i < n && candidate_r[i] <= result.edge_bracket.second * (1 + node_tolerance))
      ++i;
    if (i + 1 < n)
      {
        const double beta = (3 + exponent_s) / 2;
        const double r1 = candidate_r[i], r2 = candidate_r[i + 1];
        const double h1 = s.u[i] - (s.depth - f[i]), h2 = s.u[i + 1] - (s.depth - f[i + 1]);
        if (h1 > 0 && h2 > h1)
          {
            const double q1 = std::pow(h1, 1 / beta), q2 = std::pow(h2, 1 / beta);
            double       x  = r1 - q1 * (r2 - r1) / (q2 - q1);
            if (in_bracket(x))
              result.edge_from_gap = x;
          }
      }
    result.outer_edge = std::isfinite(result.edge_from_pressure) ? result.edge_from_pressure :
                        std::isfinite(result.edge_from_gap)      ? result.edge_from_gap :
                                                                   0.5 * (r_e + result.edge_bracket.second);
  }



  void UnilateralContactSolver::sample(const Vector<double> &u, const Vector<double> *u_indenter,
                                       const std::vector<double> &p, const std::vector<double> &q,
                                       const OutputRequest &outputs, UnilateralResult &result) const
  {
    const std::vector<SurfaceFace> &surface_faces = half_space->surface_faces;
    const std::vector<double> &vertex_r = half_space->coupling.vertex_r;
    const double edge = result.zones.empty() ? 0 : result.zones.back().r_out;
    unsigned int outside = 0;
    for (const double r : outputs.pressure_radii)
      {
        if (!(r >= 0))
          fail("UnilateralContactSolver output", "pressure radius", r, "[0, inf)");
        if (r > edge * (1 + node_tolerance))
          {
            ++outside; // p = 0 there: the sample of a radius the contact did not reach is left out
            continue;
          }
        // p is linear between the vertices.
        const auto         it = std::upper_bound(vertex_r.begin(), vertex_r.begin() + p.size(), r);
        const unsigned int k  = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - vertex_r.begin(), 1), p.size() - 1);
        const double       t  = (r - vertex_r[k - 1]) / (vertex_r[k] - vertex_r[k - 1]);
        result.pressure.push_back({r, (1 - t) * p[k - 1] + t * p[k]});
        if (!q.empty())
          result.shear.push_back({r, (1 - t) * q[k - 1] + t * q[k]});
      }
    if (outside > 0)
      result.message += " " + std::to_string(outside) + " pressure radii beyond the contact (edge " +
                        std::to_string(edge) + ") left out;";
    for (const double r : outputs.displacement_radii)
      {
        const SurfaceFace *face = find_face(surface_faces, r);
        if (!face)
          fail("UnilateralContactSolver output", "displacement radius", r,
               "on the surface [0, " + std::to_string(surface_faces.back().r1) + "]");
        result.displacement.push_back({r, face_value(*face, 1, u, r)});
        result.radial_displacement.push_back({r, face_value(*face, 0, u, r)});
        if (u_indenter)
          {
            const SurfaceFace *its = find_face(indenter->surface_faces, r);
            if (!its)
              fail("UnilateralContactSolver output", "displacement radius", r,
                   "on the indenter's surface [0, " + std::to_string(indenter->surface_faces.back().r1) + "]");
            result.indenter_displacement.push_back({r, face_value(*its, 1, *u_indenter, r) / indenter_factor});
          }
      }
    if (!outputs.vtu_file.empty())
      {
        // The half-space in vtu_file; an elastic indenter beside it, in <stem>-indenter.vtu (its own axes:
        // z into the indenter).
        const auto write = [&](const Body &body, const Vector<double> &field, const std::string &file) {
          MeridianDataOut data_out;
          data_out.surface_map =
            SurfaceMap<2>(discretization.surface_map, *body.material.modulus, body.contact_radius, body.h_edge);
          data_out.attach_dof_handler(body.dof_handler);
          std::vector<std::string> names{"u_r", "u_z"};
          if (body.used_formulation == Formulation::mixed)
            names.push_back(mixed_pressure_name(body.material));
          data_out.add_data_vector(
            with_physical_pressure(field, body.dof_handler, body.fe, body.material, body.contact_radius), names);
          write_vtu(data_out, body.mapping, discretization.degree, file, "UnilateralContactSolver");
        };
        write(*half_space, u, outputs.vtu_file);
        if (u_indenter)
          {
            Vector<double> scaled(*u_indenter);
            scaled /= indenter_factor;
            std::string file = outputs.vtu_file;
            const auto  dot  = file.rfind(".vtu");
            file.insert(dot == std::string::npos ? file.size() : dot, "-indenter");
            write(*indenter, scaled, file);
          }
      }
  }



  UnilateralResult UnilateralContactSolver::run(const UnilateralLoad &load, const OutputRequest &outputs)
  {
    load.validate();
    UnilateralResult result;
    result.start(setup_time, n_dofs(),
                 half_space->triangulation.n_active_cells() + (indenter ? indenter->triangulation.n_active_cells() : 0),
                 half_space->mesh_info);
    const std::vector<double> &candidate_r = half_space->candidate_r;
    setup_time.factorize = 0; // reported once, by the first run

    const auto            start = std::chrono::steady_clock::now();
    const SurfaceOperator op    = surface_operator(load.indenter);
    const unsigned int    n     = op.D.m();
    result.candidate_nodes      = op.D.n();
    std::vector<double> f(n);
    for (unsigned int i = 0; i < n; ++i)
      {
        f[i] = load.indenter.f(candidate_r[i]);
        if (!std::isfinite(f[i]))
          fail("UnilateralLoad (" + load.indenter.name + ")", "f(r) at r = " + std::to_string(candidate_r[i]), f[i],
               "finite");
      }
    const bool frictional = load.friction.enabled();
    if (frictional && indenter)
      throw std::invalid_argument("UnilateralContactSolver: friction (coefficient " +
                                  std::to_string(load.friction.coefficient) +
                                  ") is modelled for a rigid indenter only; this solver has an elastic one");
    ShearOperator shear;
    if (frictional)
      shear = shear_operator(op);
    const ActiveSetSolution s = frictional ? solve_frictional(load, op, shear, f) : solve_active_set(load, op, f);
    result.depth             = s.depth;
    result.iterations        = s.iterations;
    result.monotone_steps = s.monotone_steps;
    double sum               = 0;
    for (const double l : s.lambda)
      sum += l;
    result.force = 2 * numbers::PI * sum;
    edges(load, s, f, result);
    for (unsigned int i = 0; i < n; ++i)
      {
        result.nodal_gap.push_back({candidate_r[i], s.u[i] - (s.depth - f[i])});
        result.nodal_force.push_back({candidate_r[i], 2 * numbers::PI * s.lambda[i]});
      }

    // The fields of the contact forces, and the energy checks u.Au = lambda.u (the indenter's at its
    // unscaled modulus: the check does not depend on the scale).
    EnergyCheck          check;
    std::vector<types::global_dof_index> dofs(half_space->candidates.begin(), half_space->candidates.begin() + n);
    std::vector<double>                  forces = s.lambda;
    if (frictional)
      {
        dofs.insert(dofs.end(), shear.coupling.dofs.begin(), shear.coupling.dofs.end());
        forces.insert(forces.end(), s.lambda_r.begin(), s.lambda_r.end());
        result.path = s.path;
        result.stick_radius = s.path.back().stick_radius;
        for (unsigned int k = 0; k < s.active.size(); ++k)
          if (s.active[k])
            (s.slip[k] != 1 && s.slip[k] != -1 ? result.stick_nodes :
             s.q[k] < 0                     ? result.slip_outward_nodes :
                                              result.slip_inward_nodes)++;
      }
    const Vector<double> u = half_space->field(dofs, forces, check);
    if (result.active_nodes > 0)
      result.record(check);
    Vector<double> u_indenter;
    if (indenter)
      {
        // Its nodal forces: the same vertex pressures through its own coupling.
        const FullMatrix<double> &D_indenter = op.indenter.coupling.matrix;
        Vector<double>            pv(s.p.size()), lambda(D_indenter.m());
        for (unsigned int k = 0; k < s.p.size(); ++k)
          pv[k] = s.p[k];
        D_indenter.vmult(lambda, pv);
        u_indenter = indenter->field(op.indenter.coupling.dofs, std::vector<double>(lambda.begin(), lambda.end()), check);
        if (result.active_nodes > 0)
          result.record(check);
      }
    result.time.solve = seconds_since(start);

    const auto post = std::chrono::steady_clock::now();
    sample(u, indenter ? &u_indenter : nullptr, s.p, s.q, outputs, result);
    result.time.postprocess = seconds_since(post);
    return result;
  }



  UnilateralResult solve_remeshed(const Material &material, const Settings &settings, const UnilateralLoad &load,
                                  const double first_radius, const OutputRequest &outputs, const Remeshing &remeshing)
  {
    if (!(first_radius > 0) || !std::isfinite(first_radius))
      fail("solve_remeshed", "first_radius", first_radius, "(0, inf)");
    if (!(remeshing.tolerance > 0))
      fail("solve_remeshed", "tolerance", remeshing.tolerance, "(0, inf)");
    if (remeshing.max_meshes < 1)
      fail("solve_remeshed", "max_meshes", remeshing.max_meshes, ">= 1");
    if (!(remeshing.candidate_factor > 1) || !std::isfinite(remeshing.candidate_factor))
      fail("solve_remeshed", "candidate_factor", remeshing.candidate_factor, "(1, inf)");
    double             radius = first_radius;
    std::ostringstream history;
    history << "edges found on meshes graded toward";
    for (unsigned int m = 1;; ++m)
      {
        MeshParameters mesh = settings.mesh;
        mesh.contact_radius = radius;
        UnilateralContactSolver solver(material, mesh, settings.discretization, remeshing.candidate_factor * radius, {},
                                       remeshing.indenter_body);
        UnilateralResult        result = solver.run(load, outputs);
        if (result.zones.empty())
          throw std::runtime_error("solve_remeshed (" + load.indenter.name + "): no contact at this load");
        history << " " << radius << " -> " << result.outer_edge << ";";
        // Converged when the edge moves by less than the tolerance or stays within the vertex spacing
        // of the edge grading (the estimate inside a bracket scatters by about that much).
        const double change = std::abs(result.outer_edge - radius) / radius;
        if (change <= std::max(remeshing.tolerance, 2 * settings.mesh.h_edge) || result.edge_at_extent)
          return result;
        if (m == remeshing.max_meshes)
          {
            result.message += " remeshing stopped after " + std::to_string(m) + " meshes (" + history.str() + ")";
            result.reliable = false;
            return result;
          }
        radius = result.outer_edge;
      }
  }
} // namespace gradcontact::fem
