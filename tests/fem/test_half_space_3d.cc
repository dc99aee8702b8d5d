// Serial tests of the pieces of the 3D half-space model (fem/bodies/half_space_3d.h); its solves run under MPI in
// the fem3d tests of tests/fem/CMakeLists.txt.
//
// References, each independent of the code under test:
//   rigid modes   the three translations and three rotations have zero strain, so K u = 0 cell by cell
//   uniaxial      u_z = eps z in a box 0 <= z <= H: the energy is (lambda + 2 mu) eps^2 times the area times
//                 \int_0^H E(z) dz / E, for E = E0 (z/c0)^k the integral E0 H^{1+k} / ((1 + k) c0^k) (closed form),
//                 through the Gauss-Jacobi rule of the cells on z = 0 for k != 0 (one cell layer: every cell
//                 is a surface cell, where the rule is exact for the power law)
//   geometry      the half cylinder's volume pi L^3 / 2, the contact disc's area pi a^2 / 2, the disc's edge on
//                 r = a, with a quadratic mapping of the curved faces
#include <fem/base/boundary_ids.h>
#include <fem/elasticity/graded_elasticity.h>
#include <fem/grid/mesh_3d.h>
#include <fem/modulus/modulus.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

using namespace gradcontact::fem;

TEST_CASE("The 3D cell integrand shall give no energy to rigid modes and the closed-form energy to a uniaxial strain",
          "[fem][quick]")
{
  const double k = GENERATE(-0.5, 0.0, 0.5);
  CAPTURE(k);
  const double   E0 = 2e9, c0 = 0.3, nu = 0.3, H = 1.0;
  const Material material{std::make_shared<PowerLawModulus>(E0, c0, k), nu};
  DiscretizationParameters discretization;
  discretization.degree = 2;
  dealii::Triangulation<3> tria;
  dealii::GridGenerator::subdivided_hyper_rectangle(tria, {2, 2, 1}, dealii::Point<3>(-0.5, 0.0, 0.0),
                                                    dealii::Point<3>(0.5, 1.0, H));
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() && std::abs(cell->face(f)->center()[2]) < 1e-12)
        cell->face(f)->set_boundary_id(boundary_id::contact);
  const dealii::FESystem<3>  fe(dealii::FE_Q<3>(2), 3);
  dealii::DoFHandler<3>      dofs(tria);
  const dealii::MappingQ1<3> mapping;
  dofs.distribute_dofs(fe);
  CellStiffness3D cell_stiffness(material, fe, mapping, discretization, 1.0, 1e-5); // no surface map

  const auto nodal = [&](const auto &cell, const auto &value) {
    dealii::Vector<double> u(fe.n_dofs_per_cell());
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      u[i] = value(fe.system_to_component_index(i).first,
                   mapping.transform_unit_to_real_cell(cell, fe.get_unit_support_points()[i]));
    return u;
  };
  const double eps    = 1e-3;
  double       energy = 0;
  for (const auto &cell : dofs.active_cell_iterators())
    {
      const auto &K = cell_stiffness.matrix(cell);
      for (unsigned int mode = 0; mode < 6; ++mode)
        {
          // translations e_c, rotations omega_c x x
          const auto u = nodal(cell, [mode](const unsigned int c, const dealii::Point<3> &x) {
            if (mode < 3)
              return c == mode ? 1.0 : 0.0;
            const unsigned int axis = mode - 3, i = (axis + 1) % 3, j = (axis + 2) % 3;
            return c == i ? -x[j] : (c == j ? x[i] : 0.0);
          });
          dealii::Vector<double> Ku(u.size());
          K.vmult(Ku, u);
          CHECK(Ku.linfty_norm() < 1e-13 * K.linfty_norm() * u.linfty_norm());
        }
      const auto u = nodal(cell, [eps](const unsigned int c, const dealii::Point<3> &x) { return c == 2 ? eps * x[2] : 0.0; });
      energy += K.matrix_norm_square(u);
    }
  const double lame     = nu / ((1 + nu) * (1 - 2 * nu)) + 1 / (1 + nu); // (lambda + 2 mu) / E
  const double expected = lame * eps * eps * 1.0 * E0 * std::pow(H, 1 + k) / ((1 + k) * std::pow(c0, k));
  CHECK_THAT(energy, Catch::Matchers::WithinRel(expected, 1e-12));
}



