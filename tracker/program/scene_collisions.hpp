// DSMC collisions (participants.tracker.options.collisions), optional:
//
//   collisions:
//     species: Ar            # a species of the species file (tracker/dsmc/species.yaml)
//     model: vss             # hard_sphere | vhs | vss
//     selection: uniform     # uniform (Bird's NTC) | nearest (nearest neighbour in the cell)
//
// particles.mass must be the species' mass. Errors are scene::SceneError naming file,
// line, key and value.
#pragma once

#include <optional>

#include "coupler/scene/reader.hpp"
#include "tracker/step/collide.hpp"

namespace cosim::tracker::program {

std::optional<step::Collisions> read_collisions(const scene::Reader& options, double mass);

}  // namespace cosim::tracker::program
