// The scene kind (cases/scene/scene.h): decided once from the entries, with the checks that need more than one
// entry, each error naming the file, the entries and their values.
#include "scene_files.h"

#include <catch2/catch.hpp>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;
using testing::scene_with;

/// The friction coefficient a tangential scene needs (the mu of 9.80-9.87).
const std::string mu = "Friction/coefficient=0.3";

TEST_CASE("The scene kind shall follow the entries that are set", "[cases][quick]")
{
  CHECK(scene_with({}).kind == SceneKind::normal);
  CHECK(scene_with({"References/fem=false"}).kind == SceneKind::analytic);
  CHECK(scene_with({"Candidate/profile=r^2/0.02", "Candidate/force=1"}).kind == SceneKind::candidate);
  CHECK(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05"}).kind == SceneKind::adhesion);
  CHECK(scene_with({"Load/type=constant pressure", "Adhesion/tensile strength=1e6"}).kind == SceneKind::adhesion);
  CHECK(scene_with({"Tangential/study=stiffness", mu}).kind == SceneKind::tangential);
  CHECK(scene_with({"Load/type=paraboloid", "Tangential/study=partial slip", mu}).kind == SceneKind::tangential);
  // A tensile strength alone makes only the constant pressure adhesive (the optimal profile).
  CHECK(scene_with({"Adhesion/tensile strength=1e6"}).kind == SceneKind::normal);
}

TEST_CASE("Adhesion shall take precedence over a candidate, and the FE switch shall not hide a candidate", "[cases][quick]")
{
  CHECK(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05", "Candidate/profile=r^2/0.02",
                    "Candidate/force=1"})
          .kind == SceneKind::adhesion);
  CHECK(scene_with({"References/fem=false", "Candidate/profile=r^2/0.02", "Candidate/force=1"}).kind ==
        SceneKind::candidate);
}

TEST_CASE("Contradicting entries shall be an error naming the file and the entries", "[cases][quick]")
{
  REQUIRE_THROWS_WITH(scene_with({"Tangential/study=stiffness", mu, "Adhesion/work of adhesion=0.05"}),
                      Contains("defaults.prm") && Contains("Tangential/study is set and the scene is adhesive") &&
                        Contains("choose one"));
  REQUIRE_THROWS_WITH(scene_with({"Load/type=constant pressure", "Adhesion/work of adhesion=0.05"}),
                      Contains("defaults.prm") &&
                        Contains("Adhesion/work of adhesion = 0.05 with Load/type = constant pressure"));
  REQUIRE_THROWS_WITH(scene_with({"Load/type=paraboloid", "Tangential/study=oscillation", mu, "Tangential/Holl ratio=true",
                                  "Material/k=-0.5"}),
                      Contains("Tangential/Holl ratio = true with Material/k = -0.5") && Contains("k in (0, 1)"));
  REQUIRE_THROWS_WITH(scene_with({"Tangential/study=stiffness", mu, "Load/type=cone"}),
                      Contains("Tangential/study = stiffness needs Load/type = flat punch"));
  REQUIRE_THROWS_WITH(scene_with({"Load/type=paraboloid", "Tangential/study=partial slip", mu, "Load/control=force"}),
                      Contains("Load/control must be contact radius"));
  REQUIRE_THROWS_WITH(scene_with({"Candidate/profile=r^2/0.02", "Candidate/pressure=1"}),
                      Contains("Candidate/profile curvature: needed for a pressure candidate"));
  REQUIRE_THROWS_WITH(scene_with({"Candidate/profile=r^2/0.02"}), Contains("Candidate: no candidate formula given"));
  // a pressure candidate without radii checks nothing either
  REQUIRE_THROWS_WITH(scene_with({"Candidate/profile=r^2/0.02", "Candidate/profile curvature=100",
                                  "Candidate/pressure=1"}),
                      Contains("Candidate: no candidate formula given"));
}

TEST_CASE("An adhesive or tangential candidate shall be a candidate scene, its family's physics checked by name",
          "[cases][quick]")
{
  const std::string profile = "Candidate/profile=r^2/0.02";
  CHECK(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", profile, "Candidate/adhesive force=1"}).kind ==
        SceneKind::candidate);
  CHECK(scene_with({"Load/a=1e-4", profile, "Candidate/tangential stiffness=1", mu}).kind == SceneKind::candidate);
  CHECK(scene_with({"Load/a=1e-4", profile, "Candidate/tangential stiffness=1", mu}).candidate.family() ==
        CandidateParameters::Family::tangential);

  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", profile, "Candidate/critical force=1"}),
                      Contains("an adhesive candidate needs Adhesion/work of adhesion > 0"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", profile,
                                  "Candidate/adhesive force=1", "Candidate/stick radius=1"}),
                      Contains("adhesive and tangential candidate entries in one scene"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", profile,
                                  "Candidate/tangential force=1", mu}),
                      Contains("a tangential candidate is non-adhesive"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", profile,
                                  "Candidate/adhesive force=1", "Candidate/force=1"}),
                      Contains("non-adhesive normal family's"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", profile, "Candidate/tangential stiffness=1", mu, "Candidate/range=2, 1"}),
                      Contains("Candidate/range = 2, 1") && Contains("0 < range[0] < range[1]"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", profile,
                                  "Candidate/adhesive pressure=1"}),
                      Contains("Candidate/profile curvature: needed for an adhesive pressure candidate"));

  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", "Adhesion/law=Dugdale", profile,
                                  "Candidate/adhesive force=1"}),
                      Contains("Adhesion/law = Dugdale needs Adhesion/cohesive strength > 0"));
  CHECK(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", "Adhesion/law=Dugdale",
                    "Adhesion/cohesive strength=1e6", profile, "Candidate/adhesive force=1"})
          .kind == SceneKind::candidate);
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones",
                                  profile, "Candidate/adhesive force=1"}),
                      Contains("Adhesion/law = Lennard-Jones needs Adhesion/cohesive strength > 0"));
  CHECK(scene_with({"Load/a=1e-4", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones",
                    "Adhesion/cohesive strength=1e5", profile, "Candidate/adhesive force=1"})
          .kind == SceneKind::candidate);
  // Lennard-Jones outside a Tabor-parameter map and an adhesive candidate stays refused
  REQUIRE_THROWS_WITH(scene_with({"Load/type=paraboloid", "Adhesion/work of adhesion=0.05", "Adhesion/law=Lennard-Jones",
                                  "Adhesion/cohesive strength=1e5"}),
                      Contains("Lennard-Jones runs in Tabor-parameter maps and adhesive candidates only"));

  // A grading outside the chapter: against the FE only, and the tangential family by its stiffness alone.
  const std::string shifted = "Material/modulus=shifted power law", depth = "Material/surface depth=1e-5";
  CHECK(scene_with({"Load/a=1e-4", shifted, depth, profile, "Candidate/tangential stiffness=1", mu}).kind ==
        SceneKind::candidate);
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", shifted, depth, profile, "Candidate/tangential force=1", mu}),
                      Contains("only Candidate/tangential stiffness can be checked"));
  REQUIRE_THROWS_WITH(scene_with({"Load/a=1e-4", shifted, depth, "References/fem=false", profile,
                                  "Candidate/tangential stiffness=1", mu}),
                      Contains("checked against the FE only") && Contains("References/fem must be true"));
}
