// Second-order scheme: leapfrog (kick-drift-kick, i.e. velocity Verlet) in momentum form,
// with the rotational drift done by the symplectic free-rigid-body splitting of Dullweber,
// Leimkuhler and McLachlan (J. Chem. Phys. 107, 5840, 1997; see rotation.hpp).
//
// The two half kicks are merged into one full kick with the wrench at the step's midpoint
// (midpoint rule: exact for the linearly interpolated coupler wrench), and the drift uses the
// mean of the start and end momenta, which is the half-kicked momentum of the Strang
// splitting. So a step reads like semi-implicit Euler (velocity phase, contact solve,
// position phase), but is second order: exact positions for a constant force, exact
// velocities for a linear ramp, world angular momentum conserved to rounding when there is
// no torque, bounded O(h^2) energy error.
#pragma once

#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::dynamics {

// v += h (a + F / m); L = I(q) omega += h tau, omega = I(q)^-1 L. `wrench` at t + h/2.
void leapfrog_velocity(BodyState& state, const BodyInertia& body, const Wrench& wrench,
                       const Eigen::Vector3d& acceleration, double h);

// x += h (v0 + v) / 2; the body turns freely with momentum (L0 + L) / 2, then
// omega = I(q_new)^-1 L. `start` is the state before leapfrog_velocity.
void leapfrog_position(BodyState& state, const BodyState& start, const BodyInertia& body, double h);

}  // namespace cosim::rigidbody::dynamics
