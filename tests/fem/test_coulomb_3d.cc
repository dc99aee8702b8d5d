// Serial tests of the node-by-node Coulomb contact of the 3D model (fem/tangential/coulomb_contact_3d.h) on a surface whose
// nodes do not interact: a Winkler foundation, C = diag(c_t, c_t, c_n). Every node is then its own spring with a
// Coulomb slider, solved by hand:
//   normal     P_i = max(0, d - f(r_i)) / c_n (d the depth, f the profile);
//   loading    Q_i = min(delta / c_t, mu P_i) along x (the spring stretched by delta until the slider moves);
//   unloading  after the slider of node i moved by s_i = delta_A - c_t mu P_i (0 if it stuck), the force at delta
//              is the spring's (delta - s_i) / c_t, clamped to +-mu P_i (the slider moves back beyond it).
// The whole body's forces are twice the half's. These are the exact answers of the discrete problem; the
// solver (active sets and Newton on the slip law) must reach them to round-off, and zone_shape must put the
// stick-zone boundary between the nodes the hand solution says.
#include <fem/tangential/coulomb_contact_3d.h>

#include <deal.II/base/numbers.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

using namespace gradcontact::fem;

namespace
{
  /// Nodes on rings r = 0.1 j (j = 0..12) at the angles m pi / 8 (m = 0..8) of the half disc y >= 0, each with
  /// its own springs; u_y is not an unknown on the symmetry plane y = 0.
  SurfaceCompliance3D winkler(const double ct, const double cn)
  {
    SurfaceCompliance3D s;
    std::vector<double> diagonal;
    for (unsigned int j = 0; j <= 12; ++j)
      for (unsigned int m = 0; m <= (j == 0 ? 0u : 8u); ++m)
        {
          const double r = 0.1 * j, t = m * dealii::numbers::PI / 8;
          const double x = m == 4 ? 0.0 : r * std::cos(t), y = (m == 0 || m == 8) ? 0.0 : r * std::sin(t);
          s.nodes.emplace_back(x, y);
          std::array<int, 3> unknown{{-1, -1, -1}};
          unknown[0] = diagonal.size();
          diagonal.push_back(ct);
          if (y != 0)
            {
              unknown[1] = diagonal.size();
              diagonal.push_back(ct);
            }
          unknown[2] = diagonal.size();
          diagonal.push_back(cn);
          s.unknown.push_back(unknown);
          s.area.push_back(1.0);
        }
    s.C.reinit(diagonal.size(), diagonal.size());
    for (unsigned int k = 0; k < diagonal.size(); ++k)
      s.C(k, k) = diagonal[k];
    return s;
  }
} // namespace

TEST_CASE("Coulomb contact on a Winkler foundation shall give every node its spring-and-slider answer", "[fem][quick]")
{
  const double ct = 2.0, cn = 1.0, mu = 0.3, R = 10.0, d = 0.055; // contact for r^2 / 20 < d: r < 1.049
  const SurfaceCompliance3D surface = winkler(ct, cn);
  CoulombParameters         parameters;
  parameters.mu = mu;
  CoulombContact3D contact(surface, Profile::paraboloid(R), parameters);
  const auto P = [&](const dealii::Point<2> &x) { return std::max(0.0, d - x.norm_square() / (2 * R)) / cn; };

  const CoulombState3D normal = contact.step_depth(d, 0.0);
  REQUIRE(normal.converged);
  double Fz = 0;
  for (const auto &x : surface.nodes)
    Fz += 2 * P(x);
  CHECK_THAT(normal.force_z, Catch::Matchers::WithinRel(Fz, 1e-12));
  CHECK(std::abs(normal.force_x) <= 1e-14 * Fz);
  CHECK(normal.n_slip == 0); // no tangential load: nothing slips

  // Loading to delta_A: the nodes with delta_A / c_t < mu P stick.
  const double delta_A = 0.6 * mu * ct * P(dealii::Point<2>(0, 0)); // sticks for r < 0.663
  std::vector<double> slid(surface.nodes.size(), 0.0);
  for (const double delta : {0.5 * delta_A, delta_A})
    {
      const CoulombState3D s = contact.step_depth(d, delta);
      REQUIRE(s.converged);
      double       Fx    = 0;
      unsigned int stick = 0;
      for (unsigned int i = 0; i < surface.nodes.size(); ++i)
        {
          const double p = P(surface.nodes[i]);
          if (p == 0)
            continue;
          Fx += 2 * std::min(delta / ct, mu * p);
          stick += delta / ct < mu * p;
          slid[i] = std::max(0.0, delta - ct * mu * p);
        }
      CHECK_THAT(s.force_x, Catch::Matchers::WithinRel(Fx, 1e-12));
      CHECK(s.n_stick == stick);
      const ZoneShape3D shape = zone_shape(surface, s);
      // Along each ray the boundary lies between the last ring that sticks and the next: r_c^2 = 2 R (d - c_n
      // delta / (mu c_t)).
      const double rc = std::sqrt(2 * R * (d - cn * delta / (mu * ct)));
      for (const RayBracket &ray : shape.stick)
        {
          REQUIRE(ray.nodes == 13);
          CHECK(ray.inside <= rc);
          CHECK(ray.outside > rc);
          CHECK(ray.outside - ray.inside == Approx(0.1).epsilon(1e-9));
          CHECK(ray.holes == 0);
        }
      CHECK(shape.slip_angle <= 1e-12); // the springs do not couple x and y: slip along x
      CHECK(shape.slip_force_y <= 1e-12);
      // the contact zone: every node with P > 0, up to r = 1.0 of the rings (r = 1.1 is out)
      for (const RayBracket &ray : shape.contact)
        {
          CHECK(ray.inside == Approx(1.0));
          CHECK(ray.outside == Approx(1.1));
        }
    }

  // Unloading to -delta_A through 0: each slider's history decides.
  for (const double delta : {0.0, -delta_A})
    {
      const CoulombState3D s = contact.step_depth(d, delta);
      REQUIRE(s.converged);
      double Fx = 0;
      for (unsigned int i = 0; i < surface.nodes.size(); ++i)
        {
          const double p = P(surface.nodes[i]);
          Fx += 2 * std::clamp((delta - slid[i]) / ct, -mu * p, mu * p);
        }
      CHECK_THAT(s.force_x, Catch::Matchers::WithinRel(Fx, 1e-12));
    }
}

