// Issue case 2: Newton's cradle, five equal spheres exactly touching at t = 0, e = 1.
#include <gtest/gtest.h>

#include "rigidbody/dynamics/invariants.hpp"
#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

// Guards against: the impulse of a touching chain being smeared over all balls, or energy gained or lost.
TEST(Cradle, MomentumPassesThroughAndEnergyIsKept) {
  Settings s;
  s.body_forces.gravity = false;
  // Sequential restitution is an option of the impulse solvers; the soft step bounces all
  // points together after its relax, as Box2D does.
  s.solver = SolverKind::sequential_impulses;
  // Simultaneous restitution moves the chain as one body (solver README); the cradle
  // needs the impulse to travel ball by ball.
  s.restitution = solver::Restitution::sequential;
  World world(s);
  const double r = 0.05, v = 1.0;
  std::vector<std::uint32_t> balls;
  for (int i = 0; i < 5; ++i)
    balls.push_back(add_sphere(world, r, {2 * r * i, 0.0, 0.0}, {.friction = 0.3, .restitution = 1.0}));
  world.states()[balls[0]].velocity.x() = v;
  const double energy = dynamics::kinetic_energy(world.states(), world.inertias());
  const Eigen::Vector3d momentum = dynamics::linear_momentum(world.states(), world.inertias());
  world.advance(0.1);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(world.states()[balls[i]].velocity.x(), 0.0, 1e-6 * v) << "ball " << i;
  EXPECT_NEAR(world.states()[balls[4]].velocity.x(), v, 1e-6 * v);
  EXPECT_NEAR(dynamics::kinetic_energy(world.states(), world.inertias()), energy, 1e-6 * energy);
  EXPECT_LT((dynamics::linear_momentum(world.states(), world.inertias()) - momentum).norm(), 1e-12 * momentum.norm());
  EXPECT_GT(world.states()[balls[4]].position.x(), 8 * r + 0.05);  // it actually left
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
