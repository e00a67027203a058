#pragma once

#include <Eigen/Geometry>

namespace cosim::geometry {

// Where a body frame sits in the world: x_world = R x_body + position. The orientation is
// kept unit length so that to_body can use the conjugate as the inverse.
class Pose {
 public:
  Pose() = default;
  Pose(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation)
      : position_(position), orientation_(orientation.normalized()) {}

  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Quaterniond& orientation() const { return orientation_; }
  Eigen::Matrix3d rotation() const { return orientation_.toRotationMatrix(); }

  void set_position(const Eigen::Vector3d& p) { position_ = p; }
  void set_orientation(const Eigen::Quaterniond& q) { orientation_ = q.normalized(); }

  Eigen::Vector3d to_world(const Eigen::Vector3d& p_body) const { return orientation_ * p_body + position_; }
  Eigen::Vector3d to_body(const Eigen::Vector3d& p_world) const {
    return orientation_.conjugate() * (p_world - position_);
  }
  // Directions (normals, forces, support directions) rotate but do not translate.
  Eigen::Vector3d direction_to_world(const Eigen::Vector3d& d_body) const { return orientation_ * d_body; }
  Eigen::Vector3d direction_to_body(const Eigen::Vector3d& d_world) const { return orientation_.conjugate() * d_world; }

 private:
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation_ = Eigen::Quaterniond::Identity();
};

}  // namespace cosim::geometry
