#include "geometry/cylinder.hpp"

#include <cmath>
#include <numbers>

#include "geometry/detail/checks.hpp"
#include "geometry/detail/orthant_box.hpp"

namespace cosim::geometry {
namespace {

double radial(const Eigen::Vector3d& p) { return std::sqrt(p.x() * p.x() + p.y() * p.y()); }

}  // namespace

Cylinder::Cylinder(double radius, double height)
    : radius_(detail::require_positive(radius, "cylinder", "radius")),
      half_height_(0.5 * detail::require_positive(height, "cylinder", "height")) {}

double Cylinder::volume() const { return std::numbers::pi * radius_ * radius_ * 2.0 * half_height_; }

Eigen::Matrix3d Cylinder::unit_inertia() const {
  const double m = volume(), r2 = radius_ * radius_, h = 2.0 * half_height_;
  const double transverse = m * (3.0 * r2 + h * h) / 12.0;
  return Eigen::Vector3d(transverse, transverse, 0.5 * m * r2).asDiagonal();
}

// The end discs reach r sqrt(1 - a_i^2) along e_i when the axis is a.
Aabb Cylinder::world_aabb(const Pose& pose) const {
  const Eigen::Vector3d a = pose.rotation().col(2);
  const Eigen::Array3d disc = radius_ * (1.0 - a.array().square()).max(0.0).sqrt();
  return Aabb::around(pose.position(), half_height_ * a.cwiseAbs() + disc.matrix());
}

double Cylinder::signed_distance(const Eigen::Vector3d& p) const {
  return detail::orthant_box_distance<2>({radial(p), std::abs(p.z())}, {radius_, half_height_});
}

SurfacePoint Cylinder::closest(const Eigen::Vector3d& p) const {
  const double rho = radial(p);
  const auto c = detail::orthant_box_closest<2>({rho, std::abs(p.z())}, {radius_, half_height_});
  const Eigen::Vector3d u = rho > 0.0 ? Eigen::Vector3d(p.x() / rho, p.y() / rho, 0.0) : Eigen::Vector3d::UnitX();
  const double sz = p.z() < 0.0 ? -1.0 : 1.0;
  return {c.distance, c.point[0] * u + Eigen::Vector3d(0, 0, sz * c.point[1]),
          c.normal[0] * u + Eigen::Vector3d(0, 0, sz * c.normal[1])};
}

Eigen::Vector3d Cylinder::support(const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d radial_dir(direction.x(), direction.y(), 0.0);
  const double rho = radial_dir.norm();
  const Eigen::Vector3d rim = rho > 0.0 ? Eigen::Vector3d(radius_ / rho * radial_dir) : Eigen::Vector3d::Zero();
  return rim + Eigen::Vector3d(0, 0, direction.z() < 0.0 ? -half_height_ : half_height_);
}

}  // namespace cosim::geometry
