// The coupler's wrench, interpolated over the window.
#include <gtest/gtest.h>

#include "tests/rigidbody/dynamics/bodies.hpp"
#include "rigidbody/dynamics/invariants.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

TEST(WindowWrench, InterpolatesLinearlyAndHoldsEqualEnds) {
  const WindowWrench ramp{{{2.0, 0.0, 0.0}, {0.0, 0.0, 1.0}}, {{4.0, 0.0, 0.0}, {0.0, 0.0, 3.0}}};
  EXPECT_EQ(ramp.at(1.0, 3.0, 1.0).force, Eigen::Vector3d(2.0, 0.0, 0.0));
  EXPECT_EQ(ramp.at(1.0, 3.0, 2.0).force, Eigen::Vector3d(3.0, 0.0, 0.0));
  EXPECT_EQ(ramp.at(1.0, 3.0, 3.0).torque, Eigen::Vector3d(0.0, 0.0, 3.0));
  const WindowWrench held{ramp.start, ramp.start};
  EXPECT_EQ(held.at(1.0, 1.0, 1.0).force, ramp.start.force);  // even a zero-length window
}

// The midpoint rule is exact for a linear force, so v(T) = v0 + (F0 + F1) T / (2 m) exactly;
// likewise for the angular momentum of a body under a ramping torque.
TEST(WindowWrench, LinearRampGivesTheExactVelocityWithLeapfrog) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  const double mass = 1.0 / body.inverse_mass;
  const WindowWrench ramp{{{10.0, -5.0, 0.0}, {0.3, 0.0, -0.1}}, {{-20.0, 5.0, 40.0}, {0.0, 0.2, 0.4}}};
  BodyState state;
  state.velocity = {1.0, 2.0, 3.0};
  const BodyState start = state;
  const double t0 = 0.5, t1 = 0.8;
  advance({&state, 1}, {&body, 1}, {&ramp, 1}, t0, t1, {Scheme::leapfrog, 0.01, {}});
  const Eigen::Vector3d v = start.velocity + (ramp.start.force + ramp.end.force) * (t1 - t0) / (2.0 * mass);
  EXPECT_LT((state.velocity - v).norm(), 1e-13 * v.norm());
  const Eigen::Vector3d l = (ramp.start.torque + ramp.end.torque) * (t1 - t0) / 2.0;
  EXPECT_LT((spin_angular_momentum(state, body) - l).norm(), 1e-13 * l.norm());
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
