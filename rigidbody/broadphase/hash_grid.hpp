// The broad phase of the rigid-body simulator: a hierarchical hash grid (Mirtich 1996;
// Iglberger and Ruede's pe). README.md describes the algorithm and its cost.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "rigidbody/broadphase/cell.hpp"
#include "rigidbody/broadphase/layout.hpp"
#include "rigidbody/broadphase/levels.hpp"
#include "rigidbody/broadphase/object.hpp"

namespace cosim::rigidbody::broadphase {

// Cells must be a little wider than the largest span on their level: then rounding in the
// cell coordinates (relative error ~1e-16 times |x| / cell width <= 2^30) can never put two
// touching objects two cells apart. This is that bound with room to spare.
inline constexpr double kMinSafety = 1.0 + 1e-6;

struct HashGridConfig {
  // Spheres at most this far apart are candidates too (near contacts, persistent contacts).
  double margin = 0.0;
  // Width of the level-0 cells; 0 picks the span of the smallest object at every update.
  double base_cell_size = 0.0;
  // Width ratio of consecutive levels, > 1.
  double level_factor = 2.0;
  // Cells are at least safety * (2 r + margin) wide for every object r on their level;
  // >= kMinSafety.
  double safety = 1.0 + 1e-4;
};

class HashGrid {
 public:
  // Throws std::invalid_argument for a configuration outside the ranges above.
  explicit HashGrid(const HashGridConfig& config = {});

  // Rebuilds the grid from scratch for the objects' current positions; with every body
  // moving every step that beats moving objects between cells (README.md). Throws
  // std::invalid_argument for a negative or non-finite radius, a non-finite centre, or a
  // half-space with a zero or non-finite normal or offset.
  void update(std::span<const Object> objects);
  // The same for `count` objects made on the fly, object(n) for n < count, each asked for
  // once: a caller whose bodies already say what an Object does (a world) keeps no copy
  // of them beside the grid's own.
  void update(std::size_t count, const std::function<Object(std::size_t)>& object);

  // The candidate pairs of the last update, replacing out's contents (its capacity is
  // reused). Order: the grid's traversal, the same for the same input, but not sorted.
  void find_pairs(std::vector<Pair>& out) const;

  // Buckets of the table: the next power of two >= the number of finite objects.
  std::size_t table_size() const { return start_.size() - 1; }
  // Levels holding at least one object.
  std::size_t level_count() const { return occupied_.size(); }
  // Heap memory held by the grid (out of find_pairs not included).
  std::size_t memory_bytes() const;

 private:
  // A finite object in the table: what update() reads of it, then its level and cell.
  // 56 bytes.
  struct Entry {
    Eigen::Vector3d centre;
    double radius;
    Cell cell;
    Id id;
    std::uint32_t level;
    bool fixed;
  };
  static_assert(sizeof(Entry) == 56);
  // What the pair search needs to know of one level.
  struct PerLevel {
    Layout layout;
    double max_radius = 0.0;  // of the objects on the level
  };
  // For a cell inside its level's layout.
  std::uint32_t bucket_of(std::uint32_t level, const Cell& cell) const {
    return static_cast<std::uint32_t>(per_level_[level].layout.index(cell) & mask_);
  }
  std::uint32_t bucket_of(const Entry& e) const { return bucket_of(e.level, e.cell); }
  void assign_levels();
  void sort_by_bucket();
  // Pairs of a with the objects of a level in the cells around a that can hold a partner;
  // half: only the half neighbourhood (for a's own level).
  void visit(const Entry& a, std::uint32_t level, bool half, std::vector<Pair>& out) const;
  // Pairs of a with the objects in one cell, from entry `first` of its bucket on.
  void scan(const Entry& a, std::uint32_t level, const Cell& cell, std::uint32_t first, std::vector<Pair>& out) const;

  HashGridConfig config_;
  Levels levels_;
  std::uint64_t mask_ = 0;
  // Finite objects grouped by bucket: bucket b holds entries [start_[b], start_[b + 1]).
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> start_ = {0};
  std::vector<PerLevel> per_level_;      // indexed by level
  std::vector<std::uint32_t> occupied_;  // the levels holding objects, ascending
  std::vector<Object> walls_;            // the infinite objects
};

}  // namespace cosim::rigidbody::broadphase
