// Persistent contact edges between nearby bodies, and the solver's impulse memory.
#pragma once

#include <span>
#include <vector>

#include "rigidbody/broadphase/object.hpp"
#include "rigidbody/contact/contact.hpp"
#include "rigidbody/solver/impulse_cache.hpp"

namespace cosim::world {

// One edge per candidate pair of the broad phase (bounding spheres within the contact
// margin). An edge lives while the broad phase keeps reporting its pair and is dropped in
// the first update that does not, i.e. when the pair separates beyond the margin. It holds
// the pair's last manifold (empty while the shapes are near but not within the margin).
//
// Warm starting uses the solver's own ContactImpulses, keyed by (a, b, feature), owned
// here: the solver already reads the previous step's impulses from it and replaces them by
// this step's, which forgets points (and so edges) that vanished. Per-edge copies would
// only add a translation to and from that format every step.
//
// Edges are kept sorted by (a, b) so the Gauss-Seidel order, and with it the result, does
// not depend on the broad phase's traversal order.
class ContactGraph {
 public:
  struct Edge {
    contact::Manifold manifold;  // manifold.a < manifold.b
  };

  // Replaces the edge set by `pairs` (each a < b, any order), keeping the manifolds of
  // edges that persist.
  void update(std::span<const broadphase::Pair> pairs);

  std::span<Edge> edges() { return edges_; }
  std::span<const Edge> edges() const { return edges_; }

  // The non-empty manifolds, in edge order: what the contact solver works on. Rebuilt by
  // each call; the span is valid until the next one.
  std::span<const contact::Manifold> touching();

  solver::ContactImpulses& impulses() { return impulses_; }

 private:
  std::vector<Edge> edges_;
  std::vector<Edge> merged_;  // scratch of update(), kept for its capacity
  std::vector<broadphase::Pair> sorted_;
  std::vector<contact::Manifold> touching_;
  solver::ContactImpulses impulses_;
};

}  // namespace cosim::world
