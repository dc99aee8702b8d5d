// Tests of the shared FE building blocks every solver is made of: the graded-elasticity cell integrand
// (fem/elasticity/graded_elasticity.h), the surface trace (fem/elasticity/surface_trace.h) and the direct system with
// prescribed DoFs (fem/linear_algebra/direct_system.h).
//
// References, each from a path independent of the code under test:
//   rigid modes   a rigid translation (and the mode-1 rotation about y) has zero strain, so K u = 0
//                 cell by cell; a non-rigid field has positive energy
//   polynomials   the Lagrange trace reproduces polynomials of the face's degree, the traction integral
//                 of t = 1 is \int r dr = R^2 / 2 (partition of unity), and a line density in the FE
//                 space is recovered exactly from its own nodal forces
//   dense solve   the prescribed solve equals a dense LU solve of the reduced system
//   mesh cache    a damaged cached near field gives the same mesh as a fresh gmsh run
//   corner cell   \int E r dA of E = z^s over a rhombus with one vertex on z = 0, in closed form
#include <fem/base/boundary_ids.h>
#include <fem/linear_algebra/direct_system.h>
#include <fem/elasticity/graded_elasticity.h>
#include <fem/grid/mesh.h>
#include <fem/modulus/modulus.h>
#include <fem/elasticity/surface_trace.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/matrix_tools.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>
#include <vector>

using namespace gradcontact::fem;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace
{
  /// K u for the nodal values `u` of one cell, relative to ||K|| ||u|| (max norms).
  double relative_residual(const dealii::FullMatrix<double> &K, const dealii::Vector<double> &u)
  {
    dealii::Vector<double> Ku(u.size());
    K.vmult(Ku, u);
    return Ku.linfty_norm() / (K.linfty_norm() * u.linfty_norm());
  }

  /// The cell nodal vector of the field `value(component, r, z)`.
  template <class F>
  dealii::Vector<double> interpolate_on_cell(const dealii::FESystem<2> &fe,
                                              const dealii::DoFHandler<2>::active_cell_iterator &cell,
                                              const dealii::MappingQ1<2> &mapping, F value)
  {
    const std::vector<dealii::Point<2>> &unit = fe.get_unit_support_points();
    dealii::Vector<double>               u(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const dealii::Point<2> x = mapping.transform_unit_to_real_cell(cell, unit[i]);
        u[i]                     = value(fe.system_to_component_index(i).first, x[0], x[1]);
      }
    return u;
  }
} // namespace



TEST_CASE("The graded cell integrand shall give no energy to rigid modes and positive energy otherwise",
          "[fem][quick]")
{
  // Cells away from the axis (r in [0.5, 1.5]), E = E0 (z/c0)^k; the faces on z = 0 carry the id
  // `contact`, so the surface cells use the Gauss-Jacobi rule for k != 0.
  const double k = GENERATE(-0.5, 0.0, 0.5);
  CAPTURE(k);
  const Material material{std::make_shared<PowerLawModulus>(2.0e9, 0.3, k), 0.3};
  DiscretizationParameters discretization;
  discretization.degree = 2;
  dealii::Triangulation<2> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {2, 2}, dealii::Point<2>(0.5, 0.0),
                                                    dealii::Point<2>(1.5, 1.0));
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[1]) < 1e-12)
        cell->face(f)->set_boundary_id(boundary_id::contact);
  const dealii::MappingQ1<2> mapping;
  constexpr double           rigid_tolerance = 1e-13; // round-off of sums over ~30 shape functions

  SECTION("mode 0: a translation in z")
  {
    const dealii::FESystem<2> fe(dealii::FE_Q<2>(2), 2);
    dealii::DoFHandler<2>     dofs(tria);
    dofs.distribute_dofs(fe);
    CellStiffness cell_stiffness(material, fe, mapping, discretization, 1.0, 1e-5); // no surface map
    for (const auto &cell : dofs.active_cell_iterators())
      {
        const auto &K = cell_stiffness.matrix(cell);
        const auto  translation =
          interpolate_on_cell(fe, cell, mapping, [](unsigned int c, double, double) { return c == 1 ? 1.0 : 0.0; });
        CHECK(relative_residual(K, translation) < rigid_tolerance);
        // u_r = r (a radial expansion) strains the ring: positive energy.
        const auto expansion =
          interpolate_on_cell(fe, cell, mapping, [](unsigned int c, double r, double) { return c == 0 ? r : 0.0; });
        CHECK(K.matrix_norm_square(expansion) > 0);
        CHECK(relative_residual(K, expansion) > 1e-3);
      }
  }

  SECTION("mode 1: the translation in x and the rotation about y")
  {
    const dealii::FESystem<2> fe(dealii::FE_Q<2>(2), 3);
    dealii::DoFHandler<2>     dofs(tria);
    dofs.distribute_dofs(fe);
    Mode1CellStiffness cell_stiffness(material, fe, mapping, discretization, 1.0, 1e-5); // no surface map
    for (const auto &cell : dofs.active_cell_iterators())
      {
        const auto &K = cell_stiffness.matrix(cell);
        // U = V = delta, W = 0; and U = V = z, W = -r (fem/tangential/fourier_mode1_solver.h).
        const auto translation =
          interpolate_on_cell(fe, cell, mapping, [](unsigned int c, double, double) { return c < 2 ? 1.0 : 0.0; });
        const auto rotation = interpolate_on_cell(fe, cell, mapping, [](unsigned int c, double r, double z) {
          return c < 2 ? z : -r;
        });
        CHECK(relative_residual(K, translation) < rigid_tolerance);
        CHECK(relative_residual(K, rotation) < rigid_tolerance);
        // U = 1, V = 0 is no rigid mode (u_r = cos, u_theta = 0 strains the ring).
        const auto not_rigid =
          interpolate_on_cell(fe, cell, mapping, [](unsigned int c, double, double) { return c == 0 ? 1.0 : 0.0; });
        CHECK(K.matrix_norm_square(not_rigid) > 0);
      }
  }
}



