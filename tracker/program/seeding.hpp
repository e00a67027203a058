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
// or, instead of per_cell or total, temperature and drift, gases by region (seeding_regions.hpp):
//
//   particles:
//     mass: 6.63e-26
//     weight: 1e10
//     regions: [{region: {ball: {..}}, number_density: 2.4e20, temperature: 300}, ...]
//
// Read into Seeding; how the particles are drawn from it: tracker/step/seed_particles.hpp.
#pragma once

#include <filesystem>

#include "coupler/scene/reader.hpp"
#include "tracker/step/seed_particles.hpp"

namespace cosim::tracker::program {

// `folder` and `mesh_volume` (m^3): read_seed_regions'.
step::Seeding read_seeding(const scene::Reader& particles, const std::filesystem::path& folder, double mesh_volume);

}  // namespace cosim::tracker::program
