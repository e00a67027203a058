// Building the grid. Objects are counting-sorted by bucket (layout.hpp) into one contiguous
// array over a table of next_pow2(N) buckets: O(N) per update, memory proportional to N
// whatever the domain, and the objects of a bucket lie side by side for the pair search.
// Different cells sharing a bucket are told apart by their stored cell. Sorting by the
// full cell key instead would cost O(N log N) plus a binary search per neighbour lookup;
// open addressing would add an indirection per lookup and an array of keys.
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
  require(objects.size() < std::numeric_limits<std::uint32_t>::max(), "too many objects");
  walls_.clear();
  double smallest = std::numeric_limits<double>::infinity();
  std::size_t finite = 0;
  for (const Object& o : objects) {
    check(o);
    if (o.infinite) {
      walls_.push_back(o);
      continue;
    }
    ++finite;
    const double span = levels_.span(o.radius);
    if (span > 0.0) smallest = std::min(smallest, span);
  }
  // With no positive span (points, no margin) only coincident centres pair, and any cell
  // width finds them.
  const double automatic = std::isfinite(smallest) ? smallest : 1.0;
  levels_.reset(config_.base_cell_size > 0.0 ? config_.base_cell_size : automatic);
  assign_levels(objects);
  sort_by_bucket(objects, finite);
}

void HashGrid::assign_levels(std::span<const Object> objects) {
  slots_.resize(objects.size());
  per_level_.clear();
  for (std::size_t n = 0; n < objects.size(); ++n) {
    const Object& o = objects[n];
    if (o.infinite) continue;
    const std::uint32_t level = levels_.level_of(levels_.span(o.radius));
    slots_[n].level = level;
    if (level >= per_level_.size()) per_level_.resize(level + 1);
    per_level_[level].layout.include(cell_of_slot(o, slots_[n]));
    per_level_[level].max_radius = std::max(per_level_[level].max_radius, o.radius);
  }
  occupied_.clear();
  std::uint64_t offset = 0;
  for (std::uint32_t level = 0; level < per_level_.size(); ++level) {
    if (per_level_[level].layout.empty()) continue;
    offset = per_level_[level].layout.finish(offset);
    occupied_.push_back(level);
  }
}

void HashGrid::sort_by_bucket(std::span<const Object> objects, std::size_t finite) {
  const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(finite, 1));
  mask_ = buckets - 1;
  start_.assign(buckets + 1, 0);
  for (std::size_t n = 0; n < objects.size(); ++n) {
    if (objects[n].infinite) continue;
    slots_[n].bucket = bucket_of(slots_[n].level, cell_of_slot(objects[n], slots_[n]));
    ++start_[slots_[n].bucket];
  }
  // Running sum: start_[b] is now the end of bucket b. Placing backwards moves it to the
  // bucket's first entry and keeps input order within a bucket.
  std::partial_sum(start_.begin(), start_.end() - 1, start_.begin());
  start_.back() = static_cast<std::uint32_t>(finite);
  entries_.resize(finite);
  for (std::size_t n = objects.size(); n-- > 0;) {
    const Object& o = objects[n];
    if (o.infinite) continue;
    const Slot slot = slots_[n];
    entries_[--start_[slot.bucket]] = {o.centre, o.radius, cell_of_slot(o, slot), o.id, slot.level, o.fixed};
  }
}

std::size_t HashGrid::memory_bytes() const {
  return entries_.capacity() * sizeof(Entry) + start_.capacity() * sizeof(std::uint32_t) +
         slots_.capacity() * sizeof(Slot) + per_level_.capacity() * sizeof(PerLevel) +
         occupied_.capacity() * sizeof(std::uint32_t) + walls_.capacity() * sizeof(Object) + levels_.memory_bytes();
}

}  // namespace cosim::rigidbody::broadphase
