// A rigid body as the integrator and the contact solvers see it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cosim::rigidbody::dynamics {

struct BodyState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // of the centre of mass
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // world frame
};

// Inverse quantities, so a fixed body is simply zero everywhere and needs no special case.
struct BodyInertia {
  double inverse_mass = 0.0;
  Eigen::Matrix3d inertia_body = Eigen::Matrix3d::Zero();  // about the COM, body frame
  Eigen::Matrix3d inverse_inertia_body = Eigen::Matrix3d::Zero();
  bool rotates = true;  // false: translation only (angular velocity stays as it is)
  // Mean density mass / volume. Only buoyancy needs it: -rho_f V g = -(rho_f / density) m g,
  // written as a ratio so that equal densities cancel gravity exactly.
  double density = 0.0;
  // A body moving with a liquid's added inertia (added_inertia.hpp) has a larger mass than
  // gravity and buoyancy act on: their share of it, m / (m + added mass).
  double own_mass_fraction = 1.0;
  // The liquid's resistance to the body's velocity, F = -damping v and, in the body frame,
  // T = -rotational_damping omega; integrated implicitly (Substeps).
  double damping = 0.0;
  Eigen::Matrix3d rotational_damping = Eigen::Matrix3d::Zero();

  static BodyInertia fixed() { return {}; }
  static BodyInertia of(double mass, const Eigen::Matrix3d& inertia_body, bool rotates = true);
  bool is_fixed() const { return inverse_mass == 0.0; }
  // I^-1 in world frame for the given orientation (R I_b^-1 R^T).
  Eigen::Matrix3d inverse_inertia_world(const Eigen::Quaterniond& q) const;
};

// Force and torque on a body (world frame, torque about the centre of mass).
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

}  // namespace cosim::rigidbody::dynamics
