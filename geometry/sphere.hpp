#pragma once

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// Ball of radius r centred at the body origin.
class Sphere {
 public:
  explicit Sphere(double radius);

  double radius() const { return radius_; }

  double volume() const;
  Eigen::Matrix3d unit_inertia() const;  // about the centre, for density 1
  double bounding_radius() const { return radius_; }
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const { return p.norm() - radius_; }
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  double radius_;
};

}  // namespace cosim::geometry
