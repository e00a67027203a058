#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/locate.hpp"
#include "tracker/mesh/perturb.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"

#include <gtest/gtest.h>

#include <random>

namespace cosim::tracker::mesh {
namespace {

Index scan(const Mesh& mesh, const Vec3& x) {
  for (Index c = 0; c < mesh.cell_count(); ++c)
    if (contains(mesh, c, x)) return c;
  return -1;
}

// The located cell contains the point, and -1 comes exactly where no cell does; points
// are drawn from a slightly larger box so some are outside.
void agrees_with_scan(const Mesh& mesh, const Vec3& lo, const Vec3& hi) {
  const PointLocator locator(mesh);
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> uniform(-0.05, 1.05);
  int outside = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 x = lo + (hi - lo).cwiseProduct(Vec3(uniform(random), uniform(random), uniform(random)));
    const Index found = locator.locate(x), expected = scan(mesh, x);
    outside += expected < 0;
    if (expected < 0) {
      ASSERT_EQ(found, -1) << x.transpose();
    } else {
      ASSERT_TRUE(found >= 0 && contains(mesh, found, x)) << x.transpose() << " scan " << expected;
    }
  }
  EXPECT_GT(outside, 0);
}

TEST(Locate, GradedHexahedra) {
  BoxSpec spec;
  spec.axes[0] = {.min = 0.0, .max = 2.0, .cells = 12, .ratio = 5.0};
  spec.axes[1] = {.min = 0.0, .max = 1.0, .cells = 6};
  spec.axes[2] = {.min = 0.0, .max = 1.0, .cells = 5, .ratio = 0.3};
  agrees_with_scan(box_mesh(spec), Vec3::Zero(), Vec3(2.0, 1.0, 1.0));
}

// Guards against: a point in a gap between perturbed cells being located in no cell.
TEST(Locate, PerturbedTetrahedraAndHexahedra) {
  BoxSpec spec = cube(5);
  agrees_with_scan(perturbed(box_mesh(spec), {.fraction = 0.2, .seed = 8}), Vec3::Zero(), Vec3::Ones());
  spec.tetrahedra = true;
  agrees_with_scan(perturbed(box_mesh(spec), {.fraction = 0.2, .seed = 8}), Vec3::Zero(), Vec3::Ones());
}

TEST(Locate, Voronoi) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 300; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  const Mesh mesh = voronoi_mesh(points, {});
  agrees_with_scan(mesh, Vec3::Zero(), Vec3::Ones());
  // Each generator point lies in its own cell.
  const PointLocator locator(mesh);
  for (Index c = 0; c < mesh.cell_count(); ++c) EXPECT_EQ(locator.locate(points[c]), c);
}

}  // namespace
}  // namespace cosim::tracker::mesh
