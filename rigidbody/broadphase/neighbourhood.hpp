// The cells visited around an object: its 3x3x3 block, cut down to the cells that can hold
// a partner's centre.
#pragma once

#include <cmath>

#include "rigidbody/broadphase/cell.hpp"

namespace cosim::rigidbody::broadphase {

struct Block {
  Cell home;  // the object's cell
  Cell lo;    // per axis -1 or 0
  Cell hi;    // per axis 0 or +1
};

// The block around p's cell on a level whose cells are 1 / inv_size wide, for partners
// whose centres are at most reach away (r + r_max + margin, never more than a cell): on
// each axis the lower neighbour only when p is within reach of its cell's lower face, the
// upper one likewise. A small object looking into a coarse level mostly needs 8 or fewer
// of the 27 cells. Coordinates in cell units carry a rounding error below
// 2^30 * 2^-52 cells each (cell_of clamps beyond 2^30), so a face counts as within reach up
// to a tolerance well above twice that.
inline Block block_within(const Eigen::Vector3d& p, double inv_size, double reach) {
  constexpr double tolerance = 1e-6;
  const double span = reach * inv_size + tolerance;
  Block block{cell_of(p, inv_size), {-1, -1, -1}, {1, 1, 1}};
  for (int axis = 0; axis < 3; ++axis) {
    const double u = p[axis] * inv_size;
    const double floor = std::floor(u);
    if (std::abs(floor) >= kCellLimit) continue;  // clamped: keep the whole block
    if (u - floor > span) block.lo[axis] = 0;
    if (floor + 1.0 - u > span) block.hi[axis] = 0;
  }
  return block;
}

// Calls visit(cell) for every cell of the block; with half only for the offsets
// lexicographically after (0,0,0). Of two neighbouring cells A and B = A + d exactly one of
// d and -d is such, so a pair on one level is seen from one side only; pairs within one
// cell need an ordering rule of their own (hash_grid_pairs.cpp). Nested loops rather than a
// filtered offset table: the filter's branch is unpredictable.
template <class Visit>
void for_each_cell(const Block& block, bool half, Visit&& visit) {
  for (int dx = block.lo[0]; dx <= block.hi[0]; ++dx) {
    for (int dy = block.lo[1]; dy <= block.hi[1]; ++dy) {
      for (int dz = block.lo[2]; dz <= block.hi[2]; ++dz) {
        const bool after = dx > 0 || (dx == 0 && (dy > 0 || (dy == 0 && dz > 0)));
        if (half && !after) continue;
        visit(block.home + Cell{dx, dy, dz});
      }
    }
  }
}

}  // namespace cosim::rigidbody::broadphase
