// The initial particles (participants.tracker.options.particles):
//
//   particles:
//     per_cell: 20           # particles per cell, or
//     total: 10000           # in all, cells drawn by volume (exactly one of the two)
//     temperature: 300       # K: Maxwellian velocities about the drift (0: all at the drift)
//     drift: [400, 0, 0]     # m/s, optional
//     mass: 6.63e-26         # kg, also what diffuse walls re-emit with
//     weight: 1e10           # optional: real molecules per simulator (fnum), default 1
//     seed: 1                # optional: of every random draw of the run
//
// How the particles are drawn from these: seed_particles.hpp.
#pragma once

#include <cstdint>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "tracker/tracking/particle.hpp"

namespace cosim::tracker {

struct Seeding {
  int per_cell = 0;
  int total = 0;
  double temperature = 0.0;
  Vec3 drift = Vec3::Zero();
  double mass = 0.0;
  double weight = 1.0;  // real molecules per simulator (fnum)
  std::uint64_t seed = 1;
};

Seeding read_seeding(const scene::Reader& particles);

}  // namespace cosim::tracker
