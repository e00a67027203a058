#pragma once
// The flights of the algorithms part: the robustness test's adversarial moves
// (tests/tracker/tracking/hard_moves.hpp), and straight traversals for timing.

#include "tests/tracker/tracking/hard_moves.hpp"  // tests/tracker/tracking (cosim_tracking_hard_moves)
#include "tracker/tracking/move.hpp"

#include <vector>

namespace cosim::bench {

using Flight = tracker::tracking::testing::Flight;

std::vector<Flight> hard_moves(const tracker::mesh::Mesh& mesh, int count, tracker::tracking::Random& random);

// Straight flights for timing: a uniform random point of the box in the cell that holds it,
// an isotropic unit velocity, and a flight of `length` (walls reflect).
std::vector<Flight> traversals(const tracker::tracking::Domain& domain, int count, double length,
                               tracker::tracking::Random& random);

}  // namespace cosim::bench
