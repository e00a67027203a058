// A body's rows of the Poses and Forces arrays: the wire order of docs/protocol.md
// (position, quaternion w x y z, velocity, angular velocity; force, torque), both ways.
#include <gtest/gtest.h>

#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "coupler/protocol/message.hpp"

namespace cosim::participant {
namespace {

TEST(BodyRows, PosesAndForcesInTheWireOrder) {
  const PoseRow b{{1, 2, 3}, Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5), {4, 5, 6}, {7, 8, 9}};
  const std::vector<double> poses = values_of(std::vector<PoseRow>{PoseRow{}, b});
  ASSERT_EQ(poses.size(), 2 * protocol::kPoseWidth);
  const std::vector<double> second(poses.begin() + protocol::kPoseWidth, poses.end());
  EXPECT_EQ(second, (std::vector<double>{1, 2, 3, 0.5, 0.5, -0.5, 0.5, 4, 5, 6, 7, 8, 9}));
  const std::vector<PoseRow> back = pose_rows(poses);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].position, b.position);
  EXPECT_EQ(back[1].orientation.coeffs(), b.orientation.coeffs());
  EXPECT_EQ(back[1].velocity, b.velocity);
  EXPECT_EQ(back[1].angular_velocity, b.angular_velocity);
  EXPECT_EQ(back[0].orientation.w(), 1.0);

  const std::vector<double> forces =
      values_of(std::vector<ForceRow>{ForceRow{{1, 2, 3}, {4, 5, 6}}, ForceRow{{-1, -2, -3}, {-4, -5, -6}}});
  ASSERT_EQ(forces.size(), 2 * protocol::kForceWidth);
  EXPECT_EQ(forces[protocol::kForceWidth + 3], -4.0);
  const std::vector<ForceRow> rows = force_rows(forces);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].force, Eigen::Vector3d(-1, -2, -3));
  EXPECT_EQ(rows[0].torque, Eigen::Vector3d(4, 5, 6));
}

}  // namespace
}  // namespace cosim::participant
