#include "fluid/program/response_correction.hpp"

#include <algorithm>
#include <stdexcept>

#include "coupler/participant/robin.hpp"

namespace cosim::fluid::program {
namespace {

// The weight of a window against the one after it: the estimate follows the bed over about
// five windows (1 / (1 - 0.8)), quick enough for a bead that leaves its neighbours.
constexpr double kForgetting = 0.8;

}  // namespace

// Changes below a thousandth of a cell per window (the kernel's own probe,
// fluid/window_response.cpp) carry too little signal to move the estimate.
ResponseCorrection::ResponseCorrection(double window, double cell)
    : window_(window), floor_((1e-3 * cell / window) * (1e-3 * cell / window)) {}

void ResponseCorrection::observe(const Eigen::Vector3d& change, const Eigen::Vector3d& force) {
  if (predicted_) {
    const Eigen::Vector3d error = force - (hold_ - k0_ * change), step = change - last_change_;
    correlation_ = kForgetting * correlation_ - error.dot(step);
    spread_ = kForgetting * spread_ + step.squaredNorm();
    extra_ = std::max(0.0, correlation_ / (spread_ + floor_));
  }
  last_change_ = change;
}

void ResponseCorrection::apply(participant::ResponseRow& row, const Eigen::Vector3d& newest) {
  const participant::Carried carried = participant::carried(row);
  k0_ = carried.added_mass(0, 0) / window_ + 0.5 * carried.added_damping(0, 0);
  hold_ = row.hold.force;
  predicted_ = true;
  row.added_mass.topLeftCorner<3, 3>().diagonal().array() += window_ * extra_;
  row.hold.force += extra_ * newest;
}

void ResponseCorrection::state(std::vector<double>& out) const {
  out.push_back(predicted_ ? 1.0 : 0.0);
  out.insert(out.end(), hold_.data(), hold_.data() + 3);
  out.insert(out.end(), last_change_.data(), last_change_.data() + 3);
  out.insert(out.end(), {k0_, correlation_, spread_, extra_});
}

void ResponseCorrection::restore(std::span<const double> state) {
  if (state.size() != kStateSize) throw std::invalid_argument("response correction state has the wrong length");
  predicted_ = state[0] != 0;
  hold_ = Eigen::Vector3d(state.data() + 1);
  last_change_ = Eigen::Vector3d(state.data() + 4);
  k0_ = state[7];
  correlation_ = state[8];
  spread_ = state[9];
  extra_ = state[10];
}

}  // namespace cosim::fluid::program
