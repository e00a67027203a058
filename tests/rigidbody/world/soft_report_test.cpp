// What the soft step's report says: the sweeps it did (fixed, as Box2D's) and how much its
// last sweep still changed, measured like the impulse solvers' stopping test.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

constexpr double kRadius = 0.05;

// One sphere resting on the ground: one point, solved directly, so a second sweep changes
// nothing and the report says it settled.
// Guards against: the report's sweep count not being the sweeps done.
TEST(SoftReport, ARestingSphereTakesTheFixedSweepsAndSettles) {
  World world;  // the soft step
  add_ground(world);
  add_sphere(world, kRadius, {0.0, 0.0, kRadius});
  const solver::SoftOptions defaults;
  for (int step = 0; step < 200; ++step) {
    const StepReport r = world.advance(world.settings().dt);
    ASSERT_EQ(r.substeps, defaults.substeps);
    ASSERT_EQ(r.solver_iterations, defaults.iterations + defaults.relax_iterations) << "step " << step;
    ASSERT_TRUE(r.converged) << "step " << step << ", residual " << r.residual;
  }
}

// Guards against: sweeps reported for a substep without contacts.
TEST(SoftReport, NoContactsNoSweeps) {
  World world;
  add_ground(world);
  add_sphere(world, kRadius, {0.0, 0.0, 10 * kRadius});
  const StepReport r = world.advance(world.settings().dt);
  EXPECT_EQ(r.solver_iterations, 0);
  EXPECT_TRUE(r.converged);
}

// Residual of the last step of a 6 x 6 x 4 simple cubic pile of touching spheres (about
// 300 points: one Gauss-Seidel group) after `steps`, with these sweep counts.
StepReport pile(int iterations, int relax_iterations, int steps) {
  World world({.soft = {.iterations = iterations, .relax_iterations = relax_iterations}});
  add_ground(world);
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y)
      for (int z = 0; z < 4; ++z) add_sphere(world, kRadius, kRadius * Eigen::Vector3d(2 * x, 2 * y, 2 * z + 1));
  StepReport r;
  for (int step = 0; step < steps; ++step) r = world.advance(world.settings().dt);
  return r;
}

// Gauss-Seidel in a pile does not settle in six sweeps a substep: the report must say so,
// and say less is left the more sweeps run.
// Guards against: a report that calls every soft step converged.
TEST(SoftReport, APileSaysItIsNotSettledAndLessSoWithMoreSweeps) {
  const StepReport few = pile(4, 2, 20);
  const StepReport many = pile(40, 20, 20);
  std::cout << "pile, step 20: residual " << few.residual << " after 6 sweeps, " << many.residual << " after 60\n";
  EXPECT_EQ(few.solver_iterations, 6);
  EXPECT_EQ(many.solver_iterations, 60);
  EXPECT_FALSE(few.converged);
  EXPECT_GT(few.residual, 1e-6);
  EXPECT_LT(many.residual, few.residual / 10);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
