#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

TEST(ConvexHull, CubeKeepsCornersAndMergesCoplanarFacets) {
  const Eigen::Vector3d h(0.5, 1.0, 0.25);
  std::vector<Eigen::Vector3d> points = testing::box_mesh(h).vertices;
  points.emplace_back(0.0, 0.0, 0.0);   // interior
  points.emplace_back(0.5, 0.3, -0.1);  // on a face
  const ConvexHull hull(points);
  EXPECT_EQ(hull.vertices().size(), 8u);
  ASSERT_EQ(hull.faces().size(), 6u);
  EXPECT_EQ(hull.triangles().size(), 12u);
  for (const Plane& plane : hull.planes()) {
    Eigen::Index axis = 0;
    EXPECT_EQ(plane.normal.cwiseAbs().maxCoeff(&axis), 1.0);  // exactly axis-aligned
    EXPECT_EQ(plane.offset, h[axis]);
  }
}

TEST(ConvexHull, ContainsItsPointsAndFacesAreOutwardLoops) {
  std::mt19937 rng(3);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 200; ++i) points.push_back(testing::random_in_ball(rng, 1.0) + Eigen::Vector3d(2, 0, 1));
  const ConvexHull hull(points);
  for (const auto& p : points) EXPECT_LE(hull.signed_distance(p - hull.com_shift()), 1e-12);
  for (std::size_t f = 0; f < hull.faces().size(); ++f) {
    const auto& loop = hull.faces()[f];
    const auto& v = hull.vertices();
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) n += (v[loop[k]] - v[loop[0]]).cross(v[loop[k + 1]] - v[loop[0]]);
    EXPECT_GT(n.normalized().dot(hull.planes()[f].normal), 1.0 - 1e-12);
  }
}

TEST(ConvexHull, RejectsFlatAndTooSmallInput) {
  const std::vector<Eigen::Vector3d> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
  EXPECT_THROW(ConvexHull{flat}, std::invalid_argument);
  const std::vector<Eigen::Vector3d> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(ConvexHull{three}, std::invalid_argument);
}

TEST(ConvexHull, DistanceOfABoxHullIsTheBoxDistance) {
  const Eigen::Vector3d h(0.5, 1.0, 0.25);
  const ConvexHull hull(testing::box_mesh(h).vertices);
  const Box box(h);
  std::mt19937 rng(5);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d p = testing::random_in_ball(rng, 2.0);
    const SurfacePoint a = hull.closest(p), b = box.closest(p);
    EXPECT_NEAR(a.distance, b.distance, 1e-14);
    EXPECT_LT((a.point - b.point).norm(), 1e-14);
    EXPECT_EQ(hull.contains(p), box.contains(p));
  }
}

}  // namespace
}  // namespace cosim::geometry
