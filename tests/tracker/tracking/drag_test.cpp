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

namespace cosim::tracker {
namespace {

TEST(FreeMolecularDrag, SphereMatchesTheClosedFormAtSeveralSpeedRatios) {
  // Units where c_mp = 1: mass 2 k_B, T = 1 K; unit radius; the box just holds the ball.
  BoxSpec spec;
  for (AxisSpacing& axis : spec.axes) axis = {.min = -1.1, .max = 1.1, .cells = 8};
  const Mesh mesh = box_mesh(spec);
  const double mass = 2.0 * boltzmann, density = 400.0, dt = 0.05;
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), mass});
  const Obstacles ball(mesh, {{"sphere", csg::Tree(csg::ball(Vec3::Zero(), 1.0)), false,
                               {.kind = BoundaryKind::diffuse, .temperature = 1.0}}});
  for (const double s : {0.3, 1.0, 2.0, 4.0}) {
    const Inflow inflow(mesh, {0, 1, 2, 3, 4, 5},
                        {.number_density = density, .velocity = Vec3(s, 0, 0), .temperature = 1.0, .mass = mass});
    Random random(7);
    Swarm swarm(1);
    MoveTally moves;
    std::vector<ObstacleTally> tally(1);
    const int warm_up = 60, measured = 400;
    for (int step = 0; step < warm_up + measured; ++step) {
      if (step == warm_up) tally.assign(1, {});
      swarm.move_all(domain, ball, dt, random, moves, tally);
      inflow.inject(domain, ball, dt, random, swarm, moves, tally);
    }
    // Force per unit particle mass and weight: the x impulse over the measured time.
    const double drag = tally[0].impulse.x() / (measured * dt);
    const double expected = dsmc::sphere_drag_coefficient(s, 1.0) * 0.5 * density * s * s * std::numbers::pi;
    std::printf("free-molecular sphere, s = %.1f: drag %.1f, Bird %.1f (%+.2f %%), side force %.1f, %lld hits, lost %lld\n",
                s, drag, expected, 100.0 * (drag / expected - 1.0), tally[0].impulse.tail<2>().norm() / (measured * dt),
                tally[0].hits, moves.lost);
    EXPECT_NEAR(drag / expected, 1.0, 0.03) << "s = " << s;
    EXPECT_LT(tally[0].impulse.tail<2>().norm() / (measured * dt), 0.03 * expected);
    EXPECT_EQ(moves.lost, 0);
    EXPECT_EQ(tally[0].released, 0);
  }
}

TEST(FreeMolecularHeatFlow, BallAtAnotherTemperatureThanTheGasAtRest) {
  // Molecules reach a surface at n c_mean / 4 per area and bring 2 k T_gas each, diffuse
  // re-emission takes 2 k T_wall away: Q = 4 pi r^2 (n c_mean / 4) 2 k (T_gas - T_wall).
  // Units of the drag test (mass 2 k_B, so 2 k / m = 1): Q / m = pi n c_mean (T_gas - T_wall).
  BoxSpec spec;
  for (AxisSpacing& axis : spec.axes) axis = {.min = -1.1, .max = 1.1, .cells = 8};
  const Mesh mesh = box_mesh(spec);
  const double mass = 2.0 * boltzmann, density = 400.0, dt = 0.05;
  const double mean_speed = std::sqrt(4.0 / std::numbers::pi);  // sqrt(8 k T / (pi m)) at T = 1
  const Domain domain(mesh, {std::vector<BoundaryCondition>(6, {.kind = BoundaryKind::open}), mass});
  const Inflow inflow(mesh, {0, 1, 2, 3, 4, 5}, {.number_density = density, .temperature = 1.0, .mass = mass});
  for (const double wall : {0.25, 4.0}) {
    const Obstacles ball(mesh, {{"sphere", csg::Tree(csg::ball(Vec3::Zero(), 1.0)), false,
                                 {.kind = BoundaryKind::diffuse, .temperature = wall}}});
    Random random(11);
    Swarm swarm(1);
    MoveTally moves;
    std::vector<ObstacleTally> tally(1);
    const int warm_up = 60, measured = 300;
    for (int step = 0; step < warm_up + measured; ++step) {
      if (step == warm_up) tally.assign(1, {});
      swarm.move_all(domain, ball, dt, random, moves, tally);
      inflow.inject(domain, ball, dt, random, swarm, moves, tally);
    }
    const double heat = tally[0].energy / (measured * dt);
    const double expected = std::numbers::pi * density * mean_speed * (1.0 - wall);
    std::printf("free-molecular heat flow into a ball at %.2f T_gas: %.1f, kinetic theory %.1f (%+.2f %%)\n", wall, heat,
                expected, 100.0 * (heat / expected - 1.0));
    EXPECT_NEAR(heat / expected, 1.0, 0.03) << "T_wall / T_gas = " << wall;
    EXPECT_EQ(moves.lost, 0);
  }
}

}  // namespace
}  // namespace cosim::tracker
