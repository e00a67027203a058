// Bodies coming to rest and staying there: a dropped sphere, and bodies touching at t = 0.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

constexpr double kRadius = 0.1;

// Issue case 1: after settling, the height varies by less than 1e-6 r (sequential impulses).
// Guards against: a resting contact that never settles: the sphere buzzing on the ground after the impact.
TEST(Resting, DroppedSphereSettlesWithoutJitter) {
  World world;  // the soft step, dt 1e-3, gravity
  add_ground(world, {.restitution = 0.5});
  const auto ball = add_sphere(world, kRadius, {0.0, 0.0, 2.0 * kRadius});
  for (int i = 0; i < 2000; ++i) world.advance(world.settings().dt);
  const double rest = world.states()[ball].position.z();
  EXPECT_NEAR(rest, kRadius, 1e-3 * kRadius);  // the soft contact's sag, g / omega^2 = 1 um
  double jitter = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const StepReport r = world.advance(world.settings().dt);
    ASSERT_TRUE(r.converged);
    jitter = std::max(jitter, std::abs(world.states()[ball].position.z() - rest));
  }
  EXPECT_LT(jitter, 1e-6 * kRadius);
  EXPECT_LT(world.states()[ball].position.head<2>().norm(), 1e-12);
}

// The sag a soft contact settles to under any load, at the default frequency (soft_step.hpp).
const double kSoftSag = 9.81 / std::pow(2 * M_PI * solver::SoftOptions{}.hertz, 2);

// Issue case 4: a column of spheres and a box exactly touching the ground and each other
// at t = 0 under gravity: nothing may be pushed apart. Rigid contacts (SI) must not move
// them at all; soft ones (the default) let each contact sag, up to kSoftSag, but push nothing.
// Guards against: bodies in exact contact at t = 0 being pushed apart by the first solve.
class TouchingAtStart : public ::testing::TestWithParam<SolverKind> {};

TEST_P(TouchingAtStart, BodiesDoNotJumpApart) {
  World world({.solver = GetParam()});
  add_ground(world);
  std::vector<std::uint32_t> bodies;
  for (int i = 0; i < 3; ++i) bodies.push_back(add_sphere(world, kRadius, {0.0, 0.0, kRadius * (2 * i + 1)}));
  bodies.push_back(add_box(world, Eigen::Vector3d::Constant(kRadius), {1.0, 0.0, kRadius}));
  bodies.push_back(add_box(world, Eigen::Vector3d::Constant(kRadius), {1.0, 0.0, 3 * kRadius}));
  std::vector<Eigen::Vector3d> start;
  for (auto b : bodies) start.push_back(world.states()[b].position);
  double worst_speed = 0.0, worst_shift = 0.0, highest = 0.0;
  for (int i = 0; i < 500; ++i) {
    world.advance(world.settings().dt);
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      worst_speed = std::max(worst_speed, world.states()[bodies[k]].velocity.norm());
      worst_shift = std::max(worst_shift, (world.states()[bodies[k]].position - start[k]).norm());
      highest = std::max(highest, world.states()[bodies[k]].position.z() - start[k].z());
    }
  }
  // SI: the first, cold-started solve leaves a residual velocity of 2e-5 m/s, 0.2 % of the
  // gravity kick g dt it removes.
  EXPECT_LT(worst_speed, 1e-2 * 9.81 * 1e-3);
  EXPECT_LT(highest, 1e-6 * kRadius);
  // Three contacts under the top sphere.
  EXPECT_LT(worst_shift, GetParam() == SolverKind::soft ? 3 * kSoftSag : 1e-6 * kRadius);
}

INSTANTIATE_TEST_SUITE_P(Resting, TouchingAtStart, ::testing::Values(SolverKind::soft, SolverKind::sequential_impulses),
                         [](const auto& info) {
                           return info.param == SolverKind::soft ? "Soft" : "SequentialImpulses";
                         });

}  // namespace
}  // namespace cosim::rigidbody::world::test
