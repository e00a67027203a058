// The poses of a `generate: file` entry: a CSV table, or the last row of a cosim run file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "coupler/scene/reader.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::scene {

struct FilePose {
  std::string where;  // "line 7", or "body 'ball'": for messages about this pose
  Vec3 position{};
  std::optional<Quat> orientation;  // unit, when the file gives one
  std::optional<Vec3> velocity;
};

// Reads `file`, the entry's `file` resolved against the scene's folder. A `.csv` file holds
// one body per line, x,y,z[,qw,qx,qy,qz][,vx,vy,vz] (3, 6, 7 or 10 numbers, the same on every
// line), after an optional header line; blank lines and lines starting with '#' are
// skipped. A `.h5` file is a run file, whose bodies are taken where its last row leaves
// them (position and orientation). Errors name the entry's `file` key and the line or body.
std::vector<FilePose> read_pose_file(const Reader& r, const std::filesystem::path& file);

}  // namespace cosim::scene
