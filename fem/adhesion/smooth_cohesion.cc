#include <fem/base/errors.h>
#include <fem/adhesion/smooth_cohesion.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  namespace
  {
    /// Below this gap / eps the law continues linearly (header).
    constexpr double linear_below = 0.5;

    /// Newton's line search halves the update at most this often.
    constexpr unsigned int max_halvings = 12;

    /// False-position iterations per critical state.
    constexpr unsigned int max_critical_iterations = 80;

    /// Newton keeps its Jacobian (chord iteration) while each solve shrinks |R|_inf to at most this fraction of its
    /// previous value (chosen over 0.1, 0.2 and 0.5 at k = 0, lambda = 3 and k = 0.5, lambda = 1: the fewest
    /// factorisations for the same critical states to all printed digits; `cohesive_study mode=smooth path=1`).
    constexpr double chord_contraction = 0.3;

    /// |R|_inf at or below this times max(|x|_inf, eps) is round-off of the residual w - C b (a sum over the surface
    /// of the flexibility times the traction): about a thousand ulps.
    constexpr double roundoff_residual = 1e3 * std::numeric_limits<double>::epsilon();

    /// The path's step grows by 1.5 after a state found with at most this many factorisations and linear solves
    /// and shrinks by 0.7 after one with at least the second pair: a chord state takes more linear solves but
    /// fewer factorisations than a fresh Newton, so the thresholds count both, and the number of path steps
    /// stays comparable to a step control by Newton iterations (`cohesive_study mode=smooth path=1` prints them).
    constexpr unsigned int grow_factorisations = 2, grow_solves = 16, shrink_factorisations = 3, shrink_solves = 24;

    /// Folds of F(d) a resolved path can have: at large Tabor parameters the surface's bulge on approach (a maximum
    /// and a minimum of d) and the contact's formation (a maximum and the jump-off minimum); more are the mesh's
    /// (header).
    constexpr unsigned int max_depth_folds = 4;
  } // namespace



  double LennardJonesLaw::stress(const double h) const
  {
    const double eps = separation, A = 8 * work / (3 * eps);
    if (h < linear_below * eps)
      {
        const double h1 = linear_below * eps;
        return stress(h1) + slope(h1) * (h - h1);
      }
    const double q = eps / h, q3 = q * q * q;
    return A * (q3 - q3 * q3 * q3);
  }

  double LennardJonesLaw::slope(double h) const
  {
    const double eps = separation, A = 8 * work / (3 * eps);
    h                = std::max(h, linear_below * eps);
    const double q = eps / h, q3 = q * q * q;
    return A / h * (-3 * q3 + 9 * q3 * q3 * q3);
  }

  double LennardJonesLaw::max_stress() const { return 16 * work / (9 * std::sqrt(3.0) * separation); }

  LennardJonesLaw LennardJonesLaw::with_max_stress(const double max_stress, const double work)
  {
    if (!(max_stress > 0) || !std::isfinite(max_stress))
      fail("LennardJonesLaw::with_max_stress", "max_stress", max_stress, "(0, inf)");
    if (!(work > 0) || !std::isfinite(work))
      fail("LennardJonesLaw::with_max_stress", "work of adhesion", work, "(0, inf)");
    return {work, 16 * work / (9 * std::sqrt(3.0) * max_stress)};
  }

  void LennardJonesLaw::validate() const
  {
    if (!(work > 0) || !std::isfinite(work))
      fail("LennardJonesLaw", "work of adhesion", work, "(0, inf)");
    if (!(separation > 0) || !std::isfinite(separation))
      fail("LennardJonesLaw", "separation (eps)", separation, "(0, inf)");
  }

  void SmoothCohesionParameters::validate() const
  {
    if (!(start_gap > 1 && start_gap <= 1e3))
      fail("SmoothCohesionParameters", "start_gap", start_gap, "(1, 1e3]");
    if (!(min_gap >= linear_below && min_gap < 1))
      fail("SmoothCohesionParameters", "min_gap", min_gap, "[0.5, 1)");
    if (!(max_step > 0 && max_step <= 1))
      fail("SmoothCohesionParameters", "max_step", max_step, "(0, 1]");
    if (!(first_step > 0 && first_step <= max_step))
      fail("SmoothCohesionParameters", "first_step", first_step, "(0, max_step]");
    if (!(max_change > 0 && max_change <= 0.5))
      fail("SmoothCohesionParameters", "max_change", max_change, "(0, 0.5]");
    if (!std::isfinite(stop_force))
      fail("SmoothCohesionParameters", "stop_force", stop_force, "finite");
    if (!(newton_tolerance >= 1e-15 && newton_tolerance <= 1e-3))
      fail("SmoothCohesionParameters", "newton_tolerance", newton_tolerance, "[1e-15, 1e-3]");
    if (max_newton < 2 || max_newton > 200)
      fail("SmoothCohesionParameters", "max_newton", max_newton, "[2, 200]");
    if (max_steps < 10 || max_steps > 100000)
      fail("SmoothCohesionParameters", "max_steps", max_steps, "[10, 100000]");
    if (!(critical_tolerance >= 1e-15 && critical_tolerance <= 1e-2))
      fail("SmoothCohesionParameters", "critical_tolerance", critical_tolerance, "[1e-15, 1e-2]");
    if (quadrature_points < 2 || quadrature_points > 32)
      fail("SmoothCohesionParameters", "quadrature_points", quadrature_points, "[2, 32]");
    if (!(edge_band >= 1e-3 && edge_band <= 0.5))
      fail("SmoothCohesionParameters", "edge_band", edge_band, "[1e-3, 0.5]");
    if (!(smallest_frame > 0 && smallest_frame <= 1))
      fail("SmoothCohesionParameters", "smallest_frame", smallest_frame, "(0, 1]");
  }



  double rigid_force(const LennardJonesLaw &law, const Profile &profile, const double d)
  {
    law.validate();
    profile.validate();
    if (profile.shape == Profile::Shape::concave_paraboloid)
      throw std::invalid_argument("rigid_force: the profile must open monotonically (not the concave punch)");
    if (!std::isfinite(d))
      fail("rigid_force", "depth d", d, "finite");
    if (profile.exponent() <= 2.0 / 3)
      fail("rigid_force", "the profile's exponent n (f ~ r^n)", profile.exponent(),
           "(2/3, inf): below, sigma ~ h^-3 makes the integral over the surface diverge");
    const double eps = law.separation;
    const auto   f   = [&profile](const double r) { return profile(r, 1.0); };
    if (f(0) != 0)
      fail("rigid_force", "profile f(0)", f(0), "0 (the indenter's tip at r = 0)");
    // r_eps with f(r_eps) = eps (f grows monotonically): a bracket by doubling, then TOMS 748.
    double hi = eps;
    for (unsigned int i = 0; f(hi) < eps; ++i, hi *= 2)
      if (i > 2000 || !std::isfinite(hi))
        throw std::invalid_argument("rigid_force: the profile does not grow to the law's range eps");
    std::uintmax_t iterations = 200;
    hi = boost::math::tools::toms748_solve([&](const double r) { return f(r) - eps; }, 0.0, hi, -eps, f(hi) - eps,
                                           boost::math::tools::eps_tolerance<double>(50), iterations)
           .second;
    const dealii::QGauss<1> gauss(24);
    const auto              panel = [&](const double r0, const double r1) {
      double sum = 0;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double r = r0 + gauss.point(q)[0] * (r1 - r0);
          sum += law.stress(f(r) - d) * r * gauss.weight(q) * (r1 - r0);
        }
      return sum;
    };
    // Panels [0, r/8], [r/8, r/4], ..., doubling until f >= 1e7 eps + |d|; the first ones resolve the tip.
    double integral = panel(0, hi / 8);
    double r        = hi / 8;
    for (unsigned int i = 0; f(r) < 1e7 * eps + std::abs(d); ++i, r *= 2)
      {
        if (i > 2000 || !std::isfinite(r))
          throw std::invalid_argument("rigid_force: the profile does not grow to 1e7 eps");
        integral += panel(r, 2 * r);
      }
    if (!std::isfinite(integral))
      throw std::runtime_error("rigid_force: the integral is not finite (d = " + std::to_string(d / eps) + " eps)");
    return -2 * M_PI * integral;
  }

  RigidPullOff rigid_pull_off(const LennardJonesLaw &law, const Profile &profile)
  {
    // In units of eps: Brent's stopping test has an absolute part (a quarter of its tolerance), far above eps in
    // physical units.
    const double eps     = law.separation;
    const auto   minimum = boost::math::tools::brent_find_minima(
      [&](const double t) { return rigid_force(law, profile, t * eps); }, -3.0, -0.5, 50);
    const double d = minimum.first * eps;
    if (d < -2.99 * eps || d > -0.51 * eps)
      throw std::runtime_error("rigid_pull_off: the smallest force lies at the end of d in [-3, -0.5] eps (d = " +
                               std::to_string(d / eps) + " eps): not a minimum of this profile's F(d)");
    return {d, minimum.second};
  }



  Settings smooth_cohesion_settings(const Material &material, const double contact_radius, const double refinement,
                                    const double edge_refinement)
  {
    if (!(refinement >= 0.25 && refinement <= 16))
      fail("smooth_cohesion_settings", "refinement", refinement, "[0.25, 16]");
    if (!(edge_refinement >= 1 && edge_refinement <= max_edge_refinement))
      fail("smooth_cohesion_settings", "edge_refinement", edge_refinement,
           "[1, " + std::to_string(max_edge_refinement) + "]");
    if (!material.modulus)
      throw std::invalid_argument("smooth_cohesion_settings: the material has no modulus");
    Settings s = recommended_settings(contact_radius, *material.modulus, 1e-5);
    s.discretization.degree = 2;
    s.mesh.near_field_size  = 2.5;
    s.mesh.h_edge           = 5e-3 / (refinement * edge_refinement);
    s.mesh.h_surface        = 5e-2 / refinement;
    s.mesh.h_far            = 1;
    s.mesh.halving_radius   = s.mesh.near_field_size;
    use_condensed_far_field(s, material);
    return s;
  }



  struct SmoothCohesiveContact::Impl
  {
    /// A Gauss point of a surface face: r, weight times r, f(r) in the current frame (r_base, weight_base: in the
    /// settings' mesh), the face's Lagrange basis there.
    struct Point
    {
      double              r = 0, weight = 0, f = 0, r_base = 0, weight_base = 0;
      std::vector<double> basis;
    };
    struct Face
    {
      std::vector<int>   unknown; ///< per node: index into the surface unknowns, -1 when held at zero
      std::vector<Point> points;
    };

    /// A factorised bordered Jacobian with its constraint row and u = J^{-1} e_n (the unnormalised tangent).
    struct Factorised
    {
      std::shared_ptr<const dealii::LAPACKFullMatrix<double>> J;
      std::vector<double>                                     row, u;
    };

    /// A solved state: x = (w, d), its tangent dx/ds along the path and its public numbers.
    struct Solved
    {
      std::vector<double> x, tangent;
      SmoothCohesionState state;
      Factorised          jacobian; ///< at x: the chord matrix of the next step
    };

    Impl(const Material &material, const Profile &profile_, const Settings &settings,
         const SmoothCohesionParameters &parameters_)
      : profile(profile_)
      , parameters((parameters_.validate(), parameters_))
      , reference_radius(settings.mesh.contact_radius)
    {
      profile.validate();
      if (parameters.follow_edge)
        {
          if (!material.modulus || !power_law_of_depth(*material.modulus))
            throw std::invalid_argument("SmoothCohesiveContact: follow_edge needs a self-similar model, a modulus E0 "
                                        "(z / c0)^k or a homogeneous one; this material's is neither");
          exponent = material.modulus->surface_exponent();
        }
      if (profile.shape == Profile::Shape::concave_paraboloid)
        throw std::invalid_argument("SmoothCohesiveContact: the profile must open monotonically (not the concave punch)");
      const double f0 = profile(0, settings.mesh.contact_radius);
      if (f0 != 0)
        fail("SmoothCohesiveContact", "profile f(0)", f0, "0 (the indenter's tip at r = 0)");
      // The FE model is needed for its surface flexibility only: built, read and dropped (its matrices and mesh).
      AxisymmetricSolver solver(material, settings.mesh, settings.discretization);
      flexibility = solver.surface_flexibility();
      n_dofs      = solver.n_dofs();
      n           = flexibility.dofs.size();
      // C is held once, by columns (LAPACK's order): the Jacobian reads its columns, the residual multiplies by BLAS.
      C.reinit(n, n); // LAPACKFullMatrix's operator= copies into a matrix of the same size
      C                  = flexibility.matrix;
      flexibility.matrix = dealii::FullMatrix<double>();
      if (n == 0 || flexibility.r.front() > node_tolerance * settings.mesh.contact_radius)
        throw std::logic_error("SmoothCohesiveContact: no free surface z-DoF on the axis");

      std::vector<int> index_of(n_dofs, -1);
      for (unsigned int i = 0; i < n; ++i)
        index_of[flexibility.dofs[i]] = i;
      const dealii::QGauss<1> gauss(parameters.quadrature_points);
      for (const SurfaceFace &sf : flexibility.faces)
        {
          Face face;
          for (const auto d : sf.dofs[1])
            face.unknown.push_back(index_of[d]);
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              Point p;
              p.r_base      = sf.r0 + gauss.point(q)[0] * (sf.r1 - sf.r0);
              p.weight_base = gauss.weight(q) * (sf.r1 - sf.r0) * p.r_base;
              for (unsigned int a = 0; a < sf.r.size(); ++a)
                {
                  std::vector<double> y(sf.r.size(), 0.0);
                  y[a] = 1;
                  p.basis.push_back(lagrange(sf.r, y, p.r_base));
                }
              face.points.push_back(p);
            }
          faces.push_back(face);
        }
      set_frame(1);
    }

    /// The model scaled by s (header, "Following the edge"): Gauss points at s r, weights s^2, compliance s^{-(1+k)}.
    void set_frame(const double s)
    {
      scale      = s;
      compliance = std::pow(s, -(1 + exponent));
      for (Face &face : faces)
        for (Point &p : face.points)
          {
            p.r      = s * p.r_base;
            p.weight = s * s * p.weight_base;
            p.f      = profile(p.r, reference_radius);
          }
    }

    /// The frame whose centre is the contact edge r_e (the smallest frame for an edge inside it or no contact).
    double frame_for(const double edge) const
    {
      return std::max(edge / reference_radius, parameters.smallest_frame);
    }

    /// A surface field v of the current frame (its first n entries: w or the tangent's w) at the nodes of frame s:
    /// its interpolant (find_face, face_value), beyond the last face the far-field decay v(L) (L / r)^{1+k}.
    std::vector<double> interpolated(const std::vector<double> &v, const double s) const
    {
      std::vector<double> nodal(n_dofs, 0.0); // by global DoF, as face_value reads it; held DoFs stay 0
      for (unsigned int i = 0; i < n; ++i)
        nodal[flexibility.dofs[i]] = v[i];
      const SurfaceFace  &last = flexibility.faces.back();
      std::vector<double> result(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const double rho = s * flexibility.r[i] / scale; // in the settings' mesh of the current frame
          if (const SurfaceFace *face = find_face(flexibility.faces, rho))
            result[i] = face_value(*face, 1, nodal, rho);
          else
            result[i] = face_value(last, 1, nodal, last.r1) * std::pow(last.r1 / rho, 1 + exponent);
        }
      return result;
    }

    /// `from` (a state of the current frame) moved to frame s: interpolated and solved on the hyperplane of its
    /// tangent (header); where Newton does not converge, in moves of half the size (up to 16). Throws
    /// std::runtime_error when the shortest move fails too.
    Solved move_frame(const Solved &from, const double s, unsigned int &iterations)
    {
      const double start = scale;
      Solved       moved;
      for (unsigned int parts = 1;; parts *= 2)
        {
          moved = from;
          set_frame(start);
          unsigned int part = 1;
          for (; part <= parts; ++part)
            if (!try_move(moved, start + (s - start) * part / parts, iterations))
              break;
          if (part > parts)
            return moved;
          if (parts == 16)
            {
              std::ostringstream msg;
              msg << "SmoothCohesiveContact: Newton did not converge moving the edge-following mesh from frame "
                  << start << " to " << s << " (times the settings' contact radius) in 16 moves at h_c = "
                  << from.state.central_gap / eps() << " eps";
              set_frame(start);
              throw std::runtime_error(msg.str());
            }
        }
    }

    /// One move of `state` to frame s (false: Newton did not converge; `state` and the frame are then undefined);
    /// adds its linear solves to `iterations`.
    bool try_move(Solved &state, const double s, unsigned int &iterations)
    {
      Solved moved;
      moved.x       = interpolated(state.x, s);
      moved.tangent = interpolated(state.tangent, s);
      moved.x.push_back(state.x[n]); // d
      moved.tangent.push_back(state.tangent[n]);
      set_frame(s);
      const double norm = std::sqrt(metric(moved.tangent, moved.tangent));
      for (double &v : moved.tangent)
        v /= norm;
      Solved       solved;
      unsigned int solves = 0;
      const bool   converged = newton(moved.x, arclength(moved, 0), solved, solves);
      iterations += solves;
      if (!converged)
        return false;
      finish(solved, &moved.tangent);
      state = std::move(solved);
      return true;
    }

    double eps() const { return law.separation; }

    /// w(r) at a Gauss point.
    double surface_value(const Face &face, const Point &p, const std::vector<double> &w) const
    {
      double value = 0;
      for (unsigned int a = 0; a < face.unknown.size(); ++a)
        if (face.unknown[a] >= 0)
          value += p.basis[a] * w[face.unknown[a]];
      return value;
    }

    /// x = (w, d): the surface values and the depth (x[n] = d). A linear constraint closes the system:
    /// row . x = value (the central gap h_c = w_0 - d, or the pseudo-arclength of the path).
    struct Constraint
    {
      std::vector<double> row;
      double              value = 0;
    };

    /// The central-gap constraint h_c = w_0 - d = hc.
    Constraint gap_constraint(const double hc) const
    {
      Constraint c{std::vector<double>(n + 1, 0.0), hc};
      c.row[0] = 1;
      c.row[n] = -1;
      return c;
    }

    /// The path metric: |dx|^2 = dd^2 + dh_c^2 + |dw|^2 / n (the first two alone degenerate where the contact grows at
    /// fixed d and h_c, as at lambda = 10).
    double metric(const std::vector<double> &a, const std::vector<double> &b) const
    {
      double w = 0;
      for (unsigned int i = 0; i < n; ++i)
        w += a[i] * b[i];
      return a[n] * b[n] + (a[0] - a[n]) * (b[0] - b[n]) + w / n;
    }

    /// The residual (w - C b(w, d), c_w w_0 + c_d d - value).
    std::vector<double> residual(const std::vector<double> &x, const Constraint &constraint) const
    {
      const double        d = x[n];
      std::vector<double>    R(n + 1);
      dealii::Vector<double> b(n), Cb(n);
      for (const Face &face : faces)
        for (const Point &p : face.points)
          {
            const double sigma = law.stress(p.f - d + surface_value(face, p, x));
            for (unsigned int a = 0; a < face.unknown.size(); ++a)
              if (face.unknown[a] >= 0)
                b[face.unknown[a]] -= sigma * p.basis[a] * p.weight;
          }
      C.vmult(Cb, b); // BLAS dgemv: a sixth of the path's time as a plain loop
      for (unsigned int i = 0; i < n; ++i)
        R[i] = x[i] - compliance * Cb[i];
      R[n] = -constraint.value;
      for (unsigned int i = 0; i <= n; ++i)
        R[n] += constraint.row[i] * x[i];
      return R;
    }

    /// The bordered Jacobian, factorised: rows i < n: dR_i/dw_j = delta_ij - (C B')_ij, dR_i/dd = -(C s)_i with
    /// B'_ij = -\int sigma'(h) phi_i phi_j r dr and s_i = \int sigma'(h) phi_i r dr (db_i/dd = s_i); row n: the
    /// constraint.
    void jacobian(const std::vector<double> &x, const Constraint &constraint, dealii::LAPACKFullMatrix<double> &J) const
    {
      const double           d = x[n];
      dealii::Vector<double> s(n), Cs(n);
      // Column ic of J's block I - C B' from the face-local blocks of B': each product C(i, ia) local(a, c) is read
      // down the column ia of C and subtracted down the column ic of J, both contiguous in LAPACK's order (across
      // the rows of a row-major C it took a quarter of the path's time).
      J.reinit(n + 1, n + 1);
      for (const Face &face : faces)
        {
          const unsigned int         m = face.unknown.size();
          dealii::FullMatrix<double> local(m, m);
          for (const Point &p : face.points)
            {
              const double slope = law.slope(p.f - d + surface_value(face, p, x));
              for (unsigned int a = 0; a < m; ++a)
                {
                  if (face.unknown[a] >= 0)
                    s[face.unknown[a]] += slope * p.basis[a] * p.weight;
                  for (unsigned int c = 0; c < m; ++c)
                    local(a, c) -= slope * p.basis[a] * p.basis[c] * p.weight;
                }
            }
          for (unsigned int a = 0; a < m; ++a)
            if (face.unknown[a] >= 0)
              for (unsigned int c = 0; c < m; ++c)
                if (face.unknown[c] >= 0 && local(a, c) != 0)
                  {
                    const unsigned int ia = face.unknown[a], ic = face.unknown[c];
                    const double       lac  = local(a, c);
                    const double      *C_ia = &C(0, ia);
                    double            *J_ic = &J(0, ic);
                    for (unsigned int i = 0; i < n; ++i)
                      J_ic[i] -= compliance * C_ia[i] * lac;
                  }
        }
      C.vmult(Cs, s);
      for (unsigned int i = 0; i < n; ++i)
        {
          J(i, i) += 1.0;
          J(i, n) = -compliance * Cs[i];
        }
      for (unsigned int i = 0; i <= n; ++i)
        J(n, i) = constraint.row[i];
      J.compute_lu_factorization();
    }

    static double max_norm(const std::vector<double> &v)
    {
      double m = 0;
      for (const double x : v)
        m = std::max(m, std::abs(x));
      return m;
    }

    /// Solves J' y = b in place, J' the Jacobian of `f` with its last row replaced by `row`: J' = J + e_n v^T,
    /// v = row - f.row, by Sherman-Morrison, y = J^{-1} b - u (v . J^{-1} b) / (row . u) (1 + v . u = row . u, as
    /// f.row . u = 1). The denominator is the new row against the old tangent: for an arclength row of a nearby
    /// state's tangent close to its length, far from zero.
    static void solve(const Factorised &f, const std::vector<double> &row, dealii::Vector<double> &b)
    {
      f.J->solve(b);
      if (row == f.row)
        return;
      double vy = 0, ru = 0;
      for (unsigned int i = 0; i < b.size(); ++i)
        {
          vy += (row[i] - f.row[i]) * b[i];
          ru += row[i] * f.u[i];
        }
      if (ru == 0 || !std::isfinite(ru))
        throw std::runtime_error("SmoothCohesiveContact: the constraint row is orthogonal to the chord's tangent");
      for (unsigned int i = 0; i < b.size(); ++i)
        b[i] -= f.u[i] * vy / ru;
    }

    /// Newton from the predictor x under `constraint`, as a chord iteration: it starts on `chord` (a nearby state's
    /// factorised Jacobian, its row replaced by the constraint's; none: factorised at x) and factorises again only
    /// where the residual contracts by less than `chord_contraction` per iteration, and once at the converged x,
    /// whose factorisation gives the tangent dx/dvalue exactly (the critical states are roots of its components)
    /// and serves as the chord of the next state. On convergence fills `solved` and returns true; `iterations`
    /// counts the linear solves, `solved.state.factorisations` the Jacobians.
    bool newton(std::vector<double> x, const Constraint &constraint, Solved &solved, unsigned int &iterations,
                const Factorised *chord = nullptr) const
    {
      Factorised               current;
      if (chord && chord->J)
        current = *chord;
      std::vector<double>      R              = residual(x, constraint);
      bool                     fresh          = false; // `current` factorised at the current x
      bool                     refactor       = !current.J;
      unsigned int             factorisations = 0;
      unsigned int limit = parameters.max_newton;
      // The converged state at x, with the Jacobian factorised there (its bordered solve gives the tangent).
      const auto converged_at_x = [&]() {
        solved.x                       = x;
        solved.tangent                 = current.u;
        solved.jacobian                = std::move(current);
        solved.state.newton_iterations = iterations;
        solved.state.factorisations    = factorisations;
        return true;
      };
      for (iterations = 1; iterations <= limit; ++iterations)
        {
          dealii::Vector<double> delta(n + 1);
          try
            {
              if (refactor)
                {
                  auto J = std::make_shared<dealii::LAPACKFullMatrix<double>>();
                  ++factorisations_done;
                  jacobian(x, constraint, *J);
                  dealii::Vector<double> u(n + 1);
                  u[n] = 1;
                  J->solve(u);
                  current  = Factorised{J, constraint.row, std::vector<double>(u.begin(), u.end())};
                  ++factorisations;
                  fresh    = true;
                  refactor = false;
                }
              for (unsigned int i = 0; i <= n; ++i)
                delta[i] = -R[i];
              solve(current, constraint.row, delta);
            }
          catch (const std::exception &)
            {
              if (!fresh)
                {
                  refactor = true; // an older Jacobian's: a new one at x
                  continue;
                }
              return false; // an exactly singular Jacobian (LAPACK's LU): the caller shortens its step
            }
          const double step = delta.linfty_norm();
          if (!std::isfinite(step))
            {
              if (!fresh)
                {
                  refactor = true;
                  continue;
                }
              return false;
            }
          if (step <= parameters.newton_tolerance * eps())
            {
              for (unsigned int i = 0; i <= n; ++i)
                x[i] += delta[i];
              if (!fresh)
                {
                  // Converged on an older Jacobian: once more on the one at x, for the tangent (beyond the
                  // budget if need be).
                  R        = residual(x, constraint);
                  refactor = true;
                  limit    = std::max(limit, iterations + 1);
                  continue;
                }
              return converged_at_x();
            }
          // Line search on |R|_inf.
          const double norm  = max_norm(R);
          bool         taken = false;
          double       alpha = 1;
          for (unsigned int k = 0; k <= max_halvings && !taken; ++k, alpha /= 2)
            {
              std::vector<double> trial(x);
              for (unsigned int i = 0; i <= n; ++i)
                trial[i] += alpha * delta[i];
              std::vector<double> R_trial    = residual(trial, constraint);
              const double        norm_trial = max_norm(R_trial);
              if (norm_trial < norm)
                {
                  taken    = true;
                  refactor = alpha < 1 || norm_trial > chord_contraction * norm;
                  x        = std::move(trial);
                  R        = std::move(R_trial);
                }
            }
          if (!taken)
            {
              if (fresh)
                {
                  // No descent from the Jacobian at x: converged as far as round-off lets |R| fall (at large
                  // lambda |R| reaches roundoff_residual |x| while the update stays just above newton_tolerance),
                  // else failed.
                  return norm <= roundoff_residual * std::max(max_norm(x), eps()) && converged_at_x();
                }
              refactor = true; // the older Jacobian's direction does not descend: a new one at x
            }
          fresh = false;
        }
      return false;
    }

    /// The constraint of the pseudo-arclength step `ds` from `from` along its unit tangent: t . (x - x') = ds in
    /// the path metric.
    Constraint arclength(const Solved &from, const double ds) const
    {
      Constraint c{std::vector<double>(n + 1, 0.0), ds};
      for (unsigned int i = 0; i < n; ++i)
        c.row[i] = from.tangent[i] / n;
      c.row[0] += from.tangent[0] - from.tangent[n];
      c.row[n] = 2 * from.tangent[n] - from.tangent[0];
      for (unsigned int i = 0; i <= n; ++i)
        c.value += c.row[i] * from.x[i];
      return c;
    }

    /// The public numbers of a solved state; the tangent is normalised to unit length in the path metric and
    /// oriented along `previous` (the previous state's tangent; none: h_c decreasing).
    void finish(Solved &solved, const std::vector<double> *previous) const
    {
      std::vector<double> &x = solved.x, &t = solved.tangent;
      double               norm = std::sqrt(metric(t, t));
      if (previous ? metric(t, *previous) < 0 : t[0] - t[n] > 0)
        norm = -norm;
      for (double &v : t)
        v /= norm;
      SmoothCohesionState &s = solved.state;
      s.depth                = x[n];
      s.central_gap          = x[0] - x[n];
      s.depth_slope          = t[n];
      s.gap_slope            = t[0] - t[n];
      double F = 0, dF = 0, last_r = -1, last_h = 0;
      const double peak = std::pow(3.0, 1.0 / 6) * eps();
      s.contact_radius = 0;
      s.peak_radius    = 0;
      // The outermost crossing of h = level, interpolated between Gauss points.
      const auto crossing = [&last_r, &last_h](const double level, const double r, const double h, double &radius) {
        if (last_r >= 0 && last_h <= level && h > level)
          radius = last_r + (level - last_h) / (h - last_h) * (r - last_r);
      };
      for (const Face &face : faces)
        for (const Point &p : face.points)
          {
            const double h = p.f - s.depth + surface_value(face, p, x);
            F -= law.stress(h) * p.weight;
            dF -= law.slope(h) * (surface_value(face, p, t) - s.depth_slope) * p.weight;
            crossing(eps(), p.r, h, s.contact_radius);
            crossing(peak, p.r, h, s.peak_radius);
            last_r = p.r;
            last_h = h;
          }
      s.force       = 2 * M_PI * F;
      s.force_slope = 2 * M_PI * dF;
    }

    /// The state `ds` along the path from `from` (Newton from the tangent predictor).
    bool step_from(const Solved &from, const double ds, Solved &next, unsigned int &iterations) const
    {
      std::vector<double> predictor(from.x);
      for (unsigned int i = 0; i <= n; ++i)
        predictor[i] += ds * from.tangent[i];
      if (!newton(predictor, arclength(from, ds), next, iterations, &from.jacobian))
        return false;
      finish(next, &from.tangent);
      return true;
    }

    /// The state at central gap hc by Newton from the undeformed surface (x = 0, d = -hc).
    bool at_gap(const double hc, Solved &solved, unsigned int &iterations) const
    {
      std::vector<double> x(n + 1, 0.0);
      x[n] = -hc;
      if (!newton(x, gap_constraint(hc), solved, iterations))
        return false;
      finish(solved, nullptr);
      return true;
    }

    /// The counts of one follow(), added to the path's (when it is given) where the path ends or gives up.
    struct FollowCounts
    {
      unsigned int steps = 0, rejected = 0, iterations = 0;

      void add_to(SmoothCohesionPath *path) const
      {
        if (path)
          {
            path->steps += steps;
            path->rejected_steps += rejected;
            path->newton_iterations += iterations;
          }
      }
    };

    /// Follows the path from `current` (pseudo-arclength): to its end (trace, `path` given: the minimum of
    /// F passed and F >= stop_force, or h_c <= min_gap eps), or until h_c first reaches `target` (path null).
    Solved follow(Solved current, const double target, SmoothCohesionPath *path)
    {
      unsigned int postponed = 0; // frame moves put off in a row (follow_frame)
      double       ds    = parameters.first_step * eps();
      double       F_min = current.state.force;
      FollowCounts counts;
      while (!at_path_end(current, path))
        {
          if (counts.steps + counts.rejected >= parameters.max_steps)
            {
              counts.add_to(path);
              throw std::runtime_error("SmoothCohesiveContact: " + std::to_string(parameters.max_steps) +
                                       " path steps (" + std::to_string(counts.rejected) +
                                       " rejected) did not reach the end; stopped at h_c = " +
                                       std::to_string(current.state.central_gap / eps()) + " eps");
            }
          Solved       next;
          unsigned int iterations = 0;
          const bool   converged  = step_from(current, ds, next, iterations);
          counts.iterations += iterations;
          const double change_d = converged ? depth_change(current, next) : 0;
          const double change_F = converged ? force_change(current, next, F_min) : 0;
          if (!converged || change_d > parameters.max_change || change_F > parameters.max_change)
            {
              ++counts.rejected;
              ds /= 2;
              if (ds < 1e-14 * eps())
                {
                  counts.add_to(path);
                  throw std::runtime_error(stall_message(current, converged, iterations, change_d, change_F, counts));
                }
              continue;
            }
          ++counts.steps;
          if (target >= 0 && next.state.central_gap <= target)
            return at_target(current, next, ds, target);
          if (path)
            record(current, next, ds, *path, counts);
          F_min   = std::min(F_min, next.state.force);
          current = std::move(next);
          ds      = adapted_step(ds, current.state.factorisations, iterations, change_d, change_F);
          if (parameters.follow_edge)
            follow_frame(current, postponed, path, counts);
        }
      counts.add_to(path);
      return current;
    }

    /// Whether the path ends at `current`: a traced path (`path` given) past the minimum of F at F >= stop_force,
    /// or any path at h_c <= min_gap eps (a traced one that has not passed the minimum of F says so in `path`).
    bool at_path_end(const Solved &current, SmoothCohesionPath *path) const
    {
      if (path && path->has_force_minimum && current.state.force >= parameters.stop_force)
        return true;
      if (current.state.central_gap <= parameters.min_gap * eps())
        {
          if (path && !path->has_force_minimum)
            {
              path->converged = false;
              path->message += "the path reached the central gap " + std::to_string(parameters.min_gap) +
                               " eps before the minimum of F; ";
            }
          return true;
        }
      return false;
    }

    /// The change of d from `current` to `next`, relative to eps + |d|: a step's acceptance and growth.
    double depth_change(const Solved &current, const Solved &next) const
    {
      return std::abs(next.state.depth - current.state.depth) / (eps() + std::abs(current.state.depth));
    }

    /// The change of F from `current` to `next`, relative to the larger of |F| and |F_min| (the path's smallest F).
    double force_change(const Solved &current, const Solved &next, const double F_min) const
    {
      return std::abs(next.state.force - current.state.force) /
             std::max({std::abs(current.state.force), std::abs(F_min), std::numeric_limits<double>::min()});
    }

    /// The message of a path whose step has shrunk to nothing at `current`.
    std::string stall_message(const Solved &current, const bool converged, const unsigned int iterations,
                              const double change_d, const double change_F, const FollowCounts &counts) const
    {
      std::ostringstream msg;
      msg << "SmoothCohesiveContact: the path stalls at h_c = " << current.state.central_gap / eps()
          << " eps, d = " << current.state.depth / eps() << " eps (Newton "
          << (converged ? "converged" : "did not converge") << " in " << iterations << " iterations, change of d "
          << change_d << ", of F " << change_F << "; " << counts.steps << " steps, " << counts.rejected
          << " rejected)";
      return msg.str();
    }

    /// The state at central gap `target`, which lies between `current` and `next` = current + ds: false position
    /// in the arclength (h_c may fold nearby, where a step in h_c from the tangent would not be defined).
    Solved at_target(const Solved &current, const Solved &next, const double ds, const double target) const
    {
      SmoothCohesionPath scratch;
      Solved             exact;
      exact.state = root(current, next, ds,
                         [target](const SmoothCohesionState &st) { return st.central_gap - target; }, scratch);
      if (!scratch.converged)
        throw std::runtime_error("SmoothCohesiveContact: " + scratch.message + "at h_c = " +
                                 std::to_string(target / eps()) + " eps");
      return exact;
    }

    /// Adds the accepted state `next` to the traced path and locates the critical states between `current` and
    /// it; std::runtime_error when F(d) folds more often than a smooth law can (the mesh's snap-backs, header).
    void record(const Solved &current, const Solved &next, const double ds, SmoothCohesionPath &path,
                const FollowCounts &counts) const
    {
      path.states.push_back(next.state);
      locate_critical(current, next, ds, path);
      if (path.depth_folds > max_depth_folds)
        {
          counts.add_to(&path);
          throw std::runtime_error(
            "SmoothCohesiveContact: F(d) folds " + std::to_string(path.depth_folds) +
            " times (a smooth law has at most " + std::to_string(max_depth_folds) +
            "): the surface cells are too coarse for the adhesive zone, and the discrete path snaps back at "
            "every node; refine the surface where the contact edge passes (stopped at h_c = " +
            std::to_string(next.state.central_gap / eps()) + " eps)");
        }
    }

    /// The next path step after a state found with `factorisations` and `iterations` linear solves and relative
    /// changes change_d, change_F: grown by 1.5 (up to max_step eps) or shrunk by 0.7 (grow_factorisations ...).
    double adapted_step(const double ds, const unsigned int factorisations, const unsigned int iterations,
                        const double change_d, const double change_F) const
    {
      if (factorisations <= grow_factorisations && iterations <= grow_solves && change_d < parameters.max_change / 2 &&
          change_F < parameters.max_change / 2)
        return std::min(1.5 * ds, parameters.max_step * eps());
      else if (factorisations >= shrink_factorisations || iterations >= shrink_solves)
        return ds * 0.7;
      return ds;
    }

    /// The accepted state's edge has left the frame's band (its critical states were located in the old
    /// frame): it moves to the frame of its edge. Where the move flips the sign of dF/ds or dd/ds, a critical
    /// state lies within the mesh change of this state, which the next step locates in the old frame: the
    /// move waits for it (up to 4 steps; `postponed` counts them).
    void follow_frame(Solved &current, unsigned int &postponed, SmoothCohesionPath *path, FollowCounts &counts)
    {
      const double target_frame = frame_for(current.state.peak_radius);
      if (std::abs(target_frame - scale) > parameters.edge_band * scale)
        {
          const double old_frame = scale;
          Solved       moved;
          unsigned int move_iterations = 0;
          try
            {
              moved = move_frame(current, target_frame, move_iterations);
            }
          catch (const std::exception &)
            {
              counts.add_to(path);
              throw;
            }
          counts.iterations += move_iterations;
          const bool flips = (current.state.force_slope < 0) != (moved.state.force_slope < 0) ||
                             (current.state.depth_slope > 0) != (moved.state.depth_slope > 0);
          if (flips && postponed < 4)
            {
              set_frame(old_frame);
              ++postponed;
            }
          else
            {
              current   = std::move(moved);
              postponed = 0;
              if (path)
                ++path->frames;
            }
        }
    }

    /// The critical states whose derivative along the path changes sign between a and b = a + ds: dF/ds from - to +
    /// (a minimum of F), dd/ds from + to - (snap-in) and from - to + (pull-off under displacement control).
    void locate_critical(const Solved &a, const Solved &b, const double ds, SmoothCohesionPath &path) const
    {
      const auto force_slope = [](const SmoothCohesionState &s) { return s.force_slope; };
      const auto depth_slope = [](const SmoothCohesionState &s) { return s.depth_slope; };
      // Retraction from the contact follows the path backward: it leaves at the last minimum of F (force control)
      // or of d (displacement control) before the contact; approach leaves the path at its first maximum of d.
      if (a.state.force_slope < 0 && b.state.force_slope >= 0)
        {
          path.force_pull_off    = root(a, b, ds, force_slope, path);
          path.has_force_minimum = true;
        }
      if (a.state.depth_slope > 0 && b.state.depth_slope <= 0 && !path.has_snap_in)
        {
          path.snap_in     = root(a, b, ds, depth_slope, path);
          path.has_snap_in = true;
        }
      if ((a.state.depth_slope > 0) != (b.state.depth_slope > 0))
        ++path.depth_folds;
      if (a.state.depth_slope < 0 && b.state.depth_slope >= 0)
        {
          path.depth_pull_off = root(a, b, ds, depth_slope, path);
          path.has_depth_jump = true;
        }
    }

    /// False position (Illinois) in the arclength t in (0, ds) from a for g = 0 (g(a), g(b) of opposite signs).
    template <class G>
    SmoothCohesionState root(const Solved &a, const Solved &b, const double ds, const G &g,
                             SmoothCohesionPath &path) const
    {
      double              t_lo = 0, t_hi = ds, g_lo = g(a.state), g_hi = g(b.state);
      SmoothCohesionState best = std::abs(g_lo) < std::abs(g_hi) ? a.state : b.state;
      int                 side = 0;
      for (unsigned int k = 0; k < max_critical_iterations; ++k)
        {
          if (t_hi - t_lo <= parameters.critical_tolerance * eps() || g_lo == g_hi)
            break;
          const double t = t_hi - g_hi * (t_hi - t_lo) / (g_hi - g_lo);
          Solved       s;
          unsigned int iterations = 0;
          ++path.critical_evaluations;
          bool solved = step_from(a, t, s, iterations);
          if (!solved)
            {
              // From the bracket's other end, backward on its tangent's hyperplane (a trial from a failed at k = 0,
              // lambda = 10, where the path passed its minimum of F in a step of 0.25 eps).
              unsigned int more = 0;
              solved = step_from(b, t - ds, s, more);
              iterations += more;
            }
          if (!solved)
            {
              path.converged = false;
              path.message += "Newton did not converge at a critical state's trial (" + std::to_string(iterations) +
                              " iterations); ";
              break;
            }
          path.newton_iterations += iterations;
          const double gs = g(s.state);
          if (std::abs(gs) < std::abs(g(best)))
            best = s.state;
          if (gs == 0)
            break;
          if ((gs > 0) == (g_lo > 0))
            {
              t_lo = t, g_lo = gs;
              if (side == -1)
                g_hi /= 2;
              side = -1;
            }
          else
            {
              t_hi = t, g_hi = gs;
              if (side == 1)
                g_lo /= 2;
              side = 1;
            }
        }
      return best;
    }

    /// The first state, at start_gap eps, by Newton from the undeformed surface, on the first frame.
    Solved first_state()
    {
      set_frame(parameters.follow_edge ? parameters.smallest_frame : 1.0);
      Solved       s;
      unsigned int iterations = 0;
      if (!at_gap(parameters.start_gap * eps(), s, iterations))
        throw std::runtime_error("SmoothCohesiveContact: Newton did not converge at the first state (h_c = " +
                                 std::to_string(parameters.start_gap) + " eps, " + std::to_string(iterations) +
                                 " iterations); start farther apart");
      return s;
    }

    const Profile                          profile;
    LennardJonesLaw                        law; ///< of the path being followed
    const SmoothCohesionParameters         parameters;
    const double                           reference_radius; ///< the settings' contact radius (the mesh's unit)
    double                                 exponent   = 0;   ///< k of the modulus (follow_edge)
    double                                 scale      = 1;   ///< the current frame
    double                                 compliance = 1;   ///< scale^{-(1+k)}
    mutable unsigned long                  factorisations_done = 0; ///< every Jacobian factorised, failed trials too
    unsigned int                           n_dofs = 0; ///< of the FE model behind the flexibility
    SurfaceFlexibility                     flexibility;
    dealii::LAPACKFullMatrix<double>       C; ///< the surface flexibility (flexibility.matrix, moved here)
    unsigned int                           n = 0;
    std::vector<Face>                      faces;
  };



  SmoothCohesiveContact::SmoothCohesiveContact(const Material &material, const Profile &profile,
                                               const Settings &settings, const SmoothCohesionParameters &parameters)
    : impl(std::make_unique<Impl>(material, profile, settings, parameters))
  {}

  SmoothCohesiveContact::~SmoothCohesiveContact() = default;

  unsigned int SmoothCohesiveContact::n_dofs() const { return impl->n_dofs; }
  unsigned int SmoothCohesiveContact::surface_dofs() const { return impl->n; }

  SmoothCohesionPath SmoothCohesiveContact::trace(const LennardJonesLaw &law)
  {
    law.validate();
    impl->law                = law;
    const auto          start          = std::chrono::steady_clock::now();
    const unsigned long factorisations = impl->factorisations_done;
    SmoothCohesionPath  path;
    path.n_dofs              = impl->n_dofs;
    path.surface_dofs        = impl->n;
    path.flexibility_seconds = impl->flexibility.seconds;
    try
      {
        Impl::Solved first = impl->first_state();
        path.states.push_back(first.state);
        path.newton_iterations += first.state.newton_iterations;
        impl->follow(std::move(first), -1, &path);
      }
    catch (const std::exception &e)
      {
        path.converged = false;
        path.message += e.what();
      }
    path.seconds        = seconds_since(start);
    path.factorisations = static_cast<unsigned int>(impl->factorisations_done - factorisations);
    return path;
  }

  SmoothCohesionState SmoothCohesiveContact::state(const LennardJonesLaw &law, const double central_gap)
  {
    law.validate();
    impl->law        = law;
    const double eps = impl->eps();
    if (!(central_gap >= impl->parameters.min_gap * eps && central_gap <= impl->parameters.start_gap * eps))
      {
        std::ostringstream range;
        range.precision(6);
        range << "[" << impl->parameters.min_gap * eps << ", " << impl->parameters.start_gap * eps << "] (min_gap eps, "
              << "start_gap eps, eps = " << eps << ")";
        fail("SmoothCohesiveContact::state", "central gap", central_gap, range.str());
      }
    return impl->follow(impl->first_state(), central_gap, nullptr).state;
  }
} // namespace gradcontact::fem
