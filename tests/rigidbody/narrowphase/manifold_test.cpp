// Manifolds of the general convex path: faces, cylinder caps and sides and capsules lying
// on a face give the points of their contact area, not one point a call.
#include "rigidbody/narrowphase/pairs.hpp"
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using namespace geometry;
const Vec3 Z = Vec3::UnitZ();

ConvexHull hull_box(const Vec3& h) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back(h.cwiseProduct(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  return ConvexHull(corners);
}

// A floor box whose top face is z = 0, much larger than what rests on it.
const Shape floor_box = Box({2, 2, 0.5});
const Pose floor_pose = at({0.1, -0.2, -0.5});

void expect_all(const contact::Manifold& m, double distance) {
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].distance, distance, 1e-9);
    EXPECT_TRUE(m.points[i].normal.isApprox(Z, 1e-9)) << m.points[i].normal.transpose();
  }
}

TEST(Manifold, HullBoxOnABoxGivesItsFourCorners) {
  const Vec3 h(0.3, 0.2, 0.1);
  const auto q = about(Z, 0.4);
  const Vec3 centre(0.2, 0.1, 0.1 - 0.001);
  for (const Shape& ground : {floor_box, Shape(hull_box({2, 2, 0.5}))}) {
    SCOPED_TRACE(name(kind(ground)));
    const auto m = contacts(ground, floor_pose, hull_box(h), at(centre, q));
    ASSERT_EQ(m.count, 4);
    expect_all(m, -0.001);
    for (const double x : {-1.0, 1.0})
      for (const double y : {-1.0, 1.0})
        EXPECT_TRUE(has_point(m, centre + q * Vec3(x * h.x(), y * h.y(), -h.z() + 0.0005), 1e-9));
  }
}

TEST(Manifold, HullBoxOverAnEdgeGivesTheOverlapCorners) {
  // Half of a 1 m hull box beyond the edge x = 2.1 of the floor box.
  const auto m = contacts(floor_box, floor_pose, hull_box({0.5, 0.5, 0.5}), at({2.1, 0, 0.5 - 0.002}));
  ASSERT_EQ(m.count, 4);
  expect_all(m, -0.002);
  for (const double x : {1.6, 2.1})
    for (const double y : {-0.5, 0.5}) EXPECT_TRUE(has_point(m, {x, y, -0.001}, 1e-9));
}

TEST(Manifold, CylinderOnItsCapGivesPointsOnTheRim) {
  const double r = 0.2, half = 0.3;
  const Vec3 centre(-0.3, 0.4, half - 0.001);
  const auto m = contacts(floor_box, floor_pose, Cylinder(r, 2 * half), at(centre, about(Z, 1.0)));
  ASSERT_GE(m.count, 3);
  expect_all(m, -0.001);
  for (int i = 0; i < m.count; ++i) EXPECT_NEAR((m.points[i].position - centre).head<2>().norm(), r, 1e-9);
}

TEST(Manifold, CylinderOnItsSideAndCapsuleLyingDownGiveTwoPoints) {
  const auto lying = about(Vec3::UnitY(), M_PI / 2);  // axis along x
  const auto cylinder = contacts(floor_box, floor_pose, Cylinder(0.2, 0.8), at({0, 0, 0.2 - 0.001}, lying));
  ASSERT_EQ(cylinder.count, 2);
  expect_all(cylinder, -0.001);
  for (const double x : {-0.4, 0.4}) EXPECT_TRUE(has_point(cylinder, {x, 0, -0.0005}, 1e-9));
  const auto capsule = contacts(floor_box, floor_pose, Capsule(0.2, 0.8), at({0, 0, 0.2 - 0.001}, lying));
  ASSERT_EQ(capsule.count, 2);
  expect_all(capsule, -0.001);
  for (const double x : {-0.4, 0.4}) EXPECT_TRUE(has_point(capsule, {x, 0, -0.0005}, 1e-9));
}

// Tilted shapes touch at one rim point or edge: the manifold's deepest point is the
// support point (the half-space pair's answer), and nothing deeper is made up.
TEST(Manifold, TiltedShapesKeepTheExactDeepestPoint) {
  const HalfSpace plane(Z);
  for (const Shape& s : {Shape(Cylinder(0.2, 0.6)), Shape(hull_box({0.3, 0.2, 0.1})), Shape(Capsule(0.1, 0.5))}) {
    SCOPED_TRACE(name(kind(s)));
    const Pose p({0.0, 0.0, 0.25}, about(Vec3(1, 2, 0), 0.3));
    const double lowest = support(s, p, -Z).z();
    const Pose above({0.0, 0.0, 0.25 - lowest - 0.003}, p.orientation());
    const auto m = contacts(floor_box, floor_pose, s, above, 0.01);
    ASSERT_GE(m.count, 1);
    EXPECT_NEAR(min_distance(m), -0.003, 1e-6);
    EXPECT_NEAR(min_distance(m), min_distance(contacts(plane, at(), s, above, 0.01)), 1e-6);
  }
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
