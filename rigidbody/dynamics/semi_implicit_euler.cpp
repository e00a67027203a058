#include "rigidbody/dynamics/semi_implicit_euler.hpp"

#include <Eigen/LU>

#include "rigidbody/dynamics/rotation.hpp"

namespace cosim::rigidbody::dynamics {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

// Change of the world angular velocity from the gyroscopic term over h, in the principal
// frame p (principal -> world), where the inertia is diag(moments). Returned as a
// difference so that a body without one (isotropic, or spinning about a principal axis)
// keeps its angular velocity bit for bit.
Eigen::Vector3d gyroscopic_change(const Eigen::Quaterniond& p, const Eigen::Vector3d& omega,
                                  const Eigen::Vector3d& moments, double h) {
  const Eigen::Vector3d w = p.conjugate() * omega;
  const Eigen::Vector3d iw = moments.cwiseProduct(w);
  const Eigen::Vector3d residual = h * w.cross(iw);
  if (residual.isZero(0.0)) return Eigen::Vector3d::Zero();
  const Eigen::Matrix3d inertia = moments.asDiagonal();
  const Eigen::Matrix3d jacobian = inertia + h * (skew(w) * inertia - skew(iw));
  return p * Eigen::Vector3d(-jacobian.partialPivLu().solve(residual));
}

}  // namespace

void semi_implicit_velocity(BodyState& state, const BodyInertia& body, const Wrench& wrench,
                            const Eigen::Vector3d& acceleration, double h) {
  state.velocity += h * (acceleration + body.inverse_mass * wrench.force);
  if (!body.rotates) return;
  const Eigen::Vector3d gyro =
      gyroscopic_change(body.principal_frame(state.orientation), state.angular_velocity, body.principal_moments, h);
  state.angular_velocity += gyro;
  if (!wrench.torque.isZero(0.0))
    state.angular_velocity += h * (body.inverse_inertia_world(state.orientation) * wrench.torque);
}

void semi_implicit_position(BodyState& state, const BodyInertia& body, double h) {
  state.position += h * state.velocity;
  if (body.rotates) state.orientation = rotate_world(state.orientation, h * state.angular_velocity);
}

}  // namespace cosim::rigidbody::dynamics
