// What a surrounding liquid adds to a body's response, as the fluid that holds the body
// measures it: the inertia of the liquid the body must move with it (added mass and added
// moment of inertia) and the liquid's resistance to the body's velocity (added damping).
// Integrated with the body, implicitly, they are what keeps a light body stable under
// explicit coupling, where the fluid's force lags a window behind the motion that causes it
// (Banks, Henshaw, Schwendeman & Tang, J. Comput. Phys. 343 (2017), the added-mass
// partitioned scheme: the body's equations take the fluid's added-mass and added-damping
// tensors and stay stable for bodies of any mass without sub-iterations).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::dynamics {

struct AddedInertia {
  double mass = 0.0;                                             // kg, the same along every axis
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();             // kg m^2, world frame, about the centre of mass
  double damping = 0.0;                                          // N s / m
  Eigen::Matrix3d rotational_damping = Eigen::Matrix3d::Zero();  // N m s, world frame

  bool empty() const { return mass == 0.0 && damping == 0.0 && inertia.isZero(0.0) && rotational_damping.isZero(0.0); }
};

// The body as it moves with the liquid: mass m + added mass, inertia I + added inertia
// (turned into the body frame at orientation q), and the damping; gravity and buoyancy act
// on m alone (own_mass_fraction). A fixed body stays fixed.
BodyInertia with_added(const BodyInertia& body, const AddedInertia& added, const Eigen::Quaterniond& q);

}  // namespace cosim::rigidbody::dynamics
