// Friction and restitution that no declared effect uses: the warning names the body, the
// key with file and line, and the missing effect.
#include <gtest/gtest.h>

#include "tests/scene/errors.hpp"
#include "coupler/scene/unused_materials.hpp"

namespace {

using cosim::scene::unused_materials;

std::vector<std::string> warnings(const std::string& effects, const std::string& bodies) {
  // Bodies start at line 8.
  return unused_materials(cosim::scene::load_scene_from_string(
      head + "effects: " + effects + "\nparticipants:\n  rigidbody: {dt: 0.001}\nbodies:\n" + bodies, "scene.yaml"));
}

// At x: bodies of one scene need places of their own (overlapping spheres are an error).
std::string ball(const std::string& name, const std::string& material, const std::string& x = "0.5") {
  return "  - {name: " + name + ", shape: {type: sphere, radius: 0.1}, material: {density: 1000" + material +
         "}, position: [" + x + ", 0.5, 0.5]}\n";
}

// Guards against: a scene with friction coefficients but no 'friction' effect running frictionless silently.
TEST(UnusedMaterials, FrictionWithoutTheFrictionEffectNamesBodyKeyAndEffect) {
  const auto w = warnings("[gravity, contact]", ball("ball", "", "0.2") + ball("box", ", friction: 0.5", "0.4"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0],
            "scene.yaml:9: bodies[1].material.friction = 0.5: ignored for body 'box': "
            "the scene's effects do not include 'friction'");
}

// Guards against: bodies' restitution silently unused when contact is off, and friction
// blamed on 'friction' alone when 'contact' is missing too.
TEST(UnusedMaterials, WithoutContactBothAreIgnoredAndEveryMissingEffectIsNamed) {
  const auto w = warnings("[gravity]", ball("ball", ", friction: 0.3, restitution: 0.9"));
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0],
            "scene.yaml:8: bodies[0].material.friction = 0.3: ignored for body 'ball': "
            "the scene's effects include neither 'contact' nor 'friction'");
  EXPECT_EQ(w[1],
            "scene.yaml:8: bodies[0].material.restitution = 0.9: ignored for body 'ball': "
            "the scene's effects do not include 'contact'");
}

// Guards against: a bed of many grains printing one line per grain.
TEST(UnusedMaterials, ManyBodiesGiveOneLineThatCountsThem) {
  const std::string bodies = ball("a", "", "0.2") + ball("b", ", friction: 0.5", "0.4") +
                             ball("c", ", friction: 0.4", "0.6") + ball("d", ", friction: 1", "0.8");
  const auto w = warnings("[gravity, contact]", bodies);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0],
            "scene.yaml:9: bodies[1].material.friction = 0.5: ignored for body 'b' and 2 more bodies: "
            "the scene's effects do not include 'friction'");
}

// Guards against: warnings for values that are used, or that are zero.
TEST(UnusedMaterials, NothingWhenTheEffectsUseThemOrTheyAreZero) {
  EXPECT_TRUE(warnings("[gravity, contact, friction]", ball("ball", ", friction: 0.5, restitution: 0.5")).empty());
  EXPECT_TRUE(warnings("[gravity]", ball("ball", ", friction: 0, restitution: 0")).empty());
}

}  // namespace
