// Warm starting on a resting box, and a 1:1000 mass-ratio stack.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/rigidbody/solver/world.hpp"

namespace cosim::rigidbody::solver::test {
namespace {

TEST(WarmStart, ReducesIterationsOnRestingBox) {
  const Eigen::Vector3d half(0.2, 0.3, 0.1);
  World world;
  const Plane plane{.body = world.add_fixed()};
  const std::uint32_t box = world.add_box(5.0, half, {0.0, 0.0, half.z()});
  world.material.friction = 0.5;
  const Contacts contacts = [&](std::span<const dynamics::BodyState> s) {
    std::vector<contact::Manifold> out;
    keep(out, box_plane(plane, box, half, s, 0.01));
    return out;
  };
  ImpulseOptions options = ImpulseOptions::sequential_impulses();
  options.tolerance = 1e-8;
  options.max_iterations = 1000;
  for (int i = 0; i < 200; ++i) world.step(1e-3, contacts, impulses(options));

  World cold = world;
  cold.memory.clear();
  const SolveReport warm_report = world.step(1e-3, contacts, impulses(options));
  const SolveReport cold_report = cold.step(1e-3, contacts, impulses(options));
  std::cout << "resting box, 4 contacts: warm start " << warm_report.iterations << " iterations, cold start "
            << cold_report.iterations << '\n';
  EXPECT_TRUE(warm_report.converged);
  EXPECT_TRUE(cold_report.converged);
  EXPECT_LT(warm_report.iterations, cold_report.iterations);
  EXPECT_LT(world.states[box].velocity.norm(), 1e-9);
}

// A 1000 kg sphere on a 1 kg sphere on the ground: Gauss-Seidel propagates the heavy
// load slowly through the light body, so this needs many iterations (or warm starting).
// A light sphere of radius r on a plane under one a thousand times heavier, and their contacts.
struct HeavyOnLight {
  static constexpr double r = 0.5;
  World world;
  Plane plane{.body = world.add_fixed()};
  std::uint32_t light = world.add_sphere(1.0, r, {0.0, 0.0, r});
  std::uint32_t heavy = world.add_sphere(1000.0, r, {0.0, 0.0, 3.0 * r});
  Contacts contacts = [this](std::span<const dynamics::BodyState> s) {
    std::vector<contact::Manifold> out;
    keep(out, sphere_plane(plane, light, r, s, 0.01));
    keep(out, sphere_sphere(light, r, heavy, r, s, 0.01));
    return out;
  };
};

class MassRatioStack : public ::testing::TestWithParam<Preset> {};

// Guards against: the heavy sphere of a 1000:1 stack sinking through the light one.
TEST_P(MassRatioStack, StaysAtRest) {
  constexpr double r = HeavyOnLight::r;
  HeavyOnLight stack;
  auto& [world, plane, light, heavy, contacts] = stack;
  ImpulseOptions options = GetParam().options;
  // Cold Gauss-Seidel converges like (1 - 1/1000)^k on this chain.
  options.max_iterations = 30000;
  options.tolerance = 1e-8;
  SolveReport last;
  for (int i = 0; i < 100; ++i) last = world.step(1e-3, contacts, impulses(options));
  std::cout << GetParam().name << ", 1:1000 stack: " << last.iterations << " iterations in the last step\n";
  EXPECT_TRUE(last.converged);
  EXPECT_GT(world.states[light].position.z(), r - options.slop);
  EXPECT_GT(world.states[heavy].position.z() - world.states[light].position.z(), 2.0 * r - options.slop);
  EXPECT_LT(world.states[heavy].velocity.norm(), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Impulses, MassRatioStack, ::testing::Values(kPgs, kSi),
                         [](const auto& info) { return std::string(info.param.name); });

// The stopping test on the same stack, one cold step from rest: the light body's velocity
// is the small difference of two impulses a thousand times its weight, so a test relative
// to the largest impulse stops with the stack sinking at 1e-3 g dt (after 6,913 sweeps);
// measured in velocity at each contact it stops at tolerance x g dt.
class MassRatioStopping : public ::testing::TestWithParam<Preset> {};

// Guards against: the stopping test saying converged while the light body's contacts are not.
TEST_P(MassRatioStopping, StopsOnlyWhenTheLightBodysContactsHold) {
  constexpr double dt = 1e-3;
  HeavyOnLight stack;
  auto& [world, plane, light, heavy, contacts] = stack;
  ImpulseOptions options = GetParam().options;
  options.max_iterations = 100000;
  ASSERT_EQ(options.tolerance, 1e-6);
  const double kick = kGravity.norm() * dt;  // the velocity the contacts must remove
  // The velocities the solver leaves, before the positions move.
  const Solver solve = [&](const ContactScene& scene, std::span<CachedContact> memory) {
    const SolveReport report = solve_impulses(scene, memory, options);
    for (const std::uint32_t b : {light, heavy})
      EXPECT_LT(scene.states[b].velocity.norm(), 10 * options.tolerance * kick) << (b == light ? "light" : "heavy");
    return report;
  };
  const SolveReport report = world.step(dt, contacts, solve);
  std::cout << GetParam().name << ", 1:1000 stack from rest: " << report.iterations << " iterations\n";
  EXPECT_TRUE(report.converged);
  EXPECT_LE(report.residual, options.tolerance);
  EXPECT_GT(report.iterations, 1000);  // Gauss-Seidel carries the load through slowly
}

INSTANTIATE_TEST_SUITE_P(Impulses, MassRatioStopping, ::testing::Values(kPgs, kSi),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace cosim::rigidbody::solver::test
