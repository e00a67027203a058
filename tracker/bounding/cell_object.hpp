// A CSG object seen through the tracking mesh (Strobl, Bannerman & Pöschel): every cell knows
// only the primitives whose surface may pass through it or through one of its face
// neighbours, and a tree pruned to those, so a particle's logical state holds bits for its
// cell's primitives alone (local indices, at most csg::max_primitives per cell, however many
// the object has) and an event search looks at a handful of primitives instead of all.
//
// A primitive left out of a cell is constant there (the cell is wholly inside or outside
// it), and a primitive a cell has but its neighbour lacks is at least a cell away from the
// face between them: so when a particle crosses that face, the bits of the primitives both
// cells share are carried over and the others are evaluated directly, far from any surface.
// Cell boxes are enlarged by `margin` (relative to their diagonal) so that round-off in
// that test cannot leave out a surface that touches a cell.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tracker/csg/tree.hpp"
#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::bounding {

struct CellObjectStats {
  double mean_primitives = 0;  // per cell
  int max_primitives = 0;
  Index constant_cells = 0;  // cells where the object cannot change (no events)
};

class CellObject {
 public:
  // Throws std::invalid_argument naming the cell when a cell would need more primitives than
  // a logical state holds (a finer mesh, or fewer primitives near there, helps).
  CellObject(const mesh::Mesh& mesh, const csg::Tree& object, double margin = 1e-9);

  // The cell's primitives as indices into the object's, ascending; local index = position.
  std::span<const int> primitives(Index cell) const;
  // The object in the cell over local indices: evaluate() a local state with it.
  const csg::Tree& tree(Index cell) const {
    return trees_[static_cast<std::size_t>(tree_of_[static_cast<std::size_t>(cell)])];
  }
  // A particle's local state at x in `cell` by direct evaluation: away from surfaces only.
  csg::State classify(Index cell, const Vec3& x) const;
  // The local state in `to` of a particle that leaves `from` with `state` through their
  // common face at x (x as `to` sees it, periodic shift applied).
  csg::State transfer(csg::State state, Index from, Index to, const Vec3& x) const;
  // The same between two registrations (an object that moved): bits of `state` over
  // `old_primitives` carried to the primitives of cell `to` here where both have them, the
  // others evaluated at x.
  csg::State carry(std::span<const int> old_primitives, csg::State state, Index to, const Vec3& x) const;

  CellObjectStats stats() const;

 private:
  std::vector<Index> first_;  // cell c's primitives are primitives_[first_[c] .. first_[c+1])
  std::vector<int> primitives_;
  // Cell c's tree is trees_[tree_of_[c]]. Only cells with primitives have their own; the
  // others share trees_[0] (always outside) or trees_[1] (always inside), so a large mesh
  // around a small object costs 4 bytes per cell.
  std::vector<std::int32_t> tree_of_;
  std::vector<csg::Tree> trees_;
};

}  // namespace cosim::tracker::bounding
