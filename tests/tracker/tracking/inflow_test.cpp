// A Maxwellian stream through boundary faces: the inflow distribution inverted exactly, the
// count and the mean normal speed against Bird's flux formulas, and a box open on every
// side filling to the stream's density and temperature.

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/tracking/inflow.hpp"
#include "tracker/tracking/sampling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cosim::tracker::tracking {
namespace {

constexpr double sqrt_pi = 1.0 / std::numbers::inv_sqrtpi;

TEST(Inflow, NormalSpeedInvertsTheFluxDistribution) {
  // At rest: x = sqrt(-ln(1 - u)). Deep in the tail the inversion is conditioned by the
  // density there (x e^(-x^2) ~ 4e-6 at u = 1 - 1e-6): 1e-10 absolute.
  for (const double u : {1e-9, 0.1, 0.5, 0.9, 0.999999})
    EXPECT_NEAR(inflow_normal_speed(0.0, u), std::sqrt(-std::log(1.0 - u)), 1e-10);
  for (const double s : {-2.0, -0.5, 0.7, 3.0}) {
    double previous = 0.0;
    for (const double u : {0.01, 0.2, 0.5, 0.8, 0.99}) {
      const double x = inflow_normal_speed(s, u);
      const double cumulative =
          0.5 * (std::exp(-s * s) - std::exp(-(x - s) * (x - s))) + 0.5 * s * sqrt_pi * (std::erf(x - s) + std::erf(s));
      EXPECT_NEAR(cumulative / (sqrt_pi * flux_factor(s)), u, 1e-12) << "s " << s;
      EXPECT_GT(x, previous);
      previous = x;
    }
  }
}

// Mean normal speed of the entering molecules, x^2 against x moments of x e^(-(x - s)^2).
TEST(Inflow, MeanNormalSpeedIsTheFluxWeightedOne) {
  Random random(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (const double s : {-1.0, 0.0, 0.8, 2.5}) {
    const int n = 200000;
    double sum = 0.0, square = 0.0;
    for (int i = 0; i < n; ++i) {
      const double x = inflow_normal_speed(s, uniform(random));
      sum += x;
      square += x * x;
    }
    const double mean = sum / n, sigma = std::sqrt(square / n - mean * mean) / std::sqrt(n);
    const double second = 0.5 * s * std::exp(-s * s) + 0.25 * sqrt_pi * (1 + 2 * s * s) * (1 + std::erf(s));
    const double expected = second / (sqrt_pi * flux_factor(s));
    std::printf("inflow s = %4.1f: mean normal speed %.5f, flux-weighted %.5f (+- %.5f)\n", s, mean, expected, sigma);
    EXPECT_NEAR(mean, expected, 4 * sigma);
  }
}

// Units where the most probable speed is 1: mass 2 k_B, T = 1 K.
Stream unit_stream(double density, const Vec3& velocity) {
  return {.number_density = density, .velocity = velocity, .temperature = 1.0, .mass = 2.0 * boltzmann, .weight = 1.0};
}

TEST(Inflow, CountMatchesBirdsFlux) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(3));
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), 2.0 * boltzmann});
  const double s = 0.8;
  const Inflow inflow(mesh, {0}, unit_stream(1000.0, Vec3(s, 0.3, 0.0)));  // x_min, normal +x
  EXPECT_NEAR(inflow.rate(), 1000.0 * flux_factor(s), 1e-9);               // unit area, c_mp = 1
  const Obstacles none;
  Random random(2);
  Swarm swarm(0);
  MoveTally moves;
  long added = 0;
  const int steps = 2000;
  const double dt = 0.01;
  const MoveContext step{.domain = domain, .obstacles = none, .random = random, .moves = moves};
  for (int i = 0; i < steps; ++i) added += inflow.inject(step, dt, swarm);
  const double expected = inflow.rate() * dt * steps;
  // Random rounding per face and step: variance at most 1/4 each, 9 faces.
  std::printf("inflow: %ld entered, expected %.1f\n", added, expected);
  EXPECT_NEAR(added, expected, 4.0 * std::sqrt(0.25 * 9 * steps));
  EXPECT_EQ(static_cast<long long>(swarm.size()), added - moves.removed);
  EXPECT_EQ(moves.lost, 0);
}

TEST(Inflow, OpenBoxFillsToTheStreamsDensityAndTemperature) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(4));
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), 2.0 * boltzmann});
  const Inflow inflow(mesh, {0, 1, 2, 3, 4, 5}, unit_stream(4000.0, Vec3::Zero()));
  const Obstacles none;
  Random random(3);
  Swarm swarm(0);
  MoveTally moves;
  const double dt = 0.05;
  double count = 0.0, energy = 0.0;
  int samples = 0;
  for (int step = 0; step < 300; ++step) {
    const MoveContext context{.domain = domain, .obstacles = none, .random = random, .moves = moves};
    swarm.move_all(context, dt);
    inflow.inject(context, dt, swarm);
    if (step < 100) continue;  // filling: a few transit times
    count += static_cast<double>(swarm.size());
    for (std::size_t i = 0; i < swarm.size(); ++i) energy += swarm.particle(i).v.squaredNorm();
    ++samples;
  }
  const double mean = count / samples;
  const double temperature = energy / count / 1.5;  // <v^2> = 3 k T / m = 1.5 in these units
  std::printf("open box: %.1f simulators on average (stream: 4000), temperature %.4f (stream: 1); %s\n", mean,
              temperature, summary(moves).c_str());
  EXPECT_NEAR(mean / 4000.0, 1.0, 0.02);
  EXPECT_NEAR(temperature, 1.0, 0.02);
  EXPECT_EQ(moves.lost, 0);
}

