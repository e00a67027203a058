#pragma once

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// Points within `radius` of the segment from (0, 0, -height/2) to (0, 0, height/2): height
// is the distance between the hemisphere centres; centred at the body origin.
class Capsule {
 public:
  Capsule(double radius, double height);

  double radius() const { return radius_; }
  double height() const { return 2.0 * half_height_; }

  double volume() const;
  Eigen::Matrix3d unit_inertia() const;
  double bounding_radius() const { return radius_ + half_height_; }
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const { return offset(p).norm() - radius_; }
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  // p minus its closest point on the axis segment.
  Eigen::Vector3d offset(const Eigen::Vector3d& p) const;

  double radius_;
  double half_height_;
};

}  // namespace cosim::geometry
