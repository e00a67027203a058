#pragma once
// Which rank owns each cell: a table (METIS's parts, any mesh) or bricks (a structured box,
// bricks.hpp: no table, the owner found from the cell's index).

#include <optional>
#include <span>
#include <vector>

#include "tracker/parallel/bricks.hpp"

namespace cosim::tracker::parallel {

class Owners {
 public:
  explicit Owners(std::vector<int> table) : table_(std::move(table)) {}
  explicit Owners(Bricks bricks) : bricks_(std::move(bricks)) {}

  int operator()(Index cell) const { return bricks_ ? bricks_->owner(cell) : table_[static_cast<std::size_t>(cell)]; }
  const std::optional<Bricks>& bricks() const { return bricks_; }

  // As numbers (the table, or the bricks' cuts), for states, and back: `like` gives the
  // kind and the sizes. std::invalid_argument for numbers that are not such owners of
  // `cells` cells over `ranks` ranks.
  std::vector<int> saved() const;
  static Owners restored(std::span<const int> numbers, const Owners& like, Index cells, int ranks);

 private:
  std::vector<int> table_;
  std::optional<Bricks> bricks_;
};

}  // namespace cosim::tracker::parallel
