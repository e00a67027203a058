// Observed order of convergence on a tumbling asymmetric body against a very fine run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/rigidbody/dynamics/bodies.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

struct Error {
  double orientation;
  double angular_velocity;
};

Error error_at(Scheme scheme, double dt, const BodyState& reference) {
  BodyState start;
  start.angular_velocity = {2.0, -3.0, 4.0};
  const BodyState end = run(start, box_body({0.1, 0.2, 0.3}), scheme, dt, 1.0);
  return {angle_between(end.orientation, reference.orientation),
          (end.angular_velocity - reference.angular_velocity).norm()};
}

// Orders from errors at dt, dt/2, dt/4; both the orientation and the angular velocity.
void expect_order(Scheme scheme, const char* name, double expected) {
  BodyState start;
  start.angular_velocity = {2.0, -3.0, 4.0};
  const BodyState reference = run(start, box_body({0.1, 0.2, 0.3}), Scheme::leapfrog, 1e-5, 1.0);
  const double dts[] = {0.02, 0.01, 0.005};
  Error e[3];
  for (int k = 0; k < 3; ++k) e[k] = error_at(scheme, dts[k], reference);
  for (int k = 1; k < 3; ++k) {
    const double p_q = std::log2(e[k - 1].orientation / e[k].orientation);
    const double p_w = std::log2(e[k - 1].angular_velocity / e[k].angular_velocity);
    std::printf("%s dt %.4f -> %.4f: orientation error %.3e, order %.3f; angular velocity error %.3e, order %.3f\n",
                name, dts[k - 1], dts[k], e[k].orientation, p_q, e[k].angular_velocity, p_w);
    EXPECT_NEAR(p_q, expected, 0.15);
    EXPECT_NEAR(p_w, expected, 0.15);
  }
}

TEST(Convergence, LeapfrogIsSecondOrder) { expect_order(Scheme::leapfrog, "leapfrog", 2.0); }

TEST(Convergence, SemiImplicitEulerIsFirstOrder) {
  expect_order(Scheme::semi_implicit_euler, "semi-implicit Euler", 1.0);
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
