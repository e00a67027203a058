#include "coupler/participant/robin.hpp"

#include <Eigen/Eigenvalues>

namespace cosim::participant {
namespace {

// A block made symmetric, with its negative part dropped: a mass or damping it carries.
Eigen::Matrix3d positive(const Eigen::Matrix3d& block) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> s(0.5 * (block + block.transpose()));
  return s.eigenvectors() * s.eigenvalues().cwiseMax(0.0).asDiagonal() * s.eigenvectors().transpose();
}

// The translational block as its largest eigenvalue, nowhere smaller than the block: too
// large a mass or damping only slows the body's response to a change of the load, too small
// a one can let the load's lag feed back.
Matrix6d simpler(const Matrix6d& tensor) {
  Matrix6d out = Matrix6d::Zero();
  const Eigen::Matrix3d translation = positive(tensor.topLeftCorner<3, 3>());
  out.topLeftCorner<3, 3>() =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(translation, Eigen::EigenvaluesOnly).eigenvalues()(2) *
      Eigen::Matrix3d::Identity();
  out.bottomRightCorner<3, 3>() = positive(tensor.bottomRightCorner<3, 3>());
  return out;
}

Vector6d of(const ForceRow& f) { return (Vector6d() << f.force, f.torque).finished(); }

}  // namespace

Carried carried(const ResponseRow& response) { return {simpler(response.added_mass), simpler(response.added_damping)}; }

Vector6d robin_wrench(const ResponseRow& response, const Vector6d& v0) {
  return of(response.hold) + carried(response).added_damping * v0;
}

Vector6d robin_wrench(const ResponseRow& response, const ForceRow& load, const Vector6d& v0, const Vector6d& v1,
                      double w) {
  const Carried c = carried(response);
  return of(load) + c.added_mass * (v1 - v0) / w + c.added_damping * (0.5 * (v0 + v1));
}

}  // namespace cosim::participant
