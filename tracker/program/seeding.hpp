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
// Read into Seeding; how the particles are drawn from it: tracker/step/seed_particles.hpp.
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/step/seed_particles.hpp"

namespace cosim::tracker {

Seeding read_seeding(const scene::Reader& particles);

}  // namespace cosim::tracker
