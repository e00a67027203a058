// The gas by region (participants.tracker.options.particles.regions):
//
//   regions:
//     - region: {box: {centre: [..], half_extents: [..]}}   # any csg_shape.hpp shape
//       number_density: 2.4e20   # real molecules per m^3 (particles.weight of them per particle)
//       temperature: 300         # K, Maxwellian about the velocity (0: all at the velocity)
//       velocity: [400, 0, 0]    # m/s, optional: the drift
//
// Regions that overlap add their gases up. How the particles are drawn: tracker/step/seed_regions.hpp.
#pragma once

#include <filesystem>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "tracker/step/seed_regions.hpp"

namespace cosim::tracker::program {

// `folder`: where a shape's relative file is found; `mesh_volume` (m^3) and `weight` bound
// the particles a region can ask for, so that a forgotten weight is an error, not a run
// that fills the memory.
std::vector<step::SeedRegion> read_seed_regions(const scene::Reader& particles, const std::filesystem::path& folder,
                                                double mesh_volume, double weight);

}  // namespace cosim::tracker::program
