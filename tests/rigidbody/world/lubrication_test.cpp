// The lubrication film (solver/lubrication.hpp) against the integral of its own law: with
// no other force, m dw = 6 pi mu R^2 (1/s - 1/L) ds for the closing speed w at gap s, so
//   w(s) = w0 - (6 pi mu R^2 / m) [ln(s0 / s) - (s0 - s) / L],
// and a body that starts slower than the film can absorb stops at the gap where w = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

constexpr double mu = 0.058, a = 0.0075, density = 1120.0, range = 2.5e-3;

Settings film_settings(double dt) {
  Settings s;
  s.dt = dt;
  s.body_forces.gravity = false;
  s.lubrication = {.viscosity = mu, .range = range, .roughness = 1e-7};
  return s;
}

std::uint32_t add_ball(World& world, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity) {
  BodyDesc d{.shape = geometry::Sphere(a), .density = density};
  d.state.position = position;
  d.state.velocity = velocity;
  return world.add(d);
}

// The closing speed the law leaves at gap s, for a film of radius r on a mass m.
double closing_speed(double w0, double s0, double s, double r, double m) {
  return w0 - 6.0 * std::numbers::pi * mu * r * r / m * (std::log(s0 / s) - (s0 - s) / range);
}

// Where that speed reaches zero (bisection: it falls monotonically as s does).
double stopping_gap(double w0, double s0, double r, double m) {
  double lo = 1e-12, hi = s0;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (closing_speed(w0, s0, mid, r, m) > 0 ? hi : lo) = mid;
  }
  return hi;
}

const double ball_mass = density * 4.0 / 3.0 * std::numbers::pi * a * a * a;

TEST(Lubrication, SphereApproachingAWallFollowsTheFilmsLaw) {
  World world(film_settings(1e-5));
  add_ground(world);
  const double s0 = 2e-3, w0 = 0.05;
  const auto ball = add_ball(world, {0, 0, a + s0}, {0, 0, -w0});
  const double s_stop = stopping_gap(w0, s0, a, ball_mass);
  ASSERT_GT(s_stop, 1e-5);  // the case is one that stops in the film
  double worst = 0.0;
  for (int step = 0; step < 400; ++step) {
    world.advance(1e-3);
    const double s = world.states()[ball].position.z() - a;
    const double w = -world.states()[ball].velocity.z();
    if (s > 2.0 * s_stop) worst = std::max(worst, std::abs(w - closing_speed(w0, s0, s, a, ball_mass)) / w0);
  }
  EXPECT_LT(worst, 2e-3);
  EXPECT_NEAR(world.states()[ball].position.z() - a, s_stop, 0.01 * s_stop);
  EXPECT_LT(std::abs(world.states()[ball].velocity.z()), 1e-3 * w0);
}

// Two equal spheres closing head on: R = a / 2 and the reduced mass m / 2.
TEST(Lubrication, TwoSpheresClosingHeadOnFollowTheFilmsLaw) {
  World world(film_settings(1e-5));
  const double s0 = 1.5e-3, w0 = 0.02;
  const auto lower = add_ball(world, {0, 0, 0}, {0, 0, 0.5 * w0});
  const auto upper = add_ball(world, {0, 0, 2 * a + s0}, {0, 0, -0.5 * w0});
  const double s_stop = stopping_gap(w0, s0, 0.5 * a, 0.5 * ball_mass);
  world.advance(0.5);
  const auto& st = world.states();
  EXPECT_NEAR(st[upper].position.z() - st[lower].position.z() - 2 * a, s_stop, 0.01 * s_stop);
  EXPECT_NEAR(st[upper].velocity.z() + st[lower].velocity.z(), 0.0, 1e-12);  // momentum kept
  EXPECT_LT(st[upper].velocity.z() - st[lower].velocity.z(), 1e-3 * w0);
}

// A capsule arriving end-on: its cap is a sphere of its radius, so the film is a sphere's
// of that radius on the capsule's mass (its bounding sphere's radius, half its length more,
// would stop it 43 times farther out: 1.8 mm against 0.042 mm).
TEST(Lubrication, CapsuleArrivingEndOnFollowsItsCapsFilm) {
  World world(film_settings(1e-5));
  add_ground(world);
  const double radius = 0.3 * a, height = 6 * a, s0 = 2e-3, w0 = 0.02;
  const geometry::Capsule shape(radius, height);
  BodyDesc d{.shape = shape, .density = density};
  d.state.position = {0, 0, height / 2 + radius + s0};
  d.state.velocity = {0, 0, -w0};
  const auto stick = world.add(d);
  const double mass = density * geometry::volume(shape);
  const double s_stop = stopping_gap(w0, s0, radius, mass);
  ASSERT_GT(s_stop, 1e-5);
  world.advance(0.4);
  EXPECT_NEAR(world.states()[stick].position.z() - height / 2 - radius, s_stop, 0.01 * s_stop);
  EXPECT_LT(std::abs(world.states()[stick].velocity.z()), 1e-3 * w0);
}

// The film's time scale m s / (6 pi mu R^2) is 3 microseconds at the roughness; a step of a
// millisecond must neither overshoot nor bounce the sphere that gravity pushes into it.
TEST(Lubrication, StepsFarAboveTheFilmsTimeScaleStayMonotone) {
  Settings s = film_settings(1e-3);
  s.body_forces.gravity = true;
  // Rigid contact at the end of the film: the default soft contact would let the sphere
  // sink its sag g / omega^2 into the floor, which this test would read as overshoot.
  s.solver = SolverKind::sequential_impulses;
  World world(s);
  add_ground(world);
  const auto ball = add_ball(world, {0, 0, a + 2e-3}, {0, 0, -0.1});
  double previous_gap = 2e-3;
  for (int step = 0; step < 300; ++step) {
    world.advance(1e-3);
    const double gap = world.states()[ball].position.z() - a;
    EXPECT_LE(world.states()[ball].velocity.z(), 1e-12) << "step " << step;
    EXPECT_LE(gap, previous_gap + 1e-12) << "step " << step;
    EXPECT_GE(gap, -1e-9) << "step " << step;
    previous_gap = gap;
  }
}

// Beyond the range, and parallel to a wall, the film does nothing.
TEST(Lubrication, NoForceBeyondTheRangeOrAlongTheWall) {
  World world(film_settings(1e-4));
  add_ground(world);
  const auto far = add_ball(world, {0, 0, a + 1.5 * range}, {0, 0, -1e-3});
  const auto sliding = add_ball(world, {1, 0, a + 0.5 * range}, {0.01, 0, 0});
  world.advance(0.1);
  EXPECT_EQ(world.states()[far].velocity.z(), -1e-3);
  EXPECT_NEAR(world.states()[sliding].velocity.x(), 0.01, 1e-15);
}

}  // namespace
}  // namespace cosim::rigidbody::world::test
