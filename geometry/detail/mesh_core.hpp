#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/triangle.hpp"
#include "geometry/detail/triangle_bvh.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry::detail {

// What TriangleMesh and ConvexHull share: a closed, outward-oriented triangle surface with
// its nearest-triangle tree and the pseudo-normals that sign distances.
class MeshCore {
 public:
  // `triangles` must be closed and outward (see mesh_topology.hpp); `support_vertices` must
  // include every vertex of the convex hull (support and AABB look only at those).
  MeshCore(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
           std::vector<std::uint32_t> support_vertices);

  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }

  double bounding_radius() const { return bounding_radius_; }
  Aabb world_aabb(const Pose& pose) const;
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

  // Exact distance to the nearest triangle, signed by the angle-weighted pseudo-normal of
  // the nearest feature (face, edge or vertex): J. A. Baerentzen & H. Aanaes, "Signed
  // distance computation using the angle weighted pseudonormal", IEEE TVCG 11(3), 2005.
  // In the face region the distance is the plane distance n.(p - a), so a query on a face
  // gives exactly 0. `hint`: see TriangleBvh::closest; it is updated to the answer.
  SurfacePoint closest(const Eigen::Vector3d& p, std::uint32_t& hint) const;

 private:
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<Triangle> triangles_;
  std::vector<std::uint32_t> support_vertices_;
  std::vector<Eigen::Vector3d> face_normals_;
  std::vector<std::array<Eigen::Vector3d, 3>> edge_normals_;  // per triangle edge, unit
  std::vector<Eigen::Vector3d> vertex_normals_;               // unit
  TriangleBvh bvh_;
  double bounding_radius_ = 0.0;
};

}  // namespace cosim::geometry::detail
