// Hand-made scenes at the edges of the grid's reasoning: empty and tiny scenes, exact
// contact across cell boundaries, coincident centres, crowded cells, huge size ratios.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "tests/rigidbody/broadphase/expect_pairs.hpp"
#include "rigidbody/broadphase/brute_force.hpp"
#include "tests/rigidbody/broadphase/scenes.hpp"

namespace cosim::rigidbody::broadphase {
namespace {

using testing::expect_brute_force_pairs;

Object sphere(Id id, const Eigen::Vector3d& centre, double r) { return {.id = id, .centre = centre, .radius = r}; }

TEST(HashGridEdges, NoObjectsNoPairs) { EXPECT_EQ(expect_brute_force_pairs({}), 0u); }

TEST(HashGridEdges, ASingleObjectPairsOnlyWithWalls) {
  const std::vector<Object> alone = {sphere(4, {1.0, 2.0, 3.0}, 0.5)};
  EXPECT_EQ(expect_brute_force_pairs(alone), 0u);
  std::vector<Object> walled = alone;
  walled.push_back({.id = 1, .infinite = true});
  walled.push_back({.id = 9, .infinite = true, .half_space = HalfSpace{{0, 0, 1}, 2.5}});
  EXPECT_EQ(expect_brute_force_pairs(walled), 2u);
}

TEST(HashGridEdges, WallsAloneNeverPair) {
  const std::vector<Object> walls = {{.id = 0, .infinite = true}, {.id = 1, .infinite = true}};
  EXPECT_EQ(expect_brute_force_pairs(walls), 0u);
}

// Spheres of radius 1/4 on a lattice of spacing 1/2, with level-0 cells 1 wide: every
// centre lies on a cell boundary in some axis and every lattice neighbour touches exactly.
// Guards against: an exactly touching pair being missed when the centres sit on cell boundaries.
TEST(HashGridEdges, TouchingAcrossCellBoundaries) {
  std::vector<Object> objects;
  for (int x = -4; x <= 4; ++x)
    for (int y = -4; y <= 4; ++y)
      for (int z = -4; z <= 4; ++z)
        objects.push_back(sphere(static_cast<Id>(objects.size()), 0.5 * Eigen::Vector3d(x, y, z), 0.25));
  EXPECT_EQ(expect_brute_force_pairs(objects, {.base_cell_size = 1.0}), 3u * 8 * 81);
}

// A random walk of exactly touching spheres: radii and steps are powers of two, so every
// centre and distance is exact in floating point and each neighbour pair touches exactly.
std::vector<Object> touching_chain(std::uint32_t seed, double origin) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> exponent(-6, 0);
  std::uniform_int_distribution<int> axis(0, 2);
  std::vector<Object> objects;
  Eigen::Vector3d centre = Eigen::Vector3d::Constant(origin);
  double radius = 0.5;
  for (Id id = 0; id < 300; ++id) {
    objects.push_back(sphere(id, centre, radius));
    const double next = std::ldexp(1.0, exponent(rng));
    centre[axis(rng)] += (id % 3 == 0 ? -1.0 : 1.0) * (radius + next);
    radius = next;
  }
  return objects;
}

// Guards against: exactly touching pairs far from the origin being lost to round-off.
TEST(HashGridEdges, ExactlyTouchingChains) {
  for (std::uint32_t seed = 0; seed < 20; ++seed) {
    SCOPED_TRACE(seed);
    EXPECT_GE(expect_brute_force_pairs(touching_chain(seed, 0.0)), 299u);
    EXPECT_GE(expect_brute_force_pairs(touching_chain(seed, 0.0), {.base_cell_size = 0.5}), 299u);
    EXPECT_GE(expect_brute_force_pairs(touching_chain(seed, -1048576.0)), 299u);
  }
}

// Guards against: objects with coincident centres not pairing (a degenerate distance).
TEST(HashGridEdges, CoincidentCentresAllPair) {
  std::vector<Object> objects;
  for (Id id = 0; id < 50; ++id) {
    objects.push_back(sphere(id, {-1.0, 0.5, 2.0}, id % 5 == 0 ? 0.0 : 0.01 * id));
  }
  EXPECT_EQ(expect_brute_force_pairs(objects), 50u * 49 / 2);
}

TEST(HashGridEdges, PointsPairOnlyWhereTheyCoincide) {
  std::vector<Object> objects;
  for (Id id = 0; id < 60; ++id) {
    const double step = id % 20;
    objects.push_back(sphere(id, {step, -0.5 * step, 3.0}, 0.0));
  }
  EXPECT_EQ(expect_brute_force_pairs(objects), 20u * 3);
}

TEST(HashGridEdges, AllObjectsInOneCell) {
  const std::vector<Object> crowd = scenes::uniform(400, {0.2, 0.3}, 0.002, 0.01, 1);
  EXPECT_GT(expect_brute_force_pairs(crowd, {.base_cell_size = 1.0}), 100u);
  const std::vector<Object> heap = scenes::uniform(100, {0.0, 0.5}, 1.0, 1.0, 2);
  EXPECT_EQ(expect_brute_force_pairs(heap), 100u * 99 / 2);
}

// Guards against: a huge size ratio putting small objects on a level that misses the large one.
TEST(HashGridEdges, HugeAndTinyTogether) {
  std::vector<Object> objects = scenes::uniform(500, {-20.0, 20.0}, 1e-3, 1e-2, 3);
  objects.push_back(sphere(1000, {0.0, 0.0, 0.0}, 10.0));
  objects.push_back(sphere(1001, {15.0, 15.0, 15.0}, 1e3));
  EXPECT_GT(expect_brute_force_pairs(objects), 500u);
}

TEST(HashGridEdges, UpdateReplacesThePreviousScene) {
  HashGrid grid;
  grid.update(scenes::uniform(2000, {0.0, 3.0}, 1e-3, 1.0, 4));
  const std::vector<Object> next = scenes::uniform(50, {0.0, 1.0}, 0.1, 0.2, 5);
  grid.update(next);
  std::vector<Pair> pairs;
  grid.find_pairs(pairs);
  std::sort(pairs.begin(), pairs.end());
  EXPECT_EQ(pairs, brute_force_pairs(next, 0.0));
}

TEST(HashGridEdges, AllFixedNothingPairs) {
  std::vector<Object> objects = scenes::uniform(200, {0.0, 1.0}, 0.05, 0.2, 6);
  for (Object& o : objects) o.fixed = true;
  objects.push_back({.id = 500, .fixed = true, .infinite = true});
  EXPECT_EQ(expect_brute_force_pairs(objects), 0u);
}

}  // namespace
}  // namespace cosim::rigidbody::broadphase
