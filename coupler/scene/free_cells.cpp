#include "coupler/scene/free_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cosim::scene {
namespace {

// Two 4-byte entries a cell: at most 32 MiB. Larger boxes get coarser cells, which only
// costs more refused draws.
constexpr double max_cells = 1 << 22;

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

}  // namespace

FreeCells::FreeCells(const Domain& box, double edge) : origin_(box.min) {
  const auto cells_along = [&](int k, double e) { return std::max(1.0, std::ceil((box.max[k] - box.min[k]) / e)); };
  const double cells = cells_along(0, edge) * cells_along(1, edge) * cells_along(2, edge);
  if (cells > max_cells) edge *= std::cbrt(cells / max_cells) * (1 + 1e-9);
  std::size_t total = 1;
  for (int k = 0; k < 3; ++k) {
    n_[k] = static_cast<std::int64_t>(std::min(cells_along(k, edge), max_cells));
    edge_[k] = (box.max[k] - box.min[k]) / static_cast<double>(n_[k]);
    total *= static_cast<std::size_t>(n_[k]);
  }
  free_.resize(total);
  std::iota(free_.begin(), free_.end(), 0u);
  slot_ = free_;
}

std::size_t FreeCells::id(const Index& i) const {
  return static_cast<std::size_t>((i[2] * n_[1] + i[1]) * n_[0] + i[0]);
}

FreeCells::Index FreeCells::index(std::size_t id) const {
  const auto i = static_cast<std::int64_t>(id);
  return {i % n_[0], i / n_[0] % n_[1], i / (n_[0] * n_[1])};
}

Vec3 FreeCells::draw(Uniform& random) const {
  const double n = static_cast<double>(free_.size());
  const Index i = index(free_[std::min(free_.size() - 1, static_cast<std::size_t>(random(0, n)))]);
  Vec3 p{};
  for (int k = 0; k < 3; ++k) {
    const double lo = origin_[k] + static_cast<double>(i[k]) * edge_[k];
    p[k] = random(lo, lo + edge_[k]);
  }
  return p;
}

void FreeCells::exclude(const Solid& body, const Solid& placed) {
  // Only cells that meet the box of centres where `body` would touch `placed` can go.
  Index lo{}, hi{};
  for (int k = 0; k < 3; ++k) {
    const double reach = placed.half[k] + body.half[k];
    const auto cell = [&](double x) {
      const double at = edge_[k] > 0 ? std::floor((x - origin_[k]) / edge_[k]) : 0.0;
      return static_cast<std::int64_t>(std::clamp(at, -1.0, static_cast<double>(n_[k])));
    };
    lo[k] = std::max<std::int64_t>(cell(placed.centre[k] - reach), 0);
    hi[k] = std::min<std::int64_t>(cell(placed.centre[k] + reach), n_[k] - 1);
    if (lo[k] > hi[k]) return;
  }
  for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
    for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
      for (std::int64_t x = lo[0]; x <= hi[0]; ++x) {
        const std::size_t c = id({x, y, z});
        if (slot_[c] == none) continue;
        Vec3 cell_lo{}, cell_hi{};
        const Index at{x, y, z};
        for (int k = 0; k < 3; ++k) {
          cell_lo[k] = origin_[k] + static_cast<double>(at[k]) * edge_[k];
          cell_hi[k] = cell_lo[k] + edge_[k];
        }
        if (!rules_out(placed, body, cell_lo, cell_hi)) continue;
        // Swap-remove: the last free cell takes this one's place.
        const std::uint32_t last = free_.back();
        free_[slot_[c]] = last;
        slot_[last] = slot_[c];
        free_.pop_back();
        slot_[c] = none;
      }
}

void FreeCells::keep_within(const Solid& body, const std::function<double(const Vec3&)>& room) {
  // The room changes by no more than the distance moved: a cell whose centre has less
  // than the body's radius less half the cell's diagonal has no place for it.
  const double half_diagonal = 0.5 * std::hypot(edge_[0], edge_[1], edge_[2]);
  std::vector<std::uint32_t> kept;
  for (std::uint32_t c : free_) {
    const Index at = index(c);
    Vec3 centre{};
    for (int k = 0; k < 3; ++k) centre[k] = origin_[k] + (static_cast<double>(at[k]) + 0.5) * edge_[k];
    if (room(centre) + half_diagonal < body.radius) {
      slot_[c] = none;
      continue;
    }
    slot_[c] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(c);
  }
  free_ = std::move(kept);
}

}  // namespace cosim::scene
