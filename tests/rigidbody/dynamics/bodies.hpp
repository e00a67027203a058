// Bodies and runs shared by the dynamics tests.
#pragma once

#include "rigidbody/dynamics/integrator.hpp"

namespace cosim::rigidbody::dynamics::test {

// A uniform box of density 1000 with the given half extents; its principal axes are the
// body axes, with moments ordered as the squared extents say.
BodyInertia box_body(const Eigen::Vector3d& half_extents, bool rotates = true);

// One body from 0 to t_end in steps of dt with nothing but `forces`.
BodyState run(BodyState state, const BodyInertia& body, Scheme scheme, double dt, double t_end,
              const BodyForces& forces = {});

// Angle of the rotation between two orientations.
double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

}  // namespace cosim::rigidbody::dynamics::test
