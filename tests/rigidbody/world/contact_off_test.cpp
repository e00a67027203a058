// Issue case 5: with contact off there is no broad or narrow phase; bodies pass through.
#include <gtest/gtest.h>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

TEST(ContactOff, NoBroadPhaseAndBodiesFallThrough) {
  Settings s;
  s.contact = false;
  World world(s);
  add_ground(world);
  const auto a = add_sphere(world, 0.1, {0.0, 0.0, 0.1});
  const auto b = add_sphere(world, 0.1, {0.0, 0.0, 0.25});  // overlapping a
  const StepReport report = world.advance(1.0);
  EXPECT_EQ(report.substeps, 1000);
  EXPECT_EQ(report.broadphase_updates, 0u);
  EXPECT_EQ(report.pairs_tested, 0u);
  EXPECT_EQ(report.contacts, 0u);
  EXPECT_TRUE(world.graph().edges().empty());
  // Only the two integration stages ran, and took time.
  for (const Stage contact : {Stage::broad_phase, Stage::narrow_phase, Stage::solve_contacts, Stage::relax_contacts})
    EXPECT_EQ(report.seconds[contact], 0.0);
  EXPECT_GT(report.seconds[Stage::integrate_velocities], 0.0);
  EXPECT_GT(report.seconds[Stage::integrate_positions], 0.0);
  // Free fall under semi-implicit Euler: z0 - g t^2 / 2 - g t h / 2.
  const double drop = 0.5 * 9.81 * (1.0 + s.dt);
  EXPECT_NEAR(world.states()[a].position.z(), 0.1 - drop, 1e-9);
  EXPECT_NEAR(world.states()[b].position.z(), 0.25 - drop, 1e-9);
}

// A single body needs no contact graph even with contact on.
TEST(ContactOff, SingleBodySkipsTheGraph) {
  World world;
  add_sphere(world, 0.1, {0.0, 0.0, 1.0});
  const StepReport report = world.advance(0.01);
  EXPECT_EQ(report.substeps, 10);
  EXPECT_EQ(report.broadphase_updates, 0u);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
