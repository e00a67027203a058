// The pair search. Each object sits only in the cell of its centre, and cells are at least
// as wide as any pair distance on their level, so an object's partners on its own level lie
// in its 3x3x3 block. Half of that block (for_each_cell) plus the later entries of its own
// cell see each same-level pair exactly once. A pair across levels is looked for only
// from its finer object, in the 3x3x3 block around its centre on the coarser level, whose
// cells are wide enough for both spans. Either way only the cells of the block within
// reach of the object's centre are scanned (block_within).
#include <algorithm>

#include "rigidbody/broadphase/hash_grid.hpp"
#include "rigidbody/broadphase/neighbourhood.hpp"
#include "rigidbody/broadphase/overlap.hpp"

namespace cosim::rigidbody::broadphase {

void HashGrid::scan(const Entry& a, std::uint32_t level, const Cell& cell, std::uint32_t first,
                    std::vector<Pair>& out) const {
  if (!per_level_[level].layout.contains(cell)) return;
  const std::uint32_t bucket = bucket_of(level, cell);
  for (std::uint32_t q = std::max(start_[bucket], first); q < start_[bucket + 1]; ++q) {
    const Entry& b = entries_[q];
    if (b.level != level || !same_cell(b.cell, cell) || (a.fixed && b.fixed)) continue;
    if (spheres_near(a.centre, a.radius, b.centre, b.radius, config_.margin)) {
      out.push_back(ordered_pair(a.id, b.id));
    }
  }
}

void HashGrid::visit(const Entry& a, std::uint32_t level, bool half, std::vector<Pair>& out) const {
  const double reach = a.radius + config_.margin + per_level_[level].max_radius;
  for_each_cell(block_within(a.centre, levels_.inv_size(level), reach), half,
                [&](const Cell& cell) { scan(a, level, cell, 0, out); });
}

void HashGrid::find_pairs(std::vector<Pair>& out) const {
  out.clear();
  for (std::uint32_t p = 0; p < entries_.size(); ++p) {
    const Entry& a = entries_[p];
    scan(a, a.level, a.cell, p + 1, out);
    visit(a, a.level, true, out);
    const auto coarser = std::upper_bound(occupied_.begin(), occupied_.end(), a.level);
    for (auto level = coarser; level != occupied_.end(); ++level) {
      visit(a, *level, false, out);
    }
  }
  for (const Object& wall : walls_) {
    for (const Entry& e : entries_) {
      if (!(wall.fixed && e.fixed) && near_wall(wall, e.centre, e.radius, config_.margin)) {
        out.push_back(ordered_pair(wall.id, e.id));
      }
    }
  }
}

}  // namespace cosim::rigidbody::broadphase
