// Meshes through distance maps, against their analytic counterparts within the map's
// error bound (plus the faceting of the icosphere).
#include <random>

#include "tests/geometry/fixtures.hpp"
#include "tests/rigidbody/narrowphase/support.hpp"

namespace cosim::rigidbody::narrowphase::testing {
namespace {

using namespace geometry;
using geometry::testing::box_mesh;
using geometry::testing::ellipsoid_mesh;
using geometry::testing::make_mesh;
using geometry::testing::random_in_ball;
using geometry::testing::random_rotation;

TEST(Mesh, BoxMeshOnAHalfSpaceIsTheBox) {
  const Vec3 h(1, 2, 0.5);
  const Shape mesh = make_mesh(box_mesh(h)), box = Box(h), floor = HalfSpace(Vec3::UnitZ());
  const Pose resting({0.2, 0.1, 0.49}, about(Vec3::UnitZ(), 0.3));
  const auto m = contacts(floor, at(), mesh, resting, 0.05), b = contacts(floor, at(), box, resting, 0.05);
  ASSERT_EQ(m.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(has_point(b, m.points[i].position, 1e-12));
    EXPECT_NEAR(m.points[i].distance, -0.01, 1e-12);
  }
}

TEST(Mesh, AgainstASphereWithinTheMapError) {
  std::mt19937 rng(21);
  MeshMaps maps(16.0);
  const double radius = 1.0;
  const auto arrays = ellipsoid_mesh(Vec3::Constant(radius), 3);
  const TriangleMesh mesh = make_mesh(arrays);
  // The icosphere lies inside the sphere by at most the sagitta of its longest edge.
  double edge = 0.0;
  for (const auto& t : arrays.triangles)
    for (int k = 0; k < 3; ++k) edge = std::max(edge, (arrays.vertices[t[k]] - arrays.vertices[t[(k + 1) % 3]]).norm());
  const double faceting = radius - std::sqrt(radius * radius - edge * edge / 3.0);
  const double bound = maps.get(mesh).error_bound() + faceting;
  const Shape ball = Sphere(0.3), exact = Sphere(radius), m = mesh;
  for (int i = 0; i < 50; ++i) {
    const Pose pa(Vec3::Zero(), random_rotation(rng));
    const Pose pb(random_in_ball(rng, 1.4), Eigen::Quaterniond::Identity());
    const auto analytic = contacts(exact, pa, ball, pb, 0.5);
    const auto through_map = [&] {
      contact::Manifold out;
      collide(m, pa, ball, pb, 0.5, out, maps);
      return out;
    }();
    EXPECT_EQ(analytic.count > 0, through_map.count > 0 || analytic.points[0].distance > 0.5 - bound);
    if (analytic.count && through_map.count) {
      EXPECT_NEAR(min_distance(through_map), min_distance(analytic), bound);
    }
  }
}

TEST(Mesh, IcosphereOnAHalfSpace) {
  const Shape mesh = make_mesh(ellipsoid_mesh(Vec3::Constant(1.0), 3)), floor = HalfSpace(Vec3::UnitZ());
  std::mt19937 rng(22);
  for (int i = 0; i < 20; ++i) {
    const Pose p(Vec3(0, 0, 0.95), random_rotation(rng));
    const auto m = contacts(floor, at(), mesh, p, 0.01);
    ASSERT_GE(m.count, 1);
    EXPECT_NEAR(min_distance(m), -0.05, 0.02);  // the vertices' sagitta below the sphere
  }
}

TEST(Mesh, StackedBoxMeshesAgreeWithBoxBox) {
  MeshMaps maps(32.0);
  const Shape big = make_mesh(box_mesh({1, 1, 1})), small = make_mesh(box_mesh({0.5, 0.5, 0.5}));
  const auto q = about(Vec3::UnitZ(), 0.3);
  contact::Manifold m;
  ASSERT_TRUE(collide(big, at(), small, at({0, 0, 1.45}, q), 0.1, m, maps));
  const double bound = maps.get(std::get<TriangleMesh>(big)).error_bound();
  EXPECT_EQ(m.count, 4);
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].distance, -0.05, bound);
    EXPECT_NEAR(m.points[i].normal.z(), 1.0, 1e-6);
  }
}

TEST(Mesh, MapsAreBuiltOncePerMesh) {
  MeshMaps maps(8.0);
  const TriangleMesh mesh = make_mesh(box_mesh({1, 1, 1}));
  const TriangleMesh copy = mesh;
  EXPECT_EQ(&maps.get(mesh), &maps.get(copy));
  EXPECT_NE(&maps.get(mesh), &maps.get(make_mesh(box_mesh({1, 1, 1}))));
}

}  // namespace
}  // namespace cosim::rigidbody::narrowphase::testing
