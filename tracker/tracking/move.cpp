#include "tracker/tracking/move.hpp"

#include "tracker/tracking/detail/algorithms.hpp"

#include <sstream>
#include <stdexcept>

namespace cosim::tracker::tracking {

std::string_view name(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::event_driven:
      return "event-driven";
    case Algorithm::stollmeier:
      return "stollmeier";
    case Algorithm::haselbacher:
      return "haselbacher";
  }
  return "?";
}

MoveResult move(Algorithm algorithm, const Domain& domain, Particle& particle, double dt, Random& random) {
  switch (algorithm) {
    case Algorithm::event_driven:
      return detail::move_event_driven(domain, particle, dt, random);
    case Algorithm::stollmeier:
      return detail::move_face_intersection(domain, particle, dt, random, detail::Recovery::first_violated_face);
    case Algorithm::haselbacher:
      return detail::move_face_intersection(domain, particle, dt, random, detail::Recovery::neighbour_search);
  }
  return {};
}

namespace detail {

void check_carried(const Domain& domain, const Obstacles& obstacles, std::size_t states, std::size_t tallies,
                   std::size_t patches) {
  const auto objects = static_cast<std::size_t>(obstacles.count());
  if (states != objects || tallies != objects)
    throw std::invalid_argument("move: " + std::to_string(objects) + " obstacles but " + std::to_string(states) +
                                " states and " + std::to_string(tallies) + " tallies");
  if (patches != 0 && patches != domain.boundaries.patches.size())
    throw std::invalid_argument("move: " + std::to_string(patches) + " patch tallies for " +
                                std::to_string(domain.boundaries.patches.size()) + " boundary conditions");
  if (obstacles.emits() && !(domain.boundaries.mass > 0.0))
    throw std::invalid_argument("an obstacle re-emits particles but the particle mass is not positive");
}

}  // namespace detail

MoveResult move(const MoveContext& step, Particle& particle, std::span<csg::State> states, double dt) {
  detail::check_carried(step.domain, step.obstacles, states.size(), step.tallies.size(), step.patches.size());
  const MoveResult result = detail::move_event_driven(step.domain, particle, dt, step.random,
                                                      {&step.obstacles, states, step.tallies, step.patches});
  step.moves.add(result);
  return result;
}

void MoveTally::add(const MoveResult& result) {
  ++moves;
  add_rest(result);
}

void MoveTally::add_rest(const MoveResult& result) {
  faces_crossed += result.faces_crossed;
  zero_time_events += result.zero_time_events;
  boundary_hits += result.boundary_hits;
  relocations += result.relocations;
  cycles_broken += result.cycles_broken;
  stalled += result.stalled;
  removed += result.removed;
  lost += result.lost;
  object_events += result.object_events;
  primitive_tests += result.primitive_tests;
}

std::string summary(const MoveTally& tally) {
  std::ostringstream out;
  out << tally.moves << " moves: lost " << tally.lost << ", faces crossed " << tally.faces_crossed
      << ", zero-time events " << tally.zero_time_events << ", boundary hits " << tally.boundary_hits
      << ", relocations " << tally.relocations << ", cycles broken " << tally.cycles_broken << ", stalled "
      << tally.stalled << ", removed " << tally.removed << ", object events " << tally.object_events
      << ", primitive tests " << tally.primitive_tests;
  return out.str();
}

}  // namespace cosim::tracker::tracking
