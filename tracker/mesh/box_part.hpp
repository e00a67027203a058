#pragma once
// A rank's part (part.hpp) of a structured box mesh, built without the whole: the box of its
// hexahedra and three more layers around them (wrapping a periodic axis by taking all of it),
// from which the part is taken as from the whole. Faces, vertices and geometry are those of
// box_mesh(spec) to the bit, so each rank builds and stores O(its cells).

#include <array>
#include <functional>

#include "tracker/mesh/box_mesh.hpp"

namespace cosim::tracker::mesh {

// The part of box_mesh(spec) that `owner` (a cell's rank, by the whole's cell numbers) gives
// `rank`, whose cells are the hexahedra [lo, hi) (or their tetrahedra); std::invalid_argument
// for an empty or out-of-range brick.
Mesh box_part(const BoxSpec& spec, const std::array<int, 3>& lo, const std::array<int, 3>& hi,
              const std::function<int(Index)>& owner, int rank);

}  // namespace cosim::tracker::mesh
