// What cosim-fluid sends with its forces (protocol::Tag::Responses; the rigid bodies' side:
// rigidbody/program/fluid_response.hpp): per body its response tensors, fluid::window_response
// measured once per shape where the body starts and turned with the body into the world
// frame, and the load expected over the next window if the body keeps the velocity it has:
// the last window's load changed by what the changes of the motion over the windows before
// still do to it, through the response kernel; and what the kernel misses where the body is,
// estimated as the run goes (response_correction.hpp).
#pragma once

#include <Eigen/Core>

#include <deque>
#include <span>
#include <vector>

#include "coupler/participant/body_rows.hpp"
#include "fluid/program/response_correction.hpp"
#include "fluid/window_response.hpp"

namespace cosim::fluid::program {

class BodyResponses {
 public:
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  // `bodies` where they start; `same_shape[b]` the first body that is not fixed with b's
  // shape (b itself if none before it), whose tensors b shares where the grid is as fine as there. A fixed
  // body's velocity never changes: its tensors are zero, not measured (a container's could
  // not be).
  BodyResponses(const fluid::grid::Grid& grid, const std::vector<fluid::bodies::RigidBody>& bodies,
                const std::vector<std::size_t>& same_shape, const std::vector<bool>& fixed,
                const fluid::navier_stokes::FluidProperties& fluid, const fluid::navier_stokes::TimeStepOptions& steps,
                const fluid::BodyOptions& method, double window);

  // The rows after a window in which the bodies' velocities (linear, then angular; scene
  // order) changed from `start` to `end` and their orientations became `orientations`, with
  // `loads` the window's mean loads; remembers the changes. No window yet: `start` empty.
  std::vector<participant::ResponseRow> after(std::span<const Vector6d> start, std::span<const Vector6d> end,
                                              const std::vector<Eigen::Quaterniond>& orientations,
                                              std::span<const participant::ForceRow> loads);

  // The changes of the last windows and the corrections, which the next rows depend on: for
  // a rollback and a restart.
  std::vector<double> state() const;
  void restore(std::span<const double> state);

 private:
  std::vector<fluid::WindowResponse> body_frame_;
  std::vector<std::deque<Vector6d>> changes_;  // per body, the newest first
  std::vector<ResponseCorrection> corrections_;
};

}  // namespace cosim::fluid::program
