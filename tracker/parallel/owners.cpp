#include "tracker/parallel/owners.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cosim::tracker::parallel {

std::vector<int> Owners::saved() const { return bricks_ ? bricks_->cuts() : table_; }

Owners Owners::restored(std::span<const int> numbers, const Owners& like, Index cells, int ranks) {
  std::vector<int> values(numbers.begin(), numbers.end());
  if (const std::optional<Bricks>& b = like.bricks())
    return Owners(Bricks::from_cuts(b->hexahedra(), b->per_hex(), b->parts(), values));
  if (values.size() != static_cast<std::size_t>(cells) ||
      std::any_of(values.begin(), values.end(), [&](int r) { return r < 0 || r >= ranks; }))
    throw std::invalid_argument("owners: one rank of " + std::to_string(ranks) + " per cell of " +
                                std::to_string(cells));
  return Owners(std::move(values));
}

}  // namespace cosim::tracker::parallel
