#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "geometry/triangle.hpp"

// Checks and repairs of triangle soups before they become shapes. Errors are thrown as
// std::invalid_argument with a message that names the offending element by index and
// coordinates; the caller prefixes the mesh's source (its file).
namespace cosim::geometry::detail {

struct WeldedMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Triangle> triangles;
  std::size_t merged_vertices = 0;
  std::size_t dropped_triangles = 0;
};

// Merges vertices with exactly equal coordinates (STL repeats every corner; OBJ may too)
// keeping first-occurrence order, and drops triangles that then repeat a vertex: those
// collapsed to an edge or a point and bound nothing. Rejects out-of-range indices and
// non-finite coordinates.
WeldedMesh weld(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles);

// Rejects triangles of zero area (three distinct collinear corners): they have no normal,
// and dropping them would open the mesh.
void require_nondegenerate(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles);

// neighbors[t][k] is the triangle across edge k of t (corner k to corner (k + 1) % 3).
// Every edge must have exactly two triangles that traverse it in opposite directions:
// otherwise the mesh is open, non-manifold or inconsistently oriented, and is rejected.
using Neighbors = std::vector<std::array<std::uint32_t, 3>>;
Neighbors edge_neighbors(const std::vector<Eigen::Vector3d>& vertices, const std::vector<Triangle>& triangles);

// Flips whole connected components so that normals point out of the solid: a component
// must enclose positive volume unless it lies inside an odd number of other components
// (a cavity), which the generalised winding number (sum of solid angles, van Oosterom &
// Strackee 1983) decides. Returns the triangles flipped, per component.
std::vector<std::size_t> orient_outward(const std::vector<Eigen::Vector3d>& vertices, std::vector<Triangle>& triangles,
                                        const Neighbors& neighbors);

}  // namespace cosim::geometry::detail
