// The scene schema (cases/scene/scene.h): the kind decided from the entries alone, the checks apart from it, and
// one name per concept with the former names still read.
#include "scene_files.h"

#include <catch2/catch.hpp>

#include <fstream>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;
using testing::scene_with;
using testing::TemporaryFolder;

namespace
{
  /// A scene of defaults by hand, without reading or checking a file.
  Scene by_hand()
  {
    Scene s;
    s.file = "by_hand.prm";
    return s;
  }

  /// The scene of `text` written to `name` in `folder`.
  Scene scene_of(const TemporaryFolder &folder, const std::string &name, const std::string &text,
                 const std::vector<Override> &overrides = {})
  {
    const std::filesystem::path file = folder.path() / name;
    std::ofstream(file) << text;
    return read_scene(file.string(), overrides);
  }
} // namespace

TEST_CASE("The scene kind shall be decided from the entries alone, contradicting entries included", "[cases][quick]")
{
  Scene s = by_hand();
  CHECK(decide_kind(s) == SceneKind::normal);
  s.references.fem = false;
  CHECK(decide_kind(s) == SceneKind::analytic);
  // a tangential study on an adhesive scene: decided as tangential, refused by validate
  s = by_hand();
  s.tangential.study = TangentialParameters::Study::stiffness;
  s.adhesion.work_of_adhesion = 0.05;
  CHECK(decide_kind(s) == SceneKind::tangential);
  CHECK_THROWS_WITH(validate(s, decide_kind(s)), Contains("by_hand.prm") && Contains("choose one"));
  // a map wins over everything, whatever else is set
  s.map.parameter = MapParameters::Parameter::surface_depth;
  CHECK(decide_kind(s) == SceneKind::map);
  // both candidate families: a candidate, the refusal is validate's
  s = by_hand();
  s.candidate.profile = "r^2";
  s.candidate.adhesive_force = "1";
  s.candidate.tangential_stiffness = "1";
  CHECK(decide_kind(s) == SceneKind::candidate);
  CHECK_THROWS_WITH(validate(s, SceneKind::candidate), Contains("adhesive and tangential candidate entries"));
}

TEST_CASE("validate shall check a scene as the kind it is given and name the entry, its value and the range",
          "[cases][quick]")
{
  Scene s = by_hand();
  s.load.type = LoadParameters::Type::cone;
  s.tangential.study = TangentialParameters::Study::stiffness;
  s.friction.coefficient = 0.3;
  CHECK_NOTHROW(validate(s, SceneKind::normal));
  CHECK_THROWS_WITH(validate(s, SceneKind::tangential),
                    Contains("by_hand.prm") && Contains("Tangential/study = stiffness needs Load/type = flat punch"));
  s = by_hand();
  s.material.k = 1.5;
  CHECK_THROWS_WITH(validate(s, SceneKind::normal), Contains("by_hand.prm") && Contains("Material/k") &&
                                                        Contains("1.5") && Contains("(-1, 1)"));
  s = by_hand();
  s.tangential.study = TangentialParameters::Study::stiffness;
  CHECK_THROWS_WITH(validate(s, SceneKind::tangential),
                    Contains("Friction/coefficient = 0 must be in (0, inf) in a tangential scene"));
  CHECK_THROWS_WITH(require_kind(s, SceneKind::normal, "runner"), Contains("runner: scene by_hand.prm is a tangential scene"));
}

TEST_CASE("The friction coefficient shall be one entry: mu of tangential contact, friction during normal loading",
          "[cases][quick]")
{
  const Scene tangential = scene_with({"Tangential/study=stiffness", "Friction/coefficient=0.4"});
  CHECK(tangential.friction.coefficient == 0.4);
  CHECK(friction_is_tangential(tangential));
  CHECK_FALSE(frictional_loading(tangential));
  const Scene loading = scene_with({"Load/type=paraboloid", "Load/contact=unilateral", "Load/control=depth",
                                    "Friction/coefficient=0.4"});
  CHECK(frictional_loading(loading));
  CHECK_FALSE(friction_is_tangential(loading));
}

TEST_CASE("A deprecated entry name shall parse to the same scene as its new name", "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-deprecated-names");
  const std::string     load = "subsection Load\n  set type = paraboloid\nend\n";
  const std::string     study = "subsection Tangential\n  set study = oscillation\n";
  const Scene old_names = scene_of(folder, "old.prm", load + study + "  set friction coefficient = 0.4\nend\n");
  const Scene new_names =
    scene_of(folder, "new.prm", load + study + "end\nsubsection Friction\n  set coefficient = 0.4\nend\n");
  CHECK(old_names.friction.coefficient == 0.4);
  REQUIRE(old_names.notes.size() == 1);
  CHECK_THAT(old_names.notes[0], Contains("Tangential/friction coefficient is a deprecated name, read as "
                                          "Friction/coefficient"));
  CHECK(new_names.notes.empty());
  CHECK(old_names.kind == new_names.kind);
  CHECK(old_names.resolved == new_names.resolved);

  const std::string map = "subsection Load\n  set type = paraboloid\nend\nsubsection Map\n  set parameter = surface "
                          "depth\n";
  const std::string material = "subsection Material\n  set modulus = shifted power law\n  set surface depth = 1e-5\nend\n";
  const Scene old_map = scene_of(folder, "old_map.prm", material + map + "  set ratios = 1, 10\nend\n");
  const Scene new_map = scene_of(folder, "new_map.prm", material + map + "  set values = 1, 10\nend\n");
  CHECK(old_map.map.values == std::vector<double>{1, 10});
  CHECK(old_map.resolved == new_map.resolved);

  // an override, and a JSON scene, by the old name
  CHECK(scene_with({"Tangential/study=stiffness", "Tangential/friction coefficient=0.4"}).resolved ==
        scene_with({"Tangential/study=stiffness", "Friction/coefficient=0.4"}).resolved);
  const Scene json = scene_of(folder, "old.json",
                              R"({"Load": {"type": "paraboloid"}, "Tangential": {"study": "oscillation", )"
                              R"("friction coefficient": "0.4"}})");
  CHECK(json.friction.coefficient == 0.4);
}

