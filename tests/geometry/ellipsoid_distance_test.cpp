// Eberly's ellipsoid distance: on the surface, along normals, on and near the axes.
#include <gtest/gtest.h>

#include <numbers>

#include "tests/geometry/fixtures.hpp"

namespace cosim::geometry {
namespace {

const Eigen::Vector3d radii(0.8, 1.5, 0.4);  // deliberately not sorted
const Ellipsoid ellipsoid(radii);

Eigen::Vector3d on_surface(double theta, double phi) {
  return {radii.x() * std::sin(theta) * std::cos(phi), radii.y() * std::sin(theta) * std::sin(phi),
          radii.z() * std::cos(theta)};
}

Eigen::Vector3d normal_at(const Eigen::Vector3d& x) { return x.cwiseQuotient(radii.cwiseAbs2()).normalized(); }

TEST(EllipsoidDistance, SurfacePointsAreAtZeroAndTheirOwnClosestPoint) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d x = on_surface(std::acos(1 - 2 * u(rng)), 2 * std::numbers::pi * u(rng));
    const SurfacePoint s = ellipsoid.closest(x);
    EXPECT_LT(std::abs(s.distance), 1e-15);
    EXPECT_LT((s.point - x).norm(), 1e-15);
    EXPECT_LT((s.normal - normal_at(x)).norm(), 1e-12);
  }
}

// Moving along the normal by t keeps the same closest point as long as the point stays
// inside the smallest radius of curvature (c^2 / a for the sorted semi-axes a >= c).
TEST(EllipsoidDistance, PointsAlongTheNormalAreAtTheirOffset) {
  const double min_curvature_radius = std::pow(radii.minCoeff(), 2) / radii.maxCoeff();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d x = on_surface(std::acos(1 - 2 * u(rng)), 2 * std::numbers::pi * u(rng));
    const double t = -0.95 * min_curvature_radius + (0.95 * min_curvature_radius + 2.0) * u(rng);
    const SurfacePoint s = ellipsoid.closest(x + t * normal_at(x));
    EXPECT_NEAR(s.distance, t, 1e-13);
    EXPECT_LT((s.point - x).norm(), 1e-11);
  }
}

TEST(EllipsoidDistance, OnAndNearTheAxes) {
  // Outside on an axis: the vertex. The centre: the smallest semi-axis.
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      const Eigen::Vector3d p = side * (radii[axis] + 0.7) * Eigen::Vector3d::Unit(axis);
      EXPECT_NEAR(ellipsoid.signed_distance(p), 0.7, 1e-15);
      // A hair off the axis changes nothing visible: no catastrophic cancellation.
      for (int other = 0; other < 3; ++other)
        if (other != axis) {
          EXPECT_NEAR(ellipsoid.signed_distance(p + 1e-12 * Eigen::Vector3d::Unit(other)), 0.7, 1e-13);
        }
    }
  EXPECT_EQ(ellipsoid.signed_distance(Eigen::Vector3d::Zero()), -0.4);

  // Inside on the major (y) axis within its evolute, the closest point leaves the axis into
  // the plane of the minor (z) axis: y = b^2 y0 / (b^2 - c^2), z = c sqrt(1 - (y/b)^2).
  const double b = radii.y(), c = radii.z();
  for (double y0 : {0.0, 0.3, 1.0, b - c * c / b - 1e-3}) {
    const double y = b * b * y0 / (b * b - c * c), z = c * std::sqrt(1 - (y / b) * (y / b));
    const double expected = -std::hypot(y - y0, z);
    EXPECT_NEAR(ellipsoid.signed_distance({0, y0, 0}), expected, 1e-14) << y0;
    EXPECT_NEAR(ellipsoid.signed_distance({1e-12, y0, 1e-12}), expected, 1e-11) << y0;
    EXPECT_NEAR(ellipsoid.signed_distance({0, -y0, -1e-13}), expected, 1e-11) << y0;
  }
}

// Random points: the answer satisfies the optimality conditions (on the surface, p - x
// along the normal) and no surface sample is closer.
TEST(EllipsoidDistance, RandomPointsAreOptimal) {
  std::mt19937 rng(6);
  std::vector<Eigen::Vector3d> surface;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 4000; ++i)
    surface.push_back(on_surface(std::acos(1 - 2 * u(rng)), 2 * std::numbers::pi * u(rng)));
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d p = testing::random_in_ball(rng, 2.5);
    const SurfacePoint s = ellipsoid.closest(p);
    EXPECT_NEAR(s.point.cwiseQuotient(radii).squaredNorm(), 1.0, 1e-14);
    EXPECT_LT((p - s.point).cross(s.normal).norm(), 1e-12);
    double nearest = 1e300;
    for (const auto& x : surface) nearest = std::min(nearest, (p - x).norm());
    EXPECT_LE(std::abs(s.distance), nearest + 1e-15);
    EXPECT_EQ(ellipsoid.contains(p), s.distance <= 0.0);
  }
}

TEST(EllipsoidDistance, EqualRadiiGiveTheSphere) {
  const Ellipsoid round({0.7, 0.7, 0.7});
  std::mt19937 rng(8);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p = testing::random_in_ball(rng, 2.0);
    EXPECT_NEAR(round.signed_distance(p), Sphere(0.7).signed_distance(p), 1e-15);
  }
}

}  // namespace
}  // namespace cosim::geometry
