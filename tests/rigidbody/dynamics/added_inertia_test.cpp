// A liquid's added inertia and damping on a body (dynamics::with_added): what gravity and
// buoyancy act on, an implicit damping that a large step does not overshoot, and an added
// moment of inertia given in the world frame.
#include <gtest/gtest.h>

#include <cmath>

#include "rigidbody/dynamics/added_inertia.hpp"
#include "rigidbody/dynamics/integrator.hpp"
#include "tests/rigidbody/dynamics/bodies.hpp"

namespace cosim::rigidbody::dynamics::test {
namespace {

// Gravity and buoyancy act on the body's own mass, the added mass only slows it:
// (m - rho_f V) g / (m + m_a), exactly, with semi-implicit Euler.
TEST(AddedInertia, GravityAndBuoyancyActOnTheBodysOwnMass) {
  BodyInertia body = box_body({0.1, 0.1, 0.1});
  body.density = 2000;
  const double mass = 1 / body.inverse_mass, added = 0.7 * mass;
  const BodyForces forces{.gravity = true, .buoyancy = true, .fluid_density = 1000};
  const WithLiquid moving = with_added(body, {.mass = added}, Eigen::Quaterniond::Identity());
  BodyState state;
  advance({&state, 1}, {&moving.inertia, 1}, {}, 0.0, 1.0, {Scheme::semi_implicit_euler, 0.01, forces},
          {&moving.liquid, 1});
  EXPECT_NEAR(state.velocity.z(), -9.81 * (mass - 0.5 * mass) / (mass + added), 1e-12);
}

// A damping c with h c / m = 50 per step: implicit, the velocity decays as (1 + h c / m)^-n
// and never changes sign, where an explicit update would grow 49 times a step.
TEST(AddedInertia, DampingIsImplicit) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  const double mass = 1 / body.inverse_mass, h = 0.01, c = 50 * mass / h;
  const WithLiquid moving = with_added(body, {.damping = c}, Eigen::Quaterniond::Identity());
  BodyState state;
  state.velocity = {1.0, -2.0, 0.5};
  const Eigen::Vector3d v0 = state.velocity;
  advance({&state, 1}, {&moving.inertia, 1}, {}, 0.0, 3 * h, {Scheme::semi_implicit_euler, h, {}}, {&moving.liquid, 1});
  EXPECT_LT((state.velocity - v0 / std::pow(51.0, 3)).norm(), 1e-15);
}

// An added moment of inertia given in the world frame is the body frame's turned back: a
// box turned a quarter about z, with a liquid inertia about world x, gains it about its own y.
TEST(AddedInertia, AddedInertiaIsTurnedIntoTheBodyFrame) {
  const BodyInertia body = box_body({0.1, 0.2, 0.3});
  const Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  AddedInertia added;
  added.inertia(0, 0) = 0.25;
  const BodyInertia moving = with_added(body, added, q).inertia;
  const Eigen::Matrix3d gained = moving.inertia_body() - body.inertia_body();
  EXPECT_NEAR(gained(1, 1), 0.25, 1e-15);
  EXPECT_NEAR(gained.norm(), 0.25, 1e-15);
  EXPECT_LT((moving.inverse_inertia_world(Eigen::Quaterniond::Identity()) * moving.inertia_body() -
             Eigen::Matrix3d::Identity())
                .norm(),
            1e-12);
}

// A fixed body stays fixed: nothing added moves it.
TEST(AddedInertia, AFixedBodyStaysFixed) {
  const WithLiquid moving = with_added(BodyInertia::fixed(), {.mass = 1, .damping = 2}, Eigen::Quaterniond::Identity());
  EXPECT_TRUE(moving.inertia.is_fixed());
}

}  // namespace
}  // namespace cosim::rigidbody::dynamics::test
