#include "tests/tracker/mesh/checks.hpp"

#include "tracker/mesh/geometry.hpp"
#include "tracker/mesh/locate.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <stdexcept>

namespace cosim::tracker::mesh {
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

// Faces that validation once rejected as "zero area": area below 1e-9 of the square of
// the cell's size, i.e. faces some 1e-5 of the cell across. Uniform random points give a
// few dozen per 20,000 (nearly co-spherical quadruples), genuine, not round-off.
std::vector<Index> small_faces(const Mesh& mesh) {
  std::vector<Index> small;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    const double size = cell_box(mesh, c).diagonal().norm();
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f)
      if (area_vector(mesh, f).norm() <= 1e-9 * size * size) small.push_back(f);
  }
  return small;
}

Index scan(const Mesh& mesh, const Vec3& x) {
  for (Index c = 0; c < mesh.cell_count(); ++c)
    if (contains(mesh, c, x)) return c;
  return -1;
}

// Guards against: nearly co-spherical points breaking the Voronoi mesh (tiny faces dropped or inconsistent).
TEST(VoronoiMesh, ManyRandomPointsWithTinyFaces) {
  // One seed each, about 1 s per mesh in release (seeds 7 to 59, walled and periodic,
  // all build and validate; those looked at have 20 to 32 small faces).
  for (const auto& [periodic, seed] : {std::pair{false, 7}, std::pair{true, 8}}) {
    const auto start = std::chrono::steady_clock::now();
    const VoronoiSpec spec{Vec3::Zero(), Vec3::Ones(), {periodic, periodic, periodic}};
    const auto points = random_points(20000, spec.min, spec.max, seed);
    const Mesh mesh = voronoi_mesh(points, spec);  // validates
    const double built = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    SCOPED_TRACE("seed " + std::to_string(seed) + (periodic ? " periodic" : " walled"));
    ASSERT_EQ(mesh.cell_count(), 20000);
    EXPECT_NEAR(test::total_volume(mesh), 1.0, 1e-11);
    test::expect_consistent(mesh);
    if (periodic) {
      EXPECT_EQ(test::boundary_faces(mesh), 0);
    }
    const std::vector<Index> small = small_faces(mesh);
    EXPECT_GT(small.size(), 5u);

    // Point location agrees with a scan and with the nearest generator (up to images on
    // periodic axes), on random points and just off both sides of each small face.
    // A periodic cell may cross the box side: x is then in the image of a cell.
    const PointLocator locator(mesh);
    const auto images = [&](const Vec3& x, auto&& find) {
      for (int k = 0; k < (periodic ? 27 : 1); ++k) {
        const Vec3 shift(k % 3 == 2 ? -1.0 : k % 3, (k / 3) % 3 == 2 ? -1.0 : (k / 3) % 3, k / 9 == 2 ? -1.0 : k / 9);
        if (const Index c = find(Vec3(x + shift)); c >= 0) return c;
      }
      return Index(-1);
    };
    const auto locate = [&](const Vec3& x) { return images(x, [&](const Vec3& y) { return locator.locate(y); }); };
    const auto scan_all = [&](const Vec3& x) { return images(x, [&](const Vec3& y) { return scan(mesh, y); }); };
    const auto nearest = [&](const Vec3& x) {
      Index best = -1;
      double distance = 1e300;
      for (Index i = 0; i < mesh.cell_count(); ++i) {
        Vec3 d = x - points[i];
        if (periodic) d = d.array() - d.array().round();
        if (d.norm() < distance) distance = d.norm(), best = i;
      }
      return best;
    };
    std::mt19937_64 random(seed + 100);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const Vec3 x(uniform(random), uniform(random), uniform(random));
      const Index found = locate(x);
      ASSERT_EQ(found, scan_all(x)) << x.transpose();
      ASSERT_EQ(found, nearest(x)) << x.transpose();
    }
    for (const Index f : small) {
      const Face& face = mesh.faces[f];
      const double across = std::sqrt(area_vector(mesh, f).norm());
      for (const double side : {1.0, -1.0}) {
        const Vec3 x = face.point + side * 0.01 * across * face.normal;
        // Behind a periodic link the neighbour is at x moved by the face's shift.
        const Vec3 y = side > 0 ? x : Vec3(x + mesh.shifts[face.shift]);
        const Index found = locator.locate(y);
        ASSERT_GE(found, 0) << "face " << f;
        EXPECT_EQ(scan(mesh, y), found) << "face " << f;
        EXPECT_EQ(found, side > 0 ? mesh.cell_of_face(f) : face.neighbour) << "face " << f;
      }
    }
    std::printf("%s seed %d: %d small faces, built and validated in %.2f s\n", periodic ? "periodic" : "walled", seed,
                int(small.size()), built);
  }
}

}  // namespace
}  // namespace cosim::tracker::mesh
