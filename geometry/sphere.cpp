#include "geometry/sphere.hpp"

#include <numbers>

#include "geometry/detail/checks.hpp"

namespace cosim::geometry {

Sphere::Sphere(double radius) : radius_(detail::require_positive(radius, "sphere", "radius")) {}

double Sphere::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius_ * radius_ * radius_; }

Eigen::Matrix3d Sphere::unit_inertia() const {
  return Eigen::Matrix3d::Identity() * (0.4 * volume() * radius_ * radius_);
}

Aabb Sphere::world_aabb(const Pose& pose) const {
  return Aabb::around(pose.position(), Eigen::Vector3d::Constant(radius_));
}

SurfacePoint Sphere::closest(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d n = detail::unit_or(p, Eigen::Vector3d::UnitX());
  return {signed_distance(p), radius_ * n, n};
}

Eigen::Vector3d Sphere::support(const Eigen::Vector3d& direction) const {
  return radius_ * detail::unit_or(direction, Eigen::Vector3d::UnitX());
}

}  // namespace cosim::geometry