TEST_CASE("A cell that touches the surface at a vertex only shall integrate E ~ z^s with a rule collapsed onto it",
          "[fem][quick]")
{
  // Three cells meet at the surface node (0.5, 0): two have a face on z = 0, the middle one, the rhombus
  // (0.5, 0), (0.65, 0.3), (0.5, 0.6), (0.35, 0.3), only that vertex. E = (z/c0)^s is singular there (s < 0),
  // which the face rules do not see. Reference: \int E r dA over the rhombus in closed form (its width at depth z
  // is z below 0.3 and 0.6 - z above, centred on r = 0.5, so \int r dr = 0.5 width):
  //   0.5 [\int_0^0.3 z^(1+s) dz + \int_0.3^0.6 (0.6 - z) z^s dz].
  const double s = GENERATE(-0.5, -0.9);
  CAPTURE(s);
  const std::vector<dealii::Point<2>> vertices = {{0.0, 0.0}, {0.5, 0.0}, {1.0, 0.0},  {0.0, 0.5},
                                                  {0.35, 0.3}, {0.65, 0.3}, {1.0, 0.5}, {0.5, 0.6}};
  std::vector<dealii::CellData<2>> cells(3);
  cells[0].vertices = {0, 1, 3, 4}; // face (0, 0) - (0.5, 0) on the surface
  cells[1].vertices = {1, 2, 5, 6}; // face (0.5, 0) - (1, 0) on the surface
  cells[2].vertices = {1, 5, 4, 7}; // the rhombus: the vertex (0.5, 0) only
  dealii::Triangulation<2> tria;
  tria.create_triangulation(vertices, cells, dealii::SubCellData());
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[1]) < 1e-12)
        cell->face(f)->set_boundary_id(boundary_id::contact);
  const Material           material{std::make_shared<PowerLawModulus>(1.0, 1.0, s), 0.3};
  DiscretizationParameters discretization;
  discretization.degree = 2;
  const dealii::FESystem<2>  fe(dealii::FE_Q<2>(2), 2);
  const dealii::MappingQ1<2> mapping;
  dealii::DoFHandler<2>      dofs(tria);
  dofs.distribute_dofs(fe);
  GradedCellRules<2> rules(material, fe, mapping, discretization, false);

  const auto integral = [&](dealii::FEValues<2> &values, const std::vector<double> *xi) {
    double sum = 0;
    for (const unsigned int q : values.quadrature_point_indices())
      {
        const dealii::Point<2> &x = values.quadrature_point(q);
        sum += material.modulus->value(x[1]) / (xi ? std::pow((*xi)[q], s) : 1.0) * x[0] * values.JxW(q);
      }
    return sum;
  };
  const double exact = 0.5 * (std::pow(0.3, 2 + s) / (2 + s) + 0.6 * (std::pow(0.6, 1 + s) - std::pow(0.3, 1 + s)) / (1 + s) -
                              (std::pow(0.6, 2 + s) - std::pow(0.3, 2 + s)) / (2 + s));
  unsigned int corners = 0;
  for (const auto &cell : dofs.active_cell_iterators())
    {
      const auto choice = rules.select(cell);
      const bool corner = cell->index() == 2;
      CHECK(choice.subdivide == corner);
      CHECK((choice.surface_face != dealii::numbers::invalid_unsigned_int) == !corner);
      if (!corner)
        continue;
      ++corners;
      const double chosen = integral(*choice.values, choice.xi);
      const double plain  = integral(rules.plain(cell, false), nullptr);
      CAPTURE(exact, chosen, plain);
      const double subdivided = integral(rules.plain(cell, true), nullptr);
      CAPTURE(subdivided);
      // The plain Gauss rule and the subdivided one (8 copies) miss the singular vertex's share; the collapsed
      // rule (Duffy) integrates z^(1+s) exactly along its rays and a smooth factor across them.
      CHECK(std::abs(plain / exact - 1) > 1e-3);
      CHECK(std::abs(subdivided / exact - 1) > 5e-5);
      CHECK(std::abs(chosen / exact - 1) < 1e-9);
    }
  CHECK(corners == 1);
}



