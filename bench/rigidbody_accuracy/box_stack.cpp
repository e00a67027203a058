#include "bench/rigidbody_accuracy/scene.hpp"

namespace cosim::bench {

Scene build_box_stack(rigidbody::world::World& world) {
  constexpr double half = 0.1;
  constexpr int kBoxes = 10;
  const rigidbody::world::BodyMaterial material{.friction = 0.5};
  world.add({.shape = geometry::HalfSpace(Eigen::Vector3d::UnitZ()), .material = material, .fixed = true});
  for (int i = 0; i < kBoxes; ++i) {
    rigidbody::world::BodyDesc box{.shape = geometry::Box(Eigen::Vector3d::Constant(half)), .material = material};
    box.state.position = {0.0, 0.0, half * (2 * i + 1)};
    world.add(box);
  }
  return {.name = "stack", .size = half, .duration = 2.0, .at_rest = true};
}

}  // namespace cosim::bench
