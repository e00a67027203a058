// A force provider's response tensors (ResponseRow) as a rigid body takes them over a window:
// the added-mass partitioned scheme (Banks, Henshaw, Schwendeman & Tang, J. Comput. Phys. 343
// (2017)) between two programs that meet once a window (docs/coupling.md "Response tensors").
//
// Over a window the body moves as if the load followed its motion at once,
//   F = F_ref - A (a - a_ref) - B (v - v_ref),
// a its acceleration and v its mean velocity over the window, near a reference motion whose
// load F_ref is known: it carries A as added inertia and B as damping (integrated
// implicitly, contacts included), and gets the wrench F_ref + A a_ref + B v_ref, the load's
// Robin form. It carries the tensors in a simpler form (carried()): the largest eigenvalue of
// each translational block, each rotational block whole with its negative part dropped, the
// cross blocks left out; the wrench is formed with that same form, or a body in steady motion
// would not feel the load it has.
//
// The coupler forms the wrench (so that an implicit window iterates on it, with any
// accelerator, as on a fixed function); the pose provider applies it and carries the
// tensors.
#pragma once

#include <Eigen/Core>

#include "coupler/participant/body_rows.hpp"

namespace cosim::participant {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

struct Carried {
  Matrix6d added_mass = Matrix6d::Zero();     // block-diagonal: mass I, then the rotational block
  Matrix6d added_damping = Matrix6d::Zero();  // likewise
};
Carried carried(const ResponseRow& response);

// For a new window: the reference is the body keeping the velocity v0 (linear, then angular)
// it has at the window's start, whose load is the response's `hold`.
Vector6d robin_wrench(const ResponseRow& response, const Vector6d& v0);
// For a repeated window: the reference is the motion from v0 to v1 over the window's length w
// that the load F was computed for.
Vector6d robin_wrench(const ResponseRow& response, const ForceRow& load, const Vector6d& v0, const Vector6d& v1,
                      double w);

}  // namespace cosim::participant
