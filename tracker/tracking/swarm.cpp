#include "tracker/tracking/swarm.hpp"

#include "tracker/tracking/detail/algorithms.hpp"
#include "tracker/tracking/handover.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker::tracking {

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
  copy_states(states_.data() + from * objects_, states_.data() + to * objects_);
}

void Swarm::move_all(const MoveContext& step, double dt) {
  const Domain& domain = step.domain;
  const Obstacles& obstacles = step.obstacles;
  const std::span<ObstacleTally> tallies = step.tallies;
  const std::span<SurfaceTally> patches = step.patches;
  Handover* const away = step.away;
  detail::check_carried(domain, obstacles, static_cast<std::size_t>(objects_), tallies.size(), patches.size());
  if (domain.mesh.ghosts > 0 && away == nullptr)
    throw std::invalid_argument("Swarm::move_all: a part of a mesh needs a handover for the moves that leave it");
  const detail::Carried any_particle{&obstacles, {}, tallies, patches};
  // The removed ones are dropped as the loop goes: each kept particle moves down at most once.
  std::size_t kept = 0;
  long long inside = 0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    if (kept != i) copy_states(states_.data() + i * objects_, states_.data() + kept * objects_);
    // Most moves stay inside their cell: on the stored record, without the detour through a
    // Particle and a MoveResult (the same x + dt v the event loop computes for them).
    const StoredParticle& s = particles_[i];
    const Vec3 end = Vec3(s.x[0], s.x[1], s.x[2]) + dt * Vec3(s.v[0], s.v[1], s.v[2]);
    if (detail::ends_inside(domain, any_particle, s.cell, end)) {
      particles_[kept] = {{end[0], end[1], end[2]}, {s.v[0], s.v[1], s.v[2]}, s.cell};
      ++kept;
      ++inside;
      continue;
    }
    Particle p = particle(i);
    const MoveResult result =
        detail::follow_events(domain, p, dt, step.random, {&obstacles, states(kept), tallies, patches});
    step.moves.add(result);
    if (away == nullptr ? !result.removed : away->keeps(result, p, states(kept), domain.mesh)) set(kept++, p);
  }
  step.moves.moves += inside;
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
    copy_states(states_.data() + i * objects_, sorted_states_.data() + to * objects_);
  }
  particles_.swap(sorted_particles_);
  states_.swap(sorted_states_);
}

}  // namespace cosim::tracker::tracking
