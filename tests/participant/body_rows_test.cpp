// A body's rows of the Poses and Forces arrays: the wire order of docs/protocol.md
// (position, quaternion w x y z, velocity, angular velocity; force, torque), both ways.
#include <gtest/gtest.h>

#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::participant {
namespace {

TEST(BodyRows, PosesAndForcesInTheWireOrder) {
  std::vector<double> poses{};
  append(poses, PoseRow{});
  const PoseRow b{{1, 2, 3}, Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5), {4, 5, 6}, {7, 8, 9}};
  append(poses, b);
  ASSERT_EQ(poses.size(), 2 * protocol::kPoseWidth);
  const std::vector<double> second(poses.begin() + protocol::kPoseWidth, poses.end());
  EXPECT_EQ(second, (std::vector<double>{1, 2, 3, 0.5, 0.5, -0.5, 0.5, 4, 5, 6, 7, 8, 9}));
  const PoseRow back = pose_row(poses, 1);
  EXPECT_EQ(back.position, b.position);
  EXPECT_EQ(back.orientation.coeffs(), b.orientation.coeffs());
  EXPECT_EQ(back.velocity, b.velocity);
  EXPECT_EQ(back.angular_velocity, b.angular_velocity);
  EXPECT_EQ(pose_row(poses, 0).orientation.w(), 1.0);

  std::vector<double> forces;
  append(forces, ForceRow{{1, 2, 3}, {4, 5, 6}});
  append(forces, ForceRow{{-1, -2, -3}, {-4, -5, -6}});
  ASSERT_EQ(forces.size(), 2 * protocol::kForceWidth);
  EXPECT_EQ(forces[protocol::kForceWidth + 3], -4.0);
  EXPECT_EQ(force_row(forces, 1).force, Eigen::Vector3d(-1, -2, -3));
  EXPECT_EQ(force_row(forces, 0).torque, Eigen::Vector3d(4, 5, 6));
}

}  // namespace
}  // namespace cosim::participant
