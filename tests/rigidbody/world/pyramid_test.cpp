// Issue case 6: a pyramid of spheres settling with friction.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes.hpp"

namespace cosim::world::test {
namespace {

// Guards against: many simultaneous frictional contacts sinking into each other or gaining energy.
TEST(Pyramid, SpheresSettleWithoutPenetrationOrEnergyGain) {
  constexpr double r = 0.05, gap = 1e-3 * r;
  World world;
  const BodyMaterial rough{.friction = 0.6};
  add_ground(world, rough);
  // The 100 spheres: layers 8x5, 7x4, 6x3, 5x2, 4x1, each in the hollows of the
  // one below, dropped from a small gap so every contact closes during the run. Spheres
  // have no rolling resistance, so the base rolls apart: energy must only go down.
  for (int layer = 0; layer < 5; ++layer) {
    const double z = r + gap + layer * (std::sqrt(2.0) * r + gap);
    for (int i = 0; i < 8 - layer; ++i)
      for (int j = 0; j < 5 - layer; ++j)
        add_sphere(world, r, {(2 * i + layer) * (r + gap), (2 * j + layer) * (r + gap), z}, rough);
  }
  ASSERT_EQ(world.size(), 101u);
  double energy = total_energy(world);
  double deepest = 0.0;
  for (int step = 0; step < 2000; ++step) {
    world.advance(world.settings().dt);
    const double e = total_energy(world);
    ASSERT_LE(e, energy + 1e-12) << "step " << step;
    energy = e;
    deepest = std::max(deepest, world.graph().contacts().deepest_penetration());
  }
  EXPECT_LT(deepest, 0.01 * r);
}

}  // namespace
}  // namespace cosim::world::test
