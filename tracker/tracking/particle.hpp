#pragma once
// A ballistic particle as the tracking sees it, and what one move did to it.

#include "tracker/mesh/mesh.hpp"

#include <random>

namespace cosim::tracker::tracking {

// One generator per caller (thread); only diffuse and Maxwell walls draw from it.
using Random = std::mt19937_64;

struct Particle {
  Vec3 x;
  Vec3 v;
  Index cell;  // always a valid cell: the tracking never leaves it undefined
};

// The rest of a move that entered a ghost of a rank's part (Mesh::ghosts, mesh/part.hpp):
// the ghost's owner goes on with it from there (handover.hpp), as one rank would.
struct Flight {
  double remaining = 0.0;  // time left
  int entered = -1;        // the face it came in through, as its cell's k-th face; -1: none
  int streak = 0;          // zero-time events in a row so far (the event loop's cycle guard)
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
  bool handed_over = false;  // stopped in a ghost cell: `rest` is what is left of the move
  Flight rest;
};

}  // namespace cosim::tracker::tracking
