// Bodies inside a container: the deepest point and its normal (from the wall into the free
// inside) against the analytic depth in a round column and a spherical vessel.
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using geometry::Box;
using geometry::Capsule;
using geometry::Container;
using geometry::Cylinder;
using geometry::Sphere;

const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();

// The point of m with the smallest distance.
const contact::ContactPoint& deepest(const contact::Manifold& m) {
  EXPECT_GT(m.count, 0);
  int k = 0;
  for (int i = 1; i < m.count; ++i)
    if (m.points[i].distance < m.points[k].distance) k = i;
  return m.points[k];
}

const Shape column = Container(Cylinder(1.0, 4.0));  // radius 1, from z -2 to 2

TEST(Container, SphereAgainstTheSideAndTheBottom) {
  const Shape ball = Sphere(0.3);
  const auto& side = deepest(contacts(column, at(), ball, at(0.8 * X)));
  EXPECT_NEAR(side.distance, -0.1, 1e-12);
  EXPECT_TRUE(side.normal.isApprox(-X, 1e-12));
  const auto& bottom = deepest(contacts(column, at(), ball, at(-1.85 * Z)));
  EXPECT_NEAR(bottom.distance, -0.15, 1e-12);
  EXPECT_TRUE(bottom.normal.isApprox(Z, 1e-12));
  // The body first: the normal turns round.
  EXPECT_TRUE(deepest(contacts(ball, at(0.8 * X), column, at())).normal.isApprox(X, 1e-12));
  // Well inside: nothing within the margin.
  EXPECT_EQ(contacts(column, at(), ball, at({0.3, 0.2, 0.5}), 0.1).count, 0);
}

TEST(Container, BoxCornersMeetTheRoundWall) {
  const Shape box = Box({0.2, 0.2, 0.2});
  for (double c : {0.6, 0.75, 0.85}) {
    const double depth = 1.0 - std::hypot(c + 0.2, 0.2);  // the outer corners' gap
    const auto m = contacts(column, at(), box, at(c * X), 0.2);
    const auto& p = deepest(m);
    EXPECT_NEAR(p.distance, depth, 1e-12) << c;
    EXPECT_TRUE(p.normal.isApprox(-Vec3(c + 0.2, 0.2, 0).normalized(), 1e-12) ||
                p.normal.isApprox(-Vec3(c + 0.2, -0.2, 0).normalized(), 1e-12))
        << p.normal.transpose();
    // A face against a curved wall rests on its two outer corners at each end: more than one point.
    if (depth < 0) EXPECT_GE(m.count, 2) << c;
  }
}

TEST(Container, CapsuleAcrossTheColumnTouchesAtBothEnds) {
  const Shape capsule = Capsule(0.2, 1.0);  // its axis turned onto y, ends at y = ±0.5
  const auto across = about(X, M_PI / 2);
  const auto m = contacts(column, at(), capsule, at(0.7 * X, across));
  const double depth = 1.0 - std::hypot(0.7, 0.5) - 0.2;
  EXPECT_NEAR(deepest(m).distance, depth, 1e-12);
  int at_depth = 0;
  for (int i = 0; i < m.count; ++i) at_depth += std::abs(m.points[i].distance - depth) < 1e-12;
  EXPECT_EQ(at_depth, 2);
}

TEST(Container, TurnedAndMovedColumnAndASphericalVessel) {
  // The column lying along x, its axis through (0, 1, 1): a ball at y = 1.85 presses on the wall at y = 2.
  const Pose lying = at({0, 1, 1}, about(Y, M_PI / 2));
  const auto& p = deepest(contacts(column, lying, Sphere(0.3), at({0.5, 1.85, 1})));
  EXPECT_NEAR(p.distance, -0.15, 1e-12);
  EXPECT_TRUE(p.normal.isApprox(-Y, 1e-12));
  // A box in a spherical vessel of radius 1: its farthest corner decides.
  const Shape vessel = Container(Sphere(1.0));
  const Vec3 centre(0.4, 0.3, 0.2);  // its far corner 0.05 beyond the wall
  const auto& q = deepest(contacts(vessel, at(), Box({0.3, 0.3, 0.3}), at(centre)));
  EXPECT_NEAR(q.distance, 1.0 - (centre + Vec3(0.3, 0.3, 0.3)).norm(), 1e-12);
}

TEST(Container, TwoContainersNeverCollide) { EXPECT_EQ(contacts(column, at(), Container(Sphere(1.0)), at()).count, 0); }

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
