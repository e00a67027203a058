// Floods of warnings: each distinct one at most once a period, its repeats counted.
#include <gtest/gtest.h>

#include "coupler/run/warning_rate.hpp"

namespace cosim::run {
namespace {

using namespace std::chrono_literals;

TEST(WarningRate, EachWarningOnceAPeriodItsRepeatsCounted) {
  WarningRate rate(1s);
  const auto t0 = WarningRate::clock::time_point{} + 100s;
  EXPECT_EQ(rate.admit("refused a", t0), "refused a");
  EXPECT_EQ(rate.admit("refused b", t0 + 1ms), "refused b");  // another warning is not held
  for (int k = 2; k <= 501; ++k) EXPECT_FALSE(rate.admit("refused a", t0 + k * 1ms)) << k;
  EXPECT_EQ(rate.admit("refused a", t0 + 1s), "refused a (and 500 more times since it was last shown)");
  EXPECT_TRUE(rate.held_back().empty());
  EXPECT_FALSE(rate.admit("refused a", t0 + 1500ms));
  EXPECT_EQ(rate.held_back(), std::vector<std::string>{"refused a (1 more time since it was last shown)"});
  EXPECT_TRUE(rate.held_back().empty());
  EXPECT_EQ(rate.admit("refused a", t0 + 2s), "refused a");
}

}  // namespace
}  // namespace cosim::run
