// Tracers in a fluid velocity field: trilinear interpolation, a full turn of solid-body
// rotation back to the start, Stokes relaxation against its exact solution, and walls.

#include "tracker/csg/shapes.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/tracers/advance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cosim::tracker::tracers {
namespace {

std::array<std::vector<double>, 3> unit_grid(int n) {
  return {uniform_axis(0, 1, n), uniform_axis(0, 1, n), uniform_axis(0, 1, n)};
}

TEST(VelocityField, TrilinearIsExactForLinearFieldsAndClampsOutside) {
  const auto linear = [](const Vec3& x) { return Vec3(1 + 2 * x.x() - x.y(), 3 * x.z(), x.x() * 0.5 - 4); };
  const VelocityField u =
      VelocityField::sampled({uniform_axis(0, 1, 3), {0.0, 0.2, 1.0}, uniform_axis(-1, 1, 5)}, linear);
  tracking::Random random(1);
  std::uniform_real_distribution<double> in(0.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 x(in(random), in(random), 2 * in(random)-1);
    EXPECT_LT((u(x) - linear(x)).norm(), 1e-13);
  }
  // Outside: the value at the nearest boundary point.
  EXPECT_LT((u(Vec3(2.0, 0.5, 0.0)) - linear(Vec3(1.0, 0.5, 0.0))).norm(), 1e-13);
  // A bilinear field on a cell is reproduced at its centre as the mean of the corners.
  const VelocityField q =
      VelocityField::sampled({std::vector<double>{0, 1}, std::vector<double>{0, 1}, std::vector<double>{0}},
                             [](const Vec3& x) { return Vec3(x.x() * x.y(), 0, 0); });
  EXPECT_DOUBLE_EQ(q(Vec3(0.5, 0.5, 0.0)).x(), 0.25);
  EXPECT_THROW(VelocityField({std::vector<double>{0, 1}, std::vector<double>{1, 0}, std::vector<double>{0}},
                             std::vector<double>(12)),
               std::invalid_argument);
  EXPECT_THROW(VelocityField(unit_grid(1), std::vector<double>(5)), std::invalid_argument);
}

// Solid-body rotation about the box's vertical axis: one period brings every massless
// tracer back to its start (RK4: error of order (omega h)^4 per turn), through many cells.
TEST(Tracers, SolidBodyRotationReturnsAfterOnePeriod) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const tracking::Domain domain(mesh, {std::vector<tracking::BoundaryCondition>(6), 1.0});
  const double omega = 2.0 * std::numbers::pi;  // period 1
  const Vec3 centre(0.5, 0.5, 0.5);
  const VelocityField u = VelocityField::sampled(unit_grid(16), [&](const Vec3& x) {
    return Vec3(-omega * (x.y() - centre.y()), omega * (x.x() - centre.x()), 0.0);
  });
  const tracking::Obstacles none;
  tracking::Random random(2);
  std::uniform_real_distribution<double> radius(0.05, 0.4), angle(0.0, 2.0 * std::numbers::pi), height(0.1, 0.9);
  tracking::MoveTally moves;
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double r = radius(random), a = angle(random);
    const Vec3 start = centre + Vec3(r * std::cos(a), r * std::sin(a), height(random) - 0.5);
    tracking::Particle tracer{start, Vec3::Zero(), domain.locator.locate(start)};
    for (int step = 0; step < 10; ++step)
      ASSERT_TRUE(advance_tracer({.domain = domain, .obstacles = none, .random = random, .moves = moves}, u,
                                 {.substeps = 20}, tracer, {}, 0.1));
    worst = std::max(worst, (tracer.x - start).norm());
    EXPECT_FALSE(tracking::is_lost(domain, tracer));
  }
  std::printf("solid-body rotation, 200 tracers, 200 RK4 steps per turn: worst return error %.2e; %s\n", worst,
              tracking::summary(moves).c_str());
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(moves.lost, 0);
  EXPECT_GT(moves.faces_crossed, 200 * 4);  // a turn crosses several cells
}

// An inertial tracer released at rest in a uniform stream: v = U (1 - e^(-t/tau)),
// x = x0 + U (t - tau (1 - e^(-t/tau))), exactly, however few substeps.
TEST(Tracers, StokesDragRelaxesToTheStreamExactly) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(4));
  const tracking::Domain domain(mesh, {std::vector<tracking::BoundaryCondition>(6), 1.0});
  const Vec3 stream(0.5, 0.1, 0.0);
  const VelocityField u = VelocityField::sampled(unit_grid(2), [&](const Vec3&) { return stream; });
  const double tau = 0.3, t = 1.0;
  tracking::Particle tracer{{0.1, 0.2, 0.5}, Vec3::Zero(), 0};
  tracer.cell = domain.locator.locate(tracer.x);
  tracking::Random random(3);
  tracking::MoveTally moves;
  const tracking::Obstacles none;
  ASSERT_TRUE(advance_tracer({.domain = domain, .obstacles = none, .random = random, .moves = moves}, u,
                             {.response_time = tau, .substeps = 3}, tracer, {}, t));
  const double decay = std::exp(-t / tau);
  EXPECT_LT((tracer.v - stream * (1 - decay)).norm(), 1e-14);
  EXPECT_LT((tracer.x - (Vec3(0.1, 0.2, 0.5) + stream * (t - tau * (1 - decay)))).norm(), 1e-14);
}

// Tracers swirling around a fixed cylinder obstacle (its own wall) in the rotating flow:
// none enters it or is lost, and the wall is met.
TEST(Tracers, ObstaclesAndWallsHoldTracers) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  const tracking::Domain domain(mesh, {std::vector<tracking::BoundaryCondition>(6), 1.0});
  const tracking::Obstacles post(mesh,
                                 {{"post", csg::Tree(csg::cylinder({0.5, 0.75, 0.5}, {0, 0, 1}, 0.08)), false, {}}});
  const VelocityField u = VelocityField::sampled(unit_grid(16), [](const Vec3& x) -> Vec3 {
    return Vec3(-(x.y() - 0.5), x.x() - 0.5, 0.0) * 2.0 * std::numbers::pi;
  });
  tracking::Random random(4);
  std::uniform_real_distribution<double> in(0.05, 0.95);
  tracking::MoveTally moves;
  std::vector<tracking::ObstacleTally> tally(1);
  int inside = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec3 start(in(random), in(random), in(random));
    if ((start - Vec3(0.5, 0.75, start.z())).norm() < 0.1) continue;
    tracking::Particle tracer{start, Vec3::Zero(), domain.locator.locate(start)};
    csg::State state;
    post.classify(tracer.cell, tracer.x, {&state, 1});
    for (int step = 0; step < 10; ++step)
      ASSERT_TRUE(
          advance_tracer({.domain = domain, .obstacles = post, .random = random, .moves = moves, .tallies = tally}, u,
                         {.substeps = 5}, tracer, {&state, 1}, 0.1));
    inside += (tracer.x - Vec3(0.5, 0.75, tracer.x.z())).norm() < 0.08 - 1e-9;
  }
  std::printf("tracers around a post: %lld hits; %s\n", tally[0].hits, tracking::summary(moves).c_str());
  EXPECT_EQ(inside, 0);
  EXPECT_EQ(moves.lost, 0);
  EXPECT_EQ(tally[0].released, 0);
  EXPECT_GT(tally[0].hits, 10);
}

}  // namespace
}  // namespace cosim::tracker::tracers
