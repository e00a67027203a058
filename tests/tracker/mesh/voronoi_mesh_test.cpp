#include "checks.hpp"

#include "tracker/mesh/voronoi_mesh.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace cosim::tracker {
namespace {

std::vector<Vec3> random_points(int n, const Vec3& lo, const Vec3& hi, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i)
    points.push_back(lo + (hi - lo).cwiseProduct(Vec3(uniform(random), uniform(random), uniform(random))));
  return points;
}

TEST(VoronoiMesh, ClippedToTheBox) {
  const VoronoiSpec spec{Vec3(-1.0, 0.0, 0.0), Vec3(1.0, 1.0, 0.5), {false, false, false}};
  const auto points = random_points(100, spec.min, spec.max, 7);
  const Mesh mesh = voronoi_mesh(points, spec);
  ASSERT_EQ(mesh.cell_count(), 100);
  EXPECT_NEAR(test::total_volume(mesh), 1.0, 1e-12);
  test::expect_consistent(mesh);
  for (Index c = 0; c < mesh.cell_count(); ++c) EXPECT_TRUE(contains(mesh, c, points[c])) << c;
  for (const Face& face : mesh.faces) {
    if (face.neighbour >= 0) continue;
    const Index patch = patch_of(face.neighbour);
    ASSERT_LT(patch, 6);
    const double side = patch % 2 ? spec.max[patch / 2] : spec.min[patch / 2];
    EXPECT_NEAR(face.point[patch / 2], side, 1e-12) << mesh.patches[patch];
  }
}

TEST(VoronoiMesh, PeriodicLinksOppositeSides) {
  const VoronoiSpec spec{Vec3::Zero(), Vec3(1.0, 2.0, 1.0), {true, true, true}};
  const Mesh mesh = voronoi_mesh(random_points(100, spec.min, spec.max, 11), spec);
  EXPECT_NEAR(test::total_volume(mesh), 2.0, 1e-12);
  EXPECT_EQ(test::boundary_faces(mesh), 0);
  test::expect_consistent(mesh);
  EXPECT_GT(mesh.shifts.size(), 1u);
  // Across a linked face the twin sits where this face is, moved by the shift.
  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Face& face = mesh.faces[f];
    const Face& twin = mesh.faces[face.twin];
    EXPECT_LT((face.point + mesh.shifts[face.shift] - twin.point).norm(), 1e-12) << f;
    EXPECT_LT((mesh.shifts[face.shift] + mesh.shifts[twin.shift]).norm(), 1e-12) << f;
  }
}

TEST(VoronoiMesh, PeriodicInOneAxisOnly) {
  const VoronoiSpec spec{Vec3::Zero(), Vec3::Ones(), {false, false, true}};
  const Mesh mesh = voronoi_mesh(random_points(60, spec.min, spec.max, 3), spec);
  EXPECT_NEAR(test::total_volume(mesh), 1.0, 1e-12);
  test::expect_consistent(mesh);
  for (const Face& face : mesh.faces) {
    if (face.neighbour < 0) {
      EXPECT_LT(patch_of(face.neighbour), 4);  // no z walls
    }
  }
}

TEST(VoronoiMesh, RejectsPointsOutsideAndCoincidentPoints) {
  const VoronoiSpec spec;
  const std::vector<Vec3> outside{Vec3(0.5, 0.5, 0.5), Vec3(1.5, 0.5, 0.5)};
  EXPECT_THROW(voronoi_mesh(outside, spec), std::invalid_argument);
  const std::vector<Vec3> twice{Vec3(0.5, 0.5, 0.5), Vec3(0.2, 0.5, 0.5), Vec3(0.5, 0.5, 0.5)};
  EXPECT_THROW(voronoi_mesh(twice, spec), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker
