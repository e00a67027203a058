#include "rigidbody/dynamics/invariants.hpp"

namespace cosim::rigidbody::dynamics {
namespace {

double mass(const BodyInertia& body) { return body.is_fixed() ? 0.0 : 1.0 / body.inverse_mass; }

}  // namespace

Eigen::Vector3d spin_angular_momentum(const BodyState& state, const BodyInertia& body) {
  if (body.is_fixed() || !body.rotates) return Eigen::Vector3d::Zero();
  const Eigen::Matrix3d r = state.orientation.toRotationMatrix();
  return r * (body.inertia_body() * (r.transpose() * state.angular_velocity));
}

double kinetic_energy(const BodyState& state, const BodyInertia& body) {
  return 0.5 *
         (mass(body) * state.velocity.squaredNorm() + state.angular_velocity.dot(spin_angular_momentum(state, body)));
}

double kinetic_energy(std::span<const BodyState> states, std::span<const BodyInertia> inertia) {
  double e = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) e += kinetic_energy(states[i], inertia[i]);
  return e;
}

Eigen::Vector3d linear_momentum(std::span<const BodyState> states, std::span<const BodyInertia> inertia) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < states.size(); ++i) p += mass(inertia[i]) * states[i].velocity;
  return p;
}

Eigen::Vector3d angular_momentum(std::span<const BodyState> states, std::span<const BodyInertia> inertia,
                                 const Eigen::Vector3d& point) {
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < states.size(); ++i)
    l += (states[i].position - point).cross(mass(inertia[i]) * states[i].velocity) +
         spin_angular_momentum(states[i], inertia[i]);
  return l;
}

}  // namespace cosim::rigidbody::dynamics
