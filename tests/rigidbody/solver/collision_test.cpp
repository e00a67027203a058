// Impacts: two spheres head-on with restitution e, and Newton's cradle.
#include <gtest/gtest.h>

#include "tests/rigidbody/solver/world.hpp"

namespace cosim::rigidbody::solver::test {
namespace {

constexpr double kRadius = 0.5;

struct Row {
  World world;
  std::vector<std::uint32_t> balls;
  std::vector<double> masses;

  Row(std::vector<double> m, std::vector<double> v) : masses(std::move(m)) {
    world.gravity.setZero();
    for (std::size_t i = 0; i < masses.size(); ++i) {
      balls.push_back(world.add_sphere(masses[i], kRadius, {2.0 * kRadius * i, 0.0, 0.0}));
      world.states[balls.back()].velocity.x() = v[i];
    }
  }
  Contacts contacts() const {
    return [this](std::span<const dynamics::BodyState> s) {
      std::vector<contact::Manifold> out;
      for (std::size_t i = 0; i + 1 < balls.size(); ++i)
        keep(out, sphere_sphere(balls[i], kRadius, balls[i + 1], kRadius, s, 1e-3));
      return out;
    };
  }
  double velocity(std::size_t i) const { return world.states[balls[i]].velocity.x(); }
};

// Textbook one-dimensional impact with restitution e.
std::pair<double, double> after_impact(double m1, double v1, double m2, double v2, double e) {
  const double p = m1 * v1 + m2 * v2;
  return {(p + m2 * e * (v2 - v1)) / (m1 + m2), (p + m1 * e * (v1 - v2)) / (m1 + m2)};
}

class HeadOn : public ::testing::TestWithParam<Preset> {};

TEST_P(HeadOn, MatchesTextbookVelocities) {
  for (const double e : {0.0, 0.6, 1.0}) {
    Row row({1.0, 3.0}, {2.0, -0.5});
    row.world.material = {.friction = 0.3, .restitution = e};
    row.world.step(1e-3, row.contacts(), impulses(GetParam().options));
    const auto [v1, v2] = after_impact(1.0, 2.0, 3.0, -0.5, e);
    EXPECT_NEAR(row.velocity(0), v1, 1e-6) << "e = " << e;
    EXPECT_NEAR(row.velocity(1), v2, 1e-6) << "e = " << e;
  }
}

INSTANTIATE_TEST_SUITE_P(Impulses, HeadOn, ::testing::Values(kPgs, kSi, kJacobi),
                         [](const auto& info) { return std::string(info.param.name); });

// DEM resolves the impact over many steps; the damping formula sets e up to the error of
// cutting off the dashpot's pull at the end of the contact.
TEST(HeadOnDem, RestitutionFromDampingFormula) {
  for (const double e : {0.3, 0.6, 0.9}) {
    Row row({1.0, 3.0}, {2.0, -0.5});
    row.world.material = {.friction = 0.3, .restitution = e};
    DemOptions options;
    options.normal_stiffness = 1e6;
    for (int step = 0; step < 2000; ++step) row.world.step(1e-5, row.contacts(), dem(options));
    const auto [v1, v2] = after_impact(1.0, 2.0, 3.0, -0.5, e);
    const double approach = 2.5;
    EXPECT_NEAR(row.velocity(0), v1, 0.03 * approach) << "e = " << e;
    EXPECT_NEAR(row.velocity(1), v2, 0.03 * approach) << "e = " << e;
    std::cout << "DEM e = " << e << ": measured " << (row.velocity(1) - row.velocity(0)) / approach << '\n';
  }
}

// Guards against: sequential restitution moving a touching chain as one body.
TEST(NewtonsCradle, SequentialRestitutionPassesMomentumThrough) {
  Row row({1, 1, 1, 1, 1}, {1, 0, 0, 0, 0});
  row.world.material = {.friction = 0.3, .restitution = 1.0};
  ImpulseOptions options = ImpulseOptions::sequential_impulses();
  options.restitution = Restitution::sequential;
  const double energy = row.world.kinetic_energy();
  for (int step = 0; step < 100; ++step) row.world.step(1e-3, row.contacts(), impulses(options));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(row.velocity(i), 0.0, 1e-9);
  EXPECT_NEAR(row.velocity(4), 1.0, 1e-9);
  EXPECT_NEAR(row.world.kinetic_energy(), energy, 1e-6 * energy);
}

// Why the sequential mode exists: simultaneous restitution treats the touching chain as
// one body. The LCP answer conserves energy here but the first ball bounces back.
TEST(NewtonsCradle, SimultaneousRestitutionMovesTheChainAsOne) {
  Row row({1, 1, 1, 1, 1}, {1, 0, 0, 0, 0});
  row.world.material = {.friction = 0.3, .restitution = 1.0};
  ImpulseOptions options = ImpulseOptions::sequential_impulses();
  options.tolerance = 1e-10;
  options.max_iterations = 500;
  row.world.step(1e-3, row.contacts(), impulses(options));
  EXPECT_NEAR(row.velocity(0), -0.6, 1e-6);
  for (std::size_t i = 1; i < 5; ++i) EXPECT_NEAR(row.velocity(i), 0.4, 1e-6);
}

}  // namespace
}  // namespace cosim::rigidbody::solver::test
