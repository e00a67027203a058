// The normal form: differences, complements and De Morgan against direct formulas.
#include <random>

#include <gtest/gtest.h>

#include "tracker/csg/object.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

bool in_ball(const Eigen::Vector3d& x, const Eigen::Vector3d& c, double r) { return (x - c).norm() < r; }

TEST(Tree, DifferenceIsIntersectionWithTheComplement) {
  const auto b = box({0, 0, 0}, {1, 1, 1});
  const auto s = ball({0.5, 0.5, 0.5}, 0.8);
  const Object difference(b - s);
  const Object complemented(b & ~s);
  EXPECT_TRUE(difference.tree().complemented(1));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int inside = 0;
  for (int k = 0; k < 100000; ++k) {
    const Eigen::Vector3d x(u(rng), u(rng), u(rng));
    const bool expected = x.cwiseAbs().maxCoeff() < 1.0 && !in_ball(x, {0.5, 0.5, 0.5}, 0.8);
    ASSERT_EQ(difference.inside(difference.classify(x)), expected);
    ASSERT_EQ(complemented.inside(complemented.classify(x)), expected);
    inside += expected;
  }
  EXPECT_GT(inside, 10000);
}

TEST(Tree, ComplementsArePushedToTheLeaves) {
  const auto a = ball({0, 0, 0}, 1.0);
  const auto b = ball({1, 0, 0}, 1.0);
  const auto c = half_space({0, 0, 0}, {0, 0, 1});
  // ~((a | b) - c) = (~a & ~b) | c
  const Object o(~((a | b) - c));
  EXPECT_TRUE(o.tree().complemented(0));
  EXPECT_TRUE(o.tree().complemented(1));
  EXPECT_FALSE(o.tree().complemented(2));
  for (State s = 0; s < 8; ++s) {
    const bool ia = test(s, 0), ib = test(s, 1), ic = test(s, 2);
    EXPECT_EQ(o.inside(s), (!ia && !ib) || ic) << s;
  }
}

TEST(Tree, TransformsComposeDownTheTree) {
  Eigen::Affine3d shift = Eigen::Affine3d::Identity();
  shift.translation() = Eigen::Vector3d(10, 0, 0);
  const Object o(Expression::transformed(shift, ball({1, 0, 0}, 0.5) | ~half_space({0, 0, 0}, {0, 0, 1})));
  EXPECT_TRUE(o.inside(o.classify({11.2, 0, -0.1})));
  EXPECT_TRUE(o.inside(o.classify({3, 0, 1})));
  EXPECT_FALSE(o.inside(o.classify({3, 0, -1})));
}

TEST(Tree, RejectsMorePrimitivesThanTheStateHolds) {
  Expression e = ball({0, 0, 0}, 1.0);
  for (int i = 1; i < max_primitives; ++i) e = e | ball({double(i), 0, 0}, 1.0);
  EXPECT_NO_THROW(Object{e});
  EXPECT_THROW(Object(e | ball({-1, 0, 0}, 1.0)), std::invalid_argument);
}

// A balls file of 1e5 lines: the balanced union normalises in N log N, log N deep, and keeps
// the balls in order.
TEST(Tree, LongUnionsStayShallow) {
  std::vector<Expression> balls;
  for (int i = 0; i < 100000; ++i) balls.push_back(ball({3.0 * i, 0, 0}, 1.0));
  const Tree tree(Expression::unite(balls));
  ASSERT_EQ(tree.primitives().size(), 100000u);
  EXPECT_TRUE(tree.primitives()[7].contains({21.5, 0, 0}));
  EXPECT_TRUE(tree.contains({3.0 * 99999 + 0.5, 0, 0}));
  EXPECT_FALSE(tree.contains({1.5, 0, 0}));
  EXPECT_THROW(Expression::unite({}), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::csg
