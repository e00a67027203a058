// Kinetic energy and momenta (world frame), for tests and run reports. Fixed bodies count
// for nothing; translation-only bodies only with their translation.
#pragma once

#include <span>

#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::dynamics {

double kinetic_energy(const BodyState& state, const BodyInertia& body);
double kinetic_energy(std::span<const BodyState> states, std::span<const BodyInertia> inertia);

// Sum of m v.
Eigen::Vector3d linear_momentum(std::span<const BodyState> states, std::span<const BodyInertia> inertia);

// I(q) omega: a body's angular momentum about its own centre of mass.
Eigen::Vector3d spin_angular_momentum(const BodyState& state, const BodyInertia& body);

// Sum of (x - point) x m v + I(q) omega: the total angular momentum about `point`.
Eigen::Vector3d angular_momentum(std::span<const BodyState> states, std::span<const BodyInertia> inertia,
                                 const Eigen::Vector3d& point = Eigen::Vector3d::Zero());

}  // namespace cosim::rigidbody::dynamics