TEST_CASE("The surface trace shall evaluate, integrate and recover polynomials of the face degree exactly",
          "[fem][quick]")
{
  // Three quadratic faces on [0, 0.5], [0.5, 1.2], [1.2, 2] with their midpoints; DoF i of component 0
  // is node i (shared vertices share a DoF).
  const std::vector<double> vertices{0.0, 0.5, 1.2, 2.0};
  std::vector<SurfaceFace>  faces;
  for (unsigned int f = 0; f + 1 < vertices.size(); ++f)
    {
      SurfaceFace face;
      face.r0 = vertices[f];
      face.r1 = vertices[f + 1];
      face.r  = {face.r0, 0.5 * (face.r0 + face.r1), face.r1};
      face.dofs.resize(1);
      face.dofs[0] = {2 * f, 2 * f + 1, 2 * f + 2};
      faces.push_back(face);
    }
  const unsigned int n_dofs = 2 * faces.size() + 1;
  auto density              = [](const double r) { return 3.0 - 2.0 * r + 0.75 * r * r; }; // degree 2

  SECTION("evaluation")
  {
    std::vector<double> nodal(n_dofs);
    for (const SurfaceFace &face : faces)
      for (unsigned int i = 0; i < 3; ++i)
        nodal[face.dofs[0][i]] = density(face.r[i]);
    for (const double r : {0.0, 0.1, 0.5, 0.77, 1.9, 2.0})
      {
        const SurfaceFace *face = find_face(faces, r);
        REQUIRE(face != nullptr);
        CHECK_THAT(face_value(*face, 0, nodal, r), WithinRel(density(r), 1e-14));
      }
    CHECK(find_face(faces, 2.5) == nullptr);
    CHECK(find_face(faces, 1.5, 1.2) == nullptr); // beyond the limit
  }

  SECTION("traction integral and consistent recovery")
  {
    // \int_0^R 1 r dr = R^2 / 2, also when R (1.0) cuts a face, with a breakpoint inside another.
    const auto unit = traction_integrals(faces, [](double) { return 1.0; }, 1.0, {0.3}, GradedRule{}, "test");
    double     sum  = 0;
    for (const auto &face : unit)
      for (const double b : face)
        sum += b;
    CHECK_THAT(sum, WithinRel(0.5, 1e-14));

    // The nodal forces of a density of the FE space give it back at the nodes.
    const auto             forces = traction_integrals(faces, density, 2.0, {}, GradedRule{}, "test");
    dealii::Vector<double> R(n_dofs);
    for (unsigned int f = 0; f < faces.size(); ++f)
      for (unsigned int i = 0; i < 3; ++i)
        R[faces[f].dofs[0][i]] += forces[f][i];
    const std::vector<double> p = recover_line_density(faces, 0, R, 2.0, 4, n_dofs);
    for (const SurfaceFace &face : faces)
      for (unsigned int i = 0; i < 3; ++i)
        CHECK_THAT(p[face.dofs[0][i]], WithinRel(density(face.r[i]), 1e-12));
  }

  SECTION("a kink just beyond a face end is integrated as accurately as one inside a face")
  {
    // t = sqrt(b^2 - r^2) (0 beyond b), \int_0^b t r dr = b^3 / 3. The graded rule's own error at a
    // square-root kink is about 1e-10, with b inside the face [0.5, 1.2] or at its end. With b 0.017 face
    // lengths beyond that end (as the reversal radius of (9.82) in the mode-1 oscillation test) the face is
    // graded toward its end and the error stays at that level; one Gauss rule there would be orders of magnitude off.
    constexpr double kink_tolerance = 1e-9;
    for (const double b : {0.85, 1.2, 1.2 + 0.017 * 0.7})
      {
        const auto integrals =
          traction_integrals(faces, [b](const double r) { return r < b ? std::sqrt((b - r) * (b + r)) : 0.0; },
                             2.0, {b}, GradedRule{}, "test");
        double sum = 0;
        for (const auto &face : integrals)
          for (const double v : face)
            sum += v;
        CAPTURE(b, sum, b * b * b / 3, sum / (b * b * b / 3) - 1, kink_tolerance);
        CHECK_THAT(sum, WithinRel(b * b * b / 3, kink_tolerance));
      }
  }

  SECTION("a traction that is not finite is named")
  {
    CHECK_THROWS_WITH(traction_integrals(faces, [](double r) { return r < 0.3 ? 1.0 : std::sqrt(0.3 - r); }, 0.5, {},
                                         GradedRule{}, "my traction"),
                      Catch::Contains("my traction") && Catch::Contains("finite"));
  }
}



