#include "geometry/box.hpp"

#include "geometry/detail/checks.hpp"
#include "geometry/detail/orthant_box.hpp"

namespace cosim::geometry {
namespace {

// +1 for +0 too, so that a query on a symmetry plane lands on one definite face.
Eigen::Vector3d signs(const Eigen::Vector3d& v) {
  return v.unaryExpr([](double x) { return x < 0.0 ? -1.0 : 1.0; });
}

}  // namespace

Box::Box(const Eigen::Vector3d& half_extents)
    : half_extents_(detail::require_positive(half_extents, "box", "half extents")) {}

Eigen::Matrix3d Box::unit_inertia() const {
  const Eigen::Vector3d s = half_extents_.cwiseAbs2();
  return (volume() / 3.0 * Eigen::Vector3d(s[1] + s[2], s[0] + s[2], s[0] + s[1])).asDiagonal();
}

Aabb Box::world_aabb(const Pose& pose) const {
  return Aabb::around(pose.position(), pose.rotation().cwiseAbs() * half_extents_);
}

double Box::signed_distance(const Eigen::Vector3d& p) const {
  return detail::orthant_box_distance<3>(p.cwiseAbs(), half_extents_);
}

SurfacePoint Box::closest(const Eigen::Vector3d& p) const {
  const auto c = detail::orthant_box_closest<3>(p.cwiseAbs(), half_extents_);
  const Eigen::Vector3d s = signs(p);
  return {c.distance, c.point.cwiseProduct(s), c.normal.cwiseProduct(s)};
}

Eigen::Vector3d Box::support(const Eigen::Vector3d& direction) const {
  return half_extents_.cwiseProduct(signs(direction));
}

}  // namespace cosim::geometry