TEST_CASE("The 3D half-space mesh shall be the half cylinder with the contact disc and named boundaries", "[fem][quick]")
{
  HalfSpaceMesh3DParameters p;
  p.contact_radius = 2e-4;
  p.sectors        = 8;
  p.h_edge         = 1e-2;
  p.far_field_size = 6;
  const double            a = p.contact_radius, L = p.far_field_size * a;
  dealii::Triangulation<3> tria;
  HalfSpaceMesh3DInfo      info = make_coarse_mesh_3d(p, tria);
  refine_mesh_3d(p, tria, info);
  CHECK(info.coarse_cells == tria.n_active_cells());

  const dealii::FESystem<3> fe(dealii::FE_Q<3>(2), 1);
  const dealii::MappingQ<3> mapping(2);
  dealii::FEValues<3>       cell_values(mapping, fe, dealii::QGauss<3>(4), dealii::update_JxW_values);
  dealii::FEFaceValues<3>   face_values(mapping, fe, dealii::QGauss<2>(4), dealii::update_JxW_values);
  double volume = 0, contact = 0, surface = 0, largest_contact_r = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      cell_values.reinit(cell);
      for (const unsigned int q : cell_values.quadrature_point_indices())
        volume += cell_values.JxW(q);
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto id = cell->face(f)->boundary_id();
            REQUIRE(id != boundary_id::unassigned);
            if (!boundary_id::is_surface(id))
              continue;
            face_values.reinit(cell, f);
            double area = 0;
            for (const unsigned int q : face_values.quadrature_point_indices())
              area += face_values.JxW(q);
            surface += area;
            if (id == boundary_id::contact)
              {
                contact += area;
                for (const unsigned int v : cell->face(f)->vertex_indices())
                  largest_contact_r =
                    std::max(largest_contact_r, std::hypot(cell->face(f)->vertex(v)[0], cell->face(f)->vertex(v)[1]));
              }
          }
    }
  const double pi = dealii::numbers::PI;
  // The quadratic mapping of 22.5 degree arcs falls slightly short of both, well within 1e-4.
  CHECK_THAT(volume, Catch::Matchers::WithinRel(pi * L * L * L / 2, 1e-4));
  CHECK_THAT(surface, Catch::Matchers::WithinRel(pi * L * L / 2, 1e-4));
  CHECK_THAT(contact, Catch::Matchers::WithinRel(pi * a * a / 2, 1e-4));
  CHECK_THAT(largest_contact_r, Catch::Matchers::WithinRel(a, 1e-12));

  SECTION("bad parameters are refused by name")
  {
    const auto refused = [](HalfSpaceMesh3DParameters q, const std::string &name) {
      dealii::Triangulation<3> t;
      try
        {
          make_coarse_mesh_3d(q, t);
        }
      catch (const std::invalid_argument &e)
        {
          return std::string(e.what()).find(name) != std::string::npos;
        }
      return false;
    };
    HalfSpaceMesh3DParameters q = p;
    q.sectors                   = 6;
    CHECK(refused(q, "sectors"));
    q         = p;
    q.h_edge  = 0;
    CHECK(refused(q, "h_edge"));
    q                = p;
    q.far_field_size = 1;
    CHECK(refused(q, "far_field_size"));
    q                         = p;
    q.surface_layer_thickness = -1;
    CHECK(refused(q, "surface_layer_thickness"));
    q                = p;
    q.core_radius    = 1.0;
    CHECK(refused(q, "core_radius"));
    q                  = p;
    q.inner_ring_width = 0.5;
    CHECK(refused(q, "inner_ring_width"));
  }

  SECTION("inner_ring_width caps the ring widths inside the contact circle")
  {
    // The surface vertices on the positive x axis: the ring radii.
    const auto ring_radii = [](const HalfSpaceMesh3DParameters &q) {
      dealii::Triangulation<3> t;
      make_coarse_mesh_3d(q, t);
      std::vector<double> r;
      for (const auto &v : t.get_vertices())
        if (std::abs(v[1]) < 1e-12 * q.contact_radius && std::abs(v[2]) < 1e-12 * q.contact_radius && v[0] > 0)
          r.push_back(v[0] / q.contact_radius);
      std::sort(r.begin(), r.end());
      return r;
    };
    HalfSpaceMesh3DParameters q = p;
    q.inner_ring_width          = 0.05;
    const std::vector<double> capped = ring_radii(q), graded = ring_radii(p);
    // the widest ring between the core radius R0 and the contact circle
    const auto widest_inside = [](const std::vector<double> &radii, const double R0) {
      double widest = 0;
      for (std::size_t i = 1; i < radii.size(); ++i)
        if (radii[i - 1] >= R0 - 1e-12 && radii[i] <= 1 + 1e-12)
          widest = std::max(widest, radii[i] - radii[i - 1]);
      return widest;
    };
    const double widest_capped = widest_inside(capped, q.core_radius), widest_graded = widest_inside(graded, p.core_radius);
    // The last ring before the core takes what is left: at most 1.5 widths.
    CHECK(widest_capped <= 1.5 * q.inner_ring_width);
    CHECK(widest_graded > 2 * q.inner_ring_width); // without the cap the steps grow by q = 2
    CHECK(std::count_if(capped.begin(), capped.end(), [](const double r) { return std::abs(r - 1) < 1e-12; }) == 1);
  }
}
