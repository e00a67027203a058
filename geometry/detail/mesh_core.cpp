#include "geometry/detail/mesh_core.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "geometry/detail/mesh_topology.hpp"

namespace cosim::geometry::detail {

MeshCore::MeshCore(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
                   std::vector<std::uint32_t> support_vertices)
    : vertices_(std::move(vertices)),
      triangles_(std::move(triangles)),
      support_vertices_(std::move(support_vertices)),
      bvh_(vertices_, triangles_) {
  const Neighbors neighbors = edge_neighbors(vertices_, triangles_);
  face_normals_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& c = triangles_[t];
    face_normals_[t] = (vertices_[c[1]] - vertices_[c[0]]).cross(vertices_[c[2]] - vertices_[c[0]]).normalized();
  }
  // Vertex pseudo-normal: the face normals weighted by the face's angle at the vertex,
  // which makes it independent of how the surface around the vertex is triangulated.
  vertex_normals_.assign(vertices_.size(), Eigen::Vector3d::Zero());
  edge_normals_.resize(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto& c = triangles_[t];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d u = vertices_[c[(k + 1) % 3]] - vertices_[c[k]];
      const Eigen::Vector3d w = vertices_[c[(k + 2) % 3]] - vertices_[c[k]];
      vertex_normals_[c[k]] += std::atan2(u.cross(w).norm(), u.dot(w)) * face_normals_[t];
      edge_normals_[t][k] = (face_normals_[t] + face_normals_[neighbors[t][k]]).normalized();
    }
  }
  for (auto& n : vertex_normals_) n.normalize();
  for (const auto& v : vertices_) bounding_radius_ = std::max(bounding_radius_, v.norm());
}

Aabb MeshCore::world_aabb(const Pose& pose) const {
  const Eigen::Matrix3d r = pose.rotation();
  Aabb box;
  for (std::uint32_t i : support_vertices_) box.extend(r * vertices_[i]);
  box.min += pose.position();
  box.max += pose.position();
  return box;
}

Eigen::Vector3d MeshCore::support(const Eigen::Vector3d& direction) const {
  std::uint32_t best = support_vertices_.front();
  double best_dot = -std::numeric_limits<double>::infinity();
  for (std::uint32_t i : support_vertices_) {
    const double d = direction.dot(vertices_[i]);
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  return vertices_[best];
}

SurfacePoint MeshCore::closest(const Eigen::Vector3d& p, std::uint32_t& hint) const {
  const TriangleBvh::Hit hit = bvh_.closest(p, hint);
  hint = hit.triangle;
  const Triangle& c = triangles_[hit.triangle];
  const Eigen::Vector3d& q = hit.point.point;

  Eigen::Vector3d pseudo_normal;
  switch (hit.point.feature) {
    case TriangleFeature::Face: {
      // p - d n rather than the barycentric point: a query on the face is its own closest point.
      const Eigen::Vector3d& n = face_normals_[hit.triangle];
      const double d = n.dot(p - vertices_[c[0]]);
      return {d, p - d * n, n};
    }
    case TriangleFeature::Edge0:
    case TriangleFeature::Edge1:
    case TriangleFeature::Edge2:
      pseudo_normal = edge_normals_[hit.triangle][static_cast<int>(hit.point.feature) - 3];
      break;
    default:
      pseudo_normal = vertex_normals_[c[static_cast<int>(hit.point.feature)]];
  }
  const Eigen::Vector3d& offset = hit.point.offset;
  const double length = std::sqrt(hit.point.squared_distance);
  if (length == 0.0) return {0.0, q, pseudo_normal};
  const double d = offset.dot(pseudo_normal) < 0.0 ? -length : length;
  return {d, q, offset / d};
}

}  // namespace cosim::geometry::detail
