#pragma once

#include <Eigen/Core>

namespace cosim::geometry {

// The answer of a closest-point query.
struct SurfacePoint {
  double distance = 0.0;                            // signed: negative inside the shape, zero on its surface
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // closest point on the surface
  // Outward unit normal: the gradient of the signed distance at the query point where it is
  // differentiable, i.e. (query - point) / distance off the surface; on the surface itself
  // (distance 0) the surface normal, or a pseudo-normal at an edge or a vertex.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

}  // namespace cosim::geometry
