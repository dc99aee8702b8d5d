#include <fem/tangential/coulomb_contact_3d.h>
#include <fem/base/errors.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace gradcontact::fem
{
  using namespace dealii;

  namespace
  {
    /// One step of CoulombContact3D::solve from the last converged state to the load (target, delta): the trial
    /// sets, the linear system of the current sets and directions and their update (the header's "Solver").
    class CoulombStep
    {
    public:
      CoulombStep(const SurfaceCompliance3D &compliance, const std::vector<double> &f, const double c,
                  const CoulombParameters &parameters, const CoulombState3D &last, const bool force_control,
                  const double target, const double delta)
        : compliance(compliance)
        , f(f)
        , c(c)
        , last(last)
        , force_control(force_control)
        , target(target)
        , n(compliance.nodes.size())
        , m(compliance.C.m())
        , mu(parameters.mu)
        , full_stick(std::isinf(mu))
        , step(delta - last.delta)
        , set_tolerance(parameters.set_tolerance)
      {}

      /// The trial state of every step: the nodes in contact stick (the elastic predictor of a return mapping;
      /// starting from the last step's slip directions cycles when the load reverses), and under depth control
      /// the nodes the indenter would now penetrate at `depth` start in contact.
      std::vector<NodeStatus> trial_status(const double depth) const
      {
        std::vector<NodeStatus> status = last.status;
        for (NodeStatus &s : status)
          if (s == NodeStatus::slip)
            s = NodeStatus::stick;
        if (!force_control)
          for (unsigned int i = 0; i < n; ++i) // nodes the indenter would now penetrate start in contact
            if (status[i] == NodeStatus::separated && f[i] - depth + last.displacement[i][2] < 0)
              status[i] = NodeStatus::stick;
        if (force_control && std::none_of(status.begin(), status.end(), [](NodeStatus t) { return t != NodeStatus::separated; }))
          status[std::min_element(f.begin(), f.end()) - f.begin()] = NodeStatus::stick;
        return status;
      }

      /// The unknowns of the last state, where the Newton steps of the slip law start (and its depth under force
      /// control).
      void last_forces(Vector<double> &F) const
      {
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int d = 0; d < 3; ++d)
            if (compliance.unknown[i][d] >= 0)
              F(compliance.unknown[i][d]) = last.nodal_force[i][d];
        if (force_control)
          F(m) = last.depth;
      }

      /// u = C F of the current iterate (the slip law's linearisation and the set updates use it).
      void displacements(const Vector<double> &forces, Vector<double> &u) const
      {
        for (unsigned int k = 0; k < m; ++k)
          {
            double v = 0;
            for (unsigned int l = 0; l < m; ++l)
              v += compliance.C(k, l) * forces(l);
            u(k) = v;
          }
      }

      /// The linear system of the current sets `status` and directions `t` at the iterate F (u = C F): a
      /// separated node's forces vanish, a node in contact closes its gap, a sticking node keeps its tangential
      /// position relative to the indenter, a slipping one follows the slip law (slip_rows); under force control
      /// the last row is the normal force of the half body.
      void system(const std::vector<NodeStatus> &status, const double depth,
                  const std::vector<std::array<double, 2>> &t, const Vector<double> &F, const Vector<double> &u,
                  LAPACKFullMatrix<double> &A, Vector<double> &rhs) const
      {
        const auto copy_row = [&](const unsigned int row, const int k) {
          for (unsigned int l = 0; l < m; ++l)
            A(row, l) = compliance.C(k, l);
        };
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto &k = compliance.unknown[i];
            switch (status[i])
              {
                case NodeStatus::separated:
                  for (const int kc : k)
                    if (kc >= 0)
                      A(kc, kc) = 1;
                  break;
                case NodeStatus::stick:
                case NodeStatus::slip:
                  // g = 0: u_z - d = -f (d an unknown under force control)
                  copy_row(k[2], k[2]);
                  if (force_control)
                    {
                      A(k[2], m) = -1;
                      rhs(k[2])  = -f[i];
                    }
                  else
                    rhs(k[2]) = depth - f[i];
                  if (status[i] == NodeStatus::stick)
                    {
                      copy_row(k[0], k[0]);
                      rhs(k[0]) = last.displacement[i][0] + step;
                      if (k[1] >= 0)
                        {
                          copy_row(k[1], k[1]);
                          rhs(k[1]) = last.displacement[i][1];
                        }
                    }
                  else if (k[1] < 0)
                    {
                      // On the symmetry plane the slip is along x: Q_x = mu P t_x, t_x = +-1 (linear).
                      A(k[0], k[0]) = 1;
                      A(k[0], k[2]) = -mu * t[i][0];
                    }
                  else
                    slip_rows(i, t[i], F, u, A, rhs);
                  break;
              }
          }
        if (force_control)
          {
            for (unsigned int i = 0; i < n; ++i)
              A(m, compliance.unknown[i][2]) = 1;
            rhs(m) = target / 2; // the half body
          }
      }

      /// The sets and directions after a solve (F, u = C F), with the state's forces, displacements and slips
      /// filled in; `changed` when a node changes its set, `turn` the largest change of a slip direction weighted
      /// by the node's share of the largest normal force. `t` holds the new slip directions on return.
      std::vector<NodeStatus> new_sets(const Vector<double> &F, const Vector<double> &u, CoulombState3D &s,
                                       std::vector<std::array<double, 2>> &t, bool &changed, double &turn) const
      {
        changed = false;
        turn    = 0;
        s.nodal_force.assign(n, {{0, 0, 0}});
        s.displacement.assign(n, {{0, 0, 0}});
        s.slip.assign(n, {{0, 0}});
        std::vector<NodeStatus> next(n);
        double                  largest = 0;
        for (unsigned int i = 0; i < n; ++i)
          largest = std::max(largest, std::abs(F(compliance.unknown[i][2])));
        const double band = set_tolerance * largest;
        for (unsigned int i = 0; i < n; ++i)
          {
            const auto &k = compliance.unknown[i];
            for (unsigned int d = 0; d < 3; ++d)
              if (k[d] >= 0)
                {
                  s.nodal_force[i][d]  = F(k[d]);
                  s.displacement[i][d] = u(k[d]);
                }
            const double P = s.nodal_force[i][2], g = f[i] - s.depth + s.displacement[i][2];
            s.slip[i] = {{s.displacement[i][0] - last.displacement[i][0] - step,
                          s.displacement[i][1] - last.displacement[i][1]}};
            // A node changes its set only when its criterion is violated by more than `band` (a node at the
            // edge of the contact or the stick zone with a criterion at round-off level would otherwise flip
            // back and forth).
            const double normal = P - c * g;
            const bool   in_contact = s.status[i] != NodeStatus::separated;
            if (in_contact ? normal < -band : !(normal > band))
              next[i] = NodeStatus::separated;
            else
              {
                std::array<double, 2> z = {{s.nodal_force[i][0] - c * s.slip[i][0],
                                            k[1] >= 0 ? s.nodal_force[i][1] - c * s.slip[i][1] : 0.0}};
                const double size_z = std::hypot(z[0], z[1]);
                const double limit  = mu * std::max(normal, 0.0);
                if (full_stick || (s.status[i] == NodeStatus::slip ? size_z < limit - band : size_z <= limit + band))
                  next[i] = NodeStatus::stick;
                else
                  {
                    next[i] = NodeStatus::slip;
                    const std::array<double, 2> direction_i = {{z[0] / size_z, z[1] / size_z}};
                    // the direction's change weighted by the node's share of the largest normal force: what it
                    // changes in the forces (a node with a force near round-off has a direction near round-off)
                    if (s.status[i] == NodeStatus::slip)
                      turn = std::max(turn, std::hypot(direction_i[0] - t[i][0], direction_i[1] - t[i][1]) *
                                              (largest > 0 ? std::max(P, 0.0) / largest : 1.0));
                    t[i] = direction_i;
                  }
              }
            changed = changed || next[i] != s.status[i];
          }
        if (force_control && std::none_of(next.begin(), next.end(), [](NodeStatus x) { return x != NodeStatus::separated; }))
          next[std::min_element(f.begin(), f.end()) - f.begin()] = NodeStatus::stick;
        return next;
      }

    private:
      /// The rows of a slipping node i off the symmetry plane: Phi = Q - mu P t(z), t(z) = z / |z|,
      /// z = Q - c s(F), a Newton step of the slip law linearised at the current iterate F (the direction's
      /// derivative (I - t t^T) / |z| included),
      ///   dPhi = (I - M) dQ - mu t dP + c M C_t dF,   M = mu P (I - t t^T) / |z|,
      /// written as the linear system J F_new = J F - Phi(F). `t_i`: the direction when z = 0.
      void slip_rows(const unsigned int i, const std::array<double, 2> &t_i, const Vector<double> &F,
                     const Vector<double> &u, LAPACKFullMatrix<double> &A, Vector<double> &rhs) const
      {
        const auto  &k = compliance.unknown[i];
        const double P = F(k[2]);
        const std::array<double, 2> Q = {{F(k[0]), F(k[1])}};
        std::array<double, 2> z{};
        for (unsigned int j = 0; j < 2; ++j)
          z[j] = Q[j] - c * (u(k[j]) - last.displacement[i][j] - (j == 0 ? step : 0.0));
        const double size_z = std::hypot(z[0], z[1]);
        const std::array<double, 2> ti = size_z > 0 ? std::array<double, 2>{{z[0] / size_z, z[1] / size_z}} : t_i;
        double M[2][2];
        for (unsigned int a = 0; a < 2; ++a)
          for (unsigned int b = 0; b < 2; ++b)
            M[a][b] = size_z > 0 ? mu * std::max(P, 0.0) * ((a == b ? 1.0 : 0.0) - ti[a] * ti[b]) / size_z : 0.0;
        for (unsigned int a = 0; a < 2; ++a)
          {
            const unsigned int row = k[a];
            for (unsigned int l = 0; l < m; ++l)
              A(row, l) = c * (M[a][0] * compliance.C(k[0], l) + M[a][1] * compliance.C(k[1], l));
            for (unsigned int b = 0; b < 2; ++b)
              A(row, k[b]) += (a == b ? 1.0 : 0.0) - M[a][b];
            A(row, k[2]) += -mu * ti[a];
            // rhs = J F - Phi(F)
            double JF = 0;
            for (unsigned int l = 0; l < m; ++l)
              JF += A(row, l) * F(l);
            rhs(row) = JF - (Q[a] - mu * P * ti[a]);
          }
      }

      const SurfaceCompliance3D &compliance;
      const std::vector<double> &f;
      const double               c;
      const CoulombState3D      &last;
      const bool                 force_control;
      const double               target;
      const unsigned int         n, m;
      const double               mu;
      const bool                 full_stick;
      const double               step; // of the tangential position
      const double               set_tolerance;
    };
  } // namespace

  void CoulombParameters::validate() const
  {
    if (!(mu >= 0)) // NaN fails too; infinity is full stick
      fail("CoulombParameters", "mu", mu, "[0, inf]");
    if (max_iterations < 1)
      fail("CoulombParameters", "max_iterations", max_iterations, "[1, inf)");
    if (!(direction_tolerance > 0 && direction_tolerance < 1))
      fail("CoulombParameters", "direction_tolerance", direction_tolerance, "(0, 1)");
    if (!(set_tolerance >= 0 && set_tolerance < 1e-3))
      fail("CoulombParameters", "set_tolerance", set_tolerance, "[0, 1e-3)");
  }



  CoulombContact3D::CoulombContact3D(const SurfaceCompliance3D &surface, const Profile &profile_,
                                     const CoulombParameters &parameters_)
    : compliance(surface)
    , profile((profile_.validate(), profile_))
    , parameters((parameters_.validate(), parameters_))
  {
    const unsigned int n = compliance.nodes.size();
    if (n == 0 || compliance.unknown.size() != n || compliance.C.m() != compliance.C.n())
      throw std::invalid_argument("CoulombContact3D: the surface compliance is empty or inconsistent");
    f.resize(n);
    double diagonal = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        f[i] = profile(compliance.nodes[i].norm(), 0.0);
        diagonal += compliance.C(compliance.unknown[i][2], compliance.unknown[i][2]);
      }
    c = n / diagonal;
    reset();
  }



  void CoulombContact3D::reset()
  {
    const unsigned int n = compliance.nodes.size();
    last              = CoulombState3D();
    last.converged    = true;
    last.status.assign(n, NodeStatus::separated);
    last.nodal_force.assign(n, {{0, 0, 0}});
    last.displacement.assign(n, {{0, 0, 0}});
    last.slip.assign(n, {{0, 0}});
    direction.assign(n, {{1, 0}});
  }



  void CoulombContact3D::set_friction(const double mu)
  {
    CoulombParameters p = parameters;
    p.mu                = mu;
    p.validate();
    parameters = p;
  }



  CoulombState3D CoulombContact3D::step_depth(const double depth, const double delta)
  {
    if (!std::isfinite(depth) || !std::isfinite(delta))
      throw std::invalid_argument("CoulombContact3D::step_depth: depth = " + std::to_string(depth) +
                                  ", delta = " + std::to_string(delta) + "; both must be finite");
    return solve(false, depth, delta);
  }



  CoulombState3D CoulombContact3D::step_force(const double force_z, const double delta)
  {
    if (!(force_z > 0) || !std::isfinite(force_z) || !std::isfinite(delta))
      throw std::invalid_argument("CoulombContact3D::step_force: force_z = " + std::to_string(force_z) +
                                  " outside (0, inf) or delta = " + std::to_string(delta) + " not finite");
    return solve(true, force_z, delta);
  }



  CoulombState3D CoulombContact3D::solve(const bool force_control, const double target, const double delta)
  {
    const unsigned int n = compliance.nodes.size(), m = compliance.C.m(), size = m + (force_control ? 1 : 0);
    const CoulombStep  problem(compliance, f, c, parameters, last, force_control, target, delta);

    CoulombState3D s;
    s.delta  = delta;
    s.depth  = force_control ? last.depth : target;
    s.status = problem.trial_status(s.depth);
    std::vector<std::array<double, 2>> t = direction;

    Vector<double> F(size), u(m);
    problem.last_forces(F);
    problem.displacements(F, u);
    for (unsigned int it = 1; it <= parameters.max_iterations; ++it)
      {
        // The linear system of the current sets and directions.
        LAPACKFullMatrix<double> A(size, size);
        Vector<double>           rhs(size);
        problem.system(s.status, s.depth, t, F, u, A, rhs);
        A.compute_lu_factorization();
        F = rhs;
        A.solve(F);
        if (force_control)
          s.depth = F(m);
        problem.displacements(F, u);

        // The new sets and directions.
        bool                          changed = false;
        double                        turn    = 0;
        const std::vector<NodeStatus> next    = problem.new_sets(F, u, s, t, changed, turn);
        s.iterations = it;
        if (!changed && turn <= parameters.direction_tolerance)
          {
            s.converged = true;
            break;
          }
        s.status = next;
      }

    s.force_x = s.force_z = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        s.force_x += 2 * s.nodal_force[i][0];
        s.force_z += 2 * s.nodal_force[i][2];
        s.n_contact += s.status[i] != NodeStatus::separated;
        s.n_stick += s.status[i] == NodeStatus::stick;
        s.n_slip += s.status[i] == NodeStatus::slip;
      }
    if (s.converged)
      {
        last      = s;
        direction = t;
      }
    else
      {
        std::ostringstream msg;
        msg << "the active set did not converge in " << parameters.max_iterations << " iterations (d = " << s.depth
            << ", delta = " << delta << ", " << s.n_stick << " stick and " << s.n_slip << " slip nodes at the end)";
        s.message = msg.str();
      }
    return s;
  }



  SurfaceCompliance3D without_coupling(const SurfaceCompliance3D &surface)
  {
    SurfaceCompliance3D decoupled = surface;
    const unsigned int  n         = surface.nodes.size();
    std::vector<bool>   normal(surface.C.m(), false);
    for (unsigned int i = 0; i < n; ++i)
      normal[surface.unknown[i][2]] = true;
    for (unsigned int k = 0; k < surface.C.m(); ++k)
      for (unsigned int l = 0; l < surface.C.n(); ++l)
        if (normal[k] != normal[l])
          decoupled.C(k, l) = 0;
    return decoupled;
  }



  SurfaceCompliance3D along_load(const SurfaceCompliance3D &surface)
  {
    SurfaceCompliance3D restricted;
    restricted.nodes = surface.nodes;
    restricted.area  = surface.area;
    std::vector<int> kept; // the unknowns of `surface` that stay, in their order
    std::vector<int> renumbered(surface.C.m(), -1);
    if (surface.unknown.size() != surface.nodes.size() || surface.C.m() != surface.C.n())
      throw std::invalid_argument("along_load: the surface has " + std::to_string(surface.nodes.size()) + " nodes, " +
                                  std::to_string(surface.unknown.size()) + " unknown triples and a " +
                                  std::to_string(surface.C.m()) + " x " + std::to_string(surface.C.n()) + " compliance");
    for (std::size_t i = 0; i < surface.unknown.size(); ++i)
      for (const unsigned int c : {0u, 2u})
        {
          const int k = surface.unknown[i][c];
          if (k < 0 || k >= static_cast<int>(surface.C.m()))
            throw std::invalid_argument("along_load: node " + std::to_string(i) + ", component " + std::to_string(c) +
                                        ": unknown " + std::to_string(k) + " outside [0, " +
                                        std::to_string(surface.C.m()) + ")");
          renumbered[k] = 0;
        }
    for (unsigned int l = 0; l < surface.C.m(); ++l)
      if (renumbered[l] == 0)
        {
          renumbered[l] = kept.size();
          kept.push_back(l);
        }
    for (const auto &k : surface.unknown)
      restricted.unknown.push_back({{renumbered[k[0]], -1, renumbered[k[2]]}});
    restricted.C.reinit(kept.size(), kept.size());
    for (unsigned int i = 0; i < kept.size(); ++i)
      for (unsigned int j = 0; j < kept.size(); ++j)
        restricted.C(i, j) = surface.C(kept[i], kept[j]);
    return restricted;
  }



  ZoneShape3D zone_shape(const SurfaceCompliance3D &surface, const CoulombState3D &state)
  {
    const unsigned int n = surface.nodes.size();
    if (state.status.size() != n || state.nodal_force.size() != n)
      throw std::invalid_argument("zone_shape: the state has " + std::to_string(state.status.size()) +
                                  " nodes, the surface " + std::to_string(n));
    ZoneShape3D shape;
    double      largest = 0;
    for (const Point<2> &x : surface.nodes)
      largest = std::max(largest, x.norm());
    const double on_line = 1e-9 * largest;
    double       sum_y = 0, sum = 0; // slipping nodes' |Q_y| and |Q|

    // The nodes of each ray, by r: (r, status).
    std::array<std::vector<std::pair<double, NodeStatus>>, 3> rays;
    for (unsigned int i = 0; i < n; ++i)
      {
        const Point<2> &x = surface.nodes[i];
        const double    r = x.norm();
        if (r <= on_line) // the axis lies on every ray
          for (auto &ray : rays)
            ray.emplace_back(r, state.status[i]);
        else if (std::abs(x[1]) <= on_line)
          rays[x[0] > 0 ? ZoneShape3D::plus_x : ZoneShape3D::minus_x].emplace_back(r, state.status[i]);
        else if (std::abs(x[0]) <= on_line)
          rays[ZoneShape3D::plus_y].emplace_back(r, state.status[i]);
        if (state.status[i] == NodeStatus::stick)
          shape.stick_outer = std::max(shape.stick_outer, r);
        if (state.status[i] == NodeStatus::slip)
          {
            shape.slip_inner = std::min(shape.slip_inner, r);
            const double qx = state.nodal_force[i][0], qy = state.nodal_force[i][1];
            if (qx != 0 || qy != 0)
              shape.slip_angle = std::max(shape.slip_angle, std::atan2(std::abs(qy), std::abs(qx)));
            sum_y += std::abs(qy);
            sum += std::hypot(qx, qy);
          }
      }
    shape.slip_force_y = sum > 0 ? sum_y / sum : 0.0;
    // The bracket of the zone `in` along one ray (sorted by r).
    const auto bracket = [](const std::vector<std::pair<double, NodeStatus>> &ray, const auto &in) {
      RayBracket b;
      b.nodes = ray.size();
      for (const auto &[r, status] : ray)
        if (in(status))
          {
            b.inside = std::max(b.inside, r);
            b.empty  = false;
          }
      for (const auto &[r, status] : ray)
        {
          if (r > b.inside)
            {
              b.outside = std::min(b.outside, r);
            }
          else if (!in(status) && r < b.inside)
            ++b.holes;
        }
      return b;
    };
    for (unsigned int ray = 0; ray < 3; ++ray)
      {
        std::sort(rays[ray].begin(), rays[ray].end());
        shape.contact[ray] = bracket(rays[ray], [](const NodeStatus s) { return s != NodeStatus::separated; });
        // The stick zone within the contact: a separated node beyond it bounds it as well as a slipping one.
        shape.stick[ray] = bracket(rays[ray], [](const NodeStatus s) { return s == NodeStatus::stick; });
      }
    return shape;
  }



  void write_surface_vtu(const SurfaceCompliance3D &surface, const CoulombState3D &state, const std::string &filename)
  {
    const unsigned int n = surface.nodes.size();
    if (state.status.size() != n || state.nodal_force.size() != n || state.displacement.size() != n ||
        state.slip.size() != n || surface.area.size() != n)
      throw std::invalid_argument("write_surface_vtu: the state has " + std::to_string(state.status.size()) +
                                  " nodes, the surface " + std::to_string(n));
    // The half body and its mirror image (the nodes on y = 0 once).
    // (by the coordinate: a compliance along_load has no y unknown anywhere)
    double largest = 0;
    for (const Point<2> &x : surface.nodes)
      largest = std::max(largest, x.norm());
    std::vector<std::pair<unsigned int, double>> points; // (node, sign of y)
    for (unsigned int i = 0; i < n; ++i)
      {
        points.emplace_back(i, 1.0);
        if (surface.nodes[i][1] > 1e-9 * largest) // off the symmetry plane
          points.emplace_back(i, -1.0);
      }
    std::ofstream out(filename);
    out.precision(12);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << points.size()
        << "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto &[i, sy] : points)
      out << surface.nodes[i][0] << ' ' << sy * surface.nodes[i][1] << " 0\n";
    out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t p = 0; p < points.size(); ++p)
      out << p << '\n';
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t p = 0; p < points.size(); ++p)
      out << p + 1 << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t p = 0; p < points.size(); ++p)
      out << "1\n"; // VTK_VERTEX
    out << "</DataArray>\n</Cells>\n<PointData Scalars=\"status\">\n";
    const auto vector = [&](const char *name, const auto &value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const auto &[i, sy] : points)
        {
          const std::array<double, 3> v = value(i);
          out << v[0] << ' ' << sy * v[1] << ' ' << v[2] << '\n';
        }
      out << "</DataArray>\n";
    };
    const auto scalar = [&](const char *name, const auto &value) {
      out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
      for (const auto &pair : points)
        out << value(pair.first) << '\n';
      out << "</DataArray>\n";
    };
    scalar("status", [&](const unsigned int i) { return static_cast<double>(state.status[i]); });
    vector("nodal_force", [&](const unsigned int i) { return state.nodal_force[i]; });
    scalar("pressure", [&](const unsigned int i) { return state.nodal_force[i][2] / surface.area[i]; });
    vector("shear", [&](const unsigned int i) {
      return std::array<double, 3>{{state.nodal_force[i][0] / surface.area[i], state.nodal_force[i][1] / surface.area[i], 0}};
    });
    vector("displacement", [&](const unsigned int i) { return state.displacement[i]; });
    vector("slip", [&](const unsigned int i) { return std::array<double, 3>{{state.slip[i][0], state.slip[i][1], 0}}; });
    out << "</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    if (!out)
      throw std::runtime_error("write_surface_vtu: cannot write " + filename);
  }
} // namespace gradcontact::fem
