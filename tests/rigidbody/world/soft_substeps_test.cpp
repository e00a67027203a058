// The soft step's substeps (Box2D's sub-stepping): a dt's substeps share one narrow phase,
// and the springs may be as stiff as a quarter of the substep rate.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

constexpr double kRadius = 0.05;
constexpr double kG = 9.81;

double rest_height(const solver::SoftOptions& soft) {
  World world({.soft = soft});
  add_ground(world);
  const auto ball = add_sphere(world, kRadius, {0.0, 0.0, kRadius});
  for (int step = 0; step < 500; ++step) world.advance(world.settings().dt);
  return world.states()[ball].position.z();
}

// One resting sphere, solved directly: its spring holds the weight at exactly g / omega^2
// (solver/README.md "Soft step"), with omega capped at a quarter of the substep rate.
// Guards against: the substeps' springs stepped at the dt instead of the substep (the cap
// would halve the frequency and the sag would be 4 times larger), or the weight held once
// per dt instead of once per substep (the sphere would sink).
TEST(SoftSubsteps, ARestingSphereSagsByItsSpringAtTheSubstepsCap) {
  for (const int substeps : {1, 2, 4}) {
    // 1 ms steps: the cap is 250 Hz per substep, so 2000 Hz asks for more than any allows.
    const double sag = kRadius - rest_height({.hertz = 2000.0, .substeps = substeps});
    const double omega = 2 * M_PI * 250.0 * substeps;
    EXPECT_NEAR(sag, kG / (omega * omega), 1e-3 * kG / (omega * omega)) << substeps << " substeps";
  }
}

// A window of 0.7 ms with dt 1 ms: two substeps of 0.35 ms, not one of 0.7 ms (whose cap,
// 357 Hz, would soften the 500 Hz springs and nearly double the sag).
// Guards against: springs that change with the coupling window's length.
TEST(SoftSubsteps, AWindowThatIsNoWholeNumberOfSubstepsKeepsTheSprings) {
  World world;
  add_ground(world);
  const auto ball = add_sphere(world, kRadius, {0.0, 0.0, kRadius});
  for (int window = 0; window < 700; ++window) world.advance(0.7e-3);
  const double omega = 2 * M_PI * solver::SoftOptions{}.hertz;
  EXPECT_NEAR(kRadius - world.states()[ball].position.z(), kG / (omega * omega), 1e-3 * kG / (omega * omega));
}

// A sphere whose gap closes in the second substep of a dt: the first has nothing to do
// there, the second does.
// Guards against: the report's scale taken from the first substep alone (0 here: an
// infinite residual for an ordinary landing).
TEST(SoftSubsteps, ALandingInALaterSubstepReportsAFiniteResidual) {
  World world({.body_forces = {.gravity = false}});
  add_ground(world);
  const auto ball = add_sphere(world, kRadius, {0.0, 0.0, kRadius + 0.75e-3});
  world.states()[ball].velocity = {0.0, 0.0, -1.0};  // 0.5 mm per substep of 0.5 ms
  const StepReport r = world.advance(world.settings().dt);
  EXPECT_EQ(r.contacts, 1u);
  EXPECT_TRUE(std::isfinite(r.residual)) << r.residual;
  EXPECT_GT(world.states()[ball].position.z(), kRadius - 1e-5);  // stopped at the floor
}

// Guards against: a narrow phase per substep (the cost substeps are meant to save), or
// substeps not run at all.
TEST(SoftSubsteps, ADtsSubstepsShareOneNarrowPhase) {
  World world({.soft = {.substeps = 3}});
  add_ground(world);
  add_sphere(world, kRadius, {0.0, 0.0, kRadius});
  const StepReport r = world.advance(world.settings().dt);
  EXPECT_EQ(r.substeps, 3);
  EXPECT_EQ(r.broadphase_updates, 1u);
  const StepReport two = world.advance(2 * world.settings().dt);
  EXPECT_EQ(two.substeps, 6);
  EXPECT_EQ(two.broadphase_updates, 2u);
}

// The lubrication film's force needs each substep's own gaps.
// Guards against: a film force computed on a gap a substep old.
TEST(SoftSubsteps, TheLubricationFilmGetsANarrowPhaseEverySubstep) {
  World world({.soft = {.substeps = 2}, .lubrication = {.viscosity = 1e-3, .range = 1e-3, .roughness = 1e-6}});
  add_ground(world);
  add_sphere(world, kRadius, {0.0, 0.0, kRadius + 5e-4});
  const StepReport r = world.advance(world.settings().dt);
  EXPECT_EQ(r.substeps, 2);
  EXPECT_EQ(r.broadphase_updates, 2u);
}

// Guards against: a substep count below one taken as none.
TEST(SoftSubsteps, FewerThanOneIsRefused) { EXPECT_THROW(World({.soft = {.substeps = 0}}), std::invalid_argument); }

}  // namespace
}  // namespace cosim::rigidbody::world::test
