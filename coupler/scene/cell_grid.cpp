#include "coupler/scene/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace cosim::scene {
namespace {

// A solid or query touching more cells than this is tried against everything instead:
// up to 8 x 8 x 8 cells are cheaper to visit than a scene's worth of solids, and a body
// far larger than the cell would otherwise be listed in millions of them.
constexpr std::uint64_t max_cells = 512;

// Clamped so that a coordinate far out cannot overflow the cell index.
std::int64_t index_of(double x, double cell) {
  return static_cast<std::int64_t>(std::clamp(std::floor(x / cell), -1e15, 1e15));
}

template <class F>
void for_each_cell(const auto& span, F f) {
  for (std::int64_t z = span.lo[2]; z <= span.hi[2]; ++z)
    for (std::int64_t y = span.lo[1]; y <= span.hi[1]; ++y)
      for (std::int64_t x = span.lo[0]; x <= span.hi[0]; ++x) f({x, y, z});
}

}  // namespace

CellGrid::CellGrid(double cell) : cell_(cell) {}

std::size_t CellGrid::Hash::operator()(const Cell& c) const {
  // The large primes of Teschner et al. (2003), spatial hashing for collision detection.
  return static_cast<std::size_t>(static_cast<std::uint64_t>(c[0]) * 73856093u ^
                                  static_cast<std::uint64_t>(c[1]) * 19349663u ^
                                  static_cast<std::uint64_t>(c[2]) * 83492791u);
}

std::uint64_t CellGrid::Span::cells() const {
  std::uint64_t n = 1;
  for (int k = 0; k < 3; ++k) {
    n *= static_cast<std::uint64_t>(hi[k] - lo[k]) + 1;
    if (n > max_cells) return n;  // enough to know; the full product could overflow
  }
  return n;
}

CellGrid::Span CellGrid::span_of(const Solid& s) const {
  Span span;
  for (int k = 0; k < 3; ++k) {
    span.lo[k] = index_of(s.centre[k] - s.half[k], cell_);
    span.hi[k] = index_of(s.centre[k] + s.half[k], cell_);
  }
  return span;
}

void CellGrid::add(const Solid& s) {
  const std::size_t index = solids_.size();
  solids_.push_back(s);
  const Span span = span_of(s);
  if (span.cells() > max_cells) {
    large_.push_back(index);
    return;
  }
  for_each_cell(span, [&](const Cell& c) { cells_[c].push_back(index); });
}

std::optional<std::size_t> CellGrid::first_overlap(const Solid& s,
                                                   const std::function<bool(std::size_t)>& counts) const {
  std::optional<std::size_t> first;
  const auto consider = [&](std::size_t i) {
    if ((!first || i < *first) && (!counts || counts(i)) && overlap(solids_[i], s)) first = i;
  };
  const Span span = span_of(s);
  if (span.cells() > max_cells) {
    for (std::size_t i = 0; i < solids_.size(); ++i) consider(i);
    return first;
  }
  for_each_cell(span, [&](const Cell& c) {
    if (const auto it = cells_.find(c); it != cells_.end())
      for (const std::size_t i : it->second) consider(i);
  });
  for (const std::size_t i : large_) consider(i);
  return first;
}

}  // namespace cosim::scene
