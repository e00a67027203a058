#include "tracker/tracking/handover.hpp"

#include "tracker/tracking/detail/algorithms.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cosim::tracker::tracking {

void Handover::add(const Particle& particle, std::span<const csg::State> states, const Flight& rest) {
  if (states.size() != static_cast<std::size_t>(objects_))
    throw std::invalid_argument("Handover::add: " + std::to_string(states.size()) + " states for " +
                                std::to_string(objects_) + " obstacles");
  particles_.push_back(particle);
  states_.insert(states_.end(), states.begin(), states.end());
  flights_.push_back(rest);
}

bool Handover::keeps(const MoveResult& result, const Particle& particle, std::span<const csg::State> states,
                     const mesh::Mesh& mesh) {
  if (result.handed_over) {
    add(particle, states, result.rest);
    return false;
  }
  if (result.removed) return false;
  strays_ += particle.cell >= mesh.own_cells();
  return true;
}

void Handover::clear() {
  particles_.clear();
  states_.clear();
  flights_.clear();
}

void Handover::resume_all(const MoveContext& step, Swarm& swarm) {
  const Domain& domain = step.domain;
  detail::check_carried(domain, step.obstacles, static_cast<std::size_t>(objects_), step.tallies.size(),
                        step.patches.size());
  Handover again(objects_);
  again.strays_ = strays_;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    Particle& p = particles_[i];
    const std::span<csg::State> states(states_.data() + i * objects_, static_cast<std::size_t>(objects_));
    const MoveResult result = detail::resume_flight(domain, p, flights_[i], step.random,
                                                    {&step.obstacles, states, step.tallies, step.patches});
    step.moves.add_rest(result);
    if (again.keeps(result, p, states, domain.mesh)) swarm.add(p, states);
  }
  *this = std::move(again);
}

}  // namespace cosim::tracker::tracking
