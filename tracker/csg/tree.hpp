#pragma once

#include <functional>
#include <vector>

#include "tracker/csg/expression.hpp"
#include "tracker/csg/primitive.hpp"
#include "tracker/csg/state.hpp"

namespace cosim::tracker::csg {

// The normal form of an expression: unions and intersections over literals, a literal being
// a primitive or its complement. Differences become intersections with complements
// (a - b = a & ~b) and complements are pushed to the leaves by De Morgan, where they invert
// the primitive's indicator. Each occurrence of a primitive in the expression gets its own
// index, so a primitive is in exactly one literal and the object is monotone in it: its
// surface normal is the literal's (the primitive's, negated for a complement).
class Tree {
 public:
  // Any number of primitives; a logical State holds max_primitives of them (Object checks).
  explicit Tree(const Expression& expression);

  // The tree where only the primitives `kept` (global indices, in the order that becomes
  // the new local indices) still vary: every other primitive g is replaced by the constant
  // `inside(g)` (inside it or not, asked only for the primitives the tree still reaches), and unions and intersections
  // are simplified, down to a constant if nothing varies any more. Used per cell: a primitive whose surface stays away
  // from a cell is constant there.
  Tree pruned(const std::vector<int>& kept, const std::function<bool(int)>& inside) const;
  // The tree without primitives that is always `value`.
  static Tree fixed(bool value);
  // Constant: no primitive can change the answer.
  bool constant() const { return nodes_[root_].op == Op::constant; }

  const std::vector<Primitive>& primitives() const { return primitives_; }
  std::vector<Primitive>& primitives() { return primitives_; }
  bool complemented(int primitive) const { return complemented_[primitive]; }

  // Inside the object for these "inside primitive i" bits.
  bool evaluate(State state) const { return evaluate(root_, state); }
  // Inside the object at x by direct evaluation of every primitive, whatever their number.
  // Round-off decides near a surface: for set-up and checks, not for tracking.
  bool contains(const Eigen::Vector3d& x) const;
  // The state at x by direct evaluation (primitive i inside: bit i), for at most
  // max_primitives primitives; away from surfaces only, like contains().
  State classify(const Eigen::Vector3d& x) const;

 private:
  enum class Op { literal, any, all, constant };
  struct Node {
    Op op;
    int primitive;              // literal; constant: 1 inside, 0 outside
    std::vector<int> children;  // any (union), all (intersection)
  };
  Tree() = default;

  int normalise(const Expression& e, bool complement, const Eigen::Affine3d& frame);
  int combine(Op op, const Expression& a, bool complement_a, const Expression& b, bool complement_b,
              const Eigen::Affine3d& frame);
  template <typename IsInside>
  bool evaluate_with(int node, const IsInside& inside) const;
  bool evaluate(int node, State state) const;
  // Copies node `index` of `from` into this tree, `local[g]` the new index of primitive g
  // (-1: dropped, then inside(g) gives its value); returns the new node.
  int prune(const Tree& from, int index, const std::vector<int>& local, const std::function<bool(int)>& inside);
  int add_constant(bool value);

  std::vector<Primitive> primitives_;
  std::vector<bool> complemented_;
  std::vector<Node> nodes_;
  int root_ = -1;
};

}  // namespace cosim::tracker::csg
