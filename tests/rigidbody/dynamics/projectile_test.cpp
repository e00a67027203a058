// A thrown body under gravity against x0 + v0 t + g t^2 / 2.
#include <gtest/gtest.h>

#include "tests/rigidbody/dynamics/bodies.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

struct Projectile {
  BodyInertia body = box_body({0.1, 0.2, 0.3});
  BodyState start;
  BodyForces gravity{.gravity = true};
  double t = 2.0;
  double dt = 0.01;

  Projectile() {
    start.position = {1.0, -2.0, 3.0};
    start.velocity = {4.0, 0.5, 10.0};
  }
  Eigen::Vector3d exact_position() const { return start.position + start.velocity * t + 0.5 * gravity.g * t * t; }
  Eigen::Vector3d exact_velocity() const { return start.velocity + gravity.g * t; }
};

TEST(Projectile, LeapfrogIsExactForAConstantForce) {
  const Projectile p;
  const BodyState end = run(p.start, p.body, Scheme::leapfrog, p.dt, p.t, p.gravity);
  EXPECT_LT((end.position - p.exact_position()).norm(), 1e-12);
  EXPECT_LT((end.velocity - p.exact_velocity()).norm(), 1e-12);
}

// Velocities are exact; each position step uses the end-of-step velocity, which adds
// g h^2 / 2 per step: x_n = exact + g t h / 2, the O(h) error of the scheme, exactly.
TEST(Projectile, SemiImplicitEulerHasTheKnownFirstOrderPositionError) {
  for (const double dt : {0.01, 0.005}) {
    Projectile p;
    p.dt = dt;
    const BodyState end = run(p.start, p.body, Scheme::semi_implicit_euler, p.dt, p.t, p.gravity);
    EXPECT_LT((end.velocity - p.exact_velocity()).norm(), 1e-12);
    const Eigen::Vector3d drift = 0.5 * p.gravity.g * p.t * p.dt;
    EXPECT_LT((end.position - p.exact_position() - drift).norm(), 1e-11) << "dt " << dt;
  }
}

TEST(Projectile, OrientationIsUntouchedWithoutSpin) {
  const Projectile p;
  for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
    const BodyState end = run(p.start, p.body, scheme, p.dt, p.t, p.gravity);
    EXPECT_EQ(end.orientation.coeffs(), p.start.orientation.coeffs());
  }
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
