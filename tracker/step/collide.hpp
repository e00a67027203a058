// The DSMC collisions of one step: the particles of each cell (the swarm in cell order)
// collide by the no-time-counter scheme of tracker/dsmc, with each cell's (sigma g)_max and
// fractional pair carried from step to step.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tracker/dsmc/collision.hpp"
#include "tracker/dsmc/ntc.hpp"
#include "tracker/dsmc/random.hpp"
#include "tracker/tracking/swarm.hpp"

namespace cosim::tracker::step {

struct Collisions {
  dsmc::CollisionModel model;
  bool nearest = false;  // nearest neighbour in the cell, not Bird's uniform selection
};

class CellCollider {
 public:
  // `temperature`: the gas's expected temperature, for the first (sigma g)_max of a cell;
  // `weight`: real molecules per simulator.
  CellCollider(const mesh::Mesh& mesh, const Collisions& collisions, double temperature, double weight,
               std::uint64_t seed);

  // The swarm must be sorted by cell. Returns the number of collisions.
  std::int64_t collide(tracking::Swarm& swarm, double dt);
  // Draws from here on from `stream` of `seed` (Simulation::reseed).
  void reseed(std::uint64_t seed, std::uint64_t stream) { rng_ = dsmc::make_rng(seed, stream); }
  // Per cell, for rollback and checkpoints.
  std::span<dsmc::CellCollisionState> cells() { return cells_; }
  std::span<const dsmc::CellCollisionState> cells() const { return cells_; }
  // One per cell of the mesh given at construction, which has changed (a rank's new part).
  void set_cells(std::vector<dsmc::CellCollisionState> cells) { cells_ = std::move(cells); }

 private:
  const mesh::Mesh& mesh_;
  Collisions collisions_;
  double weight_;
  std::vector<dsmc::CellCollisionState> cells_;
  dsmc::Rng rng_;
  std::vector<Vec3> velocities_, positions_;  // one cell's, reused
};

}  // namespace cosim::tracker::step
