#include "tracker/step/cell_volumes.hpp"

namespace cosim::tracker::step {

std::vector<double> cell_volumes(const mesh::BoxSpec& box) {
  std::array<int, 3> hexahedra{};
  for (int a = 0; a < 3; ++a) hexahedra[a] = static_cast<int>(mesh::axis_nodes(box.axes[a]).size()) - 1;
  return cell_volumes(box, {0, 0, 0}, hexahedra);
}

std::vector<double> cell_volumes(const mesh::BoxSpec& box, const std::array<int, 3>& lo, const std::array<int, 3>& hi) {
  std::array<std::vector<double>, 3> nodes;
  for (int a = 0; a < 3; ++a) nodes[a] = mesh::axis_nodes(box.axes[a]);
  // Every Kuhn tetrahedron is a sixth of its hexahedron.
  const std::size_t per_hex = box.tetrahedra ? 6 : 1;
  std::vector<double> volume;
  volume.reserve(static_cast<std::size_t>(hi[0] - lo[0]) * static_cast<std::size_t>(hi[1] - lo[1]) *
                 static_cast<std::size_t>(hi[2] - lo[2]) * per_hex);
  for (std::size_t k = static_cast<std::size_t>(lo[2]); k < static_cast<std::size_t>(hi[2]); ++k)
    for (std::size_t j = static_cast<std::size_t>(lo[1]); j < static_cast<std::size_t>(hi[1]); ++j)
      for (std::size_t i = static_cast<std::size_t>(lo[0]); i < static_cast<std::size_t>(hi[0]); ++i) {
        const double hexahedron =
            (nodes[0][i + 1] - nodes[0][i]) * (nodes[1][j + 1] - nodes[1][j]) * (nodes[2][k + 1] - nodes[2][k]);
        volume.insert(volume.end(), per_hex, hexahedron / static_cast<double>(per_hex));
      }
  return volume;
}

}  // namespace cosim::tracker::step
