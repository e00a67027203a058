// Integer cell coordinates on one level of the grid.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <Eigen/Core>

namespace cosim::rigidbody::broadphase {

using Cell = std::array<std::int32_t, 3>;

inline constexpr double kCellLimit = 1 << 30;

// The cell holding p, on a level whose cells are 1 / inv_size wide. Coordinates are
// clamped to +-kCellLimit: objects beyond share the outermost cells. That costs speed,
// never a pair, because floor and clamp are both monotone, so points at most one cell apart
// stay at most one cell apart; the headroom below 2^31 lets neighbours be formed without
// overflow.
inline Cell cell_of(const Eigen::Vector3d& p, double inv_size) {
  Cell cell;
  for (int axis = 0; axis < 3; ++axis) {
    const double u = std::floor(p[axis] * inv_size);
    cell[axis] = static_cast<std::int32_t>(std::clamp(u, -kCellLimit, kCellLimit));
  }
  return cell;
}

// Field by field: std::array's == calls memcmp, a library call per candidate in the pair
// search.
inline bool same_cell(const Cell& a, const Cell& b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

inline Cell operator+(const Cell& a, const Cell& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

}  // namespace cosim::rigidbody::broadphase
