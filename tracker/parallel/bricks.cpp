#include "tracker/parallel/bricks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace cosim::tracker::parallel {
namespace {

// The axis to cut: the longest in hexahedra (the lowest on a tie), or -1 if every axis is
// one hexahedron (or none) long.
int longest(const Bricks::Range& r) {
  int axis = -1, length = 1;
  for (int a = 0; a < 3; ++a)
    if (r.hi[a] - r.lo[a] > length) {
      length = r.hi[a] - r.lo[a];
      axis = a;
    }
  return axis;
}

// The slabs' weights from every cell's (empty: 1 each).
Bricks::SlabWeights slabs_of(std::span<const double> weight, const std::array<int, 3>& hexahedra, int per_hex) {
  const long long cells = 1LL * hexahedra[0] * hexahedra[1] * hexahedra[2] * per_hex;
  if (!weight.empty() && static_cast<long long>(weight.size()) != cells)
    throw std::invalid_argument("bricks: " + std::to_string(weight.size()) + " weights for " + std::to_string(cells) +
                                " cells");
  return [=](const Bricks::Range& r, int axis) {
    const auto slabs = static_cast<std::size_t>(r.hi[axis] - r.lo[axis]);
    if (weight.empty())  // the cells across: no loop over them, so every rank cuts in O(the slabs)
      return std::vector<double>(slabs, static_cast<double>(r.hexahedra() / static_cast<long long>(slabs) * per_hex));
    std::vector<double> slab(slabs, 0.0);
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          const std::array<int, 3> at{i, j, k};
          double w = 0.0;
          for (int t = 0; t < per_hex; ++t)
            w += weight[static_cast<std::size_t>(mesh::box_cell_index({at, t}, hexahedra, per_hex))];
          slab[static_cast<std::size_t>(at[axis] - r.lo[axis])] += w;
        }
    return slab;
  };
}

}  // namespace

Bricks::Bricks(std::array<int, 3> hexahedra, int per_hex, int parts)
    : hexahedra_(hexahedra), per_hex_(per_hex), bricks_(static_cast<std::size_t>(std::max(parts, 0))) {
  if (parts < 1 || per_hex < 1 || hexahedra[0] < 1 || hexahedra[1] < 1 || hexahedra[2] < 1)
    throw std::invalid_argument("bricks: " + std::to_string(parts) + " parts of " + std::to_string(hexahedra[0]) +
                                " x " + std::to_string(hexahedra[1]) + " x " + std::to_string(hexahedra[2]) +
                                " hexahedra");
}

Bricks::Bricks(std::array<int, 3> hexahedra, int per_hex, int parts, std::span<const double> weight)
    : Bricks(by_slabs(hexahedra, per_hex, parts, slabs_of(weight, hexahedra, per_hex))) {}

Bricks Bricks::by_slabs(std::array<int, 3> hexahedra, int per_hex, int parts, const SlabWeights& slabs) {
  Bricks bricks(hexahedra, per_hex, parts);
  bricks.split({{0, 0, 0}, hexahedra}, 0, parts, [&](const Range& r, int axis, int low_parts, int count) {
    // The weight of each slab of hexahedra across the axis, then the cut nearest the share.
    const std::vector<double> slab = slabs(r, axis);
    if (slab.size() != static_cast<std::size_t>(r.hi[axis] - r.lo[axis]))
      throw std::invalid_argument("bricks: " + std::to_string(slab.size()) + " slab weights for " +
                                  std::to_string(r.hi[axis] - r.lo[axis]) + " slabs");
    const double total = std::accumulate(slab.begin(), slab.end(), 0.0);
    const double share = total * low_parts / count;
    // Each side keeps a hexahedron for each of its ranks where the brick has enough, and
    // at least one slab.
    const long long across = r.hexahedra() / (r.hi[axis] - r.lo[axis]);
    const auto slabs_for = [&](long long parts) {
      return static_cast<int>(std::max(1LL, (parts + across - 1) / across));
    };
    int first = r.lo[axis] + slabs_for(low_parts), last = r.hi[axis] - slabs_for(count - low_parts);
    if (first > last) first = last = std::clamp(first, r.lo[axis] + 1, r.hi[axis] - 1);
    int best = first;
    double below = 0.0, best_miss = std::numeric_limits<double>::infinity();
    for (int c = r.lo[axis] + 1; c <= last; ++c) {
      below += slab[static_cast<std::size_t>(c - 1 - r.lo[axis])];
      if (const double miss = std::abs(below - share); c >= first && miss < best_miss) {
        best_miss = miss;
        best = c;
      }
    }
    return best;
  });
  return bricks;
}

