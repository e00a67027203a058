#pragma once

#include <array>

#include "geometry/aabb.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// (x/a)^2 + (y/b)^2 + (z/c)^2 <= 1 with semi-axes radii = (a, b, c) along the body axes,
// centred at the body origin.
class Ellipsoid {
 public:
  explicit Ellipsoid(const Eigen::Vector3d& radii);

  const Eigen::Vector3d& radii() const { return radii_; }

  double volume() const;
  Eigen::Matrix3d unit_inertia() const;
  double bounding_radius() const { return radii_.maxCoeff(); }
  Aabb world_aabb(const Pose& pose) const;

  // Exact distance by Eberly's bisection (see detail/ellipsoid_distance.hpp); the sign, and
  // contains(), come from the implicit function so they agree with each other.
  double signed_distance(const Eigen::Vector3d& p) const { return closest(p).distance; }
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  bool contains(const Eigen::Vector3d& p) const { return implicit(p) <= 0.0; }
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  double implicit(const Eigen::Vector3d& p) const { return p.cwiseQuotient(radii_).squaredNorm() - 1.0; }

  Eigen::Vector3d radii_;
  std::array<int, 3> descending_;  // body axes ordered by decreasing semi-axis
};

}  // namespace cosim::geometry
