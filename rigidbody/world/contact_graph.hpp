// The contact edges between nearby bodies, this narrow phase's contacts, and what the
// solver carries from one narrow phase to the next.
#pragma once

#include <span>
#include <vector>

#include "rigidbody/broadphase/object.hpp"
#include "rigidbody/contact/contact_set.hpp"
#include "rigidbody/solver/contact_memory.hpp"

namespace cosim::rigidbody::world {

// One edge per candidate pair of the broad phase (bounding spheres within the contact
// margin). An edge lives while the broad phase keeps reporting its pair and is dropped in
// the first update that does not, i.e. when the pair separates beyond the margin.
//
// The narrow phase fills `contacts()` edge by edge, so its pairs come out sorted like the
// edges, and the Gauss-Seidel order, and with it the result, does not depend on the broad
// phase's traversal order. Warm starting matches each new point to last substep's point of
// the same pair and feature (solver::ContactMemory); a point that vanished is forgotten.
class ContactGraph {
 public:
  // Replaces the edge set by `pairs` (each a < b, any order), which it keeps as the edges:
  // the broad phase's list moved in is the only one held.
  void update(std::vector<broadphase::Pair> pairs);
  std::span<const broadphase::Pair> edges() const { return edges_; }

  // This narrow phase's contacts: clear, then add one manifold per touching edge in edge order.
  contact::ContactSet& contacts() { return contacts_; }
  const contact::ContactSet& contacts() const { return contacts_; }

  // The last narrow phase's values for this one's points, for the solver to update in place.
  std::span<solver::CachedContact> recall();
  // What the last recall() gave, as the solver left it.
  std::span<solver::CachedContact> recalled() { return values_; }
  // Keeps the solved values for the next substep.
  void remember() { memory_.remember(contacts_, values_); }
  // All the graph carries from one substep to the next (edges and contacts are rebuilt).
  solver::ContactMemory& memory() { return memory_; }
  const solver::ContactMemory& memory() const { return memory_; }

 private:
  std::vector<broadphase::Pair> edges_;  // sorted
  contact::ContactSet contacts_;
  solver::ContactMemory memory_;
  std::vector<solver::CachedContact> values_;  // one per point of contacts_
};

}  // namespace cosim::rigidbody::world
