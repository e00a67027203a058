#pragma once
// A ballistic particle as the tracking sees it, and what one move did to it.

#include "tracker/mesh/mesh.hpp"

#include <random>

namespace cosim::tracker {

// One generator per caller (thread); only diffuse and Maxwell walls draw from it.
using Random = std::mt19937_64;

struct Particle {
  Vec3 x;
  Vec3 v;
  Index cell;  // always a valid cell: the tracking never leaves it undefined
};

struct MoveResult {
  int faces_crossed = 0;     // interior and periodic faces
  int zero_time_events = 0;  // crossings or wall hits at dt = 0 exactly
  int boundary_hits = 0;     // wall reflections and removals
  int relocations = 0;       // cell changes by a recovery rule rather than a crossing
  int cycles_broken = 0;     // event-driven: jumps out of cycles of zero-time events
  int object_events = 0;     // CSG events executed: a primitive's bit flipped or a wall hit
  int primitive_tests = 0;   // CSG events generated: primitives whose next event was computed
  bool stalled = false;      // the remaining time was dropped (event cap, see README)
  bool removed = false;      // left through an open patch
  bool lost = false;         // ends outside its cell (is_lost in domain.hpp)
};

}  // namespace cosim::tracker
