// Torque-free rotation: what must be conserved is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/LU>

#include "tests/rigidbody/dynamics/bodies.hpp"
#include "rigidbody/dynamics/invariants.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

// Moments in the ratio 13 : 10 : 5 (x largest, y intermediate, z smallest).
BodyInertia asymmetric_box() { return box_body({0.1, 0.2, 0.3}); }

BodyState tumbling() {
  BodyState s;
  s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  s.angular_velocity = Eigen::Vector3d(3.0, -5.0, 8.0);
  return s;
}

double relative_change(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return (a - b).norm() / b.norm(); }

TEST(FreeRotation, LeapfrogConservesAngularMomentumToRounding) {
  const BodyInertia body = asymmetric_box();
  const BodyState start = tumbling();
  const BodyState end = run(start, body, Scheme::leapfrog, 1e-3, 20.0);  // 20000 steps
  EXPECT_LT(relative_change(spin_angular_momentum(end, body), spin_angular_momentum(start, body)), 1e-10);
}

// Symplectic and second order: the energy error stays bounded, of the size of the splitting's
// modified-Hamiltonian correction: h^2 times double Poisson brackets of the three
// principal-axis energies with Strang's constants 1/12 and 1/24, each bracket at most
// E |omega|^2, so |dE| / E <~ (h |omega|)^2 / 12 (|omega| ~ 10 here).
TEST(FreeRotation, LeapfrogEnergyErrorIsBoundedByHOmegaSquared) {
  const BodyInertia body = asymmetric_box();
  BodyState state = tumbling();
  const double e0 = kinetic_energy(state, body);
  const double h = 1e-3;
  const double bound = std::pow(h * state.angular_velocity.norm(), 2) / 12.0;
  double worst = 0.0;
  for (int window = 0; window < 200; ++window) {  // 20 s, sampled every 0.1 s
    state = run(state, body, Scheme::leapfrog, h, 0.1);
    worst = std::max(worst, std::abs(kinetic_energy(state, body) - e0) / e0);
  }
  std::printf("leapfrog: max relative energy error %.3g, bound (h |omega|)^2 / 12 = %.3g\n", worst, bound);
  EXPECT_LT(worst, bound);
}

// The implicit gyroscopic step damps tumbling: energy and |L| only decrease, by an amount of
// first order in h (the drift over a time t depends on h t alone), never growing.
double semi_implicit_drift(double dt) {
  const BodyInertia body = asymmetric_box();
  BodyState state = tumbling();
  const Eigen::Vector3d l0 = spin_angular_momentum(state, body);
  double energy = kinetic_energy(state, body);
  for (int window = 0; window < 100; ++window) {  // 10 s
    state = run(state, body, Scheme::semi_implicit_euler, dt, 0.1);
    const double e = kinetic_energy(state, body);
    EXPECT_LE(e, energy * (1.0 + 1e-14));
    energy = e;
  }
  return relative_change(spin_angular_momentum(state, body), l0);
}

TEST(FreeRotation, SemiImplicitEulerDriftsBoundedlyAndGainsNoEnergy) {
  const double coarse = semi_implicit_drift(1e-3);
  const double fine = semi_implicit_drift(5e-4);
  std::printf("semi-implicit Euler: angular momentum drift over 10 s %.3g (dt 1e-3), %.3g (dt 5e-4)\n", coarse, fine);
  EXPECT_LT(coarse, 0.1);
  EXPECT_NEAR(coarse / fine, 2.0, 0.1);
}

// The explicit gyroscopic term would blow this up; the implicit one must not.
// Guards against: the gyroscopic term blowing up at large steps (h |omega| ~ 3).
TEST(FreeRotation, SemiImplicitEulerStaysStableForFastSpinAndLargeSteps) {
  const BodyInertia body = asymmetric_box();
  BodyState start = tumbling();
  start.angular_velocity *= 20.0;  // h |omega| ~ 3 with h = 0.01
  const BodyState end = run(start, body, Scheme::semi_implicit_euler, 0.01, 10.0);
  EXPECT_LE(kinetic_energy(end, body), kinetic_energy(start, body));
  EXPECT_NEAR(end.orientation.norm(), 1.0, 1e-12);
}

TEST(FreeRotation, IsotropicBodyKeepsItsSpin) {
  const BodyInertia ball = box_body({0.2, 0.2, 0.2});  // a cube: isotropic inertia
  BodyState start;
  start.angular_velocity = {1.0, -2.0, 30.0};
  for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
    const BodyState end = run(start, ball, scheme, 1e-3, 5.0);
    // Leapfrog recomputes omega = I(q)^-1 L every step: only rounding, ~1e-15 a step.
    EXPECT_LT((end.angular_velocity - start.angular_velocity).norm(), 1e-11 * start.angular_velocity.norm());
  }
  // Semi-implicit Euler has no gyroscopic change to make, so the spin is kept bit for bit.
  EXPECT_EQ(run(start, ball, Scheme::semi_implicit_euler, 1e-3, 5.0).angular_velocity, start.angular_velocity);
}

// Rotation about the axis of the largest or the smallest moment is stable: a small tilt stays small.
TEST(FreeRotation, SpinAboutAStableAxisStaysPut) {
  const BodyInertia body = asymmetric_box();
  for (const int axis : {0, 2}) {
    for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
      BodyState start;
      start.angular_velocity = 10.0 * Eigen::Vector3d::Unit(axis) + Eigen::Vector3d::Constant(1e-3);
      const BodyState end = run(start, body, scheme, 1e-3, 10.0);
      const Eigen::Vector3d body_omega = end.orientation.conjugate() * end.angular_velocity;
      EXPECT_GT(std::abs(body_omega[axis]) / body_omega.norm(), 1.0 - 1e-5) << "axis " << axis;
      // Exactly about a principal axis there is no gyroscopic term at all.
      BodyState pure;
      pure.angular_velocity = 10.0 * Eigen::Vector3d::Unit(axis);
      EXPECT_LT((run(pure, body, scheme, 1e-3, 10.0).angular_velocity - pure.angular_velocity).norm(), 1e-12);
    }
  }
}

// A body frame that is not principal (a non-diagonal tensor, as meshes give) must move the
// body exactly as the principal description of the same body does.
TEST(FreeRotation, NonPrincipalBodyFrameGivesTheSameMotion) {
  const BodyInertia principal = asymmetric_box();
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.9, Eigen::Vector3d(-1, 2, 0.5).normalized()));
  // Body frame = principal frame turned by tilt.
  const BodyInertia tilted = BodyInertia::of(1 / principal.inverse_mass,
                                             tilt * principal.inertia_body() * tilt.conjugate().toRotationMatrix());
  BodyState start = tumbling();
  BodyState start_tilted = start;
  start_tilted.orientation = start.orientation * tilt.conjugate();
  for (const Scheme scheme : {Scheme::semi_implicit_euler, Scheme::leapfrog}) {
    const BodyState a = run(start, principal, scheme, 1e-3, 2.0);
    const BodyState b = run(start_tilted, tilted, scheme, 1e-3, 2.0);
    EXPECT_LT(angle_between(a.orientation, b.orientation * tilt), 1e-9);
    EXPECT_LT((a.angular_velocity - b.angular_velocity).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
