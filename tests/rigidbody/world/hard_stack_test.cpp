// The hard resting cases stand for 10,000 steps with the default options
// (the soft step), within 1 % of the smallest body's size.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/rigidbody/world/hard_stack.hpp"

namespace cosim::rigidbody::world::test {
namespace {

class HardStacks : public ::testing::TestWithParam<std::size_t> {};

// Guards against: a heavy or large body on a light or small one (or a frictional pyramid,
// or a tall tower) sinking, sliding or collapsing with the default solver settings.
TEST_P(HardStacks, StandAtRestWithTheDefaultOptions) {
  const HardStack& stack = hard_stacks()[GetParam()];
  World world;
  stack.build(world);
  const StackExtremes e = run_at_rest(world, 10000);
  std::cout << stack.name << ": drift " << e.drift << " m, penetration " << e.penetration << " m (bound "
            << 0.01 * stack.smallest_size << " m)\n";
  EXPECT_LT(e.drift, 0.01 * stack.smallest_size) << stack.name;
  EXPECT_LT(e.penetration, 0.01 * stack.smallest_size) << stack.name;
}

INSTANTIATE_TEST_SUITE_P(HardCases, HardStacks, ::testing::Range<std::size_t>(0, hard_stacks().size()),
                         [](const auto& info) { return hard_stacks()[info.param].id; });

}  // namespace
}  // namespace cosim::rigidbody::world::test
