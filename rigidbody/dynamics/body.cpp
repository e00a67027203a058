#include "rigidbody/dynamics/body.hpp"

#include <Eigen/LU>

namespace cosim::rigidbody::dynamics {

BodyInertia BodyInertia::of(double mass, const Eigen::Matrix3d& inertia_body, bool rotates) {
  BodyInertia b;
  b.inverse_mass = 1.0 / mass;
  b.inertia_body = inertia_body;
  b.inverse_inertia_body = rotates ? Eigen::Matrix3d(inertia_body.inverse()) : Eigen::Matrix3d::Zero();
  b.rotates = rotates;
  return b;
}

Eigen::Matrix3d BodyInertia::inverse_inertia_world(const Eigen::Quaterniond& q) const {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  return r * inverse_inertia_body * r.transpose();
}

}  // namespace cosim::rigidbody::dynamics
