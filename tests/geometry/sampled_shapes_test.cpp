#include "geometry/sampled_shapes.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cosim::geometry {
namespace {

TEST(SampledShapes, EqualShapesAreSampledOnce) {
  SampledShapes sampled;
  const auto& first = sampled.body_frame(Sphere(0.5), 0.1);
  EXPECT_EQ(&sampled.body_frame(Sphere(0.5), 0.1), &first);
  EXPECT_EQ(&sampled.body_frame(Sphere(0.5), 0.1 * (1 + 1e-12)), &first);  // a cell width's last bits
  EXPECT_NE(&sampled.body_frame(Sphere(0.6), 0.1), &first);
  EXPECT_NE(&sampled.body_frame(Sphere(0.5), 0.2), &first);
  EXPECT_NE(&sampled.body_frame(Capsule(0.5, 1.0), 0.1), &first);
}

// Placed at a pose, the body-frame samples lie on the surface there with the surface's
// outward normals, and cover its area as the samples made there do.
TEST(SampledShapes, PlacedSamplesLieOnTheSurfaceAtThePose) {
  SampledShapes sampled;
  const Shape ellipsoid = Ellipsoid({0.3, 0.2, 0.1});
  const Pose pose(Eigen::Vector3d(1, -2, 0.5),
                  Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())));
  const std::vector<SurfaceSample> placed = sampled.at(ellipsoid, pose, 0.03);
  ASSERT_EQ(placed.size(), sampled.body_frame(ellipsoid, 0.03).size());
  double area = 0;
  for (const SurfaceSample& s : placed) {
    const Eigen::Vector3d local = pose.to_body(s.point);
    EXPECT_NEAR(std::get<Ellipsoid>(ellipsoid).signed_distance(local), 0, 1e-6);
    // The gradient of x^2/a^2 + ...: the outward normal of the ellipsoid there.
    const Eigen::Vector3d gradient = local.cwiseQuotient(Eigen::Vector3d(0.09, 0.04, 0.01)).normalized();
    EXPECT_NEAR(pose.direction_to_body(s.normal).dot(gradient), 1, 1e-6);
    area += s.area;
  }
  double direct = 0;
  for (const SurfaceSample& s : sample_surface(ellipsoid, pose, 0.03)) direct += s.area;
  EXPECT_NEAR(area, direct, 0.01 * direct);
}

TEST(SampledShapes, SameShape) {
  const std::vector<Eigen::Vector3d> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const ConvexHull hull(corners);
  const ConvexHull copy = hull;
  EXPECT_TRUE(same_shape(hull, copy));
  EXPECT_FALSE(same_shape(hull, ConvexHull(corners)));  // equal, but not known to be without comparing them
  EXPECT_TRUE(same_shape(Box({1, 2, 3}), Box({1, 2, 3})));
  EXPECT_FALSE(same_shape(Box({1, 2, 3}), Box({1, 2, 3.5})));
  EXPECT_FALSE(same_shape(Cylinder(1, 2), Capsule(1, 2)));
}

}  // namespace
}  // namespace cosim::geometry
