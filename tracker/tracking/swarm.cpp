#include "tracker/tracking/swarm.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker {

void Swarm::add(const Particle& particle, std::span<const csg::State> states) {
  if (states.size() != static_cast<std::size_t>(objects_))
    throw std::invalid_argument("Swarm::add: " + std::to_string(states.size()) + " states for " +
                                std::to_string(objects_) + " obstacles");
  particles_.emplace_back();
  set(particles_.size() - 1, particle);
  states_.insert(states_.end(), states.begin(), states.end());
}

void Swarm::keep(std::size_t from, std::size_t to) {
  if (from == to) return;
  particles_[to] = particles_[from];
  std::copy_n(states_.begin() + static_cast<long>(from * objects_), objects_, states_.begin() + static_cast<long>(to * objects_));
}

void Swarm::move_all(const Domain& domain, const Obstacles& obstacles, double dt, Random& random, MoveTally& moves,
                     std::span<ObstacleTally> tallies, std::span<SurfaceTally> patches) {
  // The removed ones are dropped as the loop goes: each kept particle moves down at most once.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    Particle p = particle(i);
    const MoveResult result = move(domain, obstacles, p, states(i), dt, random, tallies, patches);
    moves.add(result);
    if (result.removed) continue;
    // Straight into its kept slot: after a removal the record would otherwise be written twice.
    if (kept != i)
      std::copy_n(states_.begin() + static_cast<long>(i * objects_), objects_,
                  states_.begin() + static_cast<long>(kept * objects_));
    set(kept++, p);
  }
  particles_.resize(kept);
  states_.resize(kept * objects_);
}

void Swarm::sort_by_cell(Index cells) {
  // Into the scratch arrays kept from the last sort, so a step allocates nothing.
  std::vector<std::size_t>& start = sort_start_;
  start.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (const StoredParticle& p : particles_) ++start[static_cast<std::size_t>(p.cell) + 1];
  for (std::size_t c = 0; c < static_cast<std::size_t>(cells); ++c) start[c + 1] += start[c];
  sorted_particles_.resize(particles_.size());
  sorted_states_.resize(states_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    const std::size_t to = start[static_cast<std::size_t>(particles_[i].cell)]++;
    sorted_particles_[to] = particles_[i];
    std::copy_n(states_.begin() + static_cast<long>(i * objects_), objects_,
                sorted_states_.begin() + static_cast<long>(to * objects_));
  }
  particles_.swap(sorted_particles_);
  states_.swap(sorted_states_);
}

}  // namespace cosim::tracker
