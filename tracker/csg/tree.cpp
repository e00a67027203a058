#include "tracker/csg/tree.hpp"

#include <stdexcept>

namespace cosim::tracker::csg {

Tree::Tree(const Expression& expression) : root_(normalise(expression, false, Eigen::Affine3d::Identity())) {}

int Tree::normalise(const Expression& e, bool complement, const Eigen::Affine3d& frame) {
  switch (e.op()) {
    case Expression::Op::primitive:
      primitives_.emplace_back(e.kind(), frame * e.affine());
      complemented_.push_back(complement);
      nodes_.push_back({Op::literal, static_cast<int>(primitives_.size()) - 1, {}});
      return static_cast<int>(nodes_.size()) - 1;
    case Expression::Op::complement:
      return normalise(e.left(), !complement, frame);
    case Expression::Op::transform:
      return normalise(e.left(), complement, frame * e.affine());
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

template <typename IsInside>
bool Tree::evaluate_with(int index, const IsInside& inside) const {
  const Node& node = nodes_[index];
  switch (node.op) {
    case Op::literal:
      return inside(node.primitive) != complemented_[node.primitive];
    case Op::any:
      for (const int child : node.children)
        if (evaluate_with(child, inside)) return true;
      return false;
    case Op::all:
      for (const int child : node.children)
        if (!evaluate_with(child, inside)) return false;
      return true;
    case Op::constant:
      return node.primitive != 0;
  }
  return false;
}

bool Tree::evaluate(int index, State state) const {
  return evaluate_with(index, [state](int primitive) { return test(state, primitive); });
}

bool Tree::contains(const Eigen::Vector3d& x) const {
  return evaluate_with(root_, [&](int primitive) { return primitives_[primitive].contains(x); });
}

State Tree::classify(const Eigen::Vector3d& x) const {
  State state = 0;
  for (std::size_t i = 0; i < primitives_.size(); ++i)
    if (primitives_[i].contains(x)) state |= bit(static_cast<int>(i));
  return state;
}

Tree Tree::pruned(const std::vector<int>& kept, const std::function<bool(int)>& inside) const {
  std::vector<int> local(primitives_.size(), -1);
  Tree out;
  for (const int g : kept) {
    local[g] = static_cast<int>(out.primitives_.size());
    out.primitives_.push_back(primitives_[g]);
    out.complemented_.push_back(complemented_[g]);
  }
  out.root_ = out.prune(*this, root_, local, inside);
  return out;
}

Tree Tree::fixed(bool value) {
  Tree out;
  out.root_ = out.add_constant(value);
  return out;
}

int Tree::add_constant(bool value) {
  nodes_.push_back({Op::constant, value ? 1 : 0, {}});
  return static_cast<int>(nodes_.size()) - 1;
}

int Tree::prune(const Tree& from, int index, const std::vector<int>& local, const std::function<bool(int)>& inside) {
  const Node& node = from.nodes_[index];
  switch (node.op) {
    case Op::constant:
      return add_constant(node.primitive != 0);
    case Op::literal:
      if (local[node.primitive] < 0) return add_constant(inside(node.primitive) != from.complemented_[node.primitive]);
      nodes_.push_back({Op::literal, local[node.primitive], {}});
      return static_cast<int>(nodes_.size()) - 1;
    case Op::any:
    case Op::all: {
      // A union is decided by one true child, an intersection by one false one; the other
      // constant drops out.
      const bool decisive = node.op == Op::any;
      std::vector<int> children;
      for (const int child : node.children) {
        const int c = prune(from, child, local, inside);
        if (nodes_[c].op != Op::constant) {
          children.push_back(c);
        } else if ((nodes_[c].primitive != 0) == decisive) {
          return add_constant(decisive);
        }
      }
      if (children.empty()) return add_constant(!decisive);
      if (children.size() == 1) return children.front();
      nodes_.push_back({node.op, -1, std::move(children)});
      return static_cast<int>(nodes_.size()) - 1;
    }
  }
  throw std::logic_error("csg: unknown tree node");
}

}  // namespace cosim::tracker::csg
