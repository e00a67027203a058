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

// Inverse mass, so a fixed body is simply zero and needs no special case. The inertia is
// held as its principal moments and axes, 56 bytes where the body-frame tensor and its
// inverse took 144: a world holds one per body (bench/rigidbody_granular/README.md "Where
// the memory goes"), and every tensor a caller needs follows from them.
struct BodyInertia {
  // Principal frame -> body frame: the identity for every analytic shape, whose body axes
  // are principal; a turn for a tensor that is not diagonal (a hull's, a mesh's).
  Eigen::Quaterniond principal_axes = Eigen::Quaterniond::Identity();
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Zero();  // about the COM; all zero: fixed
  double inverse_mass = 0.0;
  // Mean density mass / volume. Only buoyancy needs it: -rho_f V g = -(rho_f / density) m g,
  // written as a ratio so that equal densities cancel gravity exactly.
  double density = 0.0;
  bool rotates = true;  // false: translation only (angular velocity stays as it is)

  static BodyInertia fixed() { return {}; }
  // A diagonal tensor keeps its entries as the moments, bit for bit; any other is
  // diagonalised once here.
  static BodyInertia of(double mass, const Eigen::Matrix3d& inertia_body, bool rotates = true);
  bool is_fixed() const { return inverse_mass == 0.0; }
  // Principal frame -> world frame for the body at orientation q.
  Eigen::Quaterniond principal_frame(const Eigen::Quaterniond& q) const { return q * principal_axes; }
  // The tensor about the COM in the body frame, A diag(moments) A^T.
  Eigen::Matrix3d inertia_body() const;
  // I^-1 in the world frame at orientation q, R diag(1 / moments) R^T with R the principal
  // frame's; zero for a fixed body or one that does not rotate.
  Eigen::Matrix3d inverse_inertia_world(const Eigen::Quaterniond& q) const;
};

// Force and torque on a body (world frame, torque about the centre of mass).
struct Wrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

}  // namespace cosim::rigidbody::dynamics
