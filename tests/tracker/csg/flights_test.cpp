// The state is only changed by events: 1e5 random flights through a wall made of a floor and
// a few balls, reflecting specularly, end with every bit equal to direct evaluation.
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include "tests/tracker/csg/flight.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

// Guards against: the CSG state drifting from the truth after 1e5 reflections.
TEST(Flights, StateAgreesWithDirectEvaluationAfterManyReflections) {
  const Object o(half_space({0, 0, 0.15}, {0, 0, 1}) | ball({0.3, 0.3, 0.2}, 0.15) | ball({0.42, 0.35, 0.3}, 0.1) |
                 ball({0.7, 0.6, 0.6}, 0.2) | ball({0.5, 0.8, 0.5}, 0.12));
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long boundaries = 0;
  long events = 0;
  int close = 0;
  for (int k = 0; k < 100000; ++k) {
    testing::Flight p{{u(rng), u(rng), u(rng)}, testing::random_direction(rng), 0};
    p.state = o.classify(p.x);
    if (o.inside(p.state)) continue;
    testing::fly(o, p, 1.0, 0.0, 1.0);
    if (::testing::Test::HasFatalFailure()) return;
    boundaries += p.boundaries;
    events += p.events;
    ASSERT_FALSE(o.inside(p.state));
    close += testing::expect_state_matches(o, p.state, p.x, 1e-9);
  }
  std::printf("boundary events %ld of %ld events, %d bits too close to a surface to check\n", boundaries, events,
              close);
  EXPECT_GT(boundaries, 40000);
  EXPECT_LT(close, 5);
}

}  // namespace
}  // namespace cosim::tracker::csg
