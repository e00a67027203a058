// The coupler's wrench reaches the integrator.
#include <gtest/gtest.h>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

TEST(Wrench, ExternalForceBalancingGravityHolds) {
  World world;
  add_ground(world);
  const auto ball = add_sphere(world, 0.1, {0.0, 0.0, 1.0});
  const double mass = 1.0 / world.inertias()[ball].inverse_mass;
  std::vector<dynamics::WindowWrench> external(world.size());
  external[ball].start.force = external[ball].end.force = Eigen::Vector3d(0.0, 0.0, 9.81 * mass);
  world.advance(0.5, external);
  EXPECT_NEAR(world.states()[ball].position.z(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(world.time(), 0.5);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
