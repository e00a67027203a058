// Distance maps: exact at the nodes, within (sqrt(3)/2) h everywhere, converging with h
// (second order near smooth surfaces).
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/geometry/fixtures.hpp"
#include "geometry/distance_map.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

struct MapErrors {
  double max = 0.0;           // over the whole grid box
  double near_surface = 0.0;  // where |d| < 0.1
  double normal_angle = 0.0;  // largest angle between interpolated and exact normals there
};

MapErrors measure(const Shape& shape, const DistanceMap& map, std::mt19937& rng) {
  const GridSpec& g = map.grid();
  const Eigen::Vector3d span = g.spacing * Eigen::Vector3d(g.count[0] - 1, g.count[1] - 1, g.count[2] - 1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  MapErrors e;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d p = g.origin + span.cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const SurfacePoint exact = closest_point(shape, p), approx = map.closest(p);
    const double error = std::abs(approx.distance - exact.distance);
    e.max = std::max(e.max, error);
    if (std::abs(exact.distance) < 0.1) {
      e.near_surface = std::max(e.near_surface, error);
      e.normal_angle = std::max(e.normal_angle, std::acos(std::clamp(approx.normal.dot(exact.normal), -1.0, 1.0)));
    }
  }
  return e;
}

// Prints the table and checks: bound everywhere, monotone decrease, and the observed order
// near the surface over the last halving at least `order`. Normals converge only on smooth
// surfaces: at edges the interpolation blends the faces' normals over one cell.
void expect_convergence(const char* label, const Shape& shape, const std::vector<double>& spacings, double order,
                        bool smooth) {
  std::mt19937 rng(19);
  std::printf("%-12s %8s %9s %12s %12s %12s %12s\n", label, "h", "nodes", "bound", "max error", "near surface",
              "normal (rad)");
  std::vector<MapErrors> errors;
  for (double h : spacings) {
    const DistanceMap map(shape, h, 0.15);
    errors.push_back(measure(shape, map, rng));
    const MapErrors& e = errors.back();
    std::printf("%-12s %8.4f %9zu %12.3e %12.3e %12.3e %12.3e\n", "", h, map.grid().size(), map.error_bound(), e.max,
                e.near_surface, e.normal_angle);
    EXPECT_LE(e.max, map.error_bound());
    if (errors.size() > 1) {
      EXPECT_LT(e.max, errors[errors.size() - 2].max);
      EXPECT_LT(e.near_surface, errors[errors.size() - 2].near_surface);
      if (smooth) {
        EXPECT_LT(e.normal_angle, errors[errors.size() - 2].normal_angle);
      }
    }
  }
  const double observed = std::log2(errors[errors.size() - 2].near_surface / errors.back().near_surface) /
                          std::log2(spacings[spacings.size() - 2] / spacings.back());
  EXPECT_GT(observed, order) << label;
}

TEST(DistanceMap, ErrorDecreasesWithSpacing) {
  expect_convergence("sphere", Sphere(0.7), {0.2, 0.1, 0.05, 0.025}, 1.8, true);
  expect_convergence("ellipsoid", Ellipsoid({0.9, 0.5, 0.6}), {0.2, 0.1, 0.05}, 1.5, true);
  expect_convergence("box", Box({0.9, 0.4, 0.6}), {0.2, 0.1, 0.05, 0.025}, 0.9, false);
  expect_convergence("torus mesh", testing::make_mesh(testing::torus_mesh(1.0, 0.3, 48, 24)), {0.2, 0.1, 0.05}, 0.9,
                     false);
}

TEST(DistanceMap, NodesAreExactAndOutsideIsAnUpperBound) {
  const Shape shape = Box({0.9, 0.4, 0.6});
  const DistanceMap map(shape, 0.1, 0.2);
  const GridSpec& g = map.grid();
  for (std::size_t n = 0; n < g.size(); n += 7) {
    EXPECT_EQ(map.values()[n], signed_distance(shape, g.node(n)));
    EXPECT_NEAR(map.signed_distance(g.node(n)), map.values()[n], 1e-14);
  }
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(3, 0.1, -0.2), Eigen::Vector3d(-2, 2, 2)})
    EXPECT_GE(map.signed_distance(p), signed_distance(shape, p) - map.error_bound());
}

TEST(DistanceMap, RejectsUnboundedShapesAndBadSpacing) {
  EXPECT_THROW(DistanceMap(HalfSpace({0, 0, 1}), 0.1, 0.1), std::invalid_argument);
  EXPECT_THROW(DistanceMap(Sphere(1), 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(DistanceMap(Sphere(1), 0.1, -1.0), std::invalid_argument);
  EXPECT_THROW(DistanceMap(Sphere(1), 1e-5, 0.0), std::invalid_argument);  // 2e5^3 nodes
}

}  // namespace
}  // namespace cosim::geometry
