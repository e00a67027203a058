#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/triangle.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

// A face plane: n . x <= offset inside, n the outward unit normal.
struct Plane {
  Eigen::Vector3d normal;
  double offset;
  double distance(const Eigen::Vector3d& p) const { return normal.dot(p) - offset; }
};

// The convex hull of a point set (qhull), immutable and cheap to copy. Coplanar facets are
// merged, so faces are convex polygons; points that are not hull vertices are dropped. The
// vertices are moved so that the centre of mass is the body origin:
// vertex_body = point_input - com_shift().
class ConvexHull {
 public:
  // Throws std::invalid_argument for fewer than 4 points or points in a plane.
  explicit ConvexHull(std::span<const Eigen::Vector3d> points);

  const std::vector<Eigen::Vector3d>& vertices() const;          // body frame
  const std::vector<std::vector<std::uint32_t>>& faces() const;  // vertex loops, CCW seen from outside
  const std::vector<Plane>& planes() const;                      // one per face
  const std::vector<Triangle>& triangles() const;                // faces split into fans
  const Eigen::Vector3d& com_shift() const;                      // see TriangleMesh::com_shift

  double volume() const;
  const Eigen::Matrix3d& unit_inertia() const;
  double bounding_radius() const;
  Aabb world_aabb(const Pose& pose) const;

  // Inside, the distance is the largest face-plane distance (exact for convex sets: the
  // nearest plane's foot point lies on its face); outside, the nearest triangle.
  double signed_distance(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  SurfacePoint closest(const Eigen::Vector3d& p, std::uint32_t& hint) const;
  bool contains(const Eigen::Vector3d& p) const;
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  struct Data;
  struct NearestPlane {
    double distance;             // the largest plane distance
    std::size_t face;            // the first face at that distance
    Eigen::Vector3d normal_sum;  // of all faces at that distance: bisects them at edges
  };
  NearestPlane nearest_plane(const Eigen::Vector3d& p) const;
  std::shared_ptr<const Data> data_;
};

}  // namespace cosim::geometry
