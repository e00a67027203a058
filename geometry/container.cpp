#include "geometry/container.hpp"

#include <limits>

namespace cosim::geometry {

double Container::bounding_radius() const { return std::numeric_limits<double>::infinity(); }

Aabb Container::world_aabb(const Pose&) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf)};
}

double Container::signed_distance(const Eigen::Vector3d& p) const {
  return -std::visit([&](const auto& s) { return s.signed_distance(p); }, inside_);
}

SurfacePoint Container::closest(const Eigen::Vector3d& p) const {
  const SurfacePoint s = std::visit([&](const auto& shape) { return shape.closest(p); }, inside_);
  return {-s.distance, s.point, -s.normal};
}

}  // namespace cosim::geometry
