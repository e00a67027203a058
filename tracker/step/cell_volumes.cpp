#include "tracker/step/cell_volumes.hpp"

#include <array>

namespace cosim::tracker {

std::vector<double> cell_volumes(const BoxSpec& box) {
  std::array<std::vector<double>, 3> nodes;
  for (int a = 0; a < 3; ++a) nodes[a] = axis_nodes(box.axes[a]);
  // Every Kuhn tetrahedron is a sixth of its hexahedron.
  const std::size_t per_hex = box.tetrahedra ? 6 : 1;
  std::vector<double> volume;
  volume.reserve((nodes[0].size() - 1) * (nodes[1].size() - 1) * (nodes[2].size() - 1) * per_hex);
  for (std::size_t k = 0; k + 1 < nodes[2].size(); ++k)
    for (std::size_t j = 0; j + 1 < nodes[1].size(); ++j)
      for (std::size_t i = 0; i + 1 < nodes[0].size(); ++i) {
        const double hexahedron =
            (nodes[0][i + 1] - nodes[0][i]) * (nodes[1][j + 1] - nodes[1][j]) * (nodes[2][k + 1] - nodes[2][k]);
        volume.insert(volume.end(), per_hex, hexahedron / static_cast<double>(per_hex));
      }
  return volume;
}

}  // namespace cosim::tracker
