// The reference itself, on scenes small enough to work out by hand.
#include "rigidbody/broadphase/brute_force.hpp"

#include <gtest/gtest.h>

namespace cosim::rigidbody::broadphase {
namespace {

Object sphere(Id id, double x, double r, bool fixed = false) {
  return {.id = id, .centre = {x, 0.0, 0.0}, .radius = r, .fixed = fixed};
}

Object wall(Id id, std::optional<HalfSpace> half_space, bool fixed = true) {
  return {.id = id, .fixed = fixed, .infinite = true, .half_space = half_space};
}

using Pairs = std::vector<Pair>;

TEST(BruteForce, TouchingSpheresPairAndSeparatedOnesOnlyWithinTheMargin) {
  const std::vector<Object> objects = {sphere(7, 0.0, 0.5), sphere(3, 1.0, 0.5), sphere(5, 2.25, 0.5)};
  EXPECT_EQ(brute_force_pairs(objects, 0.0), (Pairs{{3, 7}}));
  EXPECT_EQ(brute_force_pairs(objects, 0.25), (Pairs{{3, 5}, {3, 7}}));
}

TEST(BruteForce, TwoFixedObjectsNeverPair) {
  const std::vector<Object> objects = {sphere(0, 0.0, 1.0, true), sphere(1, 0.5, 1.0, true), sphere(2, 1.0, 1.0)};
  EXPECT_EQ(brute_force_pairs(objects, 0.0), (Pairs{{0, 2}, {1, 2}}));
}

TEST(BruteForce, PlainInfiniteObjectsPairWithEveryFiniteOneButNotWithEachOther) {
  const std::vector<Object> objects = {wall(9, std::nullopt, false), sphere(1, 100.0, 1.0), sphere(2, -100.0, 1.0),
                                       wall(0, std::nullopt, false)};
  EXPECT_EQ(brute_force_pairs(objects, 0.0), (Pairs{{0, 1}, {0, 2}, {1, 9}, {2, 9}}));
}

TEST(BruteForce, HalfSpacesPairWithSpheresTouchingOrInsideThem) {
  // Solid x <= 1, the normal deliberately not of unit length. The spheres are 10 apart in
  // y so that they do not pair with each other.
  const HalfSpace solid{{2.0, 0.0, 0.0}, 2.0};
  auto at = [](Id id, double x, double r, bool fixed = false) {
    Object o = sphere(id, x, r, fixed);
    o.centre.y() = 10.0 * id;
    return o;
  };
  const std::vector<Object> objects = {wall(0, solid), at(1, 1.5, 0.5), at(2, -7.0, 0.1), at(3, 2.0, 0.5),
                                       at(4, 1.0, 0.5, true)};
  EXPECT_EQ(brute_force_pairs(objects, 0.0), (Pairs{{0, 1}, {0, 2}}));
  EXPECT_EQ(brute_force_pairs(objects, 0.5), (Pairs{{0, 1}, {0, 2}, {0, 3}}));
}

}  // namespace
}  // namespace cosim::rigidbody::broadphase
