// Known answers for the analytic pairs: distance, normal (from a to b) and points midway.
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using geometry::Box;
using geometry::Capsule;
using geometry::Cylinder;
using geometry::HalfSpace;
using geometry::Sphere;

const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();

void expect_single(const contact::Manifold& m, double distance, const Vec3& normal, const Vec3& position) {
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].distance, distance, 1e-12);
  EXPECT_TRUE(m.points[0].normal.isApprox(normal, 1e-12)) << m.points[0].normal.transpose();
  EXPECT_TRUE(m.points[0].position.isApprox(position, 1e-12) || (m.points[0].position - position).norm() < 1e-12)
      << m.points[0].position.transpose();
}

TEST(SphereSphere, SeparatedTouchingPenetratingCoincident) {
  const Shape a = Sphere(1.0), b = Sphere(0.5);
  EXPECT_EQ(contacts(a, at(), b, at(2 * X), 0.1).count, 0);
  expect_single(contacts(a, at(), b, at(2 * X), 1.0), 0.5, X, {1.25, 0, 0});
  expect_single(contacts(a, at(), b, at(1.5 * X), 0.0), 0.0, X, X);
  expect_single(contacts(a, at(), b, at(-1.2 * Y)), -0.3, -Y, {0, -0.85, 0});
  const auto m = contacts(a, at(), b, at());
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].distance, -1.5, 1e-12);
}

TEST(SphereHalfSpace, PlaneBelowAndTilted) {
  const Shape floor = HalfSpace(Z), ball = Sphere(1.0);
  expect_single(contacts(floor, at(), ball, at({3, 4, 0.9})), -0.1, Z, {3, 4, -0.05});
  expect_single(contacts(ball, at({3, 4, 0.9}), floor, at()), -0.1, -Z, {3, 4, -0.05});
  EXPECT_EQ(contacts(floor, at(), ball, at({0, 0, 1.2}), 0.1).count, 0);
  // The body z axis turned onto world x: a wall at x = 1.
  expect_single(contacts(floor, at(X, about(Y, M_PI / 2)), ball, at({2.5, 0, 0}), 1.0), 0.5, X, {1.25, 0, 0});
}

TEST(SphereBox, FaceEdgeAndCentreInside) {
  const Shape box = Box({1, 2, 3}), ball = Sphere(0.5);
  expect_single(contacts(box, at(), ball, at(1.4 * X)), -0.1, X, {0.95, 0, 0});
  expect_single(contacts(box, at(), ball, at({1.3, 2.4, 0})), 0.0, {0.6, 0.8, 0}, {1, 2, 0});
  expect_single(contacts(box, at(), ball, at(0.9 * X)), -0.6, X, {0.7, 0, 0});
  // Rotated box: the face normal follows the pose.
  const Pose turned = at({1, 1, 1}, about(Z, M_PI / 2));
  expect_single(contacts(box, turned, ball, at({1, 2.45, 1})), -0.05, Y, {1, 1.975, 1});
}

TEST(SphereCapsule, SideAndEnd) {
  const Shape capsule = Capsule(0.5, 2.0), ball = Sphere(0.5);
  expect_single(contacts(capsule, at(), ball, at({0.9, 0, 0.5})), -0.1, X, {0.45, 0, 0.5});
  expect_single(contacts(ball, at({0, 0, 2.2}), capsule, at(), 0.5), 0.2, -Z, {0, 0, 1.6});
}

TEST(SphereCylinder, SideCapAndRim) {
  const Shape cylinder = Cylinder(1.0, 2.0), ball = Sphere(0.5);
  expect_single(contacts(cylinder, at(), ball, at(1.4 * X)), -0.1, X, {0.95, 0, 0});
  expect_single(contacts(cylinder, at(), ball, at(1.6 * Z), 0.2), 0.1, Z, {0, 0, 1.05});
  expect_single(contacts(cylinder, at(), ball, at({1.3, 0, 1.4})), 0.0, {0.6, 0, 0.8}, {1, 0, 1});
}

