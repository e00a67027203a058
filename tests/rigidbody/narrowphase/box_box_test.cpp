// Box-box: separating axes, reference-face clipping, edge-edge points, near contacts.
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using geometry::Box;
const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();

void expect_all(const contact::Manifold& m, double distance, const Vec3& normal) {
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].distance, distance, 1e-12);
    EXPECT_TRUE(m.points[i].normal.isApprox(normal, 1e-12)) << m.points[i].normal.transpose();
  }
}

TEST(BoxBox, SmallBoxOnFaceGivesItsFourCorners) {
  const Shape big = Box({1, 1, 1}), small = Box({0.5, 0.5, 0.5});
  const auto q = about(Z, 0.3);
  const auto m = contacts(big, at(), small, at({0, 0, 1.4}, q));
  ASSERT_EQ(m.count, 4);
  expect_all(m, -0.1, Z);
  for (const double x : {-0.5, 0.5})
    for (const double y : {-0.5, 0.5}) EXPECT_TRUE(has_point(m, q * Vec3(x, y, 0) + 0.95 * Z, 1e-12));
}

TEST(BoxBox, OffsetFacesGiveTheOverlapCorners) {
  const Shape box = Box({1, 1, 1});
  const auto m = contacts(box, at(), box, at({0.5, 0.5, 1.9}));
  ASSERT_EQ(m.count, 4);
  expect_all(m, -0.1, Z);
  for (const double x : {-0.5, 1.0})
    for (const double y : {-0.5, 1.0}) EXPECT_TRUE(has_point(m, {x, y, 0.95}, 1e-12));
}

TEST(BoxBox, EdgeOnEdgeGivesOnePointBetweenTheEdges) {
  const Shape box = Box({1, 1, 1});
  const double h = std::sqrt(2.0);
  // a's top edge runs along x at height sqrt 2, b's bottom edge along y, 0.1 lower.
  const auto m =
      contacts(box, at(Vec3::Zero(), about(X, M_PI / 4)), box, at({0.3, 0.2, 2 * h - 0.1}, about(Y, M_PI / 4)));
  ASSERT_EQ(m.count, 1);
  expect_all(m, -0.1, Z);
  EXPECT_TRUE(has_point(m, {0.3, 0, h - 0.05}, 1e-12)) << m.points[0].position.transpose();
}

TEST(BoxBox, VertexOnFaceGivesOnePoint) {
  const Shape box = Box({1, 1, 1});
  const auto corner_down = Eigen::Quaterniond::FromTwoVectors(Vec3(1, 1, 1), Z);
  const auto m = contacts(box, at(), box, at({0.2, 0.1, 1 + std::sqrt(3.0) - 0.05}, corner_down));
  ASSERT_EQ(m.count, 1);
  expect_all(m, -0.05, Z);
  EXPECT_TRUE(has_point(m, {0.2, 0.1, 0.975}, 1e-12)) << m.points[0].position.transpose();
}

TEST(BoxBox, NearContactsWithinTheMarginOnly) {
  const Shape box = Box({1, 1, 1}), small = Box({0.5, 0.5, 0.5});
  const auto near = contacts(box, at(), small, at({0, 0, 1.55}), 0.1);
  ASSERT_EQ(near.count, 4);
  expect_all(near, 0.05, Z);
  EXPECT_EQ(contacts(box, at(), small, at({0, 0, 1.55}), 0.01).count, 0);
  const auto touching = contacts(box, at(), small, at({0, 0, 1.5}), 0.0);
  ASSERT_EQ(touching.count, 4);
  expect_all(touching, 0.0, Z);
}

TEST(BoxBox, SeparatedCornersUseTheTrueDistance) {
  // The best separating axis says 0.1; the corners are sqrt(3) 0.1 apart.
  const Shape box = Box({1, 1, 1});
  const auto m = contacts(box, at(), box, at({2.1, 2.1, 2.1}), 0.5);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].distance, 0.1 * std::sqrt(3.0), 1e-9);
  EXPECT_TRUE(m.points[0].normal.isApprox(Vec3(1, 1, 1).normalized(), 1e-6));
  EXPECT_TRUE(has_point(m, Vec3::Constant(1.05), 1e-6));
}

// Guards against: a wrong normal or no contact for deeply penetrating boxes with parallel faces.
TEST(BoxBox, DeepPenetrationAndParallelFaces) {
  const Shape box = Box({1, 1, 1});
  const auto deep = contacts(box, at(), box, at({0, 0, 0.3}));
  ASSERT_EQ(deep.count, 4);
  expect_all(deep, -1.7, Z);
  // Coincident boxes: every axis ties; the answer is defined, finite and 2 deep.
  const auto same = contacts(box, at(), box, at());
  ASSERT_GE(same.count, 1);
  EXPECT_NEAR(min_distance(same), -2.0, 1e-12);
}

TEST(BoxBox, RotatedStackKeepsFourPoints) {
  // b rotated about the common normal, then both rotated together: still a face contact.
  const Shape a = Box({2, 1, 0.5}), b = Box({0.4, 0.3, 0.2});
  const auto tilt = about(Vec3(1, 2, 3), 0.8);
  const auto m = contacts(a, at(Vec3::Zero(), tilt), b, at(tilt * Vec3(0.5, 0.2, 0.69), tilt * about(Z, 1.1)));
  ASSERT_EQ(m.count, 4);
  expect_all(m, -0.01, tilt * Z);
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
