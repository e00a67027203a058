#pragma once
// The particles of a run with their logical states (one per obstacle, stored next to each
// other per particle), moved together and kept in cell order for the cache. A particle is
// stored in 40 bytes: position in double, velocity in float (7 digits, as much as a DSMC
// velocity means; a specular reflection off an axis-aligned wall flips a sign and stays
// exact), cell; the tracking itself computes in double.

#include "tracker/tracking/move.hpp"

#include <algorithm>
#include <span>
#include <vector>

namespace cosim::tracker::tracking {

struct StoredParticle {
  double x[3];
  float v[3];
  Index cell;
};
static_assert(sizeof(StoredParticle) == 40);

class Swarm {
 public:
  explicit Swarm(int objects) : objects_(objects) {}

  std::size_t size() const { return particles_.size(); }
  int objects() const { return objects_; }
  Particle particle(std::size_t i) const {
    const StoredParticle& s = particles_[i];
    return {{s.x[0], s.x[1], s.x[2]}, {s.v[0], s.v[1], s.v[2]}, s.cell};
  }
  void set(std::size_t i, const Particle& p) {
    particles_[i] = {{p.x[0], p.x[1], p.x[2]},
                     {static_cast<float>(p.v[0]), static_cast<float>(p.v[1]), static_cast<float>(p.v[2])},
                     p.cell};
  }
  Index cell(std::size_t i) const { return particles_[i].cell; }
  std::span<csg::State> states(std::size_t i) {
    return {states_.data() + i * objects_, static_cast<std::size_t>(objects_)};
  }
  std::span<const csg::State> states(std::size_t i) const {
    return {states_.data() + i * objects_, static_cast<std::size_t>(objects_)};
  }

  void add(const Particle& particle, std::span<const csg::State> states);
  // Every particle's cell c becomes to(c) (another numbering of the same cells).
  template <typename To>
  void renumber_cells(const To& to) {
    for (StoredParticle& p : particles_) p.cell = to(p.cell);
  }
  // Drops the particles for whose index `removed` is true, keeping the others' order.
  template <typename Removed>
  void remove_if(const Removed& removed) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < particles_.size(); ++i)
      if (!removed(i)) keep(i, kept++);
    particles_.resize(kept);
    states_.resize(kept * objects_);
  }
  // Moves every particle by dt with the event-driven algorithm, drops the removed ones and
  // adds what happened to the step's tallies (move()). On a part of a mesh (Mesh::ghosts) a
  // move that enters a ghost stops there: the particle leaves the swarm for step.away with
  // the rest of its move (std::invalid_argument if the mesh has ghosts and there is no
  // handover).
  void move_all(const MoveContext& step, double dt);
  // Counting sort by cell (stable), as DSMC codes keep their particles: the particles of a
  // cell, and the cell's faces, are then together in memory.
  void sort_by_cell(Index cells);
  // Bytes per particle: the stored record and its states.
  std::size_t bytes_per_particle() const { return sizeof(StoredParticle) + objects_ * sizeof(csg::State); }

 private:
  void keep(std::size_t from, std::size_t to);
  // One particle's states. Most runs have one obstacle or a few: a call of memmove per
  // particle would cost more than the copy (5 % of the sphere deck's time).
  void copy_states(const csg::State* from, csg::State* to) const {
    if (objects_ == 1)
      *to = *from;
    else if (objects_ > 1)
      std::copy_n(from, objects_, to);
  }

  int objects_;
  std::vector<StoredParticle> particles_;
  // sort_by_cell's scratch, kept between calls (the previous order ends up here).
  std::vector<StoredParticle> sorted_particles_;
  std::vector<csg::State> sorted_states_;
  std::vector<std::size_t> sort_start_;
  std::vector<csg::State> states_;
};

}  // namespace cosim::tracker::tracking
