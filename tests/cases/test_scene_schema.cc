// The scene schema (cases/scene/scene.h): the kind decided from the entries alone, the checks apart from it.
#include "scene_files.h"

#include <catch2/catch.hpp>

using namespace gradcontact::cases;
using Catch::Matchers::Contains;

namespace
{
  /// A scene of defaults by hand, without reading or checking a file.
  Scene by_hand()
  {
    Scene s;
    s.file = "by_hand.prm";
    return s;
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
  CHECK_NOTHROW(validate(s, SceneKind::normal));
  CHECK_THROWS_WITH(validate(s, SceneKind::tangential),
                    Contains("by_hand.prm") && Contains("Tangential/study = stiffness needs Load/type = flat punch"));
  s = by_hand();
  s.material.k = 1.5;
  CHECK_THROWS_WITH(validate(s, SceneKind::normal), Contains("by_hand.prm") && Contains("Material/k") &&
                                                        Contains("1.5") && Contains("(-1, 1)"));
  s = by_hand();
  s.tangential.study = TangentialParameters::Study::stiffness;
  CHECK_THROWS_WITH(require_kind(s, SceneKind::normal, "runner"), Contains("runner: scene by_hand.prm is a tangential scene"));
}
