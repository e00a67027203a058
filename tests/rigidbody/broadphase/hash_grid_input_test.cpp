// Configurations and objects the grid refuses.
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "rigidbody/broadphase/hash_grid.hpp"

namespace cosim::rigidbody::broadphase {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(HashGridInput, RefusesBadConfigurations) {
  const std::vector<HashGridConfig> bad = {{.margin = -1.0},         {.margin = kNaN},      {.base_cell_size = -1.0},
                                           {.base_cell_size = kInf}, {.level_factor = 1.0}, {.level_factor = kNaN},
                                           {.safety = 1.0},          {.safety = kInf}};
  for (const HashGridConfig& config : bad) {
    EXPECT_THROW(HashGrid{config}, std::invalid_argument);
  }
}

TEST(HashGridInput, RefusesBadObjects) {
  const std::vector<Object> bad = {{.radius = -1.0},
                                   {.radius = kNaN},
                                   {.radius = kInf},
                                   {.centre = {0.0, kNaN, 0.0}},
                                   {.infinite = true, .half_space = HalfSpace{{0.0, 0.0, 0.0}, 1.0}},
                                   {.infinite = true, .half_space = HalfSpace{{0.0, 1.0, 0.0}, kInf}}};
  HashGrid grid;
  for (const Object& o : bad) {
    EXPECT_THROW(grid.update(std::span(&o, 1)), std::invalid_argument);
  }
}

TEST(HashGridInput, IgnoresTheSphereOfAnInfiniteObject) {
  const Object wall{.centre = {kNaN, 0.0, 0.0}, .radius = -1.0, .infinite = true};
  HashGrid grid;
  EXPECT_NO_THROW(grid.update(std::span(&wall, 1)));
}

}  // namespace
}  // namespace cosim::rigidbody::broadphase
