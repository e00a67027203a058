// The fluid's response, used by the bodies it holds: the added-mass partitioned scheme
// (Banks, Henshaw, Schwendeman & Tang, J. Comput. Phys. 343 (2017)) for two programs that
// meet once a window.
//
// A fluid that holds the bodies sends with its window-mean forces a ResponseRow per body
// (coupler/participant/body_rows.hpp): the added mass A and added damping B, and the load
// `hold` the next window brings if the body keeps the velocity v0 it has. Over that window
// the body then moves as if the fluid's load followed its motion at once,
//   F = hold - A a - B (v - v0),
// a its acceleration and v its mean velocity over the window: it carries A as added inertia
// and B as damping (dynamics::AddedInertia, integrated implicitly, contacts included) and
// gets the wrench hold + B v0. A load lagging a window behind the motion that causes it then
// cannot feed back on itself, whatever the body's mass. It carries the tensors in a simpler
// form: the largest eigenvalue of each translational block, each rotational block whole
// (its negative part dropped), the cross blocks left out.
//
// Under an implicit scheme a window is repeated with the fluid's load F_i of the previous
// iteration, computed for the motion the body made in it (acceleration a_i, mean velocity
// v_i): then F = F_i - A (a - a_i) - B (v - v_i), the wrench F_i + A a_i + B v_i, so the
// iterations converge to the coupled motion (the terms cancel there), each one a step with
// the fluid's own Jacobian.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <span>
#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "coupler/participant/solver.hpp"
#include "rigidbody/dynamics/added_inertia.hpp"
#include "rigidbody/dynamics/body_forces.hpp"

namespace cosim::program {

using Vector6d = Eigen::Matrix<double, 6, 1>;

class FluidResponse {
 public:
  // What the bodies carry over window w, one per body.
  struct Carried {
    std::vector<dynamics::AddedInertia> added;
    std::vector<dynamics::WindowWrench> wrenches;
  };
  // From the fluid's forces and responses and the bodies' velocities at the window's start
  // (linear, then angular).
  Carried prepare(const participant::Window& w, std::span<const participant::ForceRow> forces,
                  std::span<const participant::ResponseRow> responses, std::span<const Vector6d> start);
  // The bodies' velocities at the end of the window just run, which a repetition of it
  // refers to.
  void finish(std::span<const Vector6d> end);

 private:
  // The last window run: its index, length and the bodies' velocities at its start and end.
  // A rollback to the window's start keeps it; a new window replaces it.
  struct Trial {
    std::uint64_t window = 0;
    double length = 0;
    std::vector<Vector6d> start, end;
  };
  std::optional<Trial> trial_;
};

}  // namespace cosim::program
