// Hits on the union and the intersection of three overlapping balls lie on the analytic
// surface: on one sphere to round-off, and outside (union) or inside (intersection) the others.
#include <array>
#include <random>

#include <gtest/gtest.h>

#include "tests/tracker/csg/flight.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

const std::array<Eigen::Vector3d, 3> centres = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1.2, 0, 0),
                                                Eigen::Vector3d(0.5, 1.0, 0.2)};
const std::array<double, 3> radii = {1.0, 0.9, 0.8};

Expression three(bool intersect) {
  Expression e = ball(centres[0], radii[0]);
  for (int i = 1; i < 3; ++i) e = intersect ? (e & ball(centres[i], radii[i])) : (e | ball(centres[i], radii[i]));
  return e;
}

// Shoots rays through a permeable object from far outside and checks every boundary event.
void check_hits(bool intersect) {
  const Object o(three(intersect), true);
  std::mt19937_64 rng(intersect ? 5 : 4);
  std::uniform_real_distribution<double> u(-1, 1);
  const double tol = 1e-12;
  int hits = 0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector3d target = Eigen::Vector3d(0.5, 0.3, 0) + 0.9 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    Eigen::Vector3d x = target + 5.0 * testing::random_direction(rng);
    const Eigen::Vector3d v = (target - x).normalized() * 3.0;
    State s = o.classify(x);
    ASSERT_EQ(s, 0u);
    while (true) {
      const Event e = next_event(o, s, x, v);
      if (!e.happens()) break;
      x += e.dt * v;
      s = apply(s, e);
      if (!e.boundary) continue;
      ++hits;
      const int k0 = e.primitive;
      EXPECT_LT(std::abs((x - centres[k0]).norm() - radii[k0]), tol * radii[k0]);
      EXPECT_LT((e.normal - (x - centres[k0]).normalized()).norm(), 1e-12);
      for (int j = 0; j < 3; ++j) {
        if (j == k0) continue;
        const double d = (x - centres[j]).norm() / radii[j];
        if (intersect) {
          EXPECT_LT(d, 1.0 + tol);
        } else {
          EXPECT_GT(d, 1.0 - tol);
        }
      }
    }
    EXPECT_EQ(s, 0u);
  }
  EXPECT_GT(hits, intersect ? 4000 : 10000);
}

TEST(ThreeBalls, UnionHitsLieOnTheUnionSurface) { check_hits(false); }
TEST(ThreeBalls, IntersectionHitsLieOnTheIntersectionSurface) { check_hits(true); }

}  // namespace
}  // namespace cosim::tracker::csg
