// Chords of each primitive against closed forms, and indicator and normal conventions.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tracker/csg/object.hpp"
#include "tracker/csg/shapes.hpp"
#include "tracker/csg/tree.hpp"

namespace cosim::tracker::csg {
namespace {

const Primitive& only(const Object& o) { return o.tree().primitives().front(); }

TEST(Primitive, BallChordHasBothRootsOfALineThroughIt) {
  const Object o(ball({1, 2, 3}, 0.5));
  // Offset 0.3 from the centre, speed 2: roots where |(-4 + 2t, 0.3, 0)| = 0.5.
  const Chord c = only(o).chord({-3, 2.3, 3}, {2, 0, 0});
  const double half = std::sqrt(0.25 - 0.09) / 2.0;
  EXPECT_NEAR(c.in, 2.0 - half, 1e-15);
  EXPECT_NEAR(c.out, 2.0 + half, 1e-15);
  EXPECT_NEAR(c.mid, 2.0, 1e-15);
  EXPECT_TRUE(only(o).chord({-3, 2.6, 3}, {2, 0, 0}).is_empty());
}

TEST(Primitive, BallRootsStayAccurateFarAway) {
  // b^2 - a c cancels here to about 1e-4 relative (c ~ 1e12 in the ball's frame); the
  // distance form leaves only the round-off of roots near 1e3, a few ulps of 1e3.
  const Object o(ball({0, 0, 0}, 1e-3));
  const Chord c = only(o).chord({-1e3, 0.6e-3, 0}, {1, 0, 0});
  EXPECT_NEAR(c.out - c.in, 1.6e-3, 1e-12);
}

TEST(Primitive, HalfSpaceChordIsTheFacetRule) {
  const Object o(half_space({0, 0, 1}, {0, 0, 2}));
  const Chord down = only(o).chord({0, 0, 3}, {1, 0, -4});
  EXPECT_DOUBLE_EQ(down.in, 0.5);
  EXPECT_EQ(down.out, Chord::inf);
  const Chord up = only(o).chord({0, 0, 3}, {0, 0, 4});
  EXPECT_EQ(up.in, -Chord::inf);
  EXPECT_DOUBLE_EQ(up.out, -0.5);
  EXPECT_TRUE(only(o).chord({0, 0, 3}, {1, 0, 0}).is_empty());
  EXPECT_EQ(only(o).chord({0, 0, 0}, {1, 0, 0}).in, -Chord::inf);
}

TEST(Primitive, CylinderChordOfSkewLines) {
  // Axis z, radius 2; a line at height offset b from the axis, with any axial speed, is
  // inside while x^2 + b^2 < 4.
  const Object o(cylinder({0, 0, 7}, {0, 0, 3}, 2.0));
  for (const double w : {0.0, 0.5, -3.0}) {
    const Chord c = only(o).chord({-5, 1.5, 0}, {1, 0, w});
    EXPECT_NEAR(c.in, 5.0 - std::sqrt(4.0 - 2.25), 1e-14);
    EXPECT_NEAR(c.out, 5.0 + std::sqrt(4.0 - 2.25), 1e-14);
  }
  // Tilted axis (1, 1, 0)/sqrt 2 through the origin, radius 1: a line parallel to it at
  // distance 1/sqrt 2 is inside throughout.
  const Object tilted(cylinder({0, 0, 0}, {1, 1, 0}, 1.0));
  EXPECT_EQ(only(tilted).chord({1, 0, 0}, {1, 1, 0}).in, -Chord::inf);
  // Skew lines: squared distance of (t - 3, 1, t) to the axis is 1.5 t^2 - 4 t + 8, never 1.
  EXPECT_TRUE(only(tilted).chord({-3, 1, 0}, {1, 0, 1}).is_empty());
  // For (t - 1, 0.5, t - 1) it is 1.5 t^2 - 3.5 t + 2.125: inside between the roots of
  // 1.5 t^2 - 3.5 t + 1.125.
  const Chord d = only(tilted).chord({-1, 0.5, -1}, {1, 0, 1});
  const double disc = std::sqrt(3.5 * 3.5 - 4 * 1.5 * 1.125);
  EXPECT_NEAR(d.in, (3.5 - disc) / 3.0, 1e-14);
  EXPECT_NEAR(d.out, (3.5 + disc) / 3.0, 1e-14);
}

TEST(Primitive, BoxChordIsTheSlabIntersection) {
  const Object o(box({0, 0, 0}, {1, 2, 3}));
  const Chord c = only(o).chord({-3, 0.5, -4}, {1, 0, 1});
  EXPECT_DOUBLE_EQ(c.in, 2.0);   // x = -1 at t = 2, z = -3 at t = 1
  EXPECT_DOUBLE_EQ(c.out, 4.0);  // x = 1 at t = 4, z = 3 at t = 7
  // Rotated 90 degrees about z: half extents (2, 1, 3) in the world.
  const Object r(box({0, 0, 0}, {1, 2, 3}, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))));
  const Chord d = only(r).chord({-5, 0, 0}, {1, 0, 0});
  EXPECT_NEAR(d.in, 3.0, 1e-15);
  EXPECT_NEAR(d.out, 7.0, 1e-15);
  EXPECT_TRUE(only(o).chord({-3, 2.5, 0}, {1, 0, 0}).is_empty());
}

