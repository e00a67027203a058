// The hard resting cases (mass and size ratios, pyramids at friction 5, a
// 20-box tower), shared by the stability tests and bench/rigidbody_accuracy.
#pragma once

#include <string>
#include <vector>

#include "rigidbody/world/world.hpp"

namespace cosim::rigidbody::world::test {

struct HardStack {
  std::string name;
  std::string id;                         // the test's name
  double smallest_size = 0.0;             // the smallest body's edge or diameter: the unit of the bounds
  void (*build)(World& world) = nullptr;  // bodies exactly touching at t = 0, at rest
};

// 1:1000 heavy on light and light on heavy (0.2 m boxes), 10:1 large on small and small on
// large (0.2 and 0.02 m boxes), a box and a sphere pyramid at friction 5, a 20-box tower.
const std::vector<HardStack>& hard_stacks();

struct StackExtremes {
  double drift = 0.0;        // largest distance of a body from its start [m]
  double penetration = 0.0;  // deepest contact point [m]
};

// Steps `world` (already built) `steps` times by its dt, tracking the extremes.
StackExtremes run_at_rest(World& world, int steps);

}  // namespace cosim::rigidbody::world::test
