#pragma once
// How the load on a body changes, window by window, with the body's motion: what cosim-fluid
// sends with its forces (protocol::Tag::Responses), so that the rigid bodies move as if the
// load followed their motion at once (the added-mass partitioned scheme,
// rigidbody/program/fluid_response.hpp).
//
// The load is taken as linear in the changes of the motion: a change d_j of a body's
// velocity over window j (its rigid modes: linear, then angular), ramped over that window,
// changes the window-mean load of window j + n by -K_n d_j. The response kernel K_n (6 x 6,
// [force; torque] about the centre of mass against the modes) is measured, not modelled:
// the body alone, at rest in fluid at rest on a periodic box of the fluid grid's cells
// around it, is given a small change of each mode's velocity, ramped over one window and
// held after it, and the fluid runs kResponseWindows windows with its own steps, body
// treatment and fluid. So the kernel is this discretization's response at this window
// length: the inertia of the fluid the body moves, the drag the new velocity raises, and
// how both build up and decay over the following windows (with the immersed boundary the
// projection reaches the fluid around the body step by step, and the history force decays
// slowly: fluid/README.md "Response tensors"). Beyond the last window measured the load is
// held at its last value. Walls and other bodies near the body, which change it, are not in
// the kernel.
//
// Within a window the rigid bodies carry K_0 as an added mass A and an added damping B,
// K_0 = A / W + B / 2 for the ramp: B the steady drag's, the Stokes resistance of the sphere
// of the body's volume (6 pi mu r against the velocity, 8 pi mu r^3 against the spin; none
// in a generalized-Newtonian fluid, whose viscosity at rest is no measure of it), and A the
// rest. A is what a contact within the window meets besides the body's own mass.
//
// The box reaches three of the body's mean half-extents beyond it on every side; its
// periodic images, at a solid fraction below 1 %, raise the added mass by about 2 % (Zuber's
// factor (1 + 2 c) / (1 - c) for a suspension at solid fraction c), and the steady drag
// (Hasimoto's periodic array) by more, which the kernel's last windows begin to show.
#include <Eigen/Core>

#include <vector>

#include "fluid/bodies/rigid_body.hpp"
#include "fluid/body_methods.hpp"
#include "fluid/grid/grid.hpp"
#include "fluid/navier_stokes/navier_stokes.hpp"

namespace cosim::fluid {

inline constexpr int kResponseWindows = 16;

struct WindowResponse {
  using Matrix6d = Eigen::Matrix<double, 6, 6>;
  std::vector<Matrix6d> kernel;               // K_0 .. K_(kResponseWindows - 1)
  Matrix6d added_mass = Matrix6d::Zero();     // A: kg, kg m, kg m^2
  Matrix6d added_damping = Matrix6d::Zero();  // B: N s / m, N s, N m s
};

// In the body's frame, with the cells `grid` has where the body is (on a two-dimensional
// grid: per its layer), for windows of length `window`. Each rank measures it alone.
// Throws std::invalid_argument for a half-space.
WindowResponse window_response(const grid::Grid& grid, const bodies::RigidBody& body,
                               const navier_stokes::FluidProperties& fluid, const navier_stokes::TimeStepOptions& steps,
                               const BodyOptions& method, double window);

}  // namespace cosim::fluid
