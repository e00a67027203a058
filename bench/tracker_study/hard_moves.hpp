#pragma once
// The adversarial moves of tests/tracker/tracking/robustness_test.cpp: a start on a vertex,
// an edge or inside a face of a random cell (on a perturbed mesh often just outside that
// cell), running isotropically, exactly at a vertex of the cell, or along the face, for up to
// three cell widths at unit speed.

#include "tracker/tracking/move.hpp"

#include <vector>

namespace cosim::bench {

struct Flight {
  tracker::Particle particle;
  double dt;
};

std::vector<Flight> hard_moves(const tracker::Mesh& mesh, int count, tracker::Random& random);

// Straight flights for timing: a uniform random point of the box in the cell that holds it,
// an isotropic unit velocity, and a flight of `length` (walls reflect).
std::vector<Flight> traversals(const tracker::Domain& domain, int count, double length, tracker::Random& random);

}  // namespace cosim::bench
