#include "fluid/program/body_responses.hpp"

#include "coupler/participant/robin.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::fluid::program {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

Matrix6d turned(const Matrix6d& body_frame, const Eigen::Quaterniond& q) {
  Matrix6d r = Matrix6d::Zero();
  r.topLeftCorner<3, 3>() = r.bottomRightCorner<3, 3>() = q.toRotationMatrix();
  return r * body_frame * r.transpose();
}

// Changes remembered per body: the kernel's windows after the newest.
constexpr std::size_t kRemembered = fluid::kResponseWindows - 1;

}  // namespace

BodyResponses::BodyResponses(const fluid::grid::Grid& grid, const std::vector<fluid::bodies::RigidBody>& bodies,
                             const std::vector<std::size_t>& same_shape, const std::vector<bool>& fixed,
                             const fluid::navier_stokes::FluidProperties& fluid,
                             const fluid::navier_stokes::TimeStepOptions& steps, const fluid::BodyOptions& method,
                             double window)
    : changes_(bodies.size()) {
  const auto width = [&](const fluid::bodies::RigidBody& body) {
    const Eigen::Vector3d& x = body.pose.position();
    return grid.finest_width_at({x[0], x[1], x[2]});
  };
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    corrections_.emplace_back(window, width(bodies[b]));
    const std::size_t first = same_shape.at(b);
    // The same width to round-off: a uniform axis's cells differ in their last bits.
    const bool shared = first < b && std::abs(width(bodies[first]) - width(bodies[b])) <= 1e-9 * width(bodies[b]);
    fluid::WindowResponse still;
    still.kernel.assign(fluid::kResponseWindows, fluid::WindowResponse::Matrix6d::Zero());
    body_frame_.push_back(fixed.at(b) ? still
                          : shared    ? body_frame_[first]
                                      : fluid::window_response(grid, bodies[b], fluid, steps, method, window));
  }
}

// The next window's load with the velocity held: the change d_(k-n) of n windows ago moved
// this window's load by -K_n d and moves the next one's by -K_(n+1) d.
std::vector<participant::ResponseRow> BodyResponses::after(std::span<const Vector6d> start,
                                                           std::span<const Vector6d> end,
                                                           const std::vector<Eigen::Quaterniond>& orientations,
                                                           std::span<const participant::ForceRow> loads) {
  std::vector<participant::ResponseRow> out;
  for (std::size_t b = 0; b < body_frame_.size(); ++b) {
    const fluid::WindowResponse& r = body_frame_[b];
    const Eigen::Quaterniond& q = orientations.at(b);
    std::deque<Vector6d>& changes = changes_[b];
    if (!start.empty()) {
      changes.push_front(end[b] - start[b]);
      if (changes.size() > kRemembered) changes.pop_back();
    }
    ResponseCorrection& correction = corrections_[b];
    if (!start.empty()) correction.observe(changes.front().head<3>(), loads[b].force);
    Vector6d hold;
    hold << loads[b].force, loads[b].torque;
    for (std::size_t n = 0; n < changes.size(); ++n) hold += turned(r.kernel[n] - r.kernel[n + 1], q) * changes[n];
    participant::ResponseRow row{turned(r.added_mass, q), turned(r.added_damping, q), {hold.head<3>(), hold.tail<3>()}};
    correction.apply(row, changes.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(changes.front().head<3>()));
    out.push_back(row);
  }
  return out;
}

std::vector<double> BodyResponses::state() const {
  std::vector<double> out;
  for (std::size_t b = 0; b < changes_.size(); ++b) {
    corrections_[b].state(out);
    out.push_back(static_cast<double>(changes_[b].size()));
    for (const Vector6d& d : changes_[b]) out.insert(out.end(), d.data(), d.data() + 6);
  }
  return out;
}

void BodyResponses::restore(std::span<const double> state) {
  std::size_t at = 0;
  for (std::size_t b = 0; b < changes_.size(); ++b) {
    std::deque<Vector6d>& changes = changes_[b];
    if (at + ResponseCorrection::kStateSize >= state.size()) throw std::invalid_argument("response state too short");
    corrections_[b].restore(state.subspan(at, ResponseCorrection::kStateSize));
    at += ResponseCorrection::kStateSize;
    const auto count = static_cast<std::size_t>(state[at++]);
    if (count > kRemembered || at + 6 * count > state.size())
      throw std::invalid_argument("response state holds " + std::to_string(count) + " changes for a body, at most " +
                                  std::to_string(kRemembered));
    changes.clear();
    for (std::size_t n = 0; n < count; ++n, at += 6) changes.push_back(Vector6d(state.data() + at));
  }
  if (at != state.size()) throw std::invalid_argument("response state has values left over");
}

}  // namespace cosim::fluid::program
