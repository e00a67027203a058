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

// What a body moving with the liquid has that a body in none does without (Substeps takes
// none then); held apart from BodyInertia, which every body of a world has.
struct InLiquid {
  // Gravity and buoyancy act on the body's own mass, this share of the mass it moves with:
  // m / (m + added mass).
  double own_mass_fraction = 1.0;
  // The liquid's resistance to the body's velocity, F = -damping v and, in the body frame,
  // T = -rotational_damping omega; integrated implicitly (Substeps).
  double damping = 0.0;
  Eigen::Matrix3d rotational_damping = Eigen::Matrix3d::Zero();
};

struct WithLiquid {
  BodyInertia inertia;
  InLiquid liquid;
};

// The body as it moves with the liquid: mass m + added mass, inertia I + added inertia
// (turned into the body frame at orientation q), and the damping; gravity and buoyancy act
// on m alone (own_mass_fraction). A fixed body stays fixed.
WithLiquid with_added(const BodyInertia& body, const AddedInertia& added, const Eigen::Quaterniond& q);

}  // namespace cosim::rigidbody::dynamics
