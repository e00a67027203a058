#pragma once
// One interface to the three tracking algorithms, so studies compare them on the same
// particles. See README.md for the rules of each.

#include "tracker/tracking/domain.hpp"

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

// Sums of MoveResults over many moves, for studies and tests.
struct MoveTally {
  long long moves = 0, faces_crossed = 0, zero_time_events = 0, boundary_hits = 0, relocations = 0,
            cycles_broken = 0, stalled = 0, removed = 0, lost = 0;
  void add(const MoveResult& result);
};
std::string summary(const MoveTally& tally);

}  // namespace cosim::tracker
