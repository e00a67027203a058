// Where the cells of one level go in the table: their row-major index in the bounding box
// of the level's occupied cells, levels one after another, folded onto the table modulo its
// size. For a dense domain (box cells <~ table size) that is free of collisions, and bucket
// order is spatial order, so the pair search walks space row by row and finds neighbouring
// cells still in cache; a well-mixed hash would make every lookup a cache miss. A sparse
// or huge domain just folds more cells onto each bucket; odd strides keep a row of cells
// along any axis from folding onto a single bucket.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>

#include "rigidbody/broadphase/cell.hpp"

namespace cosim::rigidbody::broadphase {

class Layout {
 public:
  void include(const Cell& cell) {
    for (int axis = 0; axis < 3; ++axis) {
      lo_[axis] = std::min(lo_[axis], cell[axis]);
      hi_[axis] = std::max(hi_[axis], cell[axis]);
    }
  }
  bool empty() const { return lo_[0] > hi_[0]; }

  // Fixes the strides once every occupied cell is included; this level's indices start at
  // offset. Returns where the next level starts.
  std::uint64_t finish(std::uint64_t offset) {
    offset_ = offset;
    stride_y_ = extent(0) | 1;
    stride_z_ = (stride_y_ * extent(1)) | 1;
    return offset + stride_z_ * extent(2);
  }

  // Only occupied cells are in the box; any other cell is empty.
  bool contains(const Cell& cell) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (cell[axis] < lo_[axis] || cell[axis] > hi_[axis]) return false;
    }
    return true;
  }

  // For a cell inside the box. Unsigned arithmetic wraps, which is what folding wants.
  std::uint64_t index(const Cell& cell) const {
    return offset_ + from_lo(cell, 0) + stride_y_ * from_lo(cell, 1) + stride_z_ * from_lo(cell, 2);
  }

 private:
  std::uint64_t from_lo(const Cell& cell, int axis) const {
    return static_cast<std::uint64_t>(std::int64_t{cell[axis]} - lo_[axis]);
  }
  std::uint64_t extent(int axis) const { return static_cast<std::uint64_t>(std::int64_t{hi_[axis]} - lo_[axis] + 1); }

  Cell lo_ = {std::numeric_limits<std::int32_t>::max(), std::numeric_limits<std::int32_t>::max(),
              std::numeric_limits<std::int32_t>::max()};
  Cell hi_ = {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::min(),
              std::numeric_limits<std::int32_t>::min()};
  std::uint64_t stride_y_ = 0;
  std::uint64_t stride_z_ = 0;
  std::uint64_t offset_ = 0;
};

}  // namespace cosim::rigidbody::broadphase