TEST(CapsuleCapsule, CrossingParallelAndThroughEachOther) {
  const Shape a = Capsule(0.5, 2.0), b = Capsule(0.5, 2.0);
  const auto along_x = about(Y, M_PI / 2);
  expect_single(contacts(a, at(), b, at(0.9 * Y, along_x)), -0.1, Y, {0, 0.45, 0});
  // Parallel axes overlapping over z in [-0.5, 1]: the closest point (a's middle) and the
  // far end of the overlap (the near end is within a radius of the closest point).
  const auto parallel = contacts(a, at(), b, at({0.8, 0, 0.5}));
  ASSERT_EQ(parallel.count, 2);
  for (const Vec3& p : {Vec3(0.4, 0, 0), Vec3(0.4, 0, 1)}) EXPECT_TRUE(has_point(parallel, p, 1e-12)) << p.transpose();
  for (int k = 0; k < parallel.count; ++k) {
    EXPECT_NEAR(parallel.points[k].distance, -0.2, 1e-12);
    EXPECT_TRUE(parallel.points[k].normal.isApprox(X, 1e-12));
  }
  // Axes 0.1 rad apart, closest at b's lower end (gap -sin 0.1 against a's axis): the top of
  // the overlap, a's point at z = cos 0.1, is a point too with its gap to b's axis
  // (cos 0.1 (1 + sin 0.1) less both radii), kept within the margin and dropped beyond it.
  const auto turned = contacts(a, at(), b, at({1.0, 0, 0}, about(Y, 0.1)), 0.5);
  ASSERT_EQ(turned.count, 2);
  const double top = std::cos(0.1) * (1.0 + std::sin(0.1)) - 1.0;
  EXPECT_NEAR(std::min(turned.points[0].distance, turned.points[1].distance), -std::sin(0.1), 1e-12);
  EXPECT_NEAR(std::max(turned.points[0].distance, turned.points[1].distance), top, 1e-12);
  EXPECT_EQ(contacts(a, at(), b, at({1.0, 0, 0}, about(Y, 0.1)), 0.05).count, 1);
  // Axes that cross: any normal across both is right, the depth is both radii.
  const auto through = contacts(a, at(), b, at(Vec3::Zero(), along_x));
  ASSERT_EQ(through.count, 1);
  EXPECT_NEAR(through.points[0].distance, -1.0, 1e-12);
  EXPECT_NEAR(std::abs(through.points[0].normal.dot(Y)), 1.0, 1e-12);
}

TEST(CapsuleHalfSpace, LyingGivesTwoPointsStandingOne) {
  const Shape floor = HalfSpace(Z), capsule = Capsule(0.5, 2.0);
  const auto lying = contacts(floor, at(), capsule, at({0, 0, 0.45}, about(Y, M_PI / 2)));
  ASSERT_EQ(lying.count, 2);
  for (const Vec3& p : {Vec3(-1, 0, -0.025), Vec3(1, 0, -0.025)}) EXPECT_TRUE(has_point(lying, p, 1e-12));
  EXPECT_NEAR(min_distance(lying), -0.05, 1e-12);
  expect_single(contacts(floor, at(), capsule, at({0, 0, 1.5})), 0.0, Z, {0, 0, 0});
}

TEST(BoxHalfSpace, RestingFlatGivesTheFourCorners) {
  const Shape floor = HalfSpace(Z), box = Box({1, 2, 0.5});
  const auto m = contacts(floor, at(), box, at({0, 0, 0.49}, about(Z, 0.3)), 0.05);
  ASSERT_EQ(m.count, 4);
  const Eigen::Matrix3d r = about(Z, 0.3).toRotationMatrix();
  for (const double x : {-1, 1})
    for (const double y : {-2, 2}) {
      const Vec3 corner = r * Vec3(x, y, 0) + Vec3(0, 0, -0.005);
      EXPECT_TRUE(has_point(m, corner, 1e-12)) << corner.transpose();
    }
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].distance, -0.01, 1e-12);
    EXPECT_TRUE(m.points[i].normal.isApprox(Z));
  }
  // A wide margin reaches the top corners too; the four deepest are kept.
  EXPECT_NEAR(contacts(floor, at(), box, at({0, 0, 0.49}), 5.0).points[3].distance, -0.01, 1e-12);
  EXPECT_EQ(contacts(floor, at(), box, at({0, 0, 0.7}), 0.1).count, 0);
}

TEST(BoxHalfSpace, TiltedBoxTouchesOnAnEdge) {
  const Shape floor = HalfSpace(Z), box = Box({1, 1, 1});
  const double lift = std::sqrt(2.0) - 0.01;  // the box stands on an edge, 45 degrees about x
  const auto edge = contacts(floor, at(), box, at({0, 0, lift}, about(X, M_PI / 4)), 0.001);
  ASSERT_EQ(edge.count, 2);
  EXPECT_TRUE(has_point(edge, {1, 0, -0.005}, 1e-9));
  EXPECT_TRUE(has_point(edge, {-1, 0, -0.005}, 1e-9));
}

TEST(CylinderHalfSpace, StandingLyingAndTilted) {
  const Shape floor = HalfSpace(Z), cylinder = Cylinder(1.0, 2.0);
  const auto standing = contacts(floor, at(), cylinder, at({0, 0, 0.98}), 0.05);
  ASSERT_EQ(standing.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(standing.points[i].distance, -0.02, 1e-12);
    EXPECT_NEAR(standing.points[i].position.head<2>().norm(), 1.0, 1e-12);
  }
  const auto lying = contacts(floor, at(), cylinder, at({0, 0, 0.98}, about(X, M_PI / 2)), 0.05);
  ASSERT_EQ(lying.count, 2);
  EXPECT_TRUE(has_point(lying, {0, 1, -0.01}, 1e-12));
  EXPECT_TRUE(has_point(lying, {0, -1, -0.01}, 1e-12));
  // Tilted: the lowest rim point, at h/2 |n.u| + r sqrt(1 - (n.u)^2) below the centre.
  const double tilt = 0.7, low = std::cos(tilt) + std::sin(tilt);
  const auto tilted = contacts(floor, at(), cylinder, at({0, 0, low - 0.03}, about(X, tilt)), 0.01);
  ASSERT_EQ(tilted.count, 1);
  EXPECT_NEAR(tilted.points[0].distance, -0.03, 1e-12);
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
