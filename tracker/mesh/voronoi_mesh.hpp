#pragma once
// Voronoi meshes of a point set in a box (voro++).

#include "tracker/mesh/mesh.hpp"

#include <array>
#include <span>

namespace cosim::tracker::mesh {

struct VoronoiSpec {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Ones();
  // A periodic axis has no walls: cells cross the box side and link to the neighbours'
  // images on the other side (Face::shift).
  std::array<bool, 3> periodic{false, false, false};
};

// Cell i is the Voronoi cell of points[i], clipped by the walls of the non-periodic axes
// (patches x_min ... z_max as for box_mesh). Vertices that coincide to 1e-10 of the box
// size are shared. Throws std::invalid_argument for points outside the box, coincident
// points, or a mesh that fails validation.
Mesh voronoi_mesh(std::span<const Vec3> points, const VoronoiSpec& spec);

}  // namespace cosim::tracker::mesh
