#pragma once
// Structured hexahedral (or Kuhn-split tetrahedral) meshes of a box.

#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/mesh.hpp"

#include <array>
#include <vector>

namespace cosim::tracker::mesh {

// The nodes along one axis: `cells` cells from `min` to `max` whose widths grow
// geometrically by `ratio` = last width / first width (1: uniform), or, if `nodes` is not
// empty, exactly those node coordinates (increasing; min, max and cells are then ignored).
struct AxisSpacing {
  double min = 0.0;
  double max = 1.0;
  int cells = 1;
  double ratio = 1.0;
  std::vector<double> nodes{};
};

struct BoxSpec {
  std::array<AxisSpacing, 3> axes;
  // Six tetrahedra per hexahedron around its main diagonal (Kuhn/Freudenthal): every
  // hexahedron is split the same way, so the diagonals of shared faces match.
  bool tetrahedra = false;
  // A periodic axis links its two sides face to face (Face::shift, the axis's length): its
  // patches keep their names but have no faces.
  std::array<bool, 3> periodic{false, false, false};
};

// Patches 0..5 are x_min, x_max, y_min, y_max, z_min, z_max. Cell order: x fastest, then
// y, then z (times 6 tetrahedra when split). Throws std::invalid_argument on a bad spec.
Mesh box_mesh(const BoxSpec& spec);
// Its cells as face loops before assembly, in box_mesh's order: no face geometry, no
// connectivity, no periodic links (what a picture of the cells needs).
Polyhedra box_polyhedra(const BoxSpec& spec);
// The unit cube in cells^3 equal hexahedra (or six tetrahedra each).
BoxSpec cube(int cells, bool tetrahedra = false);

std::vector<double> axis_nodes(const AxisSpacing& axis);

// A cell of box_mesh's numbering (`hexahedra` per axis, `per_hex` cells in each: 1, or 6
// tetrahedra): its hexahedron's indices and its place in it, and back.
struct BoxCell {
  std::array<int, 3> hex;
  int within = 0;
};
inline BoxCell box_cell(Index cell, const std::array<int, 3>& hexahedra, int per_hex) {
  const Index h = cell / per_hex;
  return {{h % hexahedra[0], h / hexahedra[0] % hexahedra[1], h / (hexahedra[0] * hexahedra[1])}, cell % per_hex};
}
inline Index box_cell_index(const BoxCell& c, const std::array<int, 3>& hexahedra, int per_hex) {
  return ((c.hex[2] * hexahedra[1] + c.hex[1]) * hexahedra[0] + c.hex[0]) * per_hex + c.within;
}

}  // namespace cosim::tracker::mesh
