// Random scenes, many seeds: the grid finds exactly the brute-force pairs.
#include <gtest/gtest.h>

#include "tests/rigidbody/broadphase/expect_pairs.hpp"
#include "tests/rigidbody/broadphase/scenes.hpp"

namespace cosim::rigidbody::broadphase {
namespace {

using testing::expect_brute_force_pairs;

constexpr std::uint32_t kSeeds = 30;
constexpr std::size_t kObjects = 600;

// Radii over three orders of magnitude, the box straddling the origin.
std::vector<Object> mixed(std::uint32_t seed) { return scenes::uniform(kObjects, {-3.0, 2.0}, 1e-3, 1.0, seed); }

TEST(HashGridScenes, MixedSizesUniform) {
  std::size_t pairs = 0;
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    pairs += expect_brute_force_pairs(mixed(seed));
  }
  EXPECT_GT(pairs, kSeeds * kObjects);
}

TEST(HashGridScenes, MixedSizesClustered) {
  std::size_t pairs = 0;
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    pairs += expect_brute_force_pairs(scenes::clustered(kObjects, 4, 0.3, {-10.0, -5.0}, 1e-3, 1.0, seed));
  }
  EXPECT_GT(pairs, kSeeds * kObjects);
}

TEST(HashGridScenes, WithMargin) {
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    expect_brute_force_pairs(mixed(seed), {.margin = 0.05});
  }
}

// Cell coordinates near 5e8, where rounding is largest, and beyond the 2^30 clamp.
TEST(HashGridScenes, FarFromTheOrigin) {
  std::size_t pairs = 0;
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    pairs += expect_brute_force_pairs(scenes::uniform(kObjects, {1e6, 1e6 + 0.1}, 1e-3, 1e-2, seed));
    expect_brute_force_pairs(scenes::uniform(kObjects, {-1e7 - 5.0, -1e7}, 1e-3, 1.0, seed));
  }
  EXPECT_GT(pairs, kSeeds * kObjects / 2);
}

TEST(HashGridScenes, SomeObjectsFixed) {
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Object> objects = mixed(seed);
    for (std::size_t i = 0; i < objects.size(); i += 2) objects[i].fixed = true;
    expect_brute_force_pairs(objects);
  }
}

TEST(HashGridScenes, OtherLevelFactorsAndBaseSizes) {
  const std::vector<HashGridConfig> configs = {{.level_factor = 3.0},
                                               {.level_factor = 1.5, .safety = 1.2},
                                               {.base_cell_size = 1e-4},  // below every object: level 0 stays empty
                                               {.base_cell_size = 5.0},   // above every object: one level
                                               {.margin = 0.01, .base_cell_size = 0.1, .level_factor = 4.0}};
  for (std::uint32_t seed = 0; seed < 5; ++seed) {
    for (const HashGridConfig& config : configs) {
      SCOPED_TRACE(seed);
      expect_brute_force_pairs(mixed(seed), config);
    }
  }
}

TEST(HashGridScenes, GranularPacking) {
  for (std::uint32_t seed = 0; seed < 5; ++seed) {
    SCOPED_TRACE(seed);
    EXPECT_GT(expect_brute_force_pairs(scenes::packed(1000, 0.55, seed)), 1000u);
    expect_brute_force_pairs(scenes::polydisperse(1000, 0.5, 10.0, seed), {.margin = 0.1});
  }
}

TEST(HashGridScenes, Walls) {
  for (std::uint32_t seed = 0; seed < kSeeds; ++seed) {
    SCOPED_TRACE(seed);
    std::vector<Object> objects = mixed(seed);
    const auto next = static_cast<Id>(objects.size());
    objects.push_back({.id = next, .fixed = true, .infinite = true, .half_space = HalfSpace{{0.0, 0.0, 1.0}, -2.5}});
    objects.push_back(
        {.id = next + 1, .fixed = true, .infinite = true, .half_space = HalfSpace{{-1.0, 1.0, 0.5}, 0.3}});
    objects.push_back({.id = next + 2, .infinite = true});
    objects[seed].fixed = true;
    expect_brute_force_pairs(objects, {.margin = 0.02});
  }
}

}  // namespace
}  // namespace cosim::rigidbody::broadphase
