#include "tracker/csg/expression.hpp"

#include <stdexcept>

namespace cosim::tracker::csg {

Expression Expression::primitive(PrimitiveKind kind, const Eigen::Affine3d& placement) {
  // Checked now, where the mistake is made, not when an object is built from it.
  require_invertible(placement);
  return Expression(std::make_shared<const Node>(Node{Op::primitive, kind, placement, nullptr, nullptr}));
}

Expression Expression::transformed(const Eigen::Affine3d& transform, const Expression& child) {
  require_invertible(transform);
  return Expression(
      std::make_shared<const Node>(Node{Op::transform, PrimitiveKind::ball, transform, child.node_, child.node_}));
}

Expression::Expression(Op op, const Expression& a, const Expression& b)
    : node_(
          std::make_shared<const Node>(Node{op, PrimitiveKind::ball, Eigen::Affine3d::Identity(), a.node_, b.node_})) {}

namespace {

Expression balanced(std::span<const Expression> parts, bool unite) {
  if (parts.empty()) throw std::invalid_argument("csg: a union or intersection of no shapes");
  if (parts.size() == 1) return parts.front();
  const std::size_t half = parts.size() / 2;
  const Expression a = balanced(parts.first(half), unite), b = balanced(parts.subspan(half), unite);
  return unite ? (a | b) : (a & b);
}

}  // namespace

Expression Expression::unite(std::span<const Expression> parts) { return balanced(parts, true); }
Expression Expression::intersect(std::span<const Expression> parts) { return balanced(parts, false); }

}  // namespace cosim::tracker::csg
