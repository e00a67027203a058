// The part of a body's response that the kernel misses, estimated from the run itself.
//
// The response kernel (fluid/window_response.hpp) is measured for the body alone in fluid at
// rest. In a bed the liquid streams through the gaps and the neighbours are close, and the
// load answers a change of the body's velocity more strongly than that, most of all the
// window-to-window flip of velocity in which explicit coupling blows up.
// So after every window the load the body had is set against what the kernel's rows
// predicted for the velocity change d_k it made. If the body answers a change by a further
// -X d within the change's window (and not after it), that misprediction is
//   e_k = F_k - (hold_(k-1) - K_0 d_k) = -X (d_k - d_(k-1)) + (the load's own drift),
// and X (N per m/s) is estimated per body by least squares over the last windows with
// exponential forgetting, X = max(0, -sum w e . (d_k - d_(k-1)) / sum w |d_k - d_(k-1)|^2).
// The next row's translational added mass gains W X and its hold X d_k. Only added, never
// taken away: a response the kernel overstates costs accuracy within a window, one it
// understates costs stability. Translation only.
#pragma once

#include <Eigen/Core>

#include <span>
#include <vector>

#include "coupler/participant/body_rows.hpp"

namespace cosim::fluid::program {

class ResponseCorrection {
 public:
  // For windows of length `window` on cells of width `cell` where the body is.
  ResponseCorrection(double window, double cell);

  // After a window in which the body's velocity changed by `change` under the mean force
  // `force`.
  void observe(const Eigen::Vector3d& change, const Eigen::Vector3d& force);
  // Adds the missing response to the next row, `newest` the window's change; remembers what
  // the row predicted before.
  void apply(participant::ResponseRow& row, const Eigen::Vector3d& newest);

  static constexpr std::size_t kStateSize = 11;
  void state(std::vector<double>& out) const;
  void restore(std::span<const double> state);

 private:
  double window_, floor_;
  bool predicted_ = false;
  Eigen::Vector3d hold_ = Eigen::Vector3d::Zero(), last_change_ = Eigen::Vector3d::Zero();  // the kernel's
  double k0_ = 0, correlation_ = 0, spread_ = 0, extra_ = 0;
};

}  // namespace cosim::fluid::program
