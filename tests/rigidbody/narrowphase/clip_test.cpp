// The clipping step of the general convex path against hand-worked answers.
#include "rigidbody/narrowphase/clip.hpp"
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using detail::Candidates;
using detail::Feature;
using detail::Polygon;

Polygon square(double x0, double x1, double y0, double y1, double z) {
  return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

Candidates clipped(const Feature& a, const Feature& b, const Vec3& n, double margin = 0.0) {
  Candidates out;
  out.margin = margin;
  detail::clip_features(a, b, n, out);
  return out;
}

bool has(const Candidates& c, const Vec3& position, double distance) {
  return std::any_of(c.points.begin(), c.points.end(), [&](const auto& p) {
    return (p.position - position).norm() < 1e-12 && std::abs(p.distance - distance) < 1e-12;
  });
}

TEST(Clip, HalfSpaceCutsASquare) {
  const Polygon cut = detail::clip(square(0, 1, 0, 1, 0), Vec3::Zero(), Vec3::UnitX(), 0.25);
  ASSERT_EQ(cut.size(), 4u);
  for (const Vec3& p : square(0, 0.25, 0, 1, 0))
    EXPECT_TRUE(std::any_of(cut.begin(), cut.end(), [&](const Vec3& q) { return (q - p).norm() < 1e-15; }));
}

TEST(Clip, SegmentCrossingAPlaneKeepsOneCrossing) {
  const Polygon cut = detail::clip({{-1, 0, 0}, {1, 0, 0}}, Vec3::Zero(), Vec3::UnitX(), 0.5);
  ASSERT_EQ(cut.size(), 2u);
  EXPECT_EQ(cut[0], Vec3(-1, 0, 0));
  EXPECT_EQ(cut[1], Vec3(0.5, 0, 0));
}

// a's top face [-1, 1]^2 at z = 0, b's bottom face [-0.5, 1.5]^2 at z = -0.1: the overlap
// [-0.5, 1]^2, 0.1 deep, midway at z = -0.05, whichever face is the reference.
TEST(Clip, OffsetSquaresGiveTheOverlapCorners) {
  const Feature top{square(-1, 1, -1, 1, 0.0), 0}, bottom{square(-0.5, 1.5, -0.5, 1.5, -0.1), 0};
  for (const bool swapped : {false, true}) {
    const Candidates c = swapped ? clipped(bottom, top, -Vec3::UnitZ()) : clipped(top, bottom, Vec3::UnitZ());
    ASSERT_EQ(c.points.size(), 4u);
    for (const double x : {-0.5, 1.0})
      for (const double y : {-0.5, 1.0}) EXPECT_TRUE(has(c, {x, y, -0.05}, -0.1)) << x << " " << y;
  }
}

TEST(Clip, SquareTurnedOnASquareGivesTheOctagon) {
  const double s = std::sqrt(2.0);
  const Feature top{square(-1, 1, -1, 1, 0.0), 0};
  const Feature turned{{{s, 0, -0.1}, {0, s, -0.1}, {-s, 0, -0.1}, {0, -s, -0.1}}, 0};
  const Candidates c = clipped(top, turned, Vec3::UnitZ());
  ASSERT_EQ(c.points.size(), 8u);
  EXPECT_TRUE(has(c, {1, s - 1, -0.05}, -0.1));
  EXPECT_TRUE(has(c, {1 - s, -1, -0.05}, -0.1));
}

// A segment 0.05 into the face from x = -2 to 0.5: the face bounds it at x = -1.
TEST(Clip, EdgeOnFaceGivesTwoPoints) {
  const Feature face{square(-1, 1, -1, 1, 0.0), 0}, edge{{{-2, 0, -0.05}, {0.5, 0, -0.05}}, 0};
  const Candidates c = clipped(face, edge, Vec3::UnitZ());
  ASSERT_EQ(c.points.size(), 2u);
  EXPECT_TRUE(has(c, {-1, 0, -0.025}, -0.05));
  EXPECT_TRUE(has(c, {0.5, 0, -0.025}, -0.05));
}

// A tilted edge: the gap along n grows along it, and the margin drops its far end.
TEST(Clip, GapsAreMeasuredAlongTheNormalAndCutByTheMargin) {
  const Feature face{square(-1, 1, -1, 1, 0.0), 0}, edge{{{0, 0, -0.05}, {0.5, 0, 0.45}}, 0};
  ASSERT_EQ(clipped(face, edge, Vec3::UnitZ(), 1.0).points.size(), 2u);
  EXPECT_TRUE(has(clipped(face, edge, Vec3::UnitZ(), 1.0), {0.5, 0, 0.225}, 0.45));
  const Candidates c = clipped(face, edge, Vec3::UnitZ(), 0.1);
  ASSERT_EQ(c.points.size(), 1u);
  EXPECT_TRUE(has(c, {0, 0, -0.025}, -0.05));
}

TEST(Clip, ParallelSegmentsOverlapAndCrossingOnesGiveNothing) {
  const Feature a{{{-1, 0, 0}, {1, 0, 0}}, 0}, along{{{0.5, 0, -0.1}, {2, 0, -0.1}}, 0},
      across{{{0, -1, -0.1}, {0, 1, -0.1}}, 0};
  const Candidates c = clipped(a, along, Vec3::UnitZ());
  ASSERT_EQ(c.points.size(), 2u);
  EXPECT_TRUE(has(c, {0.5, 0, -0.05}, -0.1));
  EXPECT_TRUE(has(c, {1, 0, -0.05}, -0.1));
  EXPECT_TRUE(clipped(a, across, Vec3::UnitZ()).points.empty());
  EXPECT_TRUE(clipped(a, Feature{{{0, 0, -0.1}}, 0}, Vec3::UnitZ()).points.empty());
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
