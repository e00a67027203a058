// A pile of sticks: 80 capsules of configs/sedimenting-sticks.yaml (aspect ratio 10, 1.2
// times the liquid's density, its weight less buoyancy), dropped in crossed layers at
// random turns and tilts into a box, come to rest crossed and lying along each other, and
// no two resting sticks overlap by more than 1 % of their radius, the scene's goal.
// Guards against: one contact point per capsule pair, on which a stick lying along
// another see-saws and sinks an end into it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

using Eigen::Vector3d;

// Slower than this a stick rests [m/s]: a stick of the pile's top may roll off its edge
// (capsules roll without resistance) and strike it, which is an impact, not the pile.
constexpr double kResting = 0.01;

struct Pile {
  double overlap = 0.0;  // deepest overlap of two resting sticks over the last fifth, of the radius
  int resting = 0;       // sticks at rest at the end
};

Pile drop_sticks(unsigned seed) {
  constexpr double radius = 0.005, height = 0.09, side = 0.2;
  const geometry::Capsule stick(radius, height);
  Settings settings;
  settings.dt = 2e-3;  // the sticks' scene's
  settings.body_forces = {.gravity = true, .buoyancy = true, .fluid_density = 1000.0};
  World world(settings);
  add_ground(world);
  // The box's side walls: half-spaces through x, y = 0 and side, facing in.
  for (int axis = 0; axis < 2; ++axis)
    for (const double sign : {1.0, -1.0}) {
      const Vector3d normal = sign * Vector3d::Unit(axis);
      BodyDesc wall{.shape = geometry::HalfSpace(normal), .fixed = true};
      wall.state.position = sign > 0 ? Vector3d::Zero() : Vector3d(side, side, 0.0);
      world.add(wall);
    }
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::uint32_t> sticks;
  // Layers 30 mm apart, along x and along y in turn, eight sticks 25 mm apart in each, turned
  // and tilted by at most 0.12 and 0.15 rad: no two touch at the start.
  for (int layer = 0; layer < 10; ++layer)
    for (int row = 0; row < 8; ++row) {
      BodyDesc d{.shape = stick, .density = 1200.0, .material = {.friction = 0.3}};
      const double across = 0.0125 + 0.025 * row, z = 0.02 + 0.03 * layer;
      const bool along_x = layer % 2 == 0;
      d.state.position = along_x ? Vector3d(0.5 * side, across, z) : Vector3d(across, 0.5 * side, z);
      const double yaw = 0.12 * unit(random) + (along_x ? 0.0 : M_PI / 2), tilt = 0.15 * unit(random);
      d.state.orientation = Eigen::AngleAxisd(yaw, Vector3d::UnitZ()) * Eigen::AngleAxisd(tilt, Vector3d::UnitY()) *
                            Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitY());
      sticks.push_back(world.add(d));
    }
  Pile pile;
  const int steps = 1500;
  for (int i = 0; i < steps; ++i) {
    world.advance(settings.dt);
    if (i < steps - steps / 5) continue;
    const auto states = world.states();
    for (std::size_t a = 0; a < sticks.size(); ++a)
      for (std::size_t b = a + 1; b < sticks.size(); ++b) {
        const auto& sa = states[sticks[a]];
        const auto& sb = states[sticks[b]];
        if ((sa.position - sb.position).norm() > height + 2 * radius) continue;
        if (std::max(sa.velocity.norm(), sb.velocity.norm()) > kResting) continue;
        pile.overlap = std::max(pile.overlap, overlap(world, sticks[a], sticks[b]) / radius);
      }
  }
  for (const auto s : sticks) pile.resting += world.states()[s].velocity.norm() < kResting ? 1 : 0;
  return pile;
}

TEST(StickPile, SticksComeToRestWithoutOverlapping) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(testing::Message() << "seed " << seed);
    const Pile pile = drop_sticks(seed);
    EXPECT_LT(pile.overlap, 0.01);
    EXPECT_GE(pile.resting, 40);  // the overlap is a pile's, not a few sticks'
  }
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
