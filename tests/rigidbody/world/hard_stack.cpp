#include "tests/rigidbody/world/hard_stack.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::rigidbody::world::test {

namespace {

void add(World& world, const geometry::Shape& shape, const Eigen::Vector3d& at, double density, double friction) {
  BodyDesc d{.shape = shape, .density = density, .material = {.friction = friction}};
  d.state.position = at;
  world.add(d);
}

void ground(World& world, double friction = 0.5) {
  world.add(
      {.shape = geometry::HalfSpace(Eigen::Vector3d::UnitZ()), .material = {.friction = friction}, .fixed = true});
}

// Two boxes of half sizes `lower` and `upper`, densities `lower_density` and `upper_density`, on the floor.
void two_boxes(World& world, double lower, double upper, double lower_density, double upper_density) {
  ground(world);
  add(world, geometry::Box(Eigen::Vector3d::Constant(lower)), {0, 0, lower}, lower_density, 0.5);
  add(world, geometry::Box(Eigen::Vector3d::Constant(upper)), {0, 0, 2 * lower + upper}, upper_density, 0.5);
}

// Layers of 4, 3, 2, 1 boxes of 0.2 m, each box on two of the layer below, a tenth of a box
// apart in a row, friction 5.
void box_pyramid(World& world) {
  constexpr double half = 0.1, pitch = 2.2 * half;
  ground(world, 5.0);
  for (int layer = 0; layer < 4; ++layer)
    for (int i = 0; i < 4 - layer; ++i)
      add(world, geometry::Box(Eigen::Vector3d::Constant(half)), {(i + 0.5 * layer) * pitch, 0, half * (2 * layer + 1)},
          1000.0, 5.0);
}

// Square layers 3x3, 2x2, 1 of 0.1 m spheres, each in the hollow of four below, friction 5.
void sphere_pyramid(World& world) {
  constexpr double r = 0.05;
  ground(world, 5.0);
  for (int layer = 0; layer < 3; ++layer)
    for (int i = 0; i < 3 - layer; ++i)
      for (int j = 0; j < 3 - layer; ++j)
        add(world, geometry::Sphere(r), {(2 * i + layer) * r, (2 * j + layer) * r, r + layer * std::sqrt(2.0) * r},
            1000.0, 5.0);
}

void tower(World& world) {
  constexpr double half = 0.1;
  ground(world);
  for (int i = 0; i < 20; ++i)
    add(world, geometry::Box(Eigen::Vector3d::Constant(half)), {0, 0, half * (2 * i + 1)}, 1000.0, 0.5);
}

}  // namespace

const std::vector<HardStack>& hard_stacks() {
  static const std::vector<HardStack> stacks{
      {"heavy on light 1000:1", "HeavyOnLight", 0.2, [](World& w) { two_boxes(w, 0.1, 0.1, 10.0, 10000.0); }},
      {"light on heavy 1:1000", "LightOnHeavy", 0.2, [](World& w) { two_boxes(w, 0.1, 0.1, 10000.0, 10.0); }},
      {"large on small 10:1", "LargeOnSmall", 0.02, [](World& w) { two_boxes(w, 0.01, 0.1, 1000.0, 1000.0); }},
      {"small on large 1:10", "SmallOnLarge", 0.02, [](World& w) { two_boxes(w, 0.1, 0.01, 1000.0, 1000.0); }},
      {"box pyramid mu 5", "BoxPyramid", 0.2, box_pyramid},
      {"sphere pyramid mu 5", "SpherePyramid", 0.1, sphere_pyramid},
      {"20-box tower", "Tower20", 0.2, tower},
  };
  return stacks;
}

StackExtremes run_at_rest(World& world, int steps) {
  std::vector<Eigen::Vector3d> start;
  for (const auto& s : world.states()) start.push_back(s.position);
  StackExtremes e;
  for (int step = 0; step < steps; ++step) {
    world.advance(world.settings().dt);
    e.penetration = std::max(e.penetration, world.graph().contacts().deepest_penetration());
    for (std::size_t b = 0; b < start.size(); ++b)
      e.drift = std::max(e.drift, (world.states()[b].position - start[b]).norm());
  }
  return e;
}

}  // namespace cosim::rigidbody::world::test
