#pragma once
// A body as the fluid sees it: shape and pose from geometry, and the rigid
// velocity the fictitious boundary method imposes inside it.
#include <Eigen/Core>

#include "geometry/pose.hpp"
#include "geometry/shape.hpp"

namespace cosim::fluid::bodies {

struct RigidBody {
  geometry::Shape shape;
  geometry::Pose pose;  // position = centre of mass (shapes are centred there)
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // world frame

  Eigen::Vector3d velocity_at(const Eigen::Vector3d& x) const {
    return velocity + angular_velocity.cross(x - pose.position());
  }
};

}  // namespace cosim::fluid::bodies
