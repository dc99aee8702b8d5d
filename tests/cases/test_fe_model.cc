// The scene -> FE model adapter (cases/model/fe_model.h): the mesh follows the modulus field that is solved,
// and every runner gets the scene's far field and refinement level.
#include "scene_files.h"

#include <cases/model/fe_model.h>

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using namespace gradcontact;
using namespace gradcontact::cases;
using testing::scene_with;

namespace
{
  std::string text(const double x)
  {
    std::ostringstream out;
    out << x;
    return out.str();
  }
} // namespace

TEST_CASE("A layered-modulus scene shall get the surface mesh of exponent 0 and the far field of k", "[cases][quick]")
{
  const double k = GENERATE(-0.5, 0.5);
  const Scene s = scene_with({"Material/modulus=layered", "Material/k=" + text(k)});
  CAPTURE(k);
  const FeModel model = fe_model(s, 0);
  REQUIRE(model.material.modulus->surface_exponent() == 0.);

  const double tol = s.discretization.force_tolerance;
  const fem::MeshParameters flat = fem::recommended_settings(s.load.a, 0., tol).mesh;
  const fem::MeshParameters graded = fem::recommended_settings(s.load.a, k, tol).mesh;
  // The two meshes differ (else this test could not see a mesh chosen for k) ...
  REQUIRE(graded.surface_layer_thickness != flat.surface_layer_thickness);
  REQUIRE(graded.far_field_size != flat.far_field_size);
  // ... and the scene's surface is the one of its constant top layer, its far field the one of the power law
  // below the layers (the truncation error falls like (a/L)^(1+k)).
  CHECK(model.settings.mesh.surface_layer_thickness == flat.surface_layer_thickness);
  CHECK(model.settings.mesh.far_field_size == graded.far_field_size);

  // The adhesive searches ask for other contact radii: the same choice there.
  const double a = 3. * s.load.a;
  const fem::Settings at_a = fe_settings(s, model.material, a, 0);
  CHECK(at_a.mesh.contact_radius == a);
  CHECK(at_a.mesh.surface_layer_thickness == fem::recommended_settings(a, 0., tol).mesh.surface_layer_thickness);
}

TEST_CASE("A power-law scene shall get the mesh of its exponent k", "[cases][quick]")
{
  const double k = GENERATE(-0.5, 0.5);
  const Scene s = scene_with({"Material/k=" + text(k)});
  CAPTURE(k);
  const FeModel model = fe_model(s, 0);
  const fem::MeshParameters expected =
    fem::recommended_settings(s.load.a, k, s.discretization.force_tolerance).mesh;
  CHECK(model.material.modulus->surface_exponent() == k);
  CHECK(model.settings.mesh.surface_layer_thickness == expected.surface_layer_thickness);
  CHECK(model.settings.mesh.far_field_size == expected.far_field_size);
}

TEST_CASE("The FE model shall honour Discretization/far field, degree, formulation and the refinement level", "[cases][quick]")
{
  const Scene s = scene_with({"Discretization/far field=1e6", "Discretization/refinements=0,2",
                              "Discretization/degree=2", "Discretization/formulation=mixed"});
  const FeModel model = fe_model(s, 1);
  CHECK(model.settings.mesh.far_field_size == 1e6);
  CHECK(model.settings.mesh.global_refinements == 1);
  CHECK(model.settings.discretization.degree == 2);
  CHECK(model.settings.discretization.formulation == fem::Formulation::mixed);
  CHECK(finest_refinement(s) == 2);

  // far field 0: the recommended L/a
  const Scene plain = scene_with({});
  CHECK(fe_model(plain, 0).settings.mesh.far_field_size ==
        fem::recommended_settings(plain.load.a, plain.material.k, plain.discretization.force_tolerance).mesh.far_field_size);
}

TEST_CASE("The candidate's FE model shall keep Discretization/far field and the finest refinement", "[cases][quick]")
{
  const Scene s = scene_with({"Candidate/profile=r^2/(2*0.01)", "Candidate/force=1", "Discretization/far field=1e6",
                              "Discretization/refinements=0,2", "Material/modulus=layered"});
  const fem::Profile profile = fem::Profile::custom([](const double r) { return r * r / 0.02; }, 2.);
  const FeModel model = candidate_fe_model(s, profile);
  CHECK(model.settings.mesh.far_field_size == 1e6);
  CHECK(model.settings.mesh.global_refinements == 2);
  CHECK(model.load.type == fem::LoadType::indenter);
  CHECK(model.load.profile.shape == fem::Profile::Shape::custom);
  CHECK(model.settings.mesh.surface_layer_thickness ==
        fem::recommended_settings(s.load.a, 0., s.discretization.force_tolerance).mesh.surface_layer_thickness);
}

TEST_CASE("The FE load shall follow Load/type and Load/control", "[cases][quick]")
{
  CHECK(fe_model(scene_with({"Load/type=flat punch", "Load/depth=2e-6"}), 0).load.type == fem::LoadType::flat_punch);
  CHECK(fe_model(scene_with({"Load/type=flat punch", "Load/depth=2e-6"}), 0).load.depth == 2e-6);
  CHECK(fe_model(scene_with({"Load/type=constant pressure", "Load/p0=3e5"}), 0).load.pressure == 3e5);
  const fem::LoadCase cone = fe_model(scene_with({"Load/type=cone", "Load/control=force", "Load/force=0.5"}), 0).load;
  CHECK(cone.type == fem::LoadType::indenter_force);
  CHECK(cone.profile.shape == fem::Profile::Shape::cone);
  CHECK(cone.force == 0.5);
  CHECK(fe_model(scene_with({"Load/type=paraboloid", "Load/control=depth"}), 0).load.type ==
        fem::LoadType::indenter_depth);
}

TEST_CASE("Discretization/formulation shall reach the FE model", "[cases][quick]")
{
  const auto [name, formulation] =
    GENERATE(std::make_pair(std::string("displacement"), fem::Formulation::displacement),
             std::make_pair(std::string("mixed"), fem::Formulation::mixed),
             std::make_pair(std::string("automatic"), fem::Formulation::automatic));
  CAPTURE(name);
  CHECK(fe_model(scene_with({"Discretization/formulation=" + name}), 0).settings.discretization.formulation ==
        formulation);
}
