#pragma once
// One interface to the three tracking algorithms, so studies compare them on the same
// particles. See README.md for the rules of each.

#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/obstacles.hpp"

#include <array>
#include <string>
#include <string_view>

namespace cosim::tracker {

enum class Algorithm {
  event_driven,  // ours: earliest dt >= 0 with f <= 0 and f' < 0; never loses a particle
  stollmeier,    // Stollmeier & Grabe: first face intersection, one reassignment at the end
  haselbacher,   // Haselbacher, Najjar & Ferry: face intersection, in-cell test per crossing
};

std::string_view name(Algorithm algorithm);

// Moves the particle ballistically for dt through the mesh, crossing faces (periodic
// shifts applied) and handling walls; a removed particle stays where it left.
MoveResult move(Algorithm algorithm, const Domain& domain, Particle& particle, double dt, Random& random);

// The event-driven move among CSG obstacles: `states` holds the particle's logical state
// per object (kept up to date), `tallies` one entry per object (added to). The face and
// object events of the cell are merged in time order; a wall's boundary event reflects or
// absorbs the particle (`removed`), a zone's is crossed and counted. `patches`, if not
// empty, holds one tally per boundary condition of the domain (Boundaries::patches), added
// to at every hit of a boundary face of that patch.
MoveResult move(const Domain& domain, const Obstacles& obstacles, Particle& particle, std::span<csg::State> states,
                double dt, Random& random, std::span<ObstacleTally> tallies, std::span<SurfaceTally> patches = {});

// Sums of MoveResults over many moves, for studies and tests.
struct MoveTally {
  long long moves = 0, faces_crossed = 0, zero_time_events = 0, boundary_hits = 0, relocations = 0,
            cycles_broken = 0, stalled = 0, removed = 0, lost = 0, object_events = 0, primitive_tests = 0;
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

}  // namespace cosim::tracker
