// The fictitious-boundary indicator: the grid volume sum(alpha * cell volume) of a sphere
// and of a rotated box converges to the exact volume, faster with sub-cell fractions;
// only the points in the body's bounding box are tested; imposed faces carry the rigid
// velocity; a surface offset grows the imposed faces only.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fluid/staircase/fictitious_boundary.hpp"
#include "geometry/queries.hpp"

namespace cosim::fluid {

using bodies::ImposedFace;
using bodies::RigidBody;
using grid::Axis;
using grid::for_each_index;
using grid::Grid;
using grid::Index;
using grid::Point;
using staircase::FictitiousBoundary;

namespace {

Grid cube(MPI_Comm comm, int n, double size) {
  return Grid(comm,
              {Axis::uniform(n, 0, size, true), Axis::uniform(n, 0, size, true), Axis::uniform(n, 0, size, false)});
}

// Relative volume errors on n = 16, 32, 64 cells per unit length.
std::array<double, 3> volume_errors(const geometry::Shape& shape, const geometry::Pose& pose, int subsamples) {
  std::array<double, 3> errors{};
  const double exact = geometry::volume(shape);
  for (int level = 0; level < 3; ++level) {
    const Grid grid = cube(PETSC_COMM_WORLD, 16 << level, 1.0);
    FictitiousBoundary fbm(grid, {.subsamples = subsamples});
    const std::size_t b = fbm.add({shape, pose});
    errors[static_cast<std::size_t>(level)] = std::abs(fbm.grid_volume(b) - exact) / exact;
  }
  return errors;
}

void expect_volume_converges(const char* name, const geometry::Shape& shape, const geometry::Pose& pose) {
  const auto point = volume_errors(shape, pose, 1);
  const auto fraction = volume_errors(shape, pose, 4);
  PetscPrintf(PETSC_COMM_WORLD,
              "FBM grid volume of a %s, relative error at h = 1/16, 1/32, 1/64: point-sampled %.2e %.2e %.2e, "
              "4^3 sub-samples %.2e %.2e %.2e\n",
              name, point[0], point[1], point[2], fraction[0], fraction[1], fraction[2]);
  // Point sampling converges like O(h) at worst (irregularly: cells switch in groups).
  EXPECT_LT(point[2], 0.5 * point[0]);
  EXPECT_LT(point[2], 2e-2);
  EXPECT_LT(fraction[1], fraction[0]);
  EXPECT_LT(fraction[2], fraction[1]);
  EXPECT_LT(fraction[2], 2e-3);
}

TEST(FbmIndicator, SphereVolumeConverges) {
  expect_volume_converges("sphere (r = 0.3)", geometry::Sphere(0.3),
                          geometry::Pose({0.51, 0.493, 0.5}, Eigen::Quaterniond::Identity()));
}

TEST(FbmIndicator, RotatedBoxVolumeConverges) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()));
  expect_volume_converges("rotated box (0.5 x 0.3 x 0.2)", geometry::Box({0.25, 0.15, 0.1}),
                          geometry::Pose({0.5, 0.5, 0.5}, q));
}

// Same cell size, eight times the cells: the same points are tested.
TEST(FbmIndicator, TestsOnlyTheBoundingBox) {
  const RigidBody sphere{geometry::Sphere(0.1), geometry::Pose({0.3, 0.4, 0.5}, Eigen::Quaterniond::Identity())};
  std::size_t tested[2];
  for (int size = 1; size <= 2; ++size) {
    const Grid grid = cube(PETSC_COMM_SELF, 32 * size, size);
    FictitiousBoundary fbm(grid);
    tested[size - 1] = fbm.points_tested(fbm.add(sphere));
  }
  // Per kind of point at most 8 (faces: 7 along their own axis) of the 32 per unit length
  // overlap a box 0.2 wide.
  PetscPrintf(PETSC_COMM_WORLD, "FBM points tested for a sphere of 6.4 cells diameter: %zu on 32^3, %zu on 64^3\n",
              tested[0], tested[1]);
  EXPECT_EQ(tested[0], tested[1]);
  EXPECT_LE(tested[0], 4u * 8 * 8 * 8);
}

