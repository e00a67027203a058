#pragma once
// A whole box mesh of hexahedra is a tensor-product lattice: the planes of cell (i, j, k)
// are x_i, x_i+1, y_j, ... from three arrays of a few hundred bytes, and its neighbour
// across an interior face is the cell index -+ a stride. A crossing move there needs no
// face record: the records of the cells the crossings visit (384 bytes a cell, 37 MB in
// the free deck) are what the crossings waited for (bench/tracker_throughput/README.md).
//
// Exact by construction: a cell is taken as a lattice cell only where its own face records
// say what the lattice says, checked to the bit when the Domain is built (its six faces at
// 6c..6c+5 in box_mesh's order, each face's plane coordinate the array's, each linked
// neighbour, shift and twin the stride's), so the lattice scan and the crossing computed
// from the arrays read the same numbers the face records hold. Anything else (walls,
// periodic links, other ranks' cells, tetrahedra, moved vertices) keeps the records.

#include "tracker/mesh/mesh.hpp"
#include "tracker/tracking/lattice.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace cosim::tracker::tracking {

class ImplicitLattice {
 public:
  // Cell (i, j, k) of a lattice (x fastest) in a box mesh's order.
  struct Place {
    int index[3];
  };

  ImplicitLattice() = default;
  // Empty unless the mesh's cells are numbered as a lattice of axis-aligned hexahedra (a
  // whole box_mesh of hexahedra, graded or periodic or not); `lattice`: lattice_faces(mesh).
  ImplicitLattice(const mesh::Mesh& mesh, const std::vector<LatticeFaces>& lattice);

  // The cell's planes and faces are the lattice's (its face k is face 6 cell + k).
  bool plain(Index cell) const { return !flags_.empty() && (flags_[static_cast<std::size_t>(cell)] & kPlain) != 0; }
  // Face `face` of a plain cell leads into the lattice neighbour, unshifted.
  bool linked(Index cell, Index face) const {
    return plain(cell) && (flags_[static_cast<std::size_t>(cell)] >> (face - 6 * cell) & 1) != 0;
  }
  // The neighbour across a linked face, and the same face in its list (Face::twin).
  Index neighbour(Index cell, Index face) const {
    const Index k = face - 6 * cell;
    return cell + ((k & 1) != 0 ? stride_[k >> 1] : -stride_[k >> 1]);
  }
  static Index twin(Index neighbour, Index cell, Index face) { return 6 * neighbour + ((face - 6 * cell) ^ 1); }

  Place place(Index cell) const {
    // Two integer divisions instead of a per-cell record: nothing to bring from memory.
    const Index row = cell / cells_[0], layer = row / cells_[1];
    return {{cell - row * cells_[0], row - layer * cells_[1], layer}};
  }
  // The plane of axis a at node n (the low face of the cells with index n on that axis).
  double plane(int axis, int node) const { return planes_[axis][static_cast<std::size_t>(node)]; }

 private:
  static constexpr std::uint8_t kPlain = 1 << 6;  // bits 0..5: face k linked

  std::array<std::vector<double>, 3> planes_;
  std::array<Index, 3> cells_{};
  std::array<Index, 3> stride_{};
  std::vector<std::uint8_t> flags_;  // per cell, or empty
};

}  // namespace cosim::tracker::tracking
