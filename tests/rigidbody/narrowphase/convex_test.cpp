// The general convex path (GJK distance, libccd EPA) against the analytic pairs, and the
// support-based half-space pairs against closed forms.
#include <algorithm>
#include <random>

#include "tests/geometry/fixtures.hpp"
#include "rigidbody/narrowphase/pairs.hpp"
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using namespace geometry;
using geometry::testing::random_in_ball;
using geometry::testing::random_pose;
using geometry::testing::random_rotation;
using geometry::testing::random_unit;

// The deepest point of the general path (faces give more, none deeper).
contact::ContactPoint general(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
  detail::Candidates c;
  c.margin = INFINITY;
  detail::convex_pair(a, pa, b, pb, c);
  EXPECT_GE(c.points.size(), 1u);
  return *std::min_element(c.points.begin(), c.points.end(),
                           [](const auto& p, const auto& q) { return p.distance < q.distance; });
}

struct Agreement {
  int separated = 0, penetrating = 0, depth_off = 0;
  double worst_gap = 0.0, worst_overshoot = 0.0;
};

// Random placements of b around a, from far apart to deep inside.
Agreement compare(const Shape& a, const Shape& b, int count) {
  std::mt19937 rng(42);
  Agreement r;
  const double reach = bounding_radius(a) + bounding_radius(b);
  for (int i = 0; i < count; ++i) {
    const Pose pa = random_pose(rng);
    const Pose pb(pa.position() + random_in_ball(rng, 1.2 * reach), random_rotation(rng));
    const auto m = contacts(a, pa, b, pb, INFINITY);
    EXPECT_GE(m.count, 1);
    const double analytic = min_distance(m);
    const auto g = general(a, pa, b, pb);
    if (analytic > 1e-9) {
      ++r.separated;
      r.worst_gap = std::max(r.worst_gap, std::abs(analytic - g.distance));
    } else {
      ++r.penetrating;
      // Any push direction over-estimates the depth, so the general path is never deeper;
      // it can stop at a local minimum (another face) when libccd's EPA start is off.
      r.worst_overshoot = std::max(r.worst_overshoot, g.distance - analytic);
      if (std::abs(g.distance - analytic) > 1e-3) ++r.depth_off;
    }
  }
  return r;
}

TEST(ConvexPath, AgreesWithAnalyticPairs) {
  const std::vector<std::pair<Shape, Shape>> pairs{{Sphere(0.7), Sphere(0.4)},
                                                   {Box({0.9, 0.4, 0.6}), Sphere(0.5)},
                                                   {Capsule(0.4, 1.0), Sphere(0.5)},
                                                   {Cylinder(0.5, 1.6), Sphere(0.3)},
                                                   {Capsule(0.4, 1.0), Capsule(0.3, 0.8)},
                                                   {Box({0.9, 0.4, 0.6}), Box({0.5, 0.7, 0.3})}};
  for (const auto& [a, b] : pairs) {
    const Agreement r = compare(a, b, 300);
    SCOPED_TRACE(std::string(name(kind(a))) + " - " + std::string(name(kind(b))));
    EXPECT_GT(r.separated, 20);
    EXPECT_GT(r.penetrating, 20);
    EXPECT_LT(r.worst_gap, 1e-6);
    EXPECT_LT(r.worst_overshoot, 1e-9);
    EXPECT_LE(r.depth_off, r.penetrating / 20);
  }
}

TEST(ConvexPath, TouchingEllipsoidsGiveAContact) {
  const Shape e = Ellipsoid({1.0, 0.5, 0.7});
  const auto m = contacts(e, at(), e, at({2.0, 0, 0}), 0.0);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].distance, 0.0, 1e-6);
  EXPECT_TRUE(m.points[0].normal.isApprox(Vec3::UnitX(), 1e-3));
  EXPECT_TRUE((m.points[0].position - Vec3(1, 0, 0)).norm() < 1e-3);
}

TEST(ConvexPath, RoundEllipsoidsMatchSpheres) {
  std::mt19937 rng(3);
  const Shape e = Ellipsoid(Vec3::Constant(0.6)), f = Ellipsoid(Vec3::Constant(0.4));
  for (int i = 0; i < 50; ++i) {
    const Pose pa = random_pose(rng);
    const Pose pb(pa.position() + random_in_ball(rng, 2.0), random_rotation(rng));
    const auto m = contacts(e, pa, f, pb, INFINITY);
    ASSERT_EQ(m.count, 1);
    const Vec3 d = pb.position() - pa.position();
    EXPECT_NEAR(m.points[0].distance, d.norm() - 1.0, 1e-4);
    if (d.norm() > 0.05) {
      EXPECT_TRUE(m.points[0].normal.isApprox(d.normalized(), 1e-2));
    }
  }
}

TEST(HalfSpacePairs, EllipsoidDeepestPointIsTheSupport) {
  std::mt19937 rng(5);
  const Vec3 radii(1.2, 0.5, 0.8);
  const Shape e = Ellipsoid(radii), floor = HalfSpace(Vec3::UnitZ());
  for (int i = 0; i < 50; ++i) {
    const Pose pe = random_pose(rng), pf(random_in_ball(rng, 1.0), random_rotation(rng));
    const Vec3 n = pf.direction_to_world(Vec3::UnitZ());
    // min over the ellipsoid of n.x is n.c - |diag(radii) R^T n|.
    const double exact = n.dot(pe.position() - pf.position()) - radii.cwiseProduct(pe.direction_to_body(n)).norm();
    const auto m = contacts(floor, pf, e, pe, INFINITY);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].distance, exact, 1e-12);
    EXPECT_TRUE(m.points[0].normal.isApprox(n, 1e-12));
  }
}

TEST(HalfSpacePairs, HullOfABoxMatchesTheBox) {
  const Vec3 h(0.9, 0.4, 0.6);
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back(h.cwiseProduct(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)));
  const Shape hull = ConvexHull(corners), box = Box(h), floor = HalfSpace(Vec3::UnitZ());
  const Pose resting({0.3, 0.2, 0.58}, about(Vec3::UnitZ(), 0.4));
  const auto mh = contacts(floor, at(), hull, resting), mb = contacts(floor, at(), box, resting);
  ASSERT_EQ(mh.count, 4);
  ASSERT_EQ(mb.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(has_point(mb, mh.points[i].position, 1e-12));
    EXPECT_NEAR(mh.points[i].distance, -0.02, 1e-12);
  }
  // And hull against box through GJK agrees with box-box.
  std::mt19937 rng(9);
  for (int i = 0; i < 50; ++i) {
    const Pose pa = random_pose(rng), pb(pa.position() + random_in_ball(rng, 3.0), random_rotation(rng));
    const double exact = min_distance(contacts(box, pa, box, pb, INFINITY));
    const double g = min_distance(contacts(hull, pa, box, pb, INFINITY));
    if (exact > 0) {
      EXPECT_NEAR(g, exact, 1e-6);
    } else {
      EXPECT_GE(g, exact - 0.05);
      EXPECT_LE(g, exact + 1e-9);
    }
  }
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
