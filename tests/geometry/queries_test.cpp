// World-frame and batch queries answer what the body-frame single queries do.
#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

std::vector<std::pair<std::string, Shape>> all_shapes() {
  auto shapes = testing::bounded_shapes();
  shapes.emplace_back("half-space", HalfSpace({0.3, -1, 2}));
  return shapes;
}

TEST(Queries, WorldFrameIsTheBodyFrameThroughThePose) {
  std::mt19937 rng(13);
  for (const auto& [label, shape] : all_shapes()) {
    SCOPED_TRACE(label);
    for (int i = 0; i < 200; ++i) {
      const Pose pose = testing::random_pose(rng);
      const Eigen::Vector3d body = testing::random_in_ball(rng, 2.0), world = pose.to_world(body);
      const SurfacePoint b = closest_point(shape, body), w = closest_point(shape, pose, world);
      EXPECT_NEAR(w.distance, b.distance, 1e-12);
      EXPECT_NEAR(signed_distance(shape, pose, world), b.distance, 1e-12);
      EXPECT_LT((w.point - pose.to_world(b.point)).norm(), 1e-12);
      EXPECT_LT((w.normal - pose.direction_to_world(b.normal)).norm(), 1e-9);
      if (std::abs(b.distance) > 1e-12) {
        EXPECT_EQ(contains(shape, pose, world), b.distance < 0.0);
      }
    }
  }
}

TEST(Queries, BatchesEqualSingleQueries) {
  std::mt19937 rng(14);
  const Pose pose = testing::random_pose(rng);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 500; ++i) points.push_back(pose.to_world(testing::random_in_ball(rng, 2.0)));
  for (const auto& [label, shape] : all_shapes()) {
    SCOPED_TRACE(label);
    std::vector<double> distances(points.size());
    std::vector<SurfacePoint> closest(points.size());
    std::vector<std::uint8_t> inside(points.size());
    signed_distances(shape, pose, points, distances);
    closest_points(shape, pose, points, closest);
    contains(shape, pose, points, inside);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const SurfacePoint single = closest_point(shape, pose, points[i]);
      EXPECT_EQ(distances[i], single.distance);
      EXPECT_EQ(closest[i].distance, single.distance);
      // A mesh search seeded by the previous point may pick another of equidistant points.
      EXPECT_NEAR((closest[i].point - points[i]).norm(), std::abs(single.distance), 1e-12);
      EXPECT_EQ(inside[i] != 0, contains(shape, pose, points[i]));
    }
  }
}

TEST(Queries, GridBatchEqualsPointBatch) {
  GridSpec grid{{-1.1, -0.9, -0.7}, 0.1, {23, 19, 15}};
  std::vector<Eigen::Vector3d> nodes;
  for (int k = 0; k < grid.count[2]; ++k)
    for (int j = 0; j < grid.count[1]; ++j)
      for (int i = 0; i < grid.count[0]; ++i) {
        ASSERT_EQ(grid.index(i, j, k), nodes.size());
        ASSERT_EQ(grid.node(nodes.size()), grid.node(i, j, k));
        nodes.push_back(grid.node(i, j, k));
      }
  std::mt19937 rng(15);
  const Pose pose = testing::random_pose(rng);
  for (const auto& [label, shape] : all_shapes()) {
    std::vector<double> on_grid(grid.size()), on_points(grid.size());
    signed_distances(shape, pose, grid, on_grid);
    signed_distances(shape, pose, nodes, on_points);
    EXPECT_EQ(on_grid, on_points) << label;
  }
}

TEST(Queries, BatchOutputOfTheWrongSizeIsRejected) {
  const std::vector<Eigen::Vector3d> points(3, Eigen::Vector3d::Zero());
  std::vector<double> out(2);
  EXPECT_THROW(signed_distances(Shape(Sphere(1)), Pose(), points, out), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::geometry
