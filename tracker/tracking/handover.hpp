#pragma once
// Particles whose move entered a ghost cell of the rank's part (Mesh::ghosts) part-way, each
// with the rest of its move: they go to the ghost's owner (parallel/migration.hpp), which
// goes on with them as one rank would have, and hands over again those that leave its cells
// in turn, until every move of the step is done (SPARTA's move does the same in passes).
// Velocities are kept in double, as the move has them, not in the Swarm's float.

#include "tracker/tracking/swarm.hpp"

#include <vector>

namespace cosim::tracker::tracking {

class Handover {
 public:
  explicit Handover(int objects) : objects_(objects) {}

  int objects() const { return objects_; }
  std::size_t size() const { return particles_.size(); }
  const Particle& particle(std::size_t i) const { return particles_[i]; }
  std::span<const csg::State> states(std::size_t i) const {
    return {states_.data() + i * objects_, static_cast<std::size_t>(objects_)};
  }
  const Flight& flight(std::size_t i) const { return flights_[i]; }
  void add(const Particle& particle, std::span<const csg::State> states, const Flight& rest);
  void clear();
  // After a move: true if the particle stays in its swarm, false if the move handed it
  // over (it is added here) or removed it. One that stays in a ghost (a recovery put it
  // there, not a crossing) is counted: it migrates at the start of the next step.
  bool keeps(const MoveResult& result, const Particle& particle, std::span<const csg::State> states,
             const mesh::Mesh& mesh);
  long long strays() const { return strays_; }
  void forget_strays() { strays_ = 0; }

  // Goes on with every particle's move (each in one of this rank's cells) in `step`: those
  // that end it here join `swarm`, those that enter a ghost again replace the handover's
  // particles (step.away is not used).
  void resume_all(const MoveContext& step, Swarm& swarm);

 private:
  int objects_;
  std::vector<Particle> particles_;
  std::vector<csg::State> states_;
  std::vector<Flight> flights_;
  long long strays_ = 0;
};

}  // namespace cosim::tracker::tracking