// The sampled moments of the filled open box are the stream's in every cell: density n,
// velocity 0, temperature T, pressure n k T (argon-like units here: c_mp = 1).
TEST(Sampling, OpenBoxCellsHaveTheStreamsMoments) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(2));
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), 2.0 * boltzmann});
  const Inflow inflow(mesh, {0, 1, 2, 3, 4, 5}, unit_stream(8000.0, Vec3::Zero()));
  const Obstacles none;
  Random random(5);
  Swarm swarm(0);
  MoveTally moves;
  CellSampler sampler(mesh);
  for (int step = 0; step < 400; ++step) {
    const MoveContext context{.domain = domain, .obstacles = none, .random = random, .moves = moves};
    swarm.move_all(context, 0.05);
    inflow.inject(context, 0.05, swarm);
    if (step == 100) sampler.reset();
    sampler.sample(swarm);
  }
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    const CellMoments m = sampler.moments(c, 2.0 * boltzmann, 1.0);
    EXPECT_NEAR(m.number_density / 8000.0, 1.0, 0.03) << "cell " << c;
    EXPECT_LT(m.velocity.norm(), 0.03) << "cell " << c;
    EXPECT_NEAR(m.temperature, 1.0, 0.03) << "cell " << c;
    EXPECT_NEAR(m.pressure, m.number_density * boltzmann * m.temperature, 1e-12 * m.pressure);
  }
  const CellMoments first = sampler.moments(0, 2.0 * boltzmann, 1.0);
  std::printf("sampled cell 0: n %.1f (8000), |u| %.4f, T %.4f (1)\n", first.number_density, first.velocity.norm(),
              first.temperature);
  sampler.reset();
  EXPECT_EQ(sampler.moments(0, 1.0, 1.0).count, 0.0);
}

// Two simulators in a cell of volume 1/8, velocities u +- c with c = (1, 2, 0), u = (3, 0, 1),
// weight 4, mass 2 (n = 64): the pressure tensor is n m c c^T, the heat flux
// n m <|c|^2 c> / 2 = 0 (symmetric), and with a third at rest the moments follow by hand.
TEST(Sampling, StressAndHeatFluxFromTheSummedMoments) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(2));
  Swarm swarm(0);
  const Vec3 u(3, 0, 1), c(1, 2, 0);
  swarm.add({Vec3::Constant(0.25), u + c, 0}, {});
  swarm.add({Vec3::Constant(0.25), u - c, 0}, {});
  CellSampler sampler(mesh);
  sampler.sample(swarm);
  CellMoments m = sampler.moments(0, 2.0, 4.0);
  EXPECT_TRUE(m.stress.isApprox(64.0 * 2.0 * c * c.transpose(), 1e-12));
  EXPECT_LT(m.heat_flux.norm(), 1e-9);
  EXPECT_NEAR(m.pressure, m.stress.trace() / 3.0, 1e-12 * m.pressure);
  // Add one at rest: n = 96, mean u' = 2u/3, peculiar velocities u/3 + c, u/3 - c, -2u/3.
  swarm.add({Vec3::Constant(0.25), Vec3::Zero(), 0}, {});
  sampler.reset();
  sampler.sample(swarm);
  m = sampler.moments(0, 2.0, 4.0);
  const Vec3 a = u / 3 + c, b = u / 3 - c, d = -2.0 * u / 3;
  const Eigen::Matrix3d stress = 96.0 * 2.0 / 3.0 * (a * a.transpose() + b * b.transpose() + d * d.transpose());
  const Vec3 heat = 0.5 * 96.0 * 2.0 / 3.0 * (a.squaredNorm() * a + b.squaredNorm() * b + d.squaredNorm() * d);
  EXPECT_TRUE(m.stress.isApprox(stress, 1e-12));
  EXPECT_TRUE(m.heat_flux.isApprox(heat, 1e-12));
}

// Hits on a fixed wall give it momentum, its moment and energy: a head-on specular hit at
// distance r from the origin along y gives 2 v, r x 2 v and no energy; an absorbed one v,
// r x v and its kinetic energy.
TEST(Tallies, MomentEnergyAndImpulseOfHits) {
  ObstacleTally tally;
  tally.exchange(Vec3(0, 0.5, 0), Vec3::Zero(), Vec3(2, 0, 0), Vec3(-2, 0, 0));
  EXPECT_EQ(tally.impulse, Vec3(4, 0, 0));
  EXPECT_EQ(tally.angular_impulse, Vec3(0, 0, -2));
  EXPECT_EQ(tally.energy, 0.0);
  tally.exchange(Vec3(0, 0, 1), Vec3::Zero(), Vec3(0, 3, 0), Vec3::Zero());
  EXPECT_EQ(tally.impulse, Vec3(4, 3, 0));
  EXPECT_EQ(tally.angular_impulse, Vec3(-3, 0, -2));
  EXPECT_EQ(tally.energy, 4.5);
}

TEST(Inflow, RefusesBadStreamsAndEmptyPatches) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(2));
  EXPECT_THROW(Inflow(mesh, {0}, unit_stream(0.0, Vec3::Zero())), std::invalid_argument);
  EXPECT_THROW(Inflow(mesh, {7}, unit_stream(1.0, Vec3::Zero())), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::tracker::tracking
