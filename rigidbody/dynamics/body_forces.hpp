// What acts on a body besides contacts: the coupler's wrench and the optional body forces.
#pragma once

#include <Eigen/Core>

#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::dynamics {

// The coupler's wrench on one body over a coupling window [t0, t1]: linearly interpolated
// between the window's start and end values; held constant when they are equal.
struct WindowWrench {
  Wrench start;
  Wrench end;

  Wrench at(double t0, double t1, double s) const;
};

// Uniform body forces, switched on by the scene's effects. Buoyancy is the hydrostatic part
// only (the fluid solver's wrench carries the rest) and acts at the centre of mass, which is
// the centre of buoyancy of a uniform-density body, so neither force makes a torque.
struct BodyForces {
  bool gravity = false;
  bool buoyancy = false;
  Eigen::Vector3d g = Eigen::Vector3d(0.0, 0.0, -9.81);
  double fluid_density = 0.0;

  // Acceleration of the centre of mass: g (gravity) - (rho_f / rho_body) g (buoyancy), times
  // the share of the mass they act on (InLiquid::own_mass_fraction; 1 out of a liquid).
  // Throws std::invalid_argument for buoyancy on a body without a positive density.
  Eigen::Vector3d acceleration(const BodyInertia& body, double own_mass_fraction = 1.0) const;
};

}  // namespace cosim::rigidbody::dynamics
