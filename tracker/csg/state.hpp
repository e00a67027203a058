#pragma once

#include <cstdint>

namespace cosim::tracker::csg {

// A particle's logical state for one object: bit i set = inside the object's primitive i
// (local index). 8 bytes, so an object has at most 64 primitives; the bounding volumes of
// the mesh will keep the local count per cell far below that. Only events change it.
using State = std::uint64_t;
inline constexpr int max_primitives = 64;

constexpr State bit(int primitive) { return State{1} << primitive; }
constexpr bool test(State state, int primitive) { return (state & bit(primitive)) != 0; }

}  // namespace cosim::tracker::csg
