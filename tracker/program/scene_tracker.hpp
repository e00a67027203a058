// Everything the standalone tracker reads from participants.tracker of a scene: the mesh
// (scene_mesh.hpp), the walls (scene_walls.hpp), the obstacles (scene_obstacles.hpp), the
// particles (seeding.hpp), their output (scene_particle_output.hpp), the ranks' balance
// (scene_balance.hpp) and the participant's dt; checked together, so a key nobody reads is an error.
#pragma once

#include <memory>

#include "coupler/scene/scene.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/parallel/bricks.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/program/scene_balance.hpp"
#include "tracker/program/scene_collisions.hpp"
#include "tracker/program/scene_particle_output.hpp"
#include "tracker/program/scene_tracers.hpp"
#include "tracker/program/seeding.hpp"
#include "tracker/tracking/inflow.hpp"
#include "tracker/tracking/domain.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker {

struct TrackerScene {
  // On the heap: the domain and the obstacles refer to the mesh, and the whole moves. The
  // whole mesh, or (read on several ranks) this rank's part of a box.
  std::unique_ptr<Mesh> mesh;
  std::optional<BoxSpec> box;     // the mesh is this box's
  std::unique_ptr<const Domain> domain;
  Obstacles obstacles;            // bound ones at their body's initial pose
  std::vector<int> obstacle_body; // per obstacle: the scene body it moves with, or -1
  Seeding particles;
  std::vector<Inflow> inflows;
  std::optional<Collisions> collisions;
  std::optional<Tracers> tracers;  // tracer mode: no collisions, no inflow
  std::optional<ParticleOutput> particle_output;  // particles written with the fields
  Balance balance;                                 // over several ranks
  double dt = 0.0;
};

// Throws scene::SceneError naming file, line, key and value. On several `ranks` a box mesh
// (not perturbed, not in tracer mode) is built as this rank's part (mesh/box_part.hpp, the
// bricks of parallel/bricks.hpp), and the checks that need every cell are made over the
// ranks (collective).
TrackerScene read_tracker(const scene::Scene& scene, Ranks ranks = {});
// The bricks of a box over `ranks` ranks (parallel/bricks.hpp); std::invalid_argument if a
// rank would have no cell.
Bricks box_bricks(const BoxSpec& box, int ranks);

}  // namespace cosim::tracker
