#include "tracker/tracking/move.hpp"

#include "tracker/tracking/detail/algorithms.hpp"

#include <sstream>

namespace cosim::tracker {

std::string_view name(Algorithm algorithm) {
  switch (algorithm) {
    case Algorithm::event_driven: return "event-driven";
    case Algorithm::stollmeier: return "stollmeier";
    case Algorithm::haselbacher: return "haselbacher";
  }
  return "?";
}

MoveResult move(Algorithm algorithm, const Domain& domain, Particle& particle, double dt, Random& random) {
  switch (algorithm) {
    case Algorithm::event_driven: return detail::move_event_driven(domain, particle, dt, random);
    case Algorithm::stollmeier:
      return detail::move_face_intersection(domain, particle, dt, random, detail::Recovery::first_violated_face);
    case Algorithm::haselbacher:
      return detail::move_face_intersection(domain, particle, dt, random, detail::Recovery::neighbour_search);
  }
  return {};
}

void MoveTally::add(const MoveResult& result) {
  ++moves;
  faces_crossed += result.faces_crossed;
  zero_time_events += result.zero_time_events;
  boundary_hits += result.boundary_hits;
  relocations += result.relocations;
  cycles_broken += result.cycles_broken;
  stalled += result.stalled;
  removed += result.removed;
  lost += result.lost;
}

std::string summary(const MoveTally& tally) {
  std::ostringstream out;
  out << tally.moves << " moves: lost " << tally.lost << ", faces crossed " << tally.faces_crossed
      << ", zero-time events " << tally.zero_time_events << ", boundary hits " << tally.boundary_hits
      << ", relocations " << tally.relocations << ", cycles broken " << tally.cycles_broken << ", stalled " << tally.stalled << ", removed " << tally.removed;
  return out.str();
}

}  // namespace cosim::tracker
