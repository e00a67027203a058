#include "rigidbody/world/contact_graph.hpp"

#include <algorithm>

namespace cosim::rigidbody::world {

void ContactGraph::update(std::span<const broadphase::Pair> pairs) {
  edges_.assign(pairs.begin(), pairs.end());
  std::sort(edges_.begin(), edges_.end());
}

std::span<solver::CachedContact> ContactGraph::recall() {
  memory_.recall(contacts_, values_);
  return values_;
}

}  // namespace cosim::rigidbody::world
