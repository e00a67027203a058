#pragma once

#include <Eigen/Core>

namespace cosim::geometry::detail {

// Closest point on the ellipsoid with semi-axes e0 >= e1 >= e2 > 0 to a point y in the
// first octant (y_i >= 0). D. Eberly, "Distance from a point to an ellipse, an ellipsoid,
// or a hyperellipsoid" (Geometric Tools, 2013): the root of the secular equation is
// bracketed and bisected to machine precision, and the points on coordinate planes (where
// the equation degenerates) take explicit lower-dimensional branches, so there is no
// catastrophic case at the axes. One change: the root is sought as an offset from the pole
// it approaches for inside points near an axis, which keeps those points exact too.
Eigen::Vector3d closest_on_ellipsoid_octant(const Eigen::Vector3d& e, const Eigen::Vector3d& y);

}  // namespace cosim::geometry::detail
