#include "tracker/csg/tree.hpp"

#include <stdexcept>
#include <string>

namespace cosim::csg {

Tree::Tree(const Expression& expression) : root_(normalise(expression, false, Eigen::Affine3d::Identity())) {
  if (primitives_.size() > static_cast<std::size_t>(max_primitives))
    throw std::invalid_argument("csg object: " + std::to_string(primitives_.size()) + " primitives, at most " +
                                std::to_string(max_primitives) + " fit in a logical state");
}

int Tree::normalise(const Expression& e, bool complement, const Eigen::Affine3d& frame) {
  switch (e.op()) {
    case Expression::Op::primitive:
      primitives_.emplace_back(e.kind(), frame * e.affine());
      complemented_.push_back(complement);
      nodes_.push_back({Op::literal, static_cast<int>(primitives_.size()) - 1, {}});
      return static_cast<int>(nodes_.size()) - 1;
    case Expression::Op::complement: return normalise(e.left(), !complement, frame);
    case Expression::Op::transform: return normalise(e.left(), complement, frame * e.affine());
    // ~(a | b) = ~a & ~b and ~(a & b) = ~a | ~b.
    case Expression::Op::unite:
      return combine(complement ? Op::all : Op::any, e.left(), complement, e.right(), complement, frame);
    case Expression::Op::intersect:
      return combine(complement ? Op::any : Op::all, e.left(), complement, e.right(), complement, frame);
    // a - b = a & ~b, and ~(a & ~b) = ~a | b.
    case Expression::Op::subtract:
      return combine(complement ? Op::any : Op::all, e.left(), complement, e.right(), !complement, frame);
  }
  throw std::logic_error("csg: unknown expression node");
}

// Nested unions (or intersections) are flattened into one node, so evaluation walks a tree
// whose depth alternates between the two.
int Tree::combine(Op op, const Expression& a, bool complement_a, const Expression& b, bool complement_b,
                  const Eigen::Affine3d& frame) {
  std::vector<int> children;
  for (const int child : {normalise(a, complement_a, frame), normalise(b, complement_b, frame)}) {
    if (nodes_[child].op == op) {
      children.insert(children.end(), nodes_[child].children.begin(), nodes_[child].children.end());
    } else {
      children.push_back(child);
    }
  }
  nodes_.push_back({op, -1, std::move(children)});
  return static_cast<int>(nodes_.size()) - 1;
}

bool Tree::evaluate(int index, State state) const {
  const Node& node = nodes_[index];
  switch (node.op) {
    case Op::literal: return test(state, node.primitive) != complemented_[node.primitive];
    case Op::any:
      for (const int child : node.children)
        if (evaluate(child, state)) return true;
      return false;
    case Op::all:
      for (const int child : node.children)
        if (!evaluate(child, state)) return false;
      return true;
  }
  return false;
}

}  // namespace cosim::csg
