#include "rigidbody/dynamics/leapfrog.hpp"

#include "rigidbody/dynamics/rotation.hpp"

namespace cosim::rigidbody::dynamics {
namespace {

Eigen::Vector3d world_angular_momentum(const BodyState& state, const BodyInertia& body) {
  const Eigen::Matrix3d r = state.orientation.toRotationMatrix();
  return r * (body.inertia_body() * (r.transpose() * state.angular_velocity));
}

}  // namespace

void leapfrog_velocity(BodyState& state, const BodyInertia& body, const Wrench& wrench,
                       const Eigen::Vector3d& acceleration, double h) {
  state.velocity += h * (acceleration + body.inverse_mass * wrench.force);
  // The torque changes L, not omega: at fixed orientation that is omega += h I^-1 tau.
  if (body.rotates && !wrench.torque.isZero(0.0))
    state.angular_velocity += h * (body.inverse_inertia_world(state.orientation) * wrench.torque);
}

void leapfrog_position(BodyState& state, const BodyState& start, const BodyInertia& body, double h) {
  state.position += 0.5 * h * (start.velocity + state.velocity);
  if (!body.rotates || (start.angular_velocity.isZero(0.0) && state.angular_velocity.isZero(0.0))) return;
  // Momenta at the start orientation: the velocity phase (and a contact solve) changed
  // omega at fixed orientation.
  const Eigen::Vector3d l_end = world_angular_momentum(state, body);
  const Eigen::Vector3d l_mean = 0.5 * (world_angular_momentum(start, body) + l_end);
  state.orientation = free_rotation(start.orientation, body.inertia_body(), l_mean, h);
  state.angular_velocity = body.inverse_inertia_world(state.orientation) * l_end;
}

}  // namespace cosim::rigidbody::dynamics
