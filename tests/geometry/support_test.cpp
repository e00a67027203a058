// The support point maximises d . x over the shape and lies on its surface.
#include <gtest/gtest.h>

#include "tests/geometry/fixtures.hpp"
#include "geometry/queries.hpp"

namespace cosim::geometry {
namespace {

TEST(Support, MaximisesTheDirectionOverSurfaceSamples) {
  std::mt19937 rng(18);
  for (const auto& [label, shape] : testing::bounded_shapes()) {
    SCOPED_TRACE(label);
    const auto surface = testing::surface_samples(shape, 3000, rng);
    for (int i = 0; i < 100; ++i) {
      const Eigen::Vector3d d = testing::random_unit(rng) * (i % 2 ? 1.0 : 7.0);  // length must not matter
      const Eigen::Vector3d s = support(shape, d);
      EXPECT_LT(std::abs(signed_distance(shape, s)), 1e-12);
      double best = -1e300;
      for (const auto& x : surface) best = std::max(best, d.dot(x));
      EXPECT_GE(d.dot(s), best - 1e-12);
    }
    // Axis directions hit flat faces and rims, where the maximiser is not unique.
    for (int a = 0; a < 3; ++a)
      for (double sign : {-1.0, 1.0}) {
        const Eigen::Vector3d d = sign * Eigen::Vector3d::Unit(a);
        const Eigen::Vector3d s = support(shape, d);
        for (const auto& x : surface) EXPECT_GE(d.dot(s), d.dot(x) - 1e-12);
      }
  }
}

TEST(Support, HalfSpaceHasNone) {
  EXPECT_THROW(support(Shape(HalfSpace({0, 0, 1})), Eigen::Vector3d(0, 0, -1)), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::geometry
