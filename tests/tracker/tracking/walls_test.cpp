// Boundary conditions: specular mirrors, diffuse re-emission statistics, Maxwell's
// accommodation fraction, removal at open patches, and flights through periodic links.

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/move.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cosim::tracker {
namespace {

constexpr double argon = 6.63e-26;  // kg

TEST(Walls, SpecularKeepsSpeedAndMirrorsTheNormalComponent) {
  Random random(1);
  std::normal_distribution<double> gauss;
  for (int i = 0; i < 1000; ++i) {
    const Vec3 n = Vec3(gauss(random), gauss(random), gauss(random)).normalized();
    const Vec3 v(gauss(random), gauss(random), gauss(random));
    const Vec3 w = specular(v, n);
    EXPECT_NEAR(w.norm(), v.norm(), 1e-14 * v.norm());
    EXPECT_NEAR(w.dot(n), -v.dot(n), 1e-14 * v.norm());
    EXPECT_LT((w - w.dot(n) * n - (v - v.dot(n) * n)).norm(), 1e-14 * v.norm());
  }
}

TEST(Walls, DiffuseReemissionIsAWallMaxwellian) {
  const double temperature = 300.0;
  const Vec3 n = Vec3(1.0, 2.0, -0.5).normalized();
  Random random(2);
  const int samples = 100000;
  double normal = 0.0, tangential_squared = 0.0;
  for (int i = 0; i < samples; ++i) {
    const Vec3 v = diffuse(n, temperature, argon, random);
    ASSERT_GT(v.dot(n), 0.0);
    normal += v.dot(n) / samples;
    tangential_squared += (v - v.dot(n) * n).squaredNorm() / samples;
  }
  const double expected = std::sqrt(std::numbers::pi * boltzmann * temperature / (2.0 * argon));
  std::printf("diffuse wall: mean normal velocity %.2f m/s, sqrt(pi k T / (2 m)) %.2f m/s\n", normal, expected);
  EXPECT_NEAR(normal / expected, 1.0, 0.01);
  EXPECT_NEAR(tangential_squared / (2.0 * boltzmann * temperature / argon), 1.0, 0.02);
}

TEST(Walls, MaxwellAccommodationFraction) {
  const Boundaries boundaries{{{.kind = BoundaryKind::maxwell, .temperature = 300.0, .accommodation = 0.3}}, argon};
  const Vec3 n = Vec3::UnitZ(), incoming(100.0, 50.0, -400.0);
  Random random(3);
  int mirrored = 0;
  const int samples = 100000;
  for (int i = 0; i < samples; ++i) {
    Vec3 v = incoming;
    ASSERT_TRUE(hit_wall(boundaries, 0, n, v, random));
    mirrored += v == specular(incoming, n);
  }
  EXPECT_NEAR(double(mirrored) / samples, 0.7, 0.01);
}

TEST(Walls, OpenPatchRemovesAndOthersReflect) {
  BoxSpec spec;
  for (auto& axis : spec.axes) axis.cells = 3;
  const Mesh mesh = box_mesh(spec);
  Boundaries boundaries{std::vector<BoundaryCondition>(6), argon};
  boundaries.patches[1] = {.kind = BoundaryKind::open};  // x_max
  const Domain domain(mesh, boundaries);
  Random random(4);
  for (Algorithm algorithm : {Algorithm::event_driven, Algorithm::stollmeier, Algorithm::haselbacher}) {
    Particle out{Vec3(0.5, 0.5, 0.5), Vec3(1.0, 0.2, 0.0), domain.locator.locate(Vec3(0.5, 0.5, 0.5))};
    const MoveResult left = move(algorithm, domain, out, 2.0, random);
    EXPECT_TRUE(left.removed) << name(algorithm);
    EXPECT_NEAR(out.x.x(), 1.0, 1e-12);
    // Off y_max and back: specular, the speed and the path length kept.
    Particle bounce{Vec3(0.5, 0.5, 0.5), Vec3(0.0, 1.0, 0.0), domain.locator.locate(Vec3(0.5, 0.5, 0.5))};
    const MoveResult back = move(algorithm, domain, bounce, 0.8, random);
    EXPECT_EQ(back.boundary_hits, 1) << name(algorithm);
    EXPECT_LT((bounce.x - Vec3(0.5, 0.7, 0.5)).norm(), 1e-12) << name(algorithm);
    EXPECT_TRUE(contains(mesh, bounce.cell, bounce.x)) << name(algorithm);
  }
}

TEST(Walls, PeriodicLinksWrapTheFlight) {
  Random random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  const Mesh mesh = voronoi_mesh(points, {.periodic = {true, true, true}});
  // The mesh names the six box patches; the links replace them all.
  const Domain domain(mesh, {std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::periodic}), 0.0});
  for (int i = 0; i < 1000; ++i) {
    Particle p{points[i % 100], Vec3(uniform(random), uniform(random), uniform(random)) - Vec3::Constant(0.5),
               static_cast<Index>(i % 100)};
    const Vec3 unwrapped = p.x + 7.0 * p.v;
    const MoveResult result = move(Algorithm::event_driven, domain, p, 7.0, random);
    ASSERT_FALSE(result.lost);
    const Vec3 wrapped = unwrapped - p.x;  // a lattice vector: whole periods on every axis
    EXPECT_LT((wrapped - wrapped.array().round().matrix()).norm(), 1e-11);
    EXPECT_LE(outside(mesh, p.cell, p.x).depth, domain.tolerance);
  }
}

}  // namespace
}  // namespace cosim::tracker
