#include "rigidbody/dynamics/body.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace cosim::rigidbody::dynamics {

BodyInertia BodyInertia::of(double mass, const Eigen::Matrix3d& inertia_body, bool rotates) {
  BodyInertia b;
  b.inverse_mass = 1.0 / mass;
  b.rotates = rotates;
  if (inertia_body.isDiagonal(0.0)) {
    b.principal_moments = inertia_body.diagonal();
    return b;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inertia_body);
  Eigen::Matrix3d axes = eigen.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection
  b.principal_axes = Eigen::Quaterniond(axes).normalized();
  b.principal_moments = eigen.eigenvalues();
  return b;
}

Eigen::Matrix3d BodyInertia::inertia_body() const {
  const Eigen::Matrix3d a = principal_axes.toRotationMatrix();
  return a * principal_moments.asDiagonal() * a.transpose();
}

Eigen::Matrix3d BodyInertia::inverse_inertia_world(const Eigen::Quaterniond& q) const {
  if (!rotates || is_fixed()) return Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d r = principal_frame(q).toRotationMatrix();
  return r * principal_moments.cwiseInverse().asDiagonal() * r.transpose();
}

}  // namespace cosim::rigidbody::dynamics
