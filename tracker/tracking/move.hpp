#pragma once
// One interface to the three tracking algorithms, so studies compare them on the same
// particles. See README.md for the rules of each.

#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/obstacles.hpp"

#include <array>
#include <span>
#include <string>
#include <string_view>

namespace cosim::tracker::tracking {

enum class Algorithm {
  event_driven,  // ours: earliest dt >= 0 with f <= 0 and f' < 0; never loses a particle
  stollmeier,    // Stollmeier & Grabe: first face intersection, one reassignment at the end
  haselbacher,   // Haselbacher, Najjar & Ferry: face intersection, in-cell test per crossing
};

std::string_view name(Algorithm algorithm);

// Moves the particle ballistically for dt through the mesh, crossing faces (periodic
// shifts applied) and handling walls; a removed particle stays where it left.
MoveResult move(Algorithm algorithm, const Domain& domain, Particle& particle, double dt, Random& random);

// Sums of MoveResults over many moves, for studies and tests.
struct MoveTally {
  long long moves = 0, faces_crossed = 0, zero_time_events = 0, boundary_hits = 0, relocations = 0, cycles_broken = 0,
            stalled = 0, removed = 0, lost = 0, object_events = 0, primitive_tests = 0;
  void add(const MoveResult& result);
  // The rest of a move handed over by another rank (Handover): counted as a move there.
  void add_rest(const MoveResult& result);
};
std::string summary(const MoveTally& tally);
// Its counters by name, in one order: run-file columns, state arrays, sums over ranks.
struct MoveCounter {
  const char* name;
  long long MoveTally::*count;
};
inline constexpr std::array<MoveCounter, 11> kMoveCounters{{{"moves", &MoveTally::moves},
                                                            {"faces_crossed", &MoveTally::faces_crossed},
                                                            {"zero_time_events", &MoveTally::zero_time_events},
                                                            {"boundary_hits", &MoveTally::boundary_hits},
                                                            {"relocations", &MoveTally::relocations},
                                                            {"cycles_broken", &MoveTally::cycles_broken},
                                                            {"stalled", &MoveTally::stalled},
                                                            {"removed", &MoveTally::removed},
                                                            {"lost", &MoveTally::lost},
                                                            {"object_events", &MoveTally::object_events},
                                                            {"primitive_tests", &MoveTally::primitive_tests}}};

class Handover;

// What the moves of a step share: where particles move (the mesh with its walls, the CSG
// obstacles), the step's random stream, and what the moves add to: the move tally, one
// tally per obstacle, one per boundary condition of the domain (Boundaries::patches; none:
// not counted) and, on a part of a mesh (Mesh::ghosts), the handover that takes the moves
// that leave it for a ghost (handover.hpp).
struct MoveContext {
  const Domain& domain;
  const Obstacles& obstacles;
  Random& random;
  MoveTally& moves;
  std::span<ObstacleTally> tallies = {};
  std::span<SurfaceTally> patches = {};
  Handover* away = nullptr;
};

// The event-driven move among CSG obstacles: `states` holds the particle's logical state
// per object (kept up to date). The face and object events of the cell are merged in time
// order; a wall's boundary event reflects or absorbs the particle (`removed`), a zone's is
// crossed and counted. Adds the result to step.moves and the hits to step.tallies and
// step.patches; leaves step.away to the caller. Throws std::invalid_argument unless there
// are a state and a tally per obstacle and the patches' tallies are none or one per
// boundary condition.
MoveResult move(const MoveContext& step, Particle& particle, std::span<csg::State> states, double dt);

}  // namespace cosim::tracker::tracking
