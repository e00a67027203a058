// Building the grid. Each object is read once, into an entry; the entries are then
// counting-sorted by bucket (layout.hpp) in place, over a table of next_pow2(N) buckets:
// O(N) per update, memory proportional to N whatever the domain, and the objects of a
// bucket lie side by side for the pair search. Different cells sharing a bucket are told
// apart by their stored cell. Sorting by the full cell key instead would cost O(N log N)
// plus a binary search per neighbour lookup; open addressing would add an indirection per
// lookup and an array of keys.
#include "rigidbody/broadphase/hash_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace cosim::rigidbody::broadphase {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("broad phase: " + what);
}

// Returns what is wrong with o, or nullptr: the message is built only for a bad object.
const char* defect(const Object& o) {
  if (o.infinite) {
    if (!o.half_space) return nullptr;
    if (!o.half_space->normal.allFinite() || !std::isfinite(o.half_space->offset)) {
      return "half-space is not finite";
    }
    return o.half_space->normal.squaredNorm() > 0.0 ? nullptr : "half-space normal is zero";
  }
  if (!o.centre.allFinite()) return "centre is not finite";
  return std::isfinite(o.radius) && o.radius >= 0.0 ? nullptr : "radius must be finite and >= 0";
}

void check(const Object& o) {
  if (const char* what = defect(o)) {
    require(false, "object " + std::to_string(o.id) + ": " + what);
  }
}

HashGridConfig checked(const HashGridConfig& c) {
  require(std::isfinite(c.margin) && c.margin >= 0.0, "margin must be finite and >= 0");
  require(std::isfinite(c.base_cell_size) && c.base_cell_size >= 0.0, "base cell size must be finite and >= 0");
  require(std::isfinite(c.level_factor) && c.level_factor > 1.0, "level factor must be > 1");
  require(std::isfinite(c.safety) && c.safety >= kMinSafety, "safety factor must be >= " + std::to_string(kMinSafety));
  return c;
}

}  // namespace

HashGrid::HashGrid(const HashGridConfig& config)
    : config_(checked(config)), levels_(config.level_factor, config.safety, config.margin) {}

void HashGrid::update(std::span<const Object> objects) {
  update(objects.size(), [objects](std::size_t n) { return objects[n]; });
}

void HashGrid::update(std::size_t count, const std::function<Object(std::size_t)>& object) {
  require(count < std::numeric_limits<std::uint32_t>::max(), "too many objects");
  walls_.clear();
  entries_.clear();
  entries_.reserve(count);  // not left to doubling, which could hold twice the entries
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t n = 0; n < count; ++n) {
    const Object o = object(n);
    check(o);
    if (o.infinite) {
      walls_.push_back(o);
      continue;
    }
    entries_.push_back({o.centre, o.radius, Cell{}, o.id, 0, o.fixed});
    const double span = levels_.span(o.radius);
    if (span > 0.0) smallest = std::min(smallest, span);
  }
  // With no positive span (points, no margin) only coincident centres pair, and any cell
  // width finds them.
  const double automatic = std::isfinite(smallest) ? smallest : 1.0;
  levels_.reset(config_.base_cell_size > 0.0 ? config_.base_cell_size : automatic);
  assign_levels();
  sort_by_bucket();
}

void HashGrid::assign_levels() {
  per_level_.clear();
  for (Entry& e : entries_) {
    e.level = levels_.level_of(levels_.span(e.radius));
    e.cell = cell_of(e.centre, levels_.inv_size(e.level));
    if (e.level >= per_level_.size()) per_level_.resize(e.level + 1);
    per_level_[e.level].layout.include(e.cell);
    per_level_[e.level].max_radius = std::max(per_level_[e.level].max_radius, e.radius);
  }
  occupied_.clear();
  std::uint64_t offset = 0;
  for (std::uint32_t level = 0; level < per_level_.size(); ++level) {
    if (per_level_[level].layout.empty()) continue;
    offset = per_level_[level].layout.finish(offset);
    occupied_.push_back(level);
  }
}

void HashGrid::sort_by_bucket() {
  const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(entries_.size(), 1));
  mask_ = buckets - 1;
  start_.assign(buckets + 1, 0);
  for (const Entry& e : entries_) ++start_[bucket_of(e) + 1];
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  // In place (American flag sort): next[b] is where bucket b's next entry goes; an entry
  // found in another bucket's place is swapped into its own, so each moves once.
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::uint32_t b = 0; b < buckets; ++b)
    while (next[b] < start_[b + 1]) {
      Entry& e = entries_[next[b]];
      const std::uint32_t target = bucket_of(e);
      if (target == b)
        ++next[b];
      else
        std::swap(e, entries_[next[target]++]);
    }
}

std::size_t HashGrid::memory_bytes() const {
  return entries_.capacity() * sizeof(Entry) + start_.capacity() * sizeof(std::uint32_t) +
         per_level_.capacity() * sizeof(PerLevel) + occupied_.capacity() * sizeof(std::uint32_t) +
         walls_.capacity() * sizeof(Object) + levels_.memory_bytes();
}

}  // namespace cosim::rigidbody::broadphase
