// Issue case 6: a pyramid of spheres settling with friction.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {
namespace {

// Rigid contacts (SI) never add energy. Soft ones (the default) store some in their springs,
// which the sum of kinetic and potential energy leaves out and the base gives back as it
// rolls apart: at most the weight times the sag of the five contacts under the top,
// 5 g / omega^2 each (soft_step.hpp), above the lowest energy so far.
// Guards against: many simultaneous frictional contacts sinking into each other or gaining energy.
class Pyramid : public ::testing::TestWithParam<SolverKind> {};

TEST_P(Pyramid, SpheresSettleWithoutPenetrationOrEnergyGain) {
  constexpr double r = 0.05, gap = 1e-3 * r;
  World world({.solver = GetParam()});
  const BodyMaterial rough{.friction = 0.6};
  add_ground(world, rough);
  // A pyramid of 100 spheres: layers 8x5, 7x4, 6x3, 5x2, 4x1, each in the hollows of the
  // one below, dropped from a small gap so every contact closes during the run. Spheres
  // have no rolling resistance, so the base rolls apart: energy must only go down.
  for (int layer = 0; layer < 5; ++layer) {
    const double z = r + gap + layer * (std::sqrt(2.0) * r + gap);
    for (int i = 0; i < 8 - layer; ++i)
      for (int j = 0; j < 5 - layer; ++j)
        add_sphere(world, r, {(2 * i + layer) * (r + gap), (2 * j + layer) * (r + gap), z}, rough);
  }
  ASSERT_EQ(world.size(), 101u);
  double weight = 0.0;
  for (const auto& body : world.inertias())
    if (!body.is_fixed()) weight += 9.81 / body.inverse_mass;
  const double omega = 2 * M_PI * world.settings().soft.hertz;
  const double stored = GetParam() == SolverKind::soft ? weight * 5 * 9.81 / (omega * omega) : 1e-12;
  double lowest = total_energy(world);
  double deepest = 0.0;
  for (int step = 0; step < 2000; ++step) {
    world.advance(world.settings().dt);
    const double e = total_energy(world);
    ASSERT_LE(e, lowest + stored) << "step " << step;
    lowest = std::min(lowest, e);
    deepest = std::max(deepest, world.graph().contacts().deepest_penetration());
  }
  EXPECT_LT(deepest, 0.01 * r);
}

INSTANTIATE_TEST_SUITE_P(Settling, Pyramid, ::testing::Values(SolverKind::soft, SolverKind::sequential_impulses),
                         [](const auto& info) {
                           return info.param == SolverKind::soft ? "Soft" : "SequentialImpulses";
                         });

}  // namespace
}  // namespace cosim::rigidbody::world::test
