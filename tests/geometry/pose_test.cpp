#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"

namespace cosim::geometry {
namespace {

TEST(Pose, PointsRoundTripAndDirectionsIgnoreTranslation) {
  std::mt19937 rng(1);
  for (int i = 0; i < 20; ++i) {
    const Pose pose = testing::random_pose(rng);
    const Eigen::Vector3d p = testing::random_in_ball(rng, 3.0);
    EXPECT_LT((pose.to_body(pose.to_world(p)) - p).norm(), 1e-14);
    EXPECT_LT((pose.to_world(p) - (pose.rotation() * p + pose.position())).norm(), 1e-14);
    EXPECT_LT((pose.direction_to_world(p) - pose.rotation() * p).norm(), 1e-14);
    EXPECT_LT((pose.direction_to_body(pose.direction_to_world(p)) - p).norm(), 1e-14);
  }
}

TEST(Pose, OrientationIsNormalised) {
  Pose pose({1, 2, 3}, Eigen::Quaterniond(2, 0, 0, 2));
  EXPECT_NEAR(pose.orientation().norm(), 1.0, 1e-15);
  pose.set_orientation(Eigen::Quaterniond(0, 0, 3, 0));
  EXPECT_NEAR(pose.orientation().norm(), 1.0, 1e-15);
  EXPECT_LT((pose.to_world({1, 0, 0}) - Eigen::Vector3d(0, 2, 3)).norm(), 1e-15);
}

}  // namespace
}  // namespace cosim::geometry
