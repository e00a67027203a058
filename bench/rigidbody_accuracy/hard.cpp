#include "tests/rigidbody/world/hard_stack.hpp"
#include "bench/rigidbody_accuracy/scene.hpp"

namespace cosim::bench {

std::vector<SceneBuilder> hard_scenes() {
  std::vector<SceneBuilder> scenes;
  for (const rigidbody::world::test::HardStack& stack : rigidbody::world::test::hard_stacks())
    scenes.push_back([&stack](rigidbody::world::World& world) {
      stack.build(world);
      return Scene{.name = stack.id, .size = stack.smallest_size, .duration = 10.0, .at_rest = true, .hard = true};
    });
  return scenes;
}

}  // namespace cosim::bench
