#pragma once
// A rank's part of a mesh: the cells it owns, then layers of their face neighbours (ghosts)
// owned by other ranks. Particles move only in owned cells: a move that enters a ghost
// stops there and goes on on the ghost's owner (tracking/handover.hpp), so the first layer
// is what a crossing needs. The second is there for the obstacles: a cell's registration
// depends on its neighbours' (the ring, bounding/cell_object.hpp), and with both layers a
// first-layer ghost is registered as its owner registers it, so the particle's logical
// states mean the same on both ranks.

#include <functional>
#include <utility>
#include <vector>

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::mesh {

// The cells of `whole` that `owner` gives to `rank`, then `layers` layers of ghosts, each
// in the whole's order, with their faces, vertices and geometry as in the whole (Mesh::global,
// ghosts, whole_diagonal set).
Mesh extract_part(const Mesh& whole, const std::function<int(Index)>& owner, int rank, int layers = 2);

// A part's cell numbers from the whole's.
class PartCells {
 public:
  explicit PartCells(const Mesh& part);
  // The part's number of whole cell `global`, or -1 if the part does not have it.
  Index local(Index global) const;

 private:
  std::vector<std::pair<Index, Index>> by_global_;  // (global, local), ascending
};

}  // namespace cosim::tracker::mesh
