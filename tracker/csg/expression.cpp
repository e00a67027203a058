#include "tracker/csg/expression.hpp"

namespace cosim::csg {

Expression Expression::primitive(PrimitiveKind kind, const Eigen::Affine3d& placement) {
  // Checked now, where the mistake is made, not when an object is built from it.
  require_invertible(placement);
  return Expression(std::make_shared<const Node>(Node{Op::primitive, kind, placement, nullptr, nullptr}));
}

Expression Expression::transformed(const Eigen::Affine3d& transform, const Expression& child) {
  require_invertible(transform);
  return Expression(std::make_shared<const Node>(
      Node{Op::transform, PrimitiveKind::ball, transform, child.node_, child.node_}));
}

Expression::Expression(Op op, const Expression& a, const Expression& b)
    : node_(std::make_shared<const Node>(Node{op, PrimitiveKind::ball, Eigen::Affine3d::Identity(), a.node_, b.node_})) {}

}  // namespace cosim::csg
