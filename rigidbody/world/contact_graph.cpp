#include "rigidbody/world/contact_graph.hpp"

#include <algorithm>

namespace cosim::world {

void ContactGraph::update(std::span<const broadphase::Pair> pairs) {
  sorted_.assign(pairs.begin(), pairs.end());
  std::sort(sorted_.begin(), sorted_.end());
  merged_.clear();
  // Both lists are sorted: one merge pass keeps persisting edges and adds new ones.
  auto old = edges_.begin();
  for (const auto& [a, b] : sorted_) {
    const broadphase::Pair key{a, b};
    while (old != edges_.end() && broadphase::Pair{old->manifold.a, old->manifold.b} < key) ++old;
    if (old != edges_.end() && old->manifold.a == a && old->manifold.b == b)
      merged_.push_back(*old);
    else
      merged_.push_back(Edge{contact::Manifold{.a = a, .b = b}});
  }
  edges_.swap(merged_);
}

std::span<const contact::Manifold> ContactGraph::touching() {
  touching_.clear();
  for (const Edge& e : edges_)
    if (e.manifold.count > 0) touching_.push_back(e.manifold);
  return touching_;
}

}  // namespace cosim::world
