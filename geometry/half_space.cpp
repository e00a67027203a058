#include "geometry/half_space.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cosim::geometry {

HalfSpace::HalfSpace(const Eigen::Vector3d& normal) {
  const double n = normal.norm();
  if (!(n > 0.0) || !std::isfinite(n)) throw std::invalid_argument("half-space: normal must be non-zero and finite");
  normal_ = normal / n;
}

double HalfSpace::bounding_radius() const { return std::numeric_limits<double>::infinity(); }

// Unbounded except when the world normal is along a coordinate axis: then one side of that
// axis is cut off by the plane, which keeps floors and walls out of broad-phase cells.
Aabb HalfSpace::world_aabb(const Pose& pose) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Aabb box{Eigen::Vector3d::Constant(-inf), Eigen::Vector3d::Constant(inf)};
  const Eigen::Vector3d n = pose.direction_to_world(normal_);
  for (int i = 0; i < 3; ++i) {
    if (n[(i + 1) % 3] != 0.0 || n[(i + 2) % 3] != 0.0) continue;
    if (n[i] > 0.0) box.max[i] = pose.position()[i];
    if (n[i] < 0.0) box.min[i] = pose.position()[i];
  }
  return box;
}

SurfacePoint HalfSpace::closest(const Eigen::Vector3d& p) const {
  const double d = signed_distance(p);
  return {d, p - d * normal_, normal_};
}

}  // namespace cosim::geometry
