// Signed distance, closest point and normal of the analytic shapes and of polyhedra on
// their faces, edges and vertices.
#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

const Eigen::Vector3d h(0.5, 1.0, 0.25);

// Points on faces, edges (including a face diagonal of the mesh) and corners of the box h.
std::vector<Eigen::Vector3d> box_surface_points() {
  return {{0.5, 0.3, -0.1},   {-0.2, 1.0, 0.1}, {0.1, -0.7, -0.25},  {0.5, 1.0, 0.1},   {-0.5, 0.3, 0.25},
          {0.2, -1.0, -0.25}, {0.5, 1.0, 0.25}, {-0.5, -1.0, -0.25}, {0.5, 0.5, 0.125}, {0.0, 0.0, 0.25}};
}

TEST(SignedDistance, BoxAndBoxMeshAreExactlyZeroOnFacesEdgesAndCorners) {
  const Box box(h);
  const TriangleMesh mesh = testing::make_mesh(testing::box_mesh(h));
  const ConvexHull hull(testing::box_mesh(h).vertices);
  for (const Eigen::Vector3d& p : box_surface_points()) {
    SCOPED_TRACE(p.transpose());
    for (const Shape& shape : {Shape(box), Shape(mesh), Shape(hull)}) {
      SCOPED_TRACE(name(kind(shape)));
      const SurfacePoint s = closest_point(shape, p);
      EXPECT_EQ(s.distance, 0.0);
      EXPECT_EQ(s.point, p);
      EXPECT_NEAR(s.normal.norm(), 1.0, 1e-15);
      EXPECT_TRUE(contains(shape, p));
      // A step along the normal leaves the box, a step against it enters.
      EXPECT_GT(signed_distance(shape, Eigen::Vector3d(p + 1e-9 * s.normal)), 0.0);
      EXPECT_LT(signed_distance(shape, Eigen::Vector3d(p - 1e-9 * s.normal)), 0.0);
    }
  }
}

TEST(SignedDistance, BoxKnownValues) {
  const Box box(h);
  EXPECT_EQ(box.signed_distance({0, 0, 0}), -0.25);
  EXPECT_EQ(box.signed_distance({0.4, 0, 0}), 0.4 - 0.5);
  EXPECT_EQ(box.signed_distance({0.5 + 3, 1.0 + 4, 0}), 5.0);
  const SurfacePoint s = box.closest({0.5 + 3, -1.0 - 4, 0.1});
  EXPECT_EQ(s.point, Eigen::Vector3d(0.5, -1.0, 0.1));
  EXPECT_LT((s.normal - Eigen::Vector3d(0.6, -0.8, 0)).norm(), 1e-15);
  const SurfacePoint in = box.closest({0.1, 0.2, -0.2});
  EXPECT_EQ(in.point, Eigen::Vector3d(0.1, 0.2, -0.25));
  EXPECT_EQ(in.normal, Eigen::Vector3d(0, 0, -1));
}

TEST(SignedDistance, SphereCylinderCapsuleHalfSpaceKnownValues) {
  EXPECT_DOUBLE_EQ(Sphere(2.0).signed_distance({3, 4, 0}), 3.0);
  EXPECT_EQ(Sphere(2.0).signed_distance({0, 0, 0}), -2.0);
  EXPECT_EQ(Sphere(2.0).closest({0, 0, 0}).normal.norm(), 1.0);  // any direction, but a unit one

  const Cylinder cyl(1.0, 2.0);
  EXPECT_EQ(cyl.signed_distance({0, 0, 0}), -1.0);
  EXPECT_EQ(cyl.signed_distance({0, 0, 3}), 2.0);
  EXPECT_DOUBLE_EQ(cyl.signed_distance({4, 0, 5}), 5.0);  // rim: (3, 4) away
  EXPECT_EQ(cyl.signed_distance({1, 0, 0.5}), 0.0);
  EXPECT_EQ(cyl.signed_distance({0, -0.6, 1}), 0.0);
  EXPECT_DOUBLE_EQ(cyl.signed_distance({0, 0.5, 0.8}), -0.2);
  const SurfacePoint rim = cyl.closest({0, 4, -5});
  EXPECT_LT((rim.point - Eigen::Vector3d(0, 1, -1)).norm(), 1e-15);
  EXPECT_LT((rim.normal - Eigen::Vector3d(0, 0.6, -0.8)).norm(), 1e-15);

  const Capsule cap(0.5, 2.0);
  EXPECT_EQ(cap.signed_distance({0, 0, 0}), -0.5);
  EXPECT_EQ(cap.signed_distance({0, 0, 1.5}), 0.0);
  EXPECT_DOUBLE_EQ(cap.signed_distance({3, 0, 5}), 4.5);
  EXPECT_EQ(cap.signed_distance({0.5, 0, -0.7}), 0.0);
  EXPECT_DOUBLE_EQ(cap.closest({0, 0, 0.3}).point.norm(), std::hypot(0.5, 0.3));

  const HalfSpace floor({0, 0, 2});
  EXPECT_EQ(floor.signed_distance({5, -3, -1.5}), -1.5);
  EXPECT_EQ(floor.closest({5, -3, 2}).point, Eigen::Vector3d(5, -3, 0));
  EXPECT_TRUE(floor.contains({1, 1, 0}));
}

// A general tetrahedron: corners, edge points and face points are on the surface up to
// rounding of their own coordinates.
TEST(SignedDistance, MeshIsZeroOnItsVerticesEdgesAndFaces) {
  const std::array<Eigen::Vector3d, 4> c{Eigen::Vector3d(0.1, -0.3, 0.2), Eigen::Vector3d(1.3, 0.1, -0.4),
                                         Eigen::Vector3d(0.2, 1.1, 0.3), Eigen::Vector3d(0.4, 0.3, 1.5)};
  const auto arrays = testing::tetrahedron_mesh(c);
  const TriangleMesh mesh = testing::make_mesh(arrays);
  for (const auto& t : mesh.triangles()) {
    const auto &a = mesh.vertices()[t[0]], &b = mesh.vertices()[t[1]], &d = mesh.vertices()[t[2]];
    for (const Eigen::Vector3d& p : {a, Eigen::Vector3d(0.3 * a + 0.7 * b), Eigen::Vector3d((a + b + d) / 3.0)})
      EXPECT_LT(std::abs(mesh.signed_distance(p)), 1e-15);
  }
}

TEST(SignedDistance, ContainsAgreesWithTheSignForEveryShape) {
  auto shapes = testing::bounded_shapes();
  shapes.emplace_back("half-space", HalfSpace({1, 2, 3}));
  std::mt19937 rng(11);
  for (const auto& [label, shape] : shapes) {
    SCOPED_TRACE(label);
    const double reach = is_bounded(shape) ? 1.3 * bounding_radius(shape) : 2.0;
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector3d p = testing::random_in_ball(rng, reach);
      const SurfacePoint s = closest_point(shape, p);
      EXPECT_EQ(signed_distance(shape, p), s.distance);
      if (s.distance != 0.0) {
        EXPECT_EQ(contains(shape, p), s.distance < 0.0);
      }
      // The closest point is on the surface, at the distance, along the normal.
      EXPECT_LT(std::abs(signed_distance(shape, s.point)), 1e-12);
      EXPECT_NEAR((p - s.point).norm(), std::abs(s.distance), 1e-12);
      EXPECT_LT((p - s.point - s.distance * s.normal).norm(), 1e-12);
    }
  }
}

}  // namespace
}  // namespace cosim::geometry