Bricks Bricks::from_cuts(std::array<int, 3> hexahedra, int per_hex, int parts, std::span<const int> cuts) {
  Bricks bricks(hexahedra, per_hex, parts);
  std::size_t next = 0;
  bricks.split({{0, 0, 0}, hexahedra}, 0, parts, [&](const Range& r, int axis, int, int) {
    if (next == cuts.size()) throw std::invalid_argument("bricks: fewer cuts than the partition makes");
    const int cut = cuts[next++];
    if (cut <= r.lo[axis] || cut >= r.hi[axis]) throw std::invalid_argument("bricks: a cut outside its brick");
    return cut;
  });
  if (next != cuts.size()) throw std::invalid_argument("bricks: more cuts than the partition makes");
  return bricks;
}

template <typename CutOf>
int Bricks::split(const Range& range, int first, int count, const CutOf& cut_of) {
  const int axis = longest(range);
  if (count == 1 || axis < 0) {
    // One part, or one hexahedron left: it goes to the first part, the others stay empty.
    for (int p = first; p < first + count; ++p)
      bricks_[static_cast<std::size_t>(p)] = p == first ? range : Range{range.lo, range.lo};
    return -1 - first;
  }
  const int low_parts = count / 2;
  const int cut = cut_of(range, axis, low_parts, count);
  const int at = static_cast<int>(nodes_.size());
  nodes_.push_back({axis, cut, 0, 0});
  Range low = range, high = range;
  low.hi[axis] = cut;
  high.lo[axis] = cut;
  const int l = split(low, first, low_parts, cut_of);
  const int h = split(high, first + low_parts, count - low_parts, cut_of);
  nodes_[static_cast<std::size_t>(at)].low = l;
  nodes_[static_cast<std::size_t>(at)].high = h;
  return at;
}

int Bricks::owner(Index cell) const {
  const std::array<int, 3> at = mesh::box_cell(cell, hexahedra_, per_hex_).hex;
  int node = nodes_.empty() ? -1 : 0;
  while (node >= 0) {
    const Node& n = nodes_[static_cast<std::size_t>(node)];
    node = at[n.axis] < n.cut ? n.low : n.high;
  }
  return nodes_.empty() ? 0 : -1 - node;
}

std::vector<int> Bricks::cuts() const {
  std::vector<int> out;
  for (const Node& n : nodes_) out.push_back(n.cut);
  return out;
}

Bricks box_bricks(const mesh::BoxSpec& box, int ranks) {
  std::array<int, 3> hexahedra{};
  for (int a = 0; a < 3; ++a) hexahedra[a] = static_cast<int>(mesh::axis_nodes(box.axes[a]).size()) - 1;
  Bricks bricks(hexahedra, box.tetrahedra ? 6 : 1, ranks, {});
  for (int p = 0; p < ranks; ++p)
    if (bricks.brick(p).hexahedra() == 0)
      throw std::invalid_argument("a box of " + std::to_string(1LL * hexahedra[0] * hexahedra[1] * hexahedra[2]) +
                                  " hexahedra over " + std::to_string(ranks) + " ranks leaves a rank none");
  return bricks;
}

}  // namespace cosim::tracker::parallel
