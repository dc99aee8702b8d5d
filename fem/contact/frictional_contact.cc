// Coulomb friction in the unilateral contact of a rigid indenter (fem/contact/unilateral_contact.h, "Friction"):
// the shear operator of the surface vertices and the incremental active-set solve along the loading path.
#include <fem/base/errors.h>
#include <fem/contact/unilateral_contact.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    /// The tangential state of a vertex in contact: 0 stick, +1 / -1 slip with q = +mu p / -mu p, and
    /// this: it came into contact during the current load step.
    constexpr int entering = 2;
  } // namespace

  UnilateralContactSolver::ShearOperator UnilateralContactSolver::shear_operator(const SurfaceOperator &op)
  {
    const bool of_all = op.D.m() == all.D.m() && op.D.n() == all.D.n();
    if (of_all && all_shear)
      return *all_shear;
    Body &body = *half_space;
    ShearOperator s;
    // The hats of the same vertices on the u_r trace, up to the same radius as op's pressure.
    const double limit = body.coupling.vertex_r[op.D.n() - 1];
    s.coupling         = linear_density_coupling(body.surface_faces, 0, limit, discretization.degree + 2);
    const unsigned int n = op.D.m(), m = op.D.n(), n_r = s.coupling.dofs.size();
    AssertThrow(s.coupling.vertex_r.size() == m, ExcInternalError());
    for (unsigned int i = 0; i < n_r; ++i)
      if (body.constraints.is_constrained(s.coupling.dofs[i])) // u_r = 0 on the axis
        for (unsigned int k = 0; k < m; ++k)
          s.coupling.matrix(i, k) = 0;
    s.Cz.reinit(n, m);
    s.K_zr.reinit(m, m);
    s.K_rr.reinit(m, m);
    for (unsigned int k = 1; k < m; ++k) // q = 0 at the axis
      {
        Vector<double> b(body.dof_handler.n_dofs()), reaction;
        for (unsigned int i = 0; i < n_r; ++i)
          b[s.coupling.dofs[i]] = s.coupling.matrix(i, k);
        double               unused = 0;
        const Vector<double> u      = body.system.solve(false, {}, b, reaction, unused);
        for (unsigned int i = 0; i < n; ++i)
          s.Cz(i, k) = u[body.candidates[i]];
        for (unsigned int j = 0; j < m; ++j)
          {
            double zr = 0, rr = 0;
            for (unsigned int i = 0; i < n; ++i)
              zr += op.D(i, j) * u[body.candidates[i]];
            for (unsigned int i = 0; i < n_r; ++i)
              rr += s.coupling.matrix(i, j) * u[s.coupling.dofs[i]];
            s.K_zr(j, k) = zr;
            s.K_rr(j, k) = rr;
          }
      }
    // Symmetrised against the round-off of the back-substitutions; row and column 0 (the axis: q = 0, W unused)
    // are zero.
    for (unsigned int j = 1; j < m; ++j)
      for (unsigned int k = 1; k < j; ++k)
        s.K_rr(j, k) = s.K_rr(k, j) = 0.5 * (s.K_rr(j, k) + s.K_rr(k, j));
    for (unsigned int k = 0; k < m; ++k)
      s.K_rr(0, k) = s.K_rr(k, 0) = 0;
    s.K_rz.reinit(m, m);
    s.K_rz.copy_transposed(s.K_zr);
    // (no setup time of its own: the first frictional run builds it, inside its solve time)
    if (of_all)
      all_shear = std::make_unique<ShearOperator>(s);
    return s;
  }



  /// The frictional problem of solve_frictional on the candidate vertices (the header's "Friction"): the state of
  /// the contact and stick sets at one load, their primal-dual update within a load step, and the path's points.
  class UnilateralContactSolver::FrictionalProblem
  {
  public:
    /// What one load step hands to the next: the sets, the weighted radial displacements W0 and the contact set at
    /// the end of the step, and the active-set steps so far.
    struct Carried
    {
      std::vector<double> W0;
      std::vector<bool>   active;
      std::vector<int>    slip;
      std::vector<bool>   in_contact_before;
      unsigned int        total = 0;
    };

    FrictionalProblem(const UnilateralContactSolver &solver, const UnilateralLoad &load, const SurfaceOperator &op,
                      const ShearOperator &shear, const std::vector<double> &f)
      : solver(solver)
      , load(load)
      , op(op)
      , shear(shear)
      , f(f)
      , n(op.D.m())
      , m(op.D.n())
      , by_force(load.control == ContactControl::force)
      , mu(load.friction.coefficient)
      , full_stick(std::isinf(mu))
      , steps(load.friction.load_steps)
      , vertex_r(solver.half_space->coupling.vertex_r)
      , weighted(solver.weighted_profile(op, load, f))
      , D1(weighted.D1)
      , Df(weighted.Df)
      , f_vertex(weighted.f_vertex)
      , max_steps(50 + 4 * m)
      , touching_unloaded(lowest_vertices(f_vertex))
    {}

    /// The load of step j: d_j = d (j/N)^2 or F_j / (2 pi) = F / (2 pi) (j/N)^3 (the header).
    double step_target(const unsigned int j) const
    {
      const double t = double(j) / steps;
      return by_force ? load.force / (2 * numbers::PI) * t * t * t : load.depth * t * t;
    }

    /// The unloaded start, nothing in contact before, with the first step's contact set: the geometric overlap at
    /// `target` (force control: the lowest vertex of the indenter alone).
    Carried start(const double target) const
    {
      Carried c{std::vector<double>(m, 0.0), std::vector<bool>(m, false), std::vector<int>(m, 0),
                std::vector<bool>(m, false), 0};
      if (by_force)
        c.active[std::min_element(f_vertex.begin(), f_vertex.end()) - f_vertex.begin()] = true;
      else
        for (unsigned int k = 0; k < m; ++k)
          c.active[k] = target - f_vertex[k] > 0;
      return c;
    }

    /// The state of the sets at one load (target: the depth or F / (2 pi)) from the previous step's weighted
    /// radial displacements W0: p on the contact set, q on its stick vertices (q = slip mu p on its slip
    /// vertices), 0 elsewhere.
    void state(const std::vector<bool> &active, const std::vector<int> &slip, const double target,
               const std::vector<double> &W0, ActiveSetSolution &s) const
    {
      std::vector<unsigned int> P, T; // the unknowns p_P, q_T
      for (unsigned int k = 0; k < m; ++k)
        if (active[k])
          {
            P.push_back(k);
            if (k > 0 && slip[k] == 0)
              T.push_back(k);
          }
      s.p.assign(m, 0.0);
      s.q.assign(m, 0.0);
      s.depth = by_force ? 0.0 : target;
      if (!P.empty())
        solve_sets(P, T, slip, target, W0, s);
      Vector<double> pv(m), qv(m), lambda(n), lambda_r(shear.coupling.dofs.size()), u(n), uq(n), h(n), w(m), Wq(m);
      for (unsigned int k = 0; k < m; ++k)
        {
          pv[k] = s.p[k];
          qv[k] = s.q[k];
        }
      op.D.vmult(lambda, pv);
      shear.coupling.matrix.vmult(lambda_r, qv);
      op.CD.vmult(u, pv);
      shear.Cz.vmult(uq, qv);
      u += uq;
      for (unsigned int i = 0; i < n; ++i)
        h[i] = u[i] - s.depth + f[i];
      op.D.Tvmult(w, h);
      s.lambda.assign(lambda.begin(), lambda.end());
      s.lambda_r.assign(lambda_r.begin(), lambda_r.end());
      s.u.assign(u.begin(), u.end());
      s.weighted_gap.assign(w.begin(), w.end());
      s.active = active;
      s.slip   = slip;
    }

    /// The active-set steps of load step j until the contact and stick sets settle: `carried` holds the previous
    /// step's sets and W0 on entry, this step's on return. std::runtime_error when the sets do not settle in
    /// max_steps, or cycle also when changed one vertex at a time.
    void settle(const unsigned int j, const double target, Carried &carried, ActiveSetSolution &s) const
    {
      std::vector<bool> &active = carried.active;
      std::vector<int>  &slip   = carried.slip;
      std::set<std::pair<std::vector<bool>, std::vector<int>>> seen;
      bool single_changes = false;
      for (unsigned int it = 1;; ++it)
        {
          state(active, slip, target, carried.W0, s);
          ++carried.total;
          const std::vector<double> W = radial(s);
          std::vector<bool>         next =
            next_contact_set(active, s.p, s.weighted_gap, op.M, solver.gap_scale(op, s, D1));
          std::vector<int>          next_slip = next_slip_states(next, carried, s, W);
          if (next == active && next_slip == slip)
            {
              carried.W0                = W;
              carried.in_contact_before = active;
              return;
            }
          if (it >= max_steps)
            throw std::runtime_error(describe("the contact and stick sets did not settle", j, it, carried));
          seen.insert({active, slip});
          if (seen.count({next, next_slip}))
            {
              // A cycle (next to a singular edge, where a bonded punch's pressure oscillates): change one
              // vertex only, the contact condition most violated (then the stick condition); a cycle
              // of these single changes stops.
              if (single_changes)
                throw std::runtime_error(
                  describe("the contact and stick sets cycle, also one vertex at a time,", j, it, carried));
              single_changes = true;
            }
          if (single_changes)
            change_one(active, slip, s, next, next_slip);
          active = std::move(next);
          slip   = std::move(next_slip);
        }
    }

    /// The point of the loading path of a settled state: its depth, force 2 pi sum lambda, outer edge and stick
    /// radius.
    UnilateralResult::PathPoint path_point(const ActiveSetSolution &s, const unsigned int total) const
    {
      UnilateralResult::PathPoint point;
      point.depth      = s.depth;
      point.iterations = total;
      double sum       = 0;
      for (const double l : s.lambda)
        sum += l;
      point.force = 2 * numbers::PI * sum;
      UnilateralResult edge;
      solver.edges(load, s, f, edge);
      point.outer_edge = edge.outer_edge;
      // The stick zone around the axis: up to its last stick vertex, then the middle to the next vertex when
      // that one slips, the outer edge when the contact ends there.
      unsigned int k = 0;
      while (k < m && s.active[k] && (s.slip[k] == 0 || s.slip[k] == entering))
        ++k;
      point.stick_radius = k == 0                 ? std::numeric_limits<double>::quiet_NaN() : // axis not in contact
                           k == m || !s.active[k] ? edge.outer_edge :
                                                    0.5 * (vertex_r[k - 1] + vertex_r[k]);
      return point;
    }

    /// A vertex that comes into contact during a step carries no shear in that step and sticks from the next
    /// one on, at its position then (when it touched within the step is not resolved: an error of the step's
    /// size). The vertices the unloaded indenter touches (its lowest points, a flat punch's face) stick from
    /// the start: these.
    static std::vector<bool> lowest_vertices(const std::vector<double> &f_vertex)
    {
      const unsigned int m = f_vertex.size();
      std::vector<bool>  touching_unloaded(m, false);
      const double       f_min = *std::min_element(f_vertex.begin(), f_vertex.end());
      double             f_range = 0;
      for (const double x : f_vertex)
        f_range = std::max(f_range, std::abs(x - f_min));
      for (unsigned int k = 0; k < m; ++k)
        touching_unloaded[k] = f_vertex[k] - f_min <= 1e-12 * f_range;
      return touching_unloaded;
    }

    /// p on P and q on T (and the depth under force control) of the sets' linear system (the header's blocks,
    /// unsymmetric: dense LU): the normal rows K p + K_zr q = d D1 - Df, the stick rows K_rz p + K_rr q = W0,
    /// under force control D1^T p = target with the depth an unknown.
    void solve_sets(const std::vector<unsigned int> &P, const std::vector<unsigned int> &T,
                    const std::vector<int> &slip, const double target, const std::vector<double> &W0,
                    ActiveSetSolution &s) const
    {
      const unsigned int np = P.size(), nt = T.size(), size = np + nt + (by_force ? 1 : 0);
      LAPACKFullMatrix<double> A(size, size);
      Vector<double>           rhs(size);
      // The shear of a slip vertex l is slip_l mu p_l: a column of p_l.
      const auto slip_factor = [&](const unsigned int l) {
        return l > 0 && (slip[l] == 1 || slip[l] == -1) ? slip[l] * mu : 0.0;
      };
      for (unsigned int a = 0; a < np; ++a)
        {
          const unsigned int k = P[a];
          for (unsigned int b = 0; b < np; ++b)
            A(a, b) = op.K(k, P[b]) + slip_factor(P[b]) * shear.K_zr(k, P[b]);
          for (unsigned int b = 0; b < nt; ++b)
            A(a, np + b) = shear.K_zr(k, T[b]);
          rhs[a] = by_force ? -Df[k] : target * D1[k] - Df[k];
          if (by_force)
            {
              A(a, size - 1) = -D1[k];
              A(size - 1, a) = D1[k];
            }
        }
      for (unsigned int t = 0; t < nt; ++t)
        {
          const unsigned int k = T[t];
          for (unsigned int b = 0; b < np; ++b)
            A(np + t, b) = shear.K_rz(k, P[b]) + slip_factor(P[b]) * shear.K_rr(k, P[b]);
          for (unsigned int b = 0; b < nt; ++b)
            A(np + t, np + b) = shear.K_rr(k, T[b]);
          rhs[np + t] = W0[k];
        }
      if (by_force)
        rhs[size - 1] = target;
      A.compute_lu_factorization();
      A.solve(rhs);
      for (unsigned int a = 0; a < np; ++a)
        {
          s.p[P[a]] = rhs[a];
          s.q[P[a]] = slip_factor(P[a]) * rhs[a];
        }
      for (unsigned int t = 0; t < nt; ++t)
        s.q[T[t]] = rhs[np + t];
      if (by_force)
        s.depth = rhs[size - 1];
    }

    /// The weighted radial displacements of a state: W = K_rz p + K_rr q.
    std::vector<double> radial(const ActiveSetSolution &s) const
    {
      Vector<double> pv(m), qv(m), W(m), Wq(m);
      for (unsigned int k = 0; k < m; ++k)
        {
          pv[k] = s.p[k];
          qv[k] = s.q[k];
        }
      shear.K_rz.vmult(W, pv);
      shear.K_rr.vmult(Wq, qv);
      W += Wq;
      return std::vector<double>(W.begin(), W.end());
    }

    /// The update of the stick and slip sets (the header's, in one tangential direction) with the next contact
    /// set `next`: a vertex coming into contact is `entering`, one staying in contact sticks or slips by its trial
    /// shear, the others carry none.
    std::vector<int> next_slip_states(const std::vector<bool> &next, const Carried &carried, const ActiveSetSolution &s,
                                      const std::vector<double> &W) const
    {
      const std::vector<bool> &active = carried.active;
      const std::vector<int>  &slip   = carried.slip;
      std::vector<int>         next_slip(m, 0);
      for (unsigned int k = 1; k < m; ++k)
        if (next[k] && !carried.in_contact_before[k] && !touching_unloaded[k])
          next_slip[k] = entering;
        else if (next[k] && active[k] && !full_stick && slip[k] != entering)
          {
            // Stick while the trial shear q - slip increment / compliance stays inside the cone. A vertex kept
            // in contact under a small tensile pressure next to an edge (the contact set's rule) slips with
            // q = +-mu p, a shear of mu |p| against its slip: letting it slide freely instead (q = 0) made
            // the sets cycle between the two states (k = 0.5, nu = 0.2, mu = 0.3), so it is left so.
            const double xi    = s.q[k] - (W[k] - carried.W0[k]) / shear.K_rr(k, k);
            const double bound = mu * std::max(s.p[k], 0.0);
            next_slip[k]       = std::abs(xi) <= bound * (1 + 1e-12) ? 0 : (xi > 0 ? 1 : -1);
          }
      return next_slip;
    }

    /// After a cycle, of the changes from (active, slip) to (next, next_slip) the one kept: the contact condition
    /// most violated (the pressure over the largest, the weighted gap over gap_scale), else the first change of
    /// a stick or slip state.
    void change_one(const std::vector<bool> &active, const std::vector<int> &slip, const ActiveSetSolution &s,
                    std::vector<bool> &next, std::vector<int> &next_slip) const
    {
      double       p_max = 0, worst = 0;
      unsigned int pick  = m;
      for (unsigned int k = 0; k < m; ++k)
        p_max = std::max(p_max, std::abs(s.p[k]));
      const double w_scale = solver.gap_scale(op, s, D1);
      for (unsigned int k = 0; k < m; ++k)
        if (next[k] != active[k])
          {
            const double violation = active[k] ? -s.p[k] / p_max : -s.weighted_gap[k] / w_scale;
            if (pick == m || violation > worst)
              {
                pick  = k;
                worst = violation;
              }
          }
      if (pick < m)
        {
          next = active;
          next[pick] = !active[pick];
          next_slip = slip;
          if (!next[pick])
            next_slip[pick] = 0;
        }
      else
        for (unsigned int k = 0; k < m; ++k)
          if (next_slip[k] != slip[k] && next_slip[k] != entering && slip[k] != entering)
            {
              next_slip    = slip;
              next_slip[k] = next_slip[k] == 0 ? (s.q[k] > 0 ? 1 : -1) : 0;
              break;
            }
    }

    /// The message of sets that do not settle: `what`, at which step, and the sizes of the sets.
    std::string describe(const std::string &what, const unsigned int j, const unsigned int it,
                         const Carried &carried) const
    {
      const std::vector<bool> &active     = carried.active;
      const std::vector<int>  &slip       = carried.slip;
      const auto               in_contact = std::count(active.begin(), active.end(), true);
      const auto slipping = std::count(slip.begin(), slip.end(), 1) + std::count(slip.begin(), slip.end(), -1);
      std::ostringstream       msg;
      msg << "frictional contact (" << load.indenter.name << ", mu = " << mu << "): " << what << " at load step "
          << j << " of " << steps << " after " << it << " active-set steps (" << carried.total << " in all); "
          << in_contact << " of " << m << " vertices in contact, " << slipping << " of them slipping";
      return msg.str();
    }

    const UnilateralContactSolver &solver;
    const UnilateralLoad          &load;
    const SurfaceOperator         &op;
    const ShearOperator           &shear;
    const std::vector<double>     &f;
    const unsigned int             n; // displacement nodes
    const unsigned int             m; // pressure (and shear) vertices
    const bool                     by_force;
    const double                   mu;
    const bool                     full_stick;
    const unsigned int             steps; // load steps
    const std::vector<double>     &vertex_r;
    const WeightedProfile          weighted;
    const Vector<double>          &D1, &Df;
    const std::vector<double>     &f_vertex;
    const unsigned int             max_steps;         // active-set steps per load step
    const std::vector<bool>        touching_unloaded; // stick from the start (lowest_vertices)
  };



  UnilateralContactSolver::ActiveSetSolution
  UnilateralContactSolver::solve_frictional(const UnilateralLoad &load, const SurfaceOperator &op,
                                            const ShearOperator &shear, const std::vector<double> &f) const
  {
    const FrictionalProblem     problem(*this, load, op, shear, f);
    FrictionalProblem::Carried carried;
    ActiveSetSolution           s;
    for (unsigned int j = 1; j <= problem.steps; ++j)
      {
        const double target = problem.step_target(j);
        if (j == 1)
          carried = problem.start(target);
        problem.settle(j, target, carried, s);
        s.path.push_back(problem.path_point(s, carried.total));
      }
    s.iterations = carried.total;
    return s;
  }
} // namespace gradcontact::fem
