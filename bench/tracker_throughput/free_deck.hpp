#pragma once
// SPARTA's `free` deck as docs/references.md describes it: a box of N^3 cubic cells of 1e-5 m
// with specular walls, argon at 273.15 K at rest, a number of particles per cell at
// uniform random positions with Maxwellian velocities, no collisions.

#include "tracker/tracking/move.hpp"

#include <memory>
#include <vector>

namespace cosim::bench {

struct FreeDeck {
  static constexpr double kCellWidth = 1e-5;      // m
  static constexpr double kMass = 6.63e-26;       // kg, argon
  static constexpr double kTemperature = 273.15;  // K
  static constexpr double kUnsortDt = 7e-8;       // s, 30 steps of about 2.7 cells each
  static constexpr double kTimedDt = 7e-9;        // s, about 0.27 cells per step
  static constexpr int kUnsortSteps = 30;
  static constexpr double kCollideWeight = 7.07e6;  // SPARTA's collide deck: nrho 7.07e22 at 10 per cell

  int cells = 46;  // per side
  int per_cell = 10;

  long long particle_count() const { return static_cast<long long>(cells) * cells * cells * per_cell; }
};

// The mesh and the walls: the Domain and the obstacles keep a reference to the mesh, so
// they live together (and the box does not move).
struct FreeBox {
  explicit FreeBox(const FreeDeck& deck);
  FreeBox(const FreeBox&) = delete;
  tracker::mesh::Mesh mesh;
  std::unique_ptr<tracker::tracking::Domain> domain;
  // The 790-ball cluster of Table 1 (tracker_study) scaled to the box: one specular wall.
  tracker::tracking::Obstacles cluster;
};

// per_cell particles in every cell, cell by cell (so sorted by cell until they move).
std::vector<tracker::tracking::Particle> fill(const FreeDeck& deck, tracker::tracking::Random& random);

}  // namespace cosim::bench
