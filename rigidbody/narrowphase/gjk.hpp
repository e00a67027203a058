// Internal: GJK distance between two bounded convex shapes (libccd has no distance query).
#pragma once

#include "geometry/shape.hpp"

namespace cosim::rigidbody::narrowphase::detail {

struct GjkResult {
  bool overlap = false;  // the shapes touch or overlap (distance below the tolerance)
  double distance = 0.0;
  Eigen::Vector3d on_a = Eigen::Vector3d::Zero();  // closest points, world frame
  Eigen::Vector3d on_b = Eigen::Vector3d::Zero();
};

// Gilbert-Johnson-Keerthi with Ericson's closest-point-on-simplex sub-algorithm
// (Real-Time Collision Detection, 2005, 9.5 and 5.1.5-5.1.6). Stops when the lower bound
// v.w / |v| is within `tolerance` (absolute) of the distance |v|.
GjkResult gjk_distance(const geometry::Shape& a, const geometry::Pose& pa, const geometry::Shape& b,
                       const geometry::Pose& pb, double tolerance);

}  // namespace cosim::rigidbody::narrowphase::detail
