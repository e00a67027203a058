// Free-molecular drag on a sphere (a CSG ball with diffuse walls at the gas temperature) in a
// Maxwellian stream entering an open box on every side, against the closed form (Bird 1994,
// eq. 7.66; its small-s limit is Epstein's drag with 1 + pi/8) at several speed ratios; and
// the heat flow into a ball hotter or colder than the gas at rest.

#include "tracker/csg/shapes.hpp"
#include "tracker/dsmc/free_molecular.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/tracking/inflow.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

namespace cosim::tracker::tracking {
namespace {

// Units where c_mp = 1: mass 2 k_B, T = 1 K; unit radius; the box just holds the ball.
constexpr double kMass = 2.0 * boltzmann, kDensity = 400.0, kDt = 0.05;

struct Exchange {
  ObstacleTally tally;  // over the measured steps
  double time = 0;      // their length
  long long lost = 0;
};

// A unit ball, diffuse at `wall_temperature`, in an open box fed on every side by a
// Maxwellian stream at 1 K and `velocity`: 60 steps to fill the box, then `measured`.
Exchange ball_in_stream(const Vec3& velocity, double wall_temperature, int measured, std::uint64_t seed) {
  mesh::BoxSpec spec;
  for (mesh::AxisSpacing& axis : spec.axes) axis = {.min = -1.1, .max = 1.1, .cells = 8};
  const mesh::Mesh mesh = mesh::box_mesh(spec);
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), kMass});
  const Obstacles ball(mesh, {{"sphere",
                               csg::Tree(csg::ball(Vec3::Zero(), 1.0)),
                               false,
                               {.kind = BoundaryKind::diffuse, .temperature = wall_temperature}}});
  const Inflow inflow(mesh, {0, 1, 2, 3, 4, 5},
                      {.number_density = kDensity, .velocity = velocity, .temperature = 1.0, .mass = kMass});
  Random random(seed);
  Swarm swarm(1);
  MoveTally moves;
  std::vector<ObstacleTally> tally(1);
  const int warm_up = 60;
  for (int step = 0; step < warm_up + measured; ++step) {
    if (step == warm_up) tally.assign(1, {});
    const MoveContext context{.domain = domain, .obstacles = ball, .random = random, .moves = moves, .tallies = tally};
    swarm.move_all(context, kDt);
    inflow.inject(context, kDt, swarm);
  }
  return {tally[0], measured * kDt, moves.lost};
}

TEST(FreeMolecularDrag, SphereMatchesTheClosedFormAtSeveralSpeedRatios) {
  for (const double s : {0.3, 1.0, 2.0, 4.0}) {
    const Exchange e = ball_in_stream(Vec3(s, 0, 0), 1.0, 400, 7);
    // Force per unit particle mass and weight: the x impulse over the measured time.
    const double drag = e.tally.impulse.x() / e.time, side = e.tally.impulse.tail<2>().norm() / e.time;
    const double expected = dsmc::sphere_drag(kDensity, kMass, s, 1.0, 1.0) / kMass;  // per unit particle mass
    std::printf(
        "free-molecular sphere, s = %.1f: drag %.1f, Bird %.1f (%+.2f %%), side force %.1f, %lld hits, lost %lld\n", s,
        drag, expected, 100.0 * (drag / expected - 1.0), side, e.tally.hits, e.lost);
    EXPECT_NEAR(drag / expected, 1.0, 0.03) << "s = " << s;
    EXPECT_LT(side, 0.03 * expected);
    EXPECT_EQ(e.lost, 0);
    EXPECT_EQ(e.tally.released, 0);
  }
}

TEST(FreeMolecularHeatFlow, BallAtAnotherTemperatureThanTheGasAtRest) {
  // Molecules reach a surface at n c_mean / 4 per area and bring 2 k T_gas each, diffuse
  // re-emission takes 2 k T_wall away: Q = 4 pi r^2 (n c_mean / 4) 2 k (T_gas - T_wall).
  // In these units 2 k / m = 1: Q / m = pi n c_mean (T_gas - T_wall).
  const double mean_speed = std::sqrt(4.0 / std::numbers::pi);  // sqrt(8 k T / (pi m)) at T = 1
  for (const double wall : {0.25, 4.0}) {
    const Exchange e = ball_in_stream(Vec3::Zero(), wall, 300, 11);
    const double heat = e.tally.energy / e.time;
    const double expected = std::numbers::pi * kDensity * mean_speed * (1.0 - wall);
    std::printf("free-molecular heat flow into a ball at %.2f T_gas: %.1f, kinetic theory %.1f (%+.2f %%)\n", wall,
                heat, expected, 100.0 * (heat / expected - 1.0));
    EXPECT_NEAR(heat / expected, 1.0, 0.03) << "T_wall / T_gas = " << wall;
    EXPECT_EQ(e.lost, 0);
  }
}

}  // namespace
}  // namespace cosim::tracker::tracking
