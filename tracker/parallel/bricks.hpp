#pragma once
// A structured box's cells split into one brick of hexahedra per rank by recursive
// coordinate bisection, as SPARTA's `balance_grid rcb` splits its grid: each cut halves a
// brick's ranks and lies across the brick's longest axis (in cells) where the weights of
// the two sides come closest to the ratio of their ranks: the cells' count, or particles
// per cell for a re-partition by load. A cell's owner is found by walking the cuts
// (O(log ranks)), so no rank keeps a table of every cell's owner. A brick may be empty
// when there are more ranks than hexahedra to give.

#include <array>
#include <functional>
#include <span>
#include <vector>

#include "tracker/mesh/box_mesh.hpp"

namespace cosim::tracker::parallel {

class Bricks {
 public:
  struct Range {
    std::array<int, 3> lo, hi;  // hexahedra [lo, hi) per axis
    long long hexahedra() const { return 1LL * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
    bool holds(const std::array<int, 3>& at) const {
      for (int a = 0; a < 3; ++a)
        if (at[a] < lo[a] || at[a] >= hi[a]) return false;
      return true;
    }
    bool holds(const Range& r) const {
      for (int a = 0; a < 3; ++a)
        if (r.lo[a] < lo[a] || r.hi[a] > hi[a]) return false;
      return true;
    }
  };

  // `hexahedra` per axis, `per_hex` cells each (1, or 6 Kuhn tetrahedra, numbered as
  // box_mesh numbers them), over `parts` ranks; `weight`: per cell (empty: 1 each).
  // std::invalid_argument for a non-positive count or a weight array of the wrong size.
  Bricks(std::array<int, 3> hexahedra, int per_hex, int parts, std::span<const double> weight);
  // The weight of each slab of hexahedra of `range` across `axis` (range.hi - range.lo of
  // them, the lowest first): what the cuts need of the weights, so that the ranks can add
  // up theirs without any holding every cell's.
  using SlabWeights = std::function<std::vector<double>(const Range& range, int axis)>;
  static Bricks by_slabs(std::array<int, 3> hexahedra, int per_hex, int parts, const SlabWeights& slabs);
  // The bricks whose cuts() these were (a saved partition).
  static Bricks from_cuts(std::array<int, 3> hexahedra, int per_hex, int parts, std::span<const int> cuts);

  int parts() const { return static_cast<int>(bricks_.size()); }
  const std::array<int, 3>& hexahedra() const { return hexahedra_; }
  int per_hex() const { return per_hex_; }
  int owner(Index cell) const;
  const Range& brick(int part) const { return bricks_[static_cast<std::size_t>(part)]; }
  // The cut positions, in the order they were made.
  std::vector<int> cuts() const;
  bool operator==(const Bricks& other) const {
    return hexahedra_ == other.hexahedra_ && per_hex_ == other.per_hex_ && parts() == other.parts() &&
           cuts() == other.cuts();
  }

 private:
  Bricks(std::array<int, 3> hexahedra, int per_hex, int parts);
  // Splits `range` among parts [first, first + count) below node `at`; `cut_of` gives the
  // cut along an axis.
  template <typename CutOf>
  int split(const Range& range, int first, int count, const CutOf& cut_of);

  struct Node {
    int axis;
    int cut;        // hexahedra below it go to `low`
    int low, high;  // a node's index, or -1 - part for a brick
  };
  std::array<int, 3> hexahedra_;
  int per_hex_;
  std::vector<Node> nodes_;
  std::vector<Range> bricks_;
};

// The bricks of a box over `ranks` ranks; std::invalid_argument if a rank would have no cell.
Bricks box_bricks(const mesh::BoxSpec& box, int ranks);

}  // namespace cosim::tracker::parallel
