// World AABBs contain the shape for random poses and touch it on all six sides.
#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"

namespace cosim::geometry {
namespace {

TEST(WorldAabb, ContainsTheSurfaceAndIsTight) {
  std::mt19937 rng(16);
  for (const auto& [label, shape] : testing::bounded_shapes()) {
    SCOPED_TRACE(label);
    const auto surface = testing::surface_samples(shape, 1000, rng);
    for (int i = 0; i < 20; ++i) {
      const Pose pose = testing::random_pose(rng);
      const Aabb box = world_aabb(shape, pose);
      for (const auto& x : surface) EXPECT_TRUE(box.contains(pose.to_world(x), 1e-12));
      // Tight: the shape reaches every side (its support point along +-e_a is on it).
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(support(shape, pose, Eigen::Vector3d::Unit(a))[a], box.max[a], 1e-12);
        EXPECT_NEAR(support(shape, pose, -Eigen::Vector3d::Unit(a))[a], box.min[a], 1e-12);
      }
    }
  }
}

TEST(WorldAabb, BoundingRadiusEnclosesTheSurface) {
  std::mt19937 rng(17);
  for (const auto& [label, shape] : testing::bounded_shapes()) {
    double farthest = 0.0;
    for (const auto& x : testing::surface_samples(shape, 2000, rng)) farthest = std::max(farthest, x.norm());
    EXPECT_LE(farthest, bounding_radius(shape) + 1e-12) << label;
    EXPECT_GT(farthest, 0.9 * bounding_radius(shape)) << label;
  }
}

TEST(WorldAabb, HalfSpaceIsCutOnlyAlongAnAxisNormal) {
  const HalfSpace floor({0, 0, 1});
  const Aabb box = floor.world_aabb(Pose({0, 0, -2}, Eigen::Quaterniond::Identity()));
  EXPECT_EQ(box.max.z(), -2.0);
  EXPECT_TRUE(std::isinf(box.min.z()) && std::isinf(box.max.x()) && std::isinf(box.min.y()));
  const Aabb tilted = HalfSpace({0, 1, 1}).world_aabb(Pose());
  EXPECT_FALSE(tilted.is_bounded());
  EXPECT_TRUE(std::isinf(tilted.max.z()));
}

}  // namespace
}  // namespace cosim::geometry