namespace
{
  /// Laplace + shift mass of FE_Q(2) on a 3 x 3 grid (49 DoFs), no constraints, assembled into `system`.
  struct SmallSystem
  {
    dealii::Triangulation<2>          tria;
    const dealii::FESystem<2>         fe{dealii::FE_Q<2>(2), 1};
    dealii::DoFHandler<2>             dofs;
    dealii::AffineConstraints<double> constraints;
    DirectSystem                      system;

    explicit SmallSystem(const double shift)
    {
      dealii::GridGenerator::subdivided_hyper_cube(tria, 3);
      dofs.reinit(tria);
      dofs.distribute_dofs(fe);
      constraints.close();
      system.reinit(dofs, constraints);
      const dealii::QGauss<2>      quadrature(3);
      dealii::SparseMatrix<double> mass(system.sparsity());
      dealii::MatrixCreator::create_laplace_matrix(dofs, quadrature, system.matrix());
      dealii::MatrixCreator::create_mass_matrix(dofs, quadrature, mass);
      system.matrix().add(shift, mass);
    }
  };
} // namespace



TEST_CASE("The direct system shall factorise a positive definite matrix by Cholesky and an indefinite one by LU",
          "[fem][quick]")
{
  // Laplace + s mass of FE_Q(2) on a 3 x 3 grid (49 DoFs: small enough for CHOLMOD's automatic choice to be the
  // simplicial LDL^T, which does not stop at negative pivots): s = 1 is positive definite, s = -30 indefinite (the
  // discrete Neumann eigenvalues 0, 9.9, 19.7, 39.5, ... shifted by -30). Each free solve against a dense one.
  const double shift = GENERATE(1.0, -30.0);
  SmallSystem  small(shift);
  DirectSystem &system = small.system;
  system.set_prescribed_dofs({});

  const unsigned int     n = small.dofs.n_dofs();
  dealii::Vector<double> b(n);
  for (unsigned int i = 0; i < n; ++i)
    b[i] = std::cos(2.0 * i);
  dealii::Vector<double> reaction;
  double                 seconds = 0;
  const dealii::Vector<double> u = system.solve(false, {}, b, reaction, seconds);
  CAPTURE(shift, n);
  CHECK(system.cholesky(false) == (shift > 0));

  dealii::FullMatrix<double> A(n, n);
  A.copy_from(system.matrix());
  A.gauss_jordan();
  dealii::Vector<double> reference(n);
  A.vmult(reference, b);
  for (unsigned int i = 0; i < n; ++i)
    CHECK_THAT(u[i], WithinRel(reference[i], 1e-9) || WithinAbs(0.0, 1e-12 * reference.linfty_norm()));
}