TEST(FbmIndicator, ImposedFacesCarryTheRigidVelocity) {
  const Grid grid = cube(PETSC_COMM_WORLD, 24, 1.0);
  FictitiousBoundary fbm(grid);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()));
  const std::size_t b = fbm.add({geometry::Cylinder(0.15, 0.4), geometry::Pose({0.5, 0.45, 0.55}, q),
                                 Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(1, 2, -3)});
  const RigidBody& body = fbm.body(b);
  std::size_t count = 0;
  for (int c = 0; c < 3; ++c)
    for (const ImposedFace& f : fbm.imposed_faces().owned(c)) {
      const Point x = grid.position(c, f.at);
      const Eigen::Vector3d xe(x[0], x[1], x[2]);
      EXPECT_TRUE(geometry::contains(body.shape, body.pose, xe));
      EXPECT_DOUBLE_EQ(f.value, (body.velocity + body.angular_velocity.cross(xe - body.pose.position()))[c]);
      ++count;
    }
  unsigned long total = count;
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_UNSIGNED_LONG, MPI_SUM, PETSC_COMM_WORLD);
  // About 3 * volume / h^3 faces.
  const double expected = 3 * geometry::volume(body.shape) * 24 * 24 * 24;
  EXPECT_NEAR(static_cast<double>(total), expected, 0.1 * expected);
}

// With an offset the faces within offset * h outside the surface are imposed too, and the
// cell-centre fractions (the body's volume) stay as they were.
TEST(FbmIndicator, SurfaceOffsetGrowsOnlyTheImposedFaces) {
  const int n = 20;
  const double h = 1.0 / n, offset = 0.4;
  const Grid grid = cube(PETSC_COMM_WORLD, n, 1.0);
  const RigidBody box{geometry::Box({0.13, 0.2, 0.17}),
                      geometry::Pose({0.49, 0.52, 0.47}, Eigen::Quaterniond(Eigen::AngleAxisd(
                                                             0.7, Eigen::Vector3d(1, 1, 0).normalized())))};
  FictitiousBoundary plain(grid), grown(grid, {.offset = offset});
  const std::size_t b = plain.add(box);
  grown.add(box);
  EXPECT_DOUBLE_EQ(plain.grid_volume(b), grown.grid_volume(b));
  long imposed[2] = {0, 0}, expected = 0;
  for (int c = 0; c < 3; ++c) {
    imposed[0] += static_cast<long>(plain.imposed_faces().owned(c).size());
    imposed[1] += static_cast<long>(grown.imposed_faces().owned(c).size());
    for (const ImposedFace& f : grown.imposed_faces().owned(c)) {
      const Point x = grid.position(c, f.at);
      EXPECT_LE(geometry::signed_distance(box.shape, box.pose, Eigen::Vector3d(x[0], x[1], x[2])), offset * h);
    }
    for_each_index(grid.owned(grid.velocity_dm(c)), [&](const Index& p) {
      const Point x = grid.position(c, p);
      if (!grid.on_boundary(c, p) &&
          geometry::signed_distance(box.shape, box.pose, Eigen::Vector3d(x[0], x[1], x[2])) <= offset * h)
        ++expected;
    });
  }
  MPI_Allreduce(MPI_IN_PLACE, imposed, 2, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &expected, 1, MPI_LONG, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(imposed[1], expected);
  // The grown box's faces: about 3 (V + offset h A) / h^3 more than the plain one's.
  const double area = 8 * (0.13 * 0.2 + 0.2 * 0.17 + 0.13 * 0.17);  // half extents
  EXPECT_NEAR(static_cast<double>(imposed[1] - imposed[0]), 3 * offset * h * area / (h * h * h),
              0.15 * 3 * offset * area / (h * h));
}

}  // namespace
}  // namespace cosim::fluid
