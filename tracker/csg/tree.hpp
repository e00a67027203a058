#pragma once

#include <vector>

#include "tracker/csg/expression.hpp"
#include "tracker/csg/primitive.hpp"
#include "tracker/csg/state.hpp"

namespace cosim::csg {

// The normal form of an expression: unions and intersections over literals, a literal being
// a primitive or its complement. Differences become intersections with complements
// (a - b = a & ~b) and complements are pushed to the leaves by De Morgan, where they invert
// the primitive's indicator. Each occurrence of a primitive in the expression gets its own
// index, so a primitive is in exactly one literal and the object is monotone in it: its
// surface normal is the literal's (the primitive's, negated for a complement).
class Tree {
 public:
  // Throws std::invalid_argument beyond max_primitives primitives.
  explicit Tree(const Expression& expression);

  const std::vector<Primitive>& primitives() const { return primitives_; }
  std::vector<Primitive>& primitives() { return primitives_; }
  bool complemented(int primitive) const { return complemented_[primitive]; }

  // Inside the object for these "inside primitive i" bits.
  bool evaluate(State state) const { return evaluate(root_, state); }

 private:
  enum class Op { literal, any, all };
  struct Node {
    Op op;
    int primitive;               // literal
    std::vector<int> children;   // any (union), all (intersection)
  };

  int normalise(const Expression& e, bool complement, const Eigen::Affine3d& frame);
  int combine(Op op, const Expression& a, bool complement_a, const Expression& b, bool complement_b,
              const Eigen::Affine3d& frame);
  bool evaluate(int node, State state) const;

  std::vector<Primitive> primitives_;
  std::vector<bool> complemented_;
  std::vector<Node> nodes_;
  int root_;
};

}  // namespace cosim::csg
