#pragma once

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// The solid below the plane through the body origin: n . x <= 0 with n the outward unit
// normal. Infinite, so it has no volume, mass, bounding sphere or support point: it can only
// be a fixed body (walls, floors).
class HalfSpace {
 public:
  explicit HalfSpace(const Eigen::Vector3d& normal);

  const Eigen::Vector3d& normal() const { return normal_; }

  double bounding_radius() const;  // +infinity
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const { return normal_.dot(p); }
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }

 private:
  Eigen::Vector3d normal_;
};

}  // namespace cosim::geometry
