// Issue case 3: a stack of 10 boxes resting on the ground for the full 10,000 steps
// (about 1.3 s in Release; bench_box_stack prints the figures).
#include <gtest/gtest.h>

#include "tests/rigidbody/world/stack_check.hpp"

namespace cosim::rigidbody::world::test {
namespace {

// Guards against: a tall resting stack creeping sideways or exploding over a long run.
TEST(Stack, TenBoxesRestWithoutDriftOrExplosion) {
  const StackResult r = run_box_stack(kStackTestSteps);
  EXPECT_LT(r.horizontal_drift, 0.01 * r.box_size);
  EXPECT_LT(r.vertical_shift, 0.01 * r.box_size);
  // No explosion: the only motion is the cold start's first steps, where 50 iterations
  // leave a velocity error below one gravity kick g dt (measured 3.7e-3 m/s).
  EXPECT_LT(r.max_speed, 9.81 * 1e-3);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