TEST_CASE("Every shipped scene shall read under the new names and set no deprecated one", "[cases][quick]")
{
  std::size_t read = 0;
  for (const char *folder : {"cases/default", "cases/examples", "cases/validation", "cases/convergence"})
    for (const auto &entry : std::filesystem::directory_iterator(folder))
      if (entry.path().extension() == ".prm" && entry.path().stem().string().rfind("bad_", 0) != 0)
        {
          CAPTURE(entry.path().string());
          CHECK_NOTHROW(read_scene(entry.path().string(), {}));
          const std::string text = testing::read_text(entry.path());
          for (const DeprecatedName &d : deprecated_names())
            CHECK(text.find("set " + d.old_name.substr(d.old_name.find('/') + 1) + " ") == std::string::npos);
          ++read;
        }
  CHECK(read > 20);
}

TEST_CASE("A deprecated name shall be an error naming its new name when the new one is set too, or its value is bad",
          "[cases][quick]")
{
  const TemporaryFolder folder("gradcontact-deprecated-both");
  CHECK_THROWS_WITH(scene_of(folder, "both.prm",
                             "subsection Tangential\n  set study = stiffness\n  set friction coefficient = 0.4\nend\n"
                             "subsection Friction\n  set coefficient = 0.3\nend\n"),
                    Contains("both.prm") && Contains("Tangential/friction coefficient is the deprecated name of "
                                                     "Friction/coefficient") &&
                      Contains("keep Friction/coefficient only"));
  CHECK_THROWS_WITH(scene_of(folder, "bad.prm", "subsection Map\n  set ratios = -1\nend\n"),
                    Contains("bad.prm") && Contains("Map/ratios = -1 (the deprecated name of Map/values)"));
  // a line after the old name keeps its number in deal.II's errors
  CHECK_THROWS_WITH(scene_of(folder, "line.prm", "subsection Map\n  set ratios = 1\nend\nsubsection Material\n  set k = 2\nend\n"),
                    Contains("Line <5> of file") && Contains("line.prm"));
  CHECK(scene_documentation().find("Tangential/friction coefficient -> Friction/coefficient") != std::string::npos);
}

TEST_CASE("Every kind of entry shall set its member: numbers, flags, text, lists and selections", "[cases][quick]")
{
  const Scene s = scene_with({"Material/E0=2e9", "Material/layers=7", "Material/modulus=layered", "Outputs/vtu=true",
                              "Candidate/constants=R=0.01", "Outputs/pressure radii=0, 0.5", "Load/type=cone",
                              "Load/control=depth", "Discretization/memory guard=off",
                              "Discretization/formulation=mixed", "Adhesion/control=force",
                              "Adhesion/curve points=0.5, 2"});
  CHECK(s.material.E0 == 2e9);
  CHECK(s.material.layers == 7);
  CHECK(s.material.modulus == MaterialParameters::Modulus::layered);
  CHECK(s.outputs.vtu);
  CHECK(s.candidate.constants == "R=0.01");
  CHECK(s.outputs.pressure_radii == std::vector<double>{0, 0.5});
  CHECK(s.load.type == LoadParameters::Type::cone);
  CHECK(s.load.control == LoadParameters::Control::depth);
  CHECK_FALSE(s.discretization.memory_guard);
  CHECK(s.discretization.formulation == DiscretizationParameters::Formulation::mixed);
  CHECK(s.adhesion.force_control);
  CHECK_FALSE(s.adhesion.displacement_control);
  CHECK(s.adhesion.curve_points == std::vector<double>{0.5, 2});
  // the entries left alone keep the declared defaults, which are the members' initial values
  const Scene defaults = scene_with({});
  const Scene by_hand;
  CHECK(defaults.material.E0 == by_hand.material.E0);
  CHECK(defaults.adhesion.stencil_ratio == by_hand.adhesion.stencil_ratio);
  CHECK(defaults.discretization.refinements == by_hand.discretization.refinements);
  CHECK(defaults.map.thresholds == by_hand.map.thresholds);
  CHECK(defaults.candidate.range == by_hand.candidate.range);
  CHECK(defaults.tangential.study == by_hand.tangential.study);
  CHECK(defaults.discretization.surface_map == by_hand.discretization.surface_map);
}
