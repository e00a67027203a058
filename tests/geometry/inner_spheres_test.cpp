// Inner spheres lie inside the shape and cover the requested fraction of it.
#include <gtest/gtest.h>

#include <cstdio>

#include "tests/geometry/fixtures.hpp"
#include "geometry/inner_spheres.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

TEST(InnerSpheres, InsideTheShapeAndCoveringTheFraction) {
  const std::pair<const char*, Shape> cases[] = {
      {"box", Box({0.9, 0.4, 0.6})},
      {"capsule", Capsule(0.4, 1.0)},
      {"torus mesh", testing::make_mesh(testing::torus_mesh(1.0, 0.3, 48, 24))}};
  std::mt19937 rng(20);
  for (const auto& [label, shape] : cases) {
    const DistanceMap map(shape, 0.03, 0.05);
    for (double fraction : {0.5, 0.8, 0.9}) {
      SCOPED_TRACE(std::string(label) + " " + std::to_string(fraction));
      const InnerSphereSet set = inner_spheres(map, fraction);
      EXPECT_GE(set.covered_fraction, fraction);

      for (const InnerSphere& s : set.spheres)
        for (int k = 0; k < 20; ++k)
          EXPECT_LE(signed_distance(shape, Eigen::Vector3d(s.center + s.radius * testing::random_unit(rng))), 1e-12);

      // Monte Carlo over the shape's volume.
      const Aabb box = world_aabb(shape, Pose());
      std::uniform_real_distribution<double> u(0.0, 1.0);
      int inside = 0, covered = 0;
      for (int i = 0; i < 8000; ++i) {
        const Eigen::Vector3d p = box.min + (box.max - box.min).cwiseProduct(Eigen::Vector3d(u(rng), u(rng), u(rng)));
        if (!contains(shape, p)) continue;
        ++inside;
        for (const InnerSphere& s : set.spheres)
          if ((p - s.center).squaredNorm() <= s.radius * s.radius) {
            ++covered;
            break;
          }
      }
      const double mc = static_cast<double>(covered) / inside;
      const double sigma = std::sqrt(mc * (1 - mc) / inside);
      std::printf("%-10s target %.2f: %5zu spheres, estimate %.3f, Monte Carlo %.3f +- %.3f\n", label, fraction,
                  set.spheres.size(), set.covered_fraction, mc, sigma);
      EXPECT_GE(mc, fraction - 3 * sigma);
    }
  }
}

TEST(InnerSpheres, RejectsBadFractions) {
  const DistanceMap map(Sphere(1), 0.2, 0.1);
  EXPECT_THROW(inner_spheres(map, 0.0), std::invalid_argument);
  EXPECT_THROW(inner_spheres(map, 1.5), std::invalid_argument);
  // The largest candidate is a node next to the centre, at most half a cell diagonal off.
  EXPECT_GE(inner_spheres(map, 0.3).spheres.front().radius, 1.0 - std::sqrt(3.0) * 0.1 - 1e-15);
}

}  // namespace
}  // namespace cosim::geometry
