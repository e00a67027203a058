// Semi-implicit (symplectic) Euler: velocities from the forces at the start of the step, then
// positions and orientations with the new velocities. First order; the contact solvers'
// scheme, since the velocities they compute are the ones the positions then move with.
#pragma once

#include "rigidbody/dynamics/body.hpp"

namespace cosim::rigidbody::dynamics {

// v += h (a + F / m); omega gets the gyroscopic term implicitly, by one Newton step on
// I (w' - w) + h w' x I w' = 0 in the principal frame (E. Catto, "Numerical Methods", GDC 2015;
// Bullet's btRigidBody::computeGyroscopicImpulseImplicit_Body), then the torque explicitly.
// Explicit gyroscopic updates make fast-spinning asymmetric bodies gain energy; this one
// does not. `acceleration` is the body-force acceleration (gravity, buoyancy).
void semi_implicit_velocity(BodyState& state, const BodyInertia& body, const Wrench& wrench,
                            const Eigen::Vector3d& acceleration, double h);

// x += h v; q = exp(h omega) q, normalised.
void semi_implicit_position(BodyState& state, const BodyInertia& body, double h);

}  // namespace cosim::rigidbody::dynamics
