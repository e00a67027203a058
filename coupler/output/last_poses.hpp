// Where a run file's last row leaves its bodies: the settled packing another scene starts
// from (the scene's `generate: file` entries).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim::output {

struct LastPose {
  std::string body;
  std::array<double, 3> position{};
  std::array<double, 4> orientation{};  // w, x, y, z
};

// Every body of the run file, in its order, at the last row all their positions and
// orientations have (a crash inside append() can leave some series a row longer). Throws
// std::runtime_error naming the file if it is not a run file, or if it has bodies but no
// row yet.
std::vector<LastPose> last_poses(const std::filesystem::path& path);

}  // namespace cosim::output
