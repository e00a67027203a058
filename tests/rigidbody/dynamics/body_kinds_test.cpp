// Fixed and translation-only bodies, buoyancy, and the two halves of a substep.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "tests/rigidbody/dynamics/bodies.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

BodyState moving() {
  BodyState s;
  s.position = {1.0, 2.0, 3.0};
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()));
  s.velocity = {0.5, 0.0, -1.0};
  s.angular_velocity = {0.0, 3.0, 1.0};
  return s;
}

const WindowWrench kPush{{{1.0, 2.0, 3.0}, {0.5, -0.5, 0.2}}, {{3.0, 2.0, 1.0}, {0.1, 0.2, 0.3}}};

// Tries to change every velocity between the halves; it must not get through to the frozen parts.
void meddle(std::span<BodyState> states) {
  for (BodyState& s : states) {
    s.velocity += Eigen::Vector3d::Constant(1.0);
    s.angular_velocity += Eigen::Vector3d::Constant(1.0);
  }
}

TEST(BodyKinds, FixedAndTranslationOnlyBodies) {
  for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
    const std::vector<BodyInertia> inertia{BodyInertia::fixed(), box_body({0.1, 0.2, 0.3}, false)};
    std::vector<BodyState> states{moving(), moving()};
    const std::vector<WindowWrench> push{kPush, kPush};
    Substeps substeps(states, inertia, push, 0.0, 1.0, {scheme, 0.01, {.gravity = true}});
    for (long k = 0; k < substeps.count(); ++k) {
      substeps.integrate_velocities(k);
      meddle(states);
      substeps.integrate_positions();
    }
    EXPECT_EQ(states[0].position, moving().position);
    EXPECT_EQ(states[0].velocity, moving().velocity);
    EXPECT_EQ(states[0].orientation.coeffs(), moving().orientation.coeffs());
    EXPECT_EQ(states[0].angular_velocity, moving().angular_velocity);
    EXPECT_NE(states[1].position, moving().position);
    EXPECT_EQ(states[1].orientation.coeffs(), moving().orientation.coeffs());
    EXPECT_EQ(states[1].angular_velocity, moving().angular_velocity);
  }
}

TEST(BodyKinds, BuoyancyOfANeutralBodyCancelsGravityExactly) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  const BodyForces neutral{.gravity = true, .buoyancy = true, .fluid_density = body.density};
  for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
    const BodyState end = run(moving(), body, scheme, 0.01, 1.0, neutral);
    EXPECT_EQ(end.velocity, moving().velocity);
  }
}

TEST(BodyKinds, BuoyancyIsMinusFluidDensityTimesVolumeTimesG) {
  BodyInertia body = box_body({0.1, 0.2, 0.3});
  const BodyForces forces{.buoyancy = true, .fluid_density = 250.0};  // a quarter of the body's
  EXPECT_LT((forces.acceleration(body) + 0.25 * forces.g).norm(), 1e-15);
  body.density = 0.0;
  EXPECT_THROW((void)forces.acceleration(body), std::invalid_argument);
}

TEST(BodyKinds, PositionsMoveWithTheVelocitiesSetBetweenTheHalves) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  BodyState state = moving();
  Substeps substeps({&state, 1}, {&body, 1}, {}, 0.0, 1.0, {Scheme::semi_implicit_euler, 0.1, {.gravity = true}});
  for (long k = 0; k < substeps.count(); ++k) {
    substeps.integrate_velocities(k);
    state.velocity.setZero();  // a perfectly sticky contact
    substeps.integrate_positions();
  }
  EXPECT_EQ(substeps.count(), 10);
  EXPECT_DOUBLE_EQ(substeps.length(), 0.1);
  EXPECT_EQ(state.position, moving().position);
}

// dt is the longest substep: the soft step's springs are capped by it.
// Guards against: a window stepped in substeps longer than dt.
TEST(BodyKinds, SubstepCountIsTheRatioRoundedUp) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  BodyState state;
  const Substeps quarters({&state, 1}, {&body, 1}, {}, 0.0, 1.0, {Scheme::leapfrog, 0.3, {}});
  EXPECT_EQ(quarters.count(), 4);
  EXPECT_DOUBLE_EQ(quarters.length(), 0.25);
  // A whole number of substeps up to round-off gains none.
  EXPECT_EQ(Substeps({&state, 1}, {&body, 1}, {}, 0.0, 0.3, {Scheme::leapfrog, 0.1, {}}).count(), 3);
  EXPECT_EQ(Substeps({&state, 1}, {&body, 1}, {}, 1.0, 1.0, {}).count(), 0);
  EXPECT_THROW(advance({&state, 1}, {}, {}, 0.0, 1.0, {}), std::invalid_argument);
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
