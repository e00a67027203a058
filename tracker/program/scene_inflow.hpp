// Streams entering the domain (participants.tracker.options.inflow), a list:
//
//   inflow:
//     - patches: [x_min, y_min]      # patch names of the mesh; each must be `open`
//       number_density: 7.03e18      # real molecules per m^3
//       velocity: [2500, 0, 0]       # m/s, optional
//       temperature: 300             # K
//
// The molecules' mass and the simulator weight are the particles' (particles.mass,
// particles.weight). Errors are scene::SceneError naming file, line, key and value.
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/tracking/inflow.hpp"

namespace cosim::tracker::program {

std::vector<tracking::Inflow> read_inflows(const scene::Reader& options, const mesh::Mesh& mesh,
                                           const tracking::Boundaries& boundaries, double mass, double weight);

}  // namespace cosim::tracker::program
