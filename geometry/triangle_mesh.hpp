#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geometry/aabb.hpp"
#include "geometry/triangle.hpp"
#include "geometry/pose.hpp"
#include "geometry/surface_point.hpp"

namespace cosim::geometry {

namespace detail {
class MeshCore;
}

// What construction had to repair; nothing here changes the solid the mesh describes.
struct MeshReport {
  std::size_t merged_vertices = 0;     // exact duplicates welded (STL repeats every corner)
  std::size_t dropped_triangles = 0;   // collapsed to an edge or a point by welding
  std::size_t flipped_components = 0;  // closed components turned to face outward
  std::size_t flipped_triangles = 0;
  bool flipped() const { return flipped_components > 0; }
  std::string summary() const;  // one line, for logs
};

// A closed triangle surface (possibly non-convex, several components, cavities), immutable
// and cheap to copy: copies share the vertices and the search tree.
//
// Construction welds exactly equal vertices, rejects (std::invalid_argument whose message
// starts with the source, e.g. the file) meshes that are open, non-manifold, inconsistently
// oriented or have zero-area triangles, turns components inside out where needed so that
// normals point out of the solid (see report()), and moves the vertices so that the centre
// of mass is the body origin: vertex_body = vertex_input - com_shift().
class TriangleMesh {
 public:
  // `source` names the mesh in error messages.
  TriangleMesh(std::vector<Eigen::Vector3d> vertices, std::vector<Triangle> triangles,
               std::string source = "triangle mesh");
  // STL (ASCII or binary) or OBJ through assimp. Coordinates are as in the file, read in
  // single precision (assimp's ai_real).
  static TriangleMesh from_file(const std::filesystem::path& file);

  const std::string& source() const;
  const std::vector<Eigen::Vector3d>& vertices() const;  // body frame
  const std::vector<Triangle>& triangles() const;        // counter-clockwise seen from outside
  // Input-frame position of the centre of mass. A body placed by its input frame at pose
  // (x, q) sits at (x + q * com_shift(), q) in body-frame terms.
  const Eigen::Vector3d& com_shift() const;
  const MeshReport& report() const;

  double volume() const;
  const Eigen::Matrix3d& unit_inertia() const;  // about the centre of mass, density 1
  double bounding_radius() const;
  Aabb world_aabb(const Pose& pose) const;

  double signed_distance(const Eigen::Vector3d& p) const { return closest(p).distance; }
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  // The same with a hint for spatially coherent batches (see queries.hpp).
  SurfacePoint closest(const Eigen::Vector3d& p, std::uint32_t& hint) const;
  bool contains(const Eigen::Vector3d& p) const { return signed_distance(p) <= 0.0; }
  // The support of the mesh is that of its convex hull (the farthest vertex): exact for the
  // set, but GJK on it sees the hull; the narrow phase must treat meshes as non-convex.
  Eigen::Vector3d support(const Eigen::Vector3d& direction) const;

 private:
  struct Data;
  std::shared_ptr<const Data> data_;
};

}  // namespace cosim::geometry
