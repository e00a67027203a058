#pragma once

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// [-h, h] along each body axis, centred at the body origin; h = half extents.
class Box {
 public:
  explicit Box(const Eigen::Vector3d& half_extents);

  const Eigen::Vector3d& half_extents() const { return half_extents_; }

  double volume() const { return 8.0 * half_extents_.prod(); }
  Eigen::Matrix3d unit_inertia() const;
  double bounding_radius() const { return half_extents_.norm(); }
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return (p.cwiseAbs() - half_extents_).maxCoeff() <= 0.0; }
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  Eigen::Vector3d half_extents_;
};

}  // namespace cosim::geometry
