#include "geometry/ellipsoid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/detail/checks.hpp"
#include "geometry/detail/ellipsoid_distance.hpp"

namespace cosim::geometry {

Ellipsoid::Ellipsoid(const Eigen::Vector3d& radii)
    : radii_(detail::require_positive(radii, "ellipsoid", "radii")), descending_{0, 1, 2} {
  std::stable_sort(descending_.begin(), descending_.end(), [&](int i, int j) { return radii_[i] > radii_[j]; });
}

double Ellipsoid::volume() const { return 4.0 / 3.0 * std::numbers::pi * radii_.prod(); }

Eigen::Matrix3d Ellipsoid::unit_inertia() const {
  const Eigen::Vector3d s = radii_.cwiseAbs2();
  return (volume() / 5.0 * Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1])).asDiagonal();
}

// The support along e_i reaches |diag(radii) R^T e_i|.
Aabb Ellipsoid::world_aabb(const Pose& pose) const {
  return Aabb::around(pose.position(), (pose.rotation() * radii_.asDiagonal()).rowwise().norm());
}

SurfacePoint Ellipsoid::closest(const Eigen::Vector3d& p) const {
  Eigen::Vector3d e, y;
  for (int k = 0; k < 3; ++k) {
    e[k] = radii_[descending_[k]];
    y[k] = std::abs(p[descending_[k]]);
  }
  const Eigen::Vector3d x_sorted = detail::closest_on_ellipsoid_octant(e, y);
  Eigen::Vector3d x;
  for (int k = 0; k < 3; ++k) x[descending_[k]] = std::copysign(x_sorted[k], p[descending_[k]]);

  const double d = (p - x).norm();
  const Eigen::Vector3d n = x.cwiseQuotient(radii_.cwiseAbs2()).normalized();
  return {implicit(p) <= 0.0 ? -d : d, x, n};
}

// argmax_{x in E} d.x = D^2 d / |D d| with D = diag(radii).
Eigen::Vector3d Ellipsoid::support(const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d dd = radii_.cwiseProduct(direction);
  const double n = dd.norm();
  if (n == 0.0) return Eigen::Vector3d(radii_[0], 0.0, 0.0);
  return radii_.cwiseProduct(dd) / n;
}

}  // namespace cosim::geometry
