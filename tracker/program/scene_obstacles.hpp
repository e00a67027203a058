// CSG obstacles as the scene writes them (participants.tracker.options.obstacles):
//
//   obstacles:
//     - name: cluster                  # unique; names the tallies in the output
//       shape: {balls: {file: cluster.txt}}   # any shape of csg_shape.hpp
//       permeable: false               # optional; true: a zone that only counts crossings
//       wall: {kind: diffuse, temperature: 300}  # walls only, optional (default specular);
//                                      # kinds as in scene_walls.hpp, periodic excluded
//
// Errors are scene::SceneError naming file, line, key and value.
#pragma once

#include <filesystem>
#include <vector>

#include "scene/reader.hpp"
#include "tracker/tracking/obstacles.hpp"

namespace cosim::tracker {

std::vector<Obstacle> read_obstacles(const scene::Reader& options, const std::filesystem::path& scene_file);

}  // namespace cosim::tracker
