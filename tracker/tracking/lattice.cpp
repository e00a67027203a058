#include "tracker/tracking/lattice.hpp"

namespace cosim::tracker::tracking {

namespace {

constexpr LatticeFaces kNotLattice{{-1, -1, -1}, {-1, -1, -1}};

LatticeFaces of_cell(const mesh::Mesh& mesh, Index cell) {
  const Index first = mesh.cell_faces[cell];
  if (mesh.cell_faces[cell + 1] - first != 6) return kNotLattice;
  LatticeFaces found = kNotLattice;
  for (std::int8_t k = 0; k < 6; ++k) {
    const Vec3& n = mesh.faces[first + k].normal;
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (n[a] == 0.0) continue;
      if (axis >= 0 || (n[a] != 1.0 && n[a] != -1.0)) return kNotLattice;
      axis = a;
    }
    if (axis < 0) return kNotLattice;
    std::int8_t& slot = n[axis] > 0.0 ? found.low[axis] : found.high[axis];
    if (slot >= 0) return kNotLattice;
    slot = k;
  }
  return found;  // six faces, each axis once per side: every slot is filled
}

}  // namespace

std::vector<LatticeFaces> lattice_faces(const mesh::Mesh& mesh) {
  std::vector<LatticeFaces> cells(static_cast<std::size_t>(mesh.cell_count()));
  bool any = false;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    cells[static_cast<std::size_t>(c)] = of_cell(mesh, c);
    any = any || cells[static_cast<std::size_t>(c)].holds();
  }
  if (!any) cells.clear();
  return cells;
}

}  // namespace cosim::tracker::tracking
