// The levels of the hierarchy: cells of level k are base * factor^k wide, and an object
// goes to the smallest level whose cells are at least its span, safety * (2 r + margin).
// The span bounds how far apart two centres may be and still form a pair, which is what
// lets each level look only one cell around an object.
#pragma once

#include <cstdint>
#include <vector>

namespace cosim::rigidbody::broadphase {

class Levels {
 public:
  Levels(double factor, double safety, double margin);

  double span(double radius) const { return safety_ * (2.0 * radius + margin_); }

  // Forget every level; level 0 gets cells base wide (> 0).
  void reset(double base);
  // The smallest level whose cells are at least span wide; creates levels on demand.
  std::uint32_t level_of(double span);

  double size(std::uint32_t level) const { return size_[level]; }
  double inv_size(std::uint32_t level) const { return inv_size_[level]; }
  std::size_t count() const { return size_.size(); }
  std::size_t memory_bytes() const;

 private:
  void grow_to(std::uint32_t level);

  double factor_;
  double safety_;
  double margin_;
  // Each size is the previous times factor, never a power recomputed, so that level_of
  // and the cells agree on every boundary.
  std::vector<double> size_;
  std::vector<double> inv_size_;
};

}  // namespace cosim::rigidbody::broadphase
