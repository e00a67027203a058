#include "rigidbody/program/fluid_response.hpp"

#include <Eigen/Eigenvalues>

#include <stdexcept>
#include <string>

namespace cosim::program {
namespace {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// A block made symmetric, with its negative part dropped: a mass or damping it carries.
Eigen::Matrix3d positive(const Eigen::Matrix3d& block) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> s(0.5 * (block + block.transpose()));
  return s.eigenvectors() * s.eigenvalues().cwiseMax(0.0).asDiagonal() * s.eigenvectors().transpose();
}

// The tensor as the body carries it: the translational block as its largest eigenvalue,
// nowhere smaller than the block (too large a mass or damping only slows the body's
// response to a change of the load; too small a one can let the load's lag feed back).
Matrix6d carried(const Matrix6d& tensor) {
  Matrix6d out = Matrix6d::Zero();
  const Eigen::Matrix3d translation = positive(tensor.topLeftCorner<3, 3>());
  out.topLeftCorner<3, 3>() =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(translation, Eigen::EigenvaluesOnly).eigenvalues()(2) *
      Eigen::Matrix3d::Identity();
  out.bottomRightCorner<3, 3>() = positive(tensor.bottomRightCorner<3, 3>());
  return out;
}

}  // namespace

FluidResponse::Carried FluidResponse::prepare(const participant::Window& w,
                                              std::span<const participant::ForceRow> forces,
                                              std::span<const participant::ResponseRow> responses,
                                              std::span<const Vector6d> start) {
  if (responses.size() != forces.size() || start.size() < forces.size())
    throw std::runtime_error("fluid response: " + std::to_string(responses.size()) + " responses for " +
                             std::to_string(forces.size()) + " forces");
  const bool repeated = trial_ && trial_->window == w.index && trial_->end.size() == forces.size();
  Carried out;
  for (std::size_t b = 0; b < forces.size(); ++b) {
    const Matrix6d mass = carried(responses[b].added_mass), damping = carried(responses[b].added_damping);
    Vector6d wrench;
    if (repeated) {
      const Vector6d &v0 = trial_->start[b], &v1 = trial_->end[b];
      wrench << forces[b].force, forces[b].torque;
      wrench += mass * (v1 - v0) / trial_->length + damping * (0.5 * (v0 + v1));
    } else {
      wrench << responses[b].hold.force, responses[b].hold.torque;
      wrench += damping * start[b];
    }
    dynamics::AddedInertia a;
    a.mass = mass(0, 0);
    a.inertia = mass.bottomRightCorner<3, 3>();
    a.damping = damping(0, 0);
    a.rotational_damping = damping.bottomRightCorner<3, 3>();
    out.added.push_back(a);
    const dynamics::Wrench held{wrench.head<3>(), wrench.tail<3>()};
    out.wrenches.push_back({held, held});
  }
  if (!repeated) trial_ = Trial{w.index, w.t1 - w.t0, {}, {}};
  trial_->start.assign(start.begin(), start.begin() + static_cast<std::ptrdiff_t>(forces.size()));
  return out;
}

void FluidResponse::finish(std::span<const Vector6d> end) {
  if (trial_) trial_->end.assign(end.begin(), end.begin() + static_cast<std::ptrdiff_t>(trial_->start.size()));
}

}  // namespace cosim::program
