#include "geometry/capsule.hpp"

#include <algorithm>
#include <numbers>

#include "geometry/detail/checks.hpp"

namespace cosim::geometry {

Capsule::Capsule(double radius, double height)
    : radius_(detail::require_positive(radius, "capsule", "radius")),
      half_height_(0.5 * detail::require_positive(height, "capsule", "height")) {}

double Capsule::volume() const {
  const double r = radius_;
  return std::numbers::pi * r * r * (2.0 * half_height_ + 4.0 / 3.0 * r);
}

// Cylinder plus two hemispheres; a hemisphere's centroid sits 3r/8 beyond its flat face,
// which the parallel-axis terms h^2/4 + 3hr/8 account for.
Eigen::Matrix3d Capsule::unit_inertia() const {
  const double r = radius_, h = 2.0 * half_height_, r2 = r * r;
  const double m_cyl = std::numbers::pi * r2 * h;
  const double m_caps = 4.0 / 3.0 * std::numbers::pi * r2 * r;
  const double axial = m_cyl * r2 / 2.0 + m_caps * 0.4 * r2;
  const double transverse = m_cyl * (3.0 * r2 + h * h) / 12.0 + m_caps * (0.4 * r2 + h * h / 4.0 + 3.0 * h * r / 8.0);
  return Eigen::Vector3d(transverse, transverse, axial).asDiagonal();
}

Aabb Capsule::world_aabb(const Pose& pose) const {
  const Eigen::Vector3d a = pose.rotation().col(2);
  return Aabb::around(pose.position(), (half_height_ * a.cwiseAbs()).array() + radius_);
}

Eigen::Vector3d Capsule::offset(const Eigen::Vector3d& p) const {
  return {p.x(), p.y(), p.z() - std::clamp(p.z(), -half_height_, half_height_)};
}

SurfacePoint Capsule::closest(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d v = offset(p);
  const Eigen::Vector3d n = detail::unit_or(v, Eigen::Vector3d::UnitX());
  return {v.norm() - radius_, p - v + radius_ * n, n};
}

Eigen::Vector3d Capsule::support(const Eigen::Vector3d& direction) const {
  const double end = direction.z() < 0.0 ? -half_height_ : half_height_;
  return Eigen::Vector3d(0, 0, end) + radius_ * detail::unit_or(direction, Eigen::Vector3d::UnitZ());
}

}  // namespace cosim::geometry
