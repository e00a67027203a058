#pragma once

#include <memory>
#include <span>

#include <Eigen/Geometry>

#include "tracker/csg/primitive.hpp"

namespace cosim::tracker::csg {

// A CSG expression as the user writes it: primitives combined by union (|), intersection
// (&), difference (-), complement (~) and affine transforms. Immutable and cheap to copy
// (shared nodes). Objects turn it into the normal form of tree.hpp.
class Expression {
 public:
  enum class Op { primitive, unite, intersect, subtract, complement, transform };

  static Expression primitive(PrimitiveKind kind, const Eigen::Affine3d& placement);
  // Applies `transform` (object frame from the expression's frame) to every primitive below.
  static Expression transformed(const Eigen::Affine3d& transform, const Expression& child);

  friend Expression operator|(const Expression& a, const Expression& b) { return {Op::unite, a, b}; }
  friend Expression operator&(const Expression& a, const Expression& b) { return {Op::intersect, a, b}; }
  friend Expression operator-(const Expression& a, const Expression& b) { return {Op::subtract, a, b}; }
  friend Expression operator~(const Expression& a) { return {Op::complement, a, a}; }
  // The union (intersection) of all `parts`, paired off into a balanced tree: a chain
  // a | b | c | ... of N would make normalisation N deep and O(N^2) (a balls file, a
  // lattice). Throws std::invalid_argument for no parts.
  static Expression unite(std::span<const Expression> parts);
  static Expression intersect(std::span<const Expression> parts);

  Op op() const { return node_->op; }
  PrimitiveKind kind() const { return node_->kind; }
  // The primitive's placement, or the transform of a transform node.
  const Eigen::Affine3d& affine() const { return node_->affine; }
  Expression left() const { return Expression(node_->left); }
  Expression right() const { return Expression(node_->right); }

 private:
  struct Node {
    Op op;
    PrimitiveKind kind;
    Eigen::Affine3d affine;
    std::shared_ptr<const Node> left;
    std::shared_ptr<const Node> right;
  };
  explicit Expression(std::shared_ptr<const Node> node) : node_(std::move(node)) {}
  Expression(Op op, const Expression& a, const Expression& b);

  std::shared_ptr<const Node> node_;
};

}  // namespace cosim::tracker::csg