TEST_CASE("The direct system shall impose prescribed values and agree with a dense solve of the reduced system",
          "[fem][quick]")
{
  // A = Laplace + mass (SPD) of FE_Q(2) on a 3 x 3 grid, no constraints; P = the DoFs on x = 0.
  SmallSystem                  small(1.0);
  const dealii::DoFHandler<2> &dofs   = small.dofs;
  DirectSystem                &system = small.system;

  const unsigned int              n = dofs.n_dofs();
  std::vector<dealii::Point<2>>   support(n);
  dealii::DoFTools::map_dofs_to_support_points(dealii::MappingQ1<2>(), dofs, support);
  std::vector<dealii::types::global_dof_index> prescribed;
  std::vector<double>                          g;
  for (unsigned int i = 0; i < n; ++i)
    if (support[i][0] == 0.0)
      {
        prescribed.push_back(i);
        g.push_back(1.0 + support[i][1]);
      }
  system.set_prescribed_dofs(prescribed);
  dealii::Vector<double> b(n);
  for (unsigned int i = 0; i < n; ++i)
    b[i] = std::sin(3.0 * i);

  dealii::Vector<double> reaction;
  double                 seconds = 0;
  const dealii::Vector<double> u = system.solve(true, g, b, reaction, seconds);

  // Dense reference: A_ff u_f = b_f - A_fp g.
  std::vector<bool> is_prescribed(n, false);
  for (const auto i : prescribed)
    is_prescribed[i] = true;
  std::vector<unsigned int> free;
  for (unsigned int i = 0; i < n; ++i)
    if (!is_prescribed[i])
      free.push_back(i);
  dealii::FullMatrix<double> A_ff(free.size(), free.size());
  dealii::Vector<double>     rhs(free.size());
  for (unsigned int a = 0; a < free.size(); ++a)
    {
      rhs[a] = b[free[a]];
      for (unsigned int c = 0; c < free.size(); ++c)
        A_ff(a, c) = system.matrix().el(free[a], free[c]);
      for (unsigned int p = 0; p < prescribed.size(); ++p)
        rhs[a] -= system.matrix().el(free[a], prescribed[p]) * g[p];
    }
  A_ff.gauss_jordan();
  dealii::Vector<double> u_free(free.size());
  A_ff.vmult(u_free, rhs);

  for (unsigned int p = 0; p < prescribed.size(); ++p)
    CHECK_THAT(u[prescribed[p]], WithinRel(g[p], 1e-14));
  for (unsigned int a = 0; a < free.size(); ++a)
    CHECK_THAT(u[free[a]], WithinRel(u_free[a], 1e-10) || WithinAbs(0.0, 1e-12));
  // Reactions vanish off P; the energy is u.Au.
  for (const unsigned int i : free)
    CHECK_THAT(reaction[i], WithinAbs(0.0, 1e-12 * b.linfty_norm()));
  CHECK_THAT(system.energy(u), WithinRel(system.matrix().matrix_norm_square(u), 1e-14));
  // The free solve (no prescribed DoFs) has no reactions anywhere.
  const dealii::Vector<double> v = system.solve(false, {}, b, reaction, seconds);
  CHECK(reaction.linfty_norm() < 1e-12 * b.linfty_norm());
  CHECK(v.l2_norm() > 0);
}

TEST_CASE("A damaged cached near-field mesh shall be detected and made again", "[fem][quick]")
{
  namespace fs = std::filesystem;
  const fs::path cache = fs::temp_directory_path() / ("gradcontact-cache-test-" + std::to_string(::getpid()));
  fs::remove_all(cache);
  MeshParameters p;
  p.h_edge          = 1e-2; // a small gmsh mesh (a second)
  p.far_field_size  = 1e3;
  p.cache_directory = cache.string();

  dealii::Triangulation<2> fresh;
  const MeshInfo first = make_mesh(p, fresh);
  REQUIRE_FALSE(first.cache_hit);
  dealii::Triangulation<2> cached;
  REQUIRE(make_mesh(p, cached).cache_hit);
  REQUIRE(cached.n_active_cells() == fresh.n_active_cells());

  // Truncate the cached .msh to half its length (a full disk), then change one byte and keep the length (a
  // damaged copy): each is found, gmsh runs again, and the mesh is the fresh one.
  const fs::path msh = first.near_field_source;
  const auto size = fs::file_size(msh);
  fs::resize_file(msh, size / 2);
  dealii::Triangulation<2> after_truncation;
  const MeshInfo repaired = make_mesh(p, after_truncation);
  CHECK_FALSE(repaired.cache_hit);
  CHECK(after_truncation.n_active_cells() == fresh.n_active_cells());
  CHECK(fs::file_size(msh) == size);
  {
    std::fstream f(msh, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size / 2));
    f.put('#');
  }
  dealii::Triangulation<2> after_change;
  CHECK_FALSE(make_mesh(p, after_change).cache_hit);
  CHECK(after_change.n_active_cells() == fresh.n_active_cells());
  fs::remove_all(cache);
}
