#include "tracker/tracking/implicit_lattice.hpp"

#include <algorithm>
#include <bit>

namespace cosim::tracker::tracking {

namespace {

// box_mesh's face order: x low, x high, y low, y high, z low, z high.
bool in_box_order(const mesh::Mesh& mesh, const std::vector<LatticeFaces>& lattice, Index cell) {
  const LatticeFaces& faces = lattice[static_cast<std::size_t>(cell)];
  return mesh.cell_faces[cell] == 6 * cell && faces.low[0] == 0 && faces.high[0] == 1 && faces.low[1] == 2 &&
         faces.high[1] == 3 && faces.low[2] == 4 && faces.high[2] == 5;
}

// The cells along `axis` from cell 0, following the high faces' unshifted links.
Index run(const mesh::Mesh& mesh, const std::vector<LatticeFaces>& lattice, int axis, Index stride) {
  Index n = 1;
  for (Index c = 0; in_box_order(mesh, lattice, c); c += stride, ++n) {
    const mesh::Face& high = mesh.faces[6 * c + 2 * axis + 1];
    if (high.neighbour != c + stride || high.shift != 0) break;
  }
  return n;
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

}  // namespace

ImplicitLattice::ImplicitLattice(const mesh::Mesh& mesh, const std::vector<LatticeFaces>& lattice) {
  // Particles move in a part's own cells only, which are not numbered as a lattice.
  const Index count = mesh.cell_count();
  if (lattice.empty() || mesh.ghosts > 0 || count == 0 || !in_box_order(mesh, lattice, 0)) return;
  cells_[0] = run(mesh, lattice, 0, 1);
  cells_[1] = run(mesh, lattice, 1, cells_[0]);
  cells_[2] = run(mesh, lattice, 2, cells_[0] * cells_[1]);
  if (static_cast<long long>(cells_[0]) * cells_[1] * cells_[2] != count) return;
  stride_ = {1, cells_[0], cells_[0] * cells_[1]};
  // The planes as the faces' points have them (a face's vertex mean, which need not be the
  // node coordinate to the bit), from the cells along each axis from cell 0.
  for (int a = 0; a < 3; ++a)
    for (Index i = 0; i < cells_[a]; ++i) {
      const Index c = i * stride_[a];
      if (!in_box_order(mesh, lattice, c)) return;
      planes_[a].push_back(mesh.faces[6 * c + 2 * a].point[a]);
      if (i + 1 == cells_[a]) planes_[a].push_back(mesh.faces[6 * c + 2 * a + 1].point[a]);
    }
  flags_.assign(static_cast<std::size_t>(count), 0);
  for (Index c = 0; c < count; ++c) {
    if (!in_box_order(mesh, lattice, c)) continue;
    const Place at = place(c);
    std::uint8_t flags = kPlain;
    for (Index k = 0; k < 6 && flags != 0; ++k) {
      const int a = k / 2, side = k % 2;
      const mesh::Face& face = mesh.faces[6 * c + k];
      if (!same_bits(face.point[a], plane(a, at.index[a] + side))) flags = 0;
      const int beyond = at.index[a] + (side != 0 ? 1 : -1);
      if (flags == 0 || beyond < 0 || beyond >= cells_[a]) continue;  // the record says what is there
      const Index n = neighbour(c, 6 * c + k);
      if (face.neighbour == n && face.shift == 0 && face.twin == twin(n, c, 6 * c + k))
        flags = static_cast<std::uint8_t>(flags | 1 << k);
    }
    flags_[static_cast<std::size_t>(c)] = flags;
  }
  if (std::none_of(flags_.begin(), flags_.end(), [](std::uint8_t f) { return f != 0; })) *this = {};
}

}  // namespace cosim::tracker::tracking
