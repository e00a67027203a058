// Everything the standalone tracker reads from participants.tracker of a scene: the mesh
// (scene_mesh.hpp), the walls (scene_walls.hpp), the obstacles (scene_obstacles.hpp), the
// particles (seeding.hpp), their output (scene_particle_output.hpp), the ranks' balance
// (scene_balance.hpp) and the participant's dt; checked together, so a key nobody reads is an error.
#pragma once

#include <optional>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/program/scene_particle_output.hpp"
#include "tracker/step/gas_setup.hpp"

namespace cosim::tracker::program {

// The gas a Simulation is made from (obstacles bound to a body at the body's initial pose),
// and what only the program needs besides.
struct TrackerScene : step::GasSetup {
  std::vector<int> obstacle_body;                 // per obstacle: the scene body it moves with, or -1
  std::optional<ParticleOutput> particle_output;  // particles written with the fields
};

// Throws scene::SceneError naming file, line, key and value. On several `ranks` a box mesh
// (not perturbed, not in tracer mode) is built as this rank's part (mesh/box_part.hpp, the
// bricks of parallel/bricks.hpp), and the checks that need every cell are made over the
// ranks (collective).
TrackerScene read_tracker(const scene::Scene& scene, parallel::Ranks ranks = {});
// Places the obstacles bound to bodies at `body_poses` (one per scene body, world from body
// frame; none: they stay where the scene puts the bodies); std::runtime_error for too few.
void place_bound_obstacles(TrackerScene& setup, const std::vector<Eigen::Isometry3d>& body_poses);

}  // namespace cosim::tracker::program
