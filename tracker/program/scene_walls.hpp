// Wall conditions as the scene writes them, for the mesh's patches and for obstacle walls:
//
//   {kind: specular | diffuse | maxwell | open | periodic, temperature: 300, accommodation: 0.8,
//    velocity: [50, 0, 0]}
//
// temperature (K, > 0) only for diffuse and maxwell, accommodation (the diffuse fraction,
// [0, 1]) only for maxwell; velocity (m/s, optional, default at rest) only for diffuse and
// maxwell: the wall slides at its tangential part (BoundaryCondition::velocity); periodic
// only for mesh patches the mesh links.
//
//   boundaries:                 # participants.tracker.options.boundaries
//     default: {kind: specular} # every patch not named; optional
//     x_min: {kind: open}       # a patch name of the mesh (box: x_min, x_max, ..., z_max)
//
// Errors are scene::SceneError naming file, line, key and value.
#pragma once

#include "coupler/scene/reader.hpp"
#include "tracker/mesh/mesh.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/tracking/boundaries.hpp"

namespace cosim::tracker::program {

tracking::BoundaryCondition read_condition(const scene::Reader& r, bool allow_periodic);

// The `boundaries` of the tracker's options: one condition per patch of `mesh`. Every patch
// with boundary faces needs one (its own or the default); a patch without faces (linked
// periodically by the mesh) gets `periodic`.
// On a rank's part of a mesh (mesh/part.hpp), which patches have faces is asked of all
// `ranks` (collective).
tracking::Boundaries read_boundaries(const scene::Reader& options, const mesh::Mesh& mesh, double mass,
                                     const parallel::Ranks& ranks = {});

}  // namespace cosim::tracker::program
