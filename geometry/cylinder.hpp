#pragma once

#include <cmath>

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// Solid circular cylinder: axis = body z, centred at the body origin, |z| <= height / 2
// (height is the full length) and x^2 + y^2 <= radius^2.
class Cylinder {
 public:
  Cylinder(double radius, double height);

  double radius() const { return radius_; }
  double height() const { return 2.0 * half_height_; }

  double volume() const;
  Eigen::Matrix3d unit_inertia() const;
  double bounding_radius() const { return std::hypot(radius_, half_height_); }
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  double radius_;
  double half_height_;
};

}  // namespace cosim::geometry
