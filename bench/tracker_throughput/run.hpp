#pragma once
// One timed run of the free deck with one algorithm and one particle storage.

#include "bench/tracker_throughput/free_deck.hpp"
#include "tracker/tracking/swarm.hpp"

#include <string>

namespace cosim::bench {

// particle: a vector of tracker::Particle (56 bytes), moved in place by any algorithm;
// swarm: the program's tracker::Swarm (40-byte records with float velocities, plus a state
// per obstacle), event-driven, sorted by cell every `sort_every` steps.
enum class Storage { particle, swarm };

struct RunOptions {
  tracker::tracking::Algorithm algorithm = tracker::tracking::Algorithm::event_driven;
  Storage storage = Storage::particle;
  int steps = 100;       // timed, at FreeDeck::kTimedDt
  int sort_every = 0;    // swarm: sort the particles by cell every this many steps (0: never)
  bool cluster = false;  // swarm: among the sphere cluster (FreeBox::cluster)
  bool collide = false;  // swarm: SPARTA's collide deck, VSS argon collisions each step
};

struct RunResult {
  RunOptions options;
  long long particles = 0;
  double seconds = 0.0;                // wall time of the timed steps (steady_clock), sorting included
  double cpu_seconds = 0.0;            // the process's CPU time over the same steps (std::clock): on a
                                       // shared machine, the figure that does not count waiting
  double bytes_per_particle = 0;       // the stored record and states (a sort allocates a second copy while it runs)
  tracker::tracking::MoveTally tally;  // the timed steps
  long long lost = 0;                  // is_lost at the end
  long long outside = 0;               // outside their cell by more than the tolerance at the end
  double energy_drift = 0.0;           // |E_end - E_start| / E_start over the timed steps
  long long obstacle_hits = 0;         // reflections off the cluster
  long long collisions = 0;            // the collide deck's

  double moves_per_second() const { return static_cast<double>(tally.moves) / seconds; }
  double moves_per_cpu_second() const { return static_cast<double>(tally.moves) / cpu_seconds; }
};

// Times `options.steps` steps of the (already unsorted) particles; a copy is moved.
RunResult run(const FreeBox& box, const std::vector<tracker::tracking::Particle>& particles, const RunOptions& options);

std::string label(const RunOptions& options);

// The swarm's particles in its order, velocities widened to double.
std::vector<tracker::tracking::Particle> contents(const tracker::tracking::Swarm& swarm);

// Particles is_lost, and outside their cell by more than the tolerance.
struct Misplaced {
  long long lost = 0, outside = 0;
};
Misplaced misplaced(const tracker::tracking::Domain& domain, const std::vector<tracker::tracking::Particle>& particles);

}  // namespace cosim::bench
