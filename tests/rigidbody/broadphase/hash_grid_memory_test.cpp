// The grid's memory follows the number of objects, never the extent of the domain.
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "rigidbody/broadphase/hash_grid.hpp"
#include "tests/rigidbody/broadphase/scenes.hpp"

namespace cosim::rigidbody::broadphase {
namespace {

TEST(HashGridMemory, TableSizeIsProportionalToTheObjectCount) {
  for (const std::size_t n : {1u, 7u, 1000u, 1024u, 1025u, 30000u}) {
    HashGrid grid;
    grid.update(scenes::uniform(n, {-1.0, 1.0}, 1e-3, 1.0, 0));
    EXPECT_GE(grid.table_size(), n);
    EXPECT_LT(grid.table_size(), 2 * n);
  }
}

TEST(HashGridMemory, SpreadingTheObjectsOverAHugeDomainCostsNothing) {
  const std::vector<Object> dense = scenes::uniform(20000, {0.0, 10.0}, 1e-3, 1.0, 1);
  std::vector<Object> spread = dense;
  for (Object& o : spread) o.centre *= 1e6;
  HashGrid a;
  HashGrid b;
  a.update(dense);
  b.update(spread);
  EXPECT_EQ(a.table_size(), b.table_size());
  EXPECT_EQ(a.memory_bytes(), b.memory_bytes());
}

TEST(HashGridMemory, BytesPerObjectAtOneHundredThousand) {
  constexpr std::size_t n = 100000;
  HashGrid grid;
  grid.update(scenes::packed(n, 0.55, 2));
  const double per_object = static_cast<double>(grid.memory_bytes()) / n;
  std::cout << "bytes per object at N = 1e5: " << per_object << "\n";
  RecordProperty("bytes_per_object", std::to_string(per_object));
  EXPECT_LE(per_object, 80.0);
}

TEST(HashGridMemory, LevelsOnlyWhereObjectsAre) {
  HashGrid grid;
  grid.update(scenes::packed(1000, 0.55, 3));
  EXPECT_EQ(grid.level_count(), 1u);
  // Spans from 2e-3 to 2 need levels 0..10 with factor 2.
  grid.update(scenes::uniform(5000, {0.0, 10.0}, 1e-3, 1.0, 3));
  EXPECT_GE(grid.level_count(), 10u);
  EXPECT_LE(grid.level_count(), 11u);
}

}  // namespace
}  // namespace cosim::rigidbody::broadphase
