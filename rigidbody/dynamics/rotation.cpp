#include "rigidbody/dynamics/rotation.hpp"

#include <Eigen/Eigenvalues>

namespace cosim::rigidbody::dynamics {

Eigen::Quaterniond rotate_world(const Eigen::Quaterniond& q, const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  if (angle == 0.0) return q;
  return (Eigen::Quaterniond(Eigen::AngleAxisd(angle, theta / angle)) * q).normalized();
}

Eigen::Quaterniond free_rotation(const Eigen::Quaterniond& q, const Eigen::Matrix3d& inertia_body,
                                 const Eigen::Vector3d& angular_momentum, double h) {
  // Work in the principal frame, where the kinetic energy splits into three exactly
  // integrable terms; a general (e.g. mesh) inertia tensor is not diagonal in the body frame.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(inertia_body);
  Eigen::Matrix3d axes = eigen.eigenvectors();
  if (axes.determinant() < 0.0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection
  const Eigen::Vector3d moments = eigen.eigenvalues();
  const Eigen::Quaterniond to_principal(axes);

  Eigen::Quaterniond p = q * to_principal;                // principal frame -> world
  Eigen::Vector3d pi = p.conjugate() * angular_momentum;  // in the principal frame
  const auto flow = [&](int k, double tau) {
    const double angle = tau * pi[k] / moments[k];
    const Eigen::AngleAxisd turn(angle, Eigen::Vector3d::Unit(k));
    p = p * Eigen::Quaterniond(turn);
    pi = turn.inverse() * pi;
  };
  flow(0, 0.5 * h);
  flow(1, 0.5 * h);
  flow(2, h);
  flow(1, 0.5 * h);
  flow(0, 0.5 * h);
  return (p * to_principal.conjugate()).normalized();
}

}  // namespace cosim::rigidbody::dynamics
