// CSG obstacles as the scene writes them (participants.tracker.options.obstacles):
//
//   obstacles:
//     - name: cluster                  # unique; names the tallies in the output
//       shape: {balls: {file: cluster.txt}}   # any shape of csg_shape.hpp
//       permeable: false               # optional; true: a zone that only counts crossings
//       wall: {kind: diffuse, temperature: 300}  # walls only, optional (default specular);
//                                      # kinds as in scene_walls.hpp, periodic excluded
//     - name: ball
//       body: ball                     # optional: moves with this scene body; the gas's
//                                      # force and torque on it go to the body
//       # shape: optional with a body: given in the body's frame (origin at its position,
//       # axes along its orientation); without one, the body's own sphere, box or cylinder
//
// Errors are scene::SceneError naming file, line, key and value.
#pragma once

#include <vector>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker::program {

struct SceneObstacles {
  std::vector<tracking::Obstacle> objects;  // bound ones in their body's frame
  std::vector<int> body;                    // per object: its index in scene.bodies, or -1
};

SceneObstacles read_obstacles(const scene::Reader& options, const scene::Scene& scene);

// Where body b of the scene starts: its frame in the world.
Eigen::Isometry3d initial_pose(const scene::Body& body);

}  // namespace cosim::tracker::program