TEST_CASE("The decoupled compliance shall keep the normal and tangential blocks and drop the rest", "[fem][quick]")
{
  SurfaceCompliance3D s = winkler(2.0, 1.0);
  const unsigned int  n = s.C.m();
  for (unsigned int k = 0; k < n; ++k)
    for (unsigned int l = 0; l < n; ++l)
      s.C(k, l) += 1e-3 * (k + 1) * (l + 2);
  const SurfaceCompliance3D d = without_coupling(s);
  std::vector<bool>         normal(n, false);
  for (const auto &u : s.unknown)
    normal[u[2]] = true;
  unsigned int kept = 0, dropped = 0;
  for (unsigned int k = 0; k < n; ++k)
    for (unsigned int l = 0; l < n; ++l)
      if (normal[k] == normal[l])
        kept += d.C(k, l) == s.C(k, l);
      else
        dropped += d.C(k, l) == 0;
  unsigned int normals = std::count(normal.begin(), normal.end(), true);
  CHECK(kept == normals * normals + (n - normals) * (n - normals));
  CHECK(dropped == 2 * normals * (n - normals));
}

TEST_CASE("zone_shape shall refuse a state of another surface", "[fem][quick]")
{
  const SurfaceCompliance3D surface = winkler(1.0, 1.0);
  CoulombState3D            state;
  state.status.assign(3, NodeStatus::stick);
  state.nodal_force.assign(3, {{0, 0, 1}});
  CHECK_THROWS_WITH(zone_shape(surface, state), Catch::Contains("3 nodes") && Catch::Contains("109"));
}

TEST_CASE("The compliance along the load shall keep the x and z blocks and leave every node's force along x",
          "[fem][quick]")
{
  // A Winkler foundation whose nodes also move in y under a force in x and back (C_xy = C_yx = 0.5 c_t at each
  // node off the symmetry plane): with the y forces free a sticking node needs Q_y != 0 to keep u_y = 0; along the
  // load (Cattaneo-Mindlin's assumption) Q_y = 0, only u_x sticks, and each node is again the spring c_t with its
  // slider: Q_x = min(delta / c_t, mu P).
  const double        ct = 2.0, cn = 1.0, mu = 0.3, R = 10.0, d = 0.055;
  SurfaceCompliance3D s = winkler(ct, cn);
  for (const auto &u : s.unknown)
    if (u[1] >= 0)
      s.C(u[0], u[1]) = s.C(u[1], u[0]) = 0.5 * ct;
  const SurfaceCompliance3D x = along_load(s);
  REQUIRE(x.nodes.size() == s.nodes.size());
  REQUIRE(x.C.m() == 2 * s.nodes.size());
  unsigned int same = 0;
  for (unsigned int i = 0; i < s.nodes.size(); ++i)
    {
      CHECK(x.unknown[i][1] == -1);
      for (unsigned int j = 0; j < s.nodes.size(); ++j)
        for (const unsigned int a : {0u, 2u})
          for (const unsigned int b : {0u, 2u})
            same += x.C(x.unknown[i][a], x.unknown[j][b]) == s.C(s.unknown[i][a], s.unknown[j][b]);
    }
  CHECK(same == 4 * s.nodes.size() * s.nodes.size());

  CoulombParameters parameters;
  parameters.mu = mu;
  const auto P  = [&](const dealii::Point<2> &p) { return std::max(0.0, d - p.norm_square() / (2 * R)) / cn; };
  const double delta = 0.6 * mu * ct * P(dealii::Point<2>(0, 0));
  double       Fx    = 0;
  for (const auto &p : s.nodes)
    Fx += 2 * std::min(delta / ct, mu * P(p));

  CoulombContact3D along(x, Profile::paraboloid(R), parameters);
  REQUIRE(along.step_depth(d, 0.0).converged);
  const CoulombState3D loaded = along.step_depth(d, delta);
  REQUIRE(loaded.converged);
  CHECK_THAT(loaded.force_x, Catch::Matchers::WithinRel(Fx, 1e-12));
  for (const auto &q : loaded.nodal_force)
    CHECK(q[1] == 0);

  // The same surface with the y forces free: the sticking nodes carry Q_y, and F_x is another.
  CoulombContact3D free(s, Profile::paraboloid(R), parameters);
  REQUIRE(free.step_depth(d, 0.0).converged);
  const CoulombState3D coupled = free.step_depth(d, delta);
  REQUIRE(coupled.converged);
  double largest_y = 0;
  for (const auto &q : coupled.nodal_force)
    largest_y = std::max(largest_y, std::abs(q[1]));
  CHECK(largest_y > 1e-3 * mu * P(dealii::Point<2>(0, 0)));
  CHECK(std::abs(coupled.force_x / Fx - 1) > 1e-3);
}