TEST(Primitive, AffineTransformMakesAnEllipsoid) {
  Eigen::Affine3d stretch = Eigen::Affine3d::Identity();
  stretch.linear() = Eigen::Vector3d(3, 1, 1).asDiagonal();
  const Object o(Expression::transformed(stretch, ball({0, 0, 0}, 1.0)));
  const Chord c = only(o).chord({-5, 0, 0}, {1, 0, 0});
  EXPECT_NEAR(c.in, 2.0, 1e-15);
  EXPECT_NEAR(c.out, 8.0, 1e-15);
  // grad of x^2/9 + y^2 + z^2 at (3 cos a, sin a, 0) is along (cos a / 3, sin a, 0).
  const double a = 0.7;
  const Eigen::Vector3d n = only(o).normal({3 * std::cos(a), std::sin(a), 0});
  EXPECT_NEAR(n.dot(Eigen::Vector3d(std::cos(a) / 3, std::sin(a), 0).normalized()), 1.0, 1e-15);
}

TEST(Primitive, IndicatorIsNegativeInsideAndNormalPointsOut) {
  const Object o(ball({0, 0, 0}, 2.0) & half_space({0, 0, 0}, {0, 0, 1}) & cylinder({0, 0, 0}, {0, 0, 1}, 1.0) &
                 box({0, 0, 0}, {1, 1, 1}));
  for (const Primitive& p : o.tree().primitives()) {
    EXPECT_LT(p.indicator({0.1, 0.2, -0.3}), 0.0);
    EXPECT_GT(p.indicator({5, 5, 5}), 0.0);
  }
  EXPECT_NEAR(o.tree().primitives()[0].normal({0, 2, 0}).y(), 1.0, 1e-15);
  EXPECT_NEAR(o.tree().primitives()[1].normal({3, 4, 0}).z(), 1.0, 1e-15);
  EXPECT_NEAR(o.tree().primitives()[2].normal({-1, 0, 9}).x(), -1.0, 1e-15);
  EXPECT_NEAR(o.tree().primitives()[3].normal({0.2, -1, 0.5}).y(), -1.0, 1e-15);
}

TEST(Primitive, RejectsDegenerateInput) {
  EXPECT_THROW(ball({0, 0, 0}, 0.0), std::invalid_argument);
  EXPECT_THROW(half_space({0, 0, 0}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(box({0, 0, 0}, {1, -1, 1}), std::invalid_argument);
  Eigen::Affine3d flat = Eigen::Affine3d::Identity();
  flat.linear()(2, 2) = 0.0;
  EXPECT_THROW(Expression::transformed(flat, ball({0, 0, 0}, 1.0)), std::invalid_argument);
}

// The bounding test through the mesh: false only for boxes wholly inside or outside.
TEST(Primitive, SurfaceMayMeetABoxOnlyWhereItPasses) {
  const auto box = [](double lo, double hi) {
    return Eigen::AlignedBox3d(Eigen::Vector3d::Constant(lo), Eigen::Vector3d::Constant(hi));
  };
  const auto only = [](const Expression& e) { return Tree(e).primitives().front(); };
  const Primitive b = only(ball({0, 0, 0}, 1.0));
  EXPECT_FALSE(b.surface_may_meet(box(-0.5, 0.5)));  // inside
  EXPECT_FALSE(b.surface_may_meet(box(0.6, 0.8)));   // outside, though within the ball's bounding box
  EXPECT_TRUE(b.surface_may_meet(box(0.5, 0.7)));
  const Primitive h = only(half_space({0, 0, 0.3}, {0, 0, 1}));
  EXPECT_FALSE(h.surface_may_meet(box(-1, 0.2)));
  EXPECT_FALSE(h.surface_may_meet(box(0.4, 1)));
  EXPECT_TRUE(h.surface_may_meet(box(0.2, 0.4)));
  const Primitive c = only(cylinder({0, 0, 0}, {0, 0, 1}, 1.0));
  EXPECT_FALSE(c.surface_may_meet(box(5, 6)));
  EXPECT_FALSE(
      c.surface_may_meet(Eigen::AlignedBox3d(Eigen::Vector3d(-0.5, -0.5, 100), Eigen::Vector3d(0.5, 0.5, 200))));
  EXPECT_TRUE(c.surface_may_meet(box(0.6, 0.8)));
  const Primitive cube = only(csg::box({0, 0, 0}, {1, 1, 1}));
  EXPECT_FALSE(cube.surface_may_meet(box(-0.9, 0.9)));
  EXPECT_FALSE(cube.surface_may_meet(box(1.1, 2)));
  EXPECT_TRUE(cube.surface_may_meet(box(0.9, 1.1)));
}

// Bounds hold every point of the solid and are tight along the axes of an axis-aligned one.
TEST(Primitive, BoundsHoldTheSolid) {
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const Object tilted(box({1, -2, 0.5}, {0.3, 0.1, 0.2}, turn));
  const Object round(ball({0.5, 0.5, 0.5}, 0.25));
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> uniform(-3.0, 3.0);
  int inside = 0;
  for (int i = 0; i < 100000; ++i) {
    const Eigen::Vector3d x(uniform(random), uniform(random), uniform(random));
    for (const Object* o : {&tilted, &round}) {
      if (!only(*o).contains(x)) continue;
      ++inside;
      EXPECT_TRUE(only(*o).bounds().contains(x)) << x.transpose();
    }
  }
  EXPECT_GT(inside, 10);
  EXPECT_LT((only(round).bounds().min() - Eigen::Vector3d::Constant(0.25)).norm(), 1e-15);
  EXPECT_LT((only(round).bounds().max() - Eigen::Vector3d::Constant(0.75)).norm(), 1e-15);
  EXPECT_TRUE(only(Object(half_space({0, 0, 0}, {0, 0, 1}))).bounds().contains(Eigen::Vector3d(1e300, -1e300, 0)));
}

}  // namespace
}  // namespace cosim::tracker::csg
