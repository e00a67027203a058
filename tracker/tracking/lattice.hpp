#pragma once
// Axis-aligned hexahedral cells, a box mesh's (graded or not): each face lies in a plane
// x_a = const, and fit_geometry gives it an inward normal of exactly +e_a or -e_a (two
// components 0, the third +-1: the area vector of a face whose vertices share x_a has zero
// components elsewhere, and c / sqrt(c^2) is +-1). Then n.v is +-v_a and n.(x - point)
// is +-(x_a - point_a) to the bit (a zero's sign aside; for finite x and v: the general
// scan's 0 * inf is NaN), so the face a path leaves through
// is found from three coordinates instead of six dot products, with the same times, face
// and `behind` as the general scan (detail::first_exit).

#include "tracker/mesh/mesh.hpp"

#include <cstdint>
#include <vector>

namespace cosim::tracker::tracking {

// Where such a cell's faces are in its face list. The scan reads the planes' coordinates
// from the faces themselves: a copy per cell would be one more record to bring into the
// cache on every crossing, and it measured slower (bench/tracker_throughput/README.md).
struct LatticeFaces {
  // low[a]: the face with inward normal +e_a (the low side of axis a), high[a]: the one
  // with -e_a. low[0] < 0: the cell is not such a hexahedron.
  std::int8_t low[3];
  std::int8_t high[3];
  bool holds() const { return low[0] >= 0; }
};

// Every cell's, or none if no cell is an axis-aligned hexahedron.
std::vector<LatticeFaces> lattice_faces(const mesh::Mesh& mesh);

}  // namespace cosim::tracker::tracking
