#include "rigidbody/world/contact_graph.hpp"

#include <algorithm>
#include <utility>

namespace cosim::rigidbody::world {

void ContactGraph::update(std::vector<broadphase::Pair> pairs) {
  edges_ = std::move(pairs);
  std::sort(edges_.begin(), edges_.end());
}

std::span<solver::CachedContact> ContactGraph::recall() {
  memory_.recall(contacts_, values_);
  return values_;
}

}  // namespace cosim::rigidbody::world
