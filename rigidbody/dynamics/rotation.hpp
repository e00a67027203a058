// Orientation updates shared by the integration schemes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace cosim::rigidbody::dynamics {

// Rotates q by the world-frame rotation vector theta (the exponential map, exact for a
// constant angular velocity over the step) and renormalises.
Eigen::Quaterniond rotate_world(const Eigen::Quaterniond& q, const Eigen::Vector3d& theta);

// Torque-free motion over time h of a body with constant world angular momentum L, by the
// Strang splitting of the kinetic energy into the three principal-axis terms, each an exact
// rotation about one principal axis (Dullweber, Leimkuhler, McLachlan, J. Chem. Phys. 107,
// 5840, 1997; Touma & Wisdom, Astron. J. 107, 1189, 1994). Symplectic, time-reversible,
// second order; L is conserved to rounding since every substep only rotates the body about
// an axis along which it holds L fixed. Returns the new, normalised orientation.
Eigen::Quaterniond free_rotation(const Eigen::Quaterniond& q, const Eigen::Matrix3d& inertia_body,
                                 const Eigen::Vector3d& angular_momentum, double h);

}  // namespace cosim::rigidbody::dynamics
