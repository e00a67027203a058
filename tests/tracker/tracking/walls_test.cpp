// Boundary conditions: specular mirrors, diffuse re-emission statistics, Maxwell's
// accommodation fraction, moving walls, patch tallies, removal at open patches, and flights
// through periodic links.

#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/voronoi_mesh.hpp"
#include "tracker/tracking/move.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cosim::tracker::tracking {
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

TEST(Walls, MovingWallsReEmitAboutTheirTangentialVelocity) {
  // The normal part of the velocity (here 30 m/s along n) is dropped: the patch does not move.
  const Vec3 n = Vec3::UnitY(), velocity(100.0, 30.0, -40.0);
  for (const BoundaryKind kind : {BoundaryKind::diffuse, BoundaryKind::maxwell}) {
    const Boundaries boundaries{{{.kind = kind, .temperature = 300.0, .accommodation = 1.0, .velocity = velocity}},
                                argon};
    Random random(6);
    const int samples = 100000;
    Vec3 mean = Vec3::Zero();
    for (int i = 0; i < samples; ++i) {
      Vec3 v(0.0, -300.0, 0.0);
      ASSERT_TRUE(hit_wall(boundaries, 0, n, v, random));
      mean += v / samples;
    }
    // Tangential components: standard error sqrt(k T / m) / sqrt(samples) = 0.8 m/s.
    const double normal = std::sqrt(std::numbers::pi * boltzmann * 300.0 / (2.0 * argon));
    EXPECT_NEAR(mean.x(), 100.0, 4.0);
    EXPECT_NEAR(mean.z(), -40.0, 4.0);
    EXPECT_NEAR(mean.y() / normal, 1.0, 0.01);
  }
  // A mirror sliding along itself is the plain mirror: refused rather than ignored.
  mesh::BoxSpec spec;
  const mesh::Mesh mesh = mesh::box_mesh(spec);
  Boundaries sliding{std::vector<BoundaryCondition>(6), argon};
  sliding.patches[2].velocity = Vec3(1.0, 0.0, 0.0);
  EXPECT_THROW(Domain(mesh, sliding), std::invalid_argument);
  const BoundaryCondition mirror{.kind = BoundaryKind::specular, .velocity = Vec3(1.0, 0.0, 0.0)};
  EXPECT_THROW(Obstacles(mesh, {{"ball", csg::Tree(csg::ball(Vec3::Constant(0.5), 0.2)), false, mirror}}),
               std::invalid_argument);
}

TEST(Walls, PatchTalliesBalanceTheParticlesMomentumAndEnergy) {
  // A closed box whose patches re-emit at two temperatures, slide, mirror and absorb: what
  // the patches took is what the particles lost, to round-off (moved as Particles in double).
  mesh::BoxSpec spec = mesh::cube(3);
  const mesh::Mesh mesh = mesh::box_mesh(spec);
  Boundaries boundaries{std::vector<BoundaryCondition>(6), argon};
  boundaries.patches[0] = {.kind = BoundaryKind::diffuse, .temperature = 200.0, .velocity = Vec3(0, 50, 0)};
  boundaries.patches[1] = {.kind = BoundaryKind::diffuse, .temperature = 400.0};
  boundaries.patches[2] = {
      .kind = BoundaryKind::maxwell, .temperature = 300.0, .accommodation = 0.5, .velocity = Vec3(-80, 0, 0)};
  boundaries.patches[5] = {.kind = BoundaryKind::open};
  const Domain domain(mesh, boundaries);
  const Obstacles none;
  Random random(7);
  std::normal_distribution<double> gauss(0.0, 300.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<SurfaceTally> patches(6);
  MoveTally moves;
  Vec3 lost_momentum = Vec3::Zero();
  double lost_energy = 0.0;
  long long removed = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 x(uniform(random), uniform(random), uniform(random));
    Particle p{x, Vec3(gauss(random), gauss(random), gauss(random)), domain.locator.locate(x)};
    const Vec3 before = p.v;
    const MoveResult result =
        move({.domain = domain, .obstacles = none, .random = random, .moves = moves, .patches = patches}, p, {}, 0.05);
    const Vec3 after = result.removed ? Vec3::Zero() : p.v;
    removed += result.removed;
    lost_momentum += before - after;
    lost_energy += 0.5 * (before.squaredNorm() - after.squaredNorm());
  }
  SurfaceTally all;
  for (const SurfaceTally& t : patches) all.add(t);
  EXPECT_GT(all.hits, 2000);
  EXPECT_EQ(all.absorbed, removed);
  EXPECT_EQ(patches[5].absorbed, removed);
  EXPECT_GT(patches[3].hits, 0);  // the specular y_max
  EXPECT_LT((all.impulse - lost_momentum).norm(), 1e-9 * lost_momentum.norm());
  EXPECT_NEAR(all.energy, lost_energy, 1e-9 * std::abs(lost_energy));
  // Wrong sizes are refused.
  std::vector<SurfaceTally> five(5);
  Particle p{Vec3::Constant(0.5), Vec3::UnitX(), domain.locator.locate(Vec3::Constant(0.5))};
  EXPECT_THROW(
      move({.domain = domain, .obstacles = none, .random = random, .moves = moves, .patches = five}, p, {}, 0.05),
      std::invalid_argument);
}

TEST(Walls, OpenPatchRemovesAndOthersReflect) {
  mesh::BoxSpec spec = mesh::cube(3);
  const mesh::Mesh mesh = mesh::box_mesh(spec);
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
    EXPECT_TRUE(mesh::contains(mesh, bounce.cell, bounce.x)) << name(algorithm);
  }
}

// Guards against: a long flight through periodic faces being lost or wrapped by a wrong lattice vector.
TEST(Walls, PeriodicLinksWrapTheFlight) {
  Random random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.emplace_back(uniform(random), uniform(random), uniform(random));
  const mesh::Mesh mesh = mesh::voronoi_mesh(points, {.periodic = {true, true, true}});
  // The mesh names the six box patches; the links replace them all.
  const Domain domain(mesh,
                      {std::vector<BoundaryCondition>(mesh.patches.size(), {.kind = BoundaryKind::periodic}), 0.0});
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
}  // namespace cosim::tracker::tracking
