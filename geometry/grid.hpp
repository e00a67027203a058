#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>

namespace cosim::geometry {

// A regular grid of nodes origin + spacing * (i, j, k), 0 <= i < count[0] etc., stored
// with i fastest (index = i + nx (j + ny k)), as the fluid stores its fields.
struct GridSpec {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double spacing = 1.0;
  std::array<int, 3> count{0, 0, 0};

  std::size_t size() const {
    return static_cast<std::size_t>(count[0]) * static_cast<std::size_t>(count[1]) * static_cast<std::size_t>(count[2]);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(count[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(count[1]) * k);
  }
  Eigen::Vector3d node(int i, int j, int k) const { return origin + spacing * Eigen::Vector3d(i, j, k); }
  Eigen::Vector3d node(std::size_t index) const {
    const auto nx = static_cast<std::size_t>(count[0]), ny = static_cast<std::size_t>(count[1]);
    return node(static_cast<int>(index % nx), static_cast<int>(index / nx % ny), static_cast<int>(index / (nx * ny)));
  }
};

}  // namespace cosim::geometry
