// Issue hard case: a 1:1000 mass ratio in a stack, heavy on light and light on heavy, with
// sequential impulses named (the default soft step holds them with its defaults:
// hard_stack_test.cpp). Warm-started sequential impulses must hold both still with the
// iterations given: no sinking, no drift, no jitter that grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

struct Extremes {
  double penetration = 0.0;  // deepest overlap of any contact
  double drift = 0.0;        // largest distance of a box from its start
  double speed = 0.0;        // largest speed of a box
};

// Two 0.2 m boxes touching on the floor, the lower of density `lower`, the upper `upper`.
Extremes run_stack(double lower, double upper, int steps, int iterations) {
  constexpr double half = 0.1;
  World stack({.solver = SolverKind::sequential_impulses, .iterations = iterations});
  add_ground(stack);
  const double densities[2] = {lower, upper};
  for (int i = 0; i < 2; ++i) {
    BodyDesc box{.shape = geometry::Box(Eigen::Vector3d::Constant(half)), .density = densities[i]};
    box.state.position = {0.0, 0.0, half * (2 * i + 1)};
    stack.add(box);
  }
  const dynamics::BodyState start[2] = {stack.states()[1], stack.states()[2]};
  Extremes e;
  for (int step = 0; step < steps; ++step) {
    stack.advance(stack.settings().dt);
    e.penetration = std::max(e.penetration, stack.graph().contacts().deepest_penetration());
    for (int b = 0; b < 2; ++b) {
      const auto& s = stack.states()[b + 1];
      e.drift = std::max(e.drift, (s.position - start[b].position).norm());
      e.speed = std::max(e.speed, s.velocity.norm());
    }
  }
  return e;
}

void expect_stable(const Extremes& e) {
  constexpr double size = 0.2;
  EXPECT_LT(e.penetration, 0.01 * size);
  EXPECT_LT(e.drift, 0.01 * size);
  EXPECT_LT(e.speed, 0.01);  // m/s: what a 2 mm drift in 0.2 s would need
}

// Gauss-Seidel passes the heavy box's weight through the light one slowly: the default 50
// iterations let the cold-started stack sag and slide apart (drift 3.9 cm, 0.52 m/s);
// 1000 converge in the first steps, and the warm start then holds the stack.
// Guards against: a 1000:1 heavy-on-light stack sagging and sliding apart (slow Gauss-Seidel).
TEST(MassRatio, HeavyBoxOnALightOneStaysPut) { expect_stable(run_stack(10.0, 10000.0, 3000, 1000)); }

// The iterations each step needed, as the step report gives them, on a 1:1000 sphere
// stack (one point per contact, so every step can converge): the cold first step carries
// the heavy sphere's weight through the light one slowly; warm started, the next need few.
// Guards against: the step report losing the iteration count, or a converged step that is not.
TEST(MassRatio, TheStepReportSaysHowManyIterationsEachStepNeeded) {
  constexpr double r = 0.1;
  World stack({.solver = SolverKind::sequential_impulses, .iterations = 100000});
  add_ground(stack);
  for (int i = 0; i < 2; ++i) {
    BodyDesc sphere{.shape = geometry::Sphere(r), .density = i == 0 ? 10.0 : 10000.0};
    sphere.state.position = {0.0, 0.0, r * (2 * i + 1)};
    stack.add(sphere);
  }
  std::vector<int> iterations;
  for (int step = 0; step < 100; ++step) {
    const StepReport report = stack.advance(stack.settings().dt);
    ASSERT_TRUE(report.converged) << "step " << step;
    iterations.push_back(report.solver_iterations);
  }
  std::cout << "1:1000 sphere stack: " << iterations[0] << ", " << iterations[1] << ", " << iterations[2]
            << " iterations in steps 0, 1, 2; at most " << *std::max_element(iterations.begin() + 10, iterations.end())
            << " from step 10 on\n";
  EXPECT_GT(iterations[0], 1000);
  // Within the default 50: warm started, the stack needs only what the cold start cannot give.
  EXPECT_LT(*std::max_element(iterations.begin() + 10, iterations.end()), 50);
  for (int b : {1, 2}) EXPECT_LT(stack.states()[b].velocity.norm(), 1e-6) << b;
}

// Guards against: a 1:1000 light-on-heavy stack jittering or drifting.
TEST(MassRatio, LightBoxOnAHeavyOneStaysPut) { expect_stable(run_stack(10000.0, 10.0, 3000, 0)); }

}  // namespace
}  // namespace cosim::rigidbody::world::test
