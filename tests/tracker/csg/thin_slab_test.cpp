// A slab 1e-14 thick at x = 1, about 45 ulps of its position: particles crossing it, as a zone
// or bouncing off it as a wall, are never lost and their bits agree with direct evaluation
// away from the surfaces.
#include <random>

#include <gtest/gtest.h>

#include "tests/tracker/csg/flight.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

Expression slab() { return half_space({1 + 1e-14, 0, 0}, {1, 0, 0}) & half_space({1, 0, 0}, {-1, 0, 0}); }

void run(bool permeable) {
  const Object o(slab(), permeable);
  std::mt19937_64 rng(permeable ? 7 : 8);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  long boundaries = 0;
  for (int k = 0; k < 20000; ++k) {
    testing::Flight p{{u(rng), u(rng), u(rng)}, testing::random_direction(rng), 0};
    if (std::abs(p.x.x() - 1.0) < 1e-6) continue;
    p.state = o.classify(p.x);
    const bool left_side = p.x.x() < 1.0;
    testing::fly(o, p, 5.0, 0.0, 2.0);
    boundaries += p.boundaries;
    EXPECT_FALSE(o.inside(p.state));
    EXPECT_EQ(testing::expect_state_matches(o, p.state, p.x, 1e-9), 0);
    if (!permeable) {
      EXPECT_EQ(p.x.x() < 1.0, left_side);
    }
  }
  EXPECT_GT(boundaries, 20000);
}

// Guards against: a particle skipping both faces of a slab thinner than its step.
TEST(ThinSlab, ParticlesCrossAPermeableSlab) { run(true); }
// Guards against: a particle tunnelling through a thin wall slab.
TEST(ThinSlab, ParticlesBounceOffAWallSlab) { run(false); }

}  // namespace
}  // namespace cosim::tracker::csg
