// Event rules on one ball and one half-space: tangent and grazing lines, particles exactly on
// a surface, and no cycling of zero-time events.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tracker/csg/events.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

// Follows x + v t for `duration` and returns the events that happened.
std::vector<Event> follow(const Object& o, State& state, Eigen::Vector3d x, const Eigen::Vector3d& v, double duration) {
  std::vector<Event> events;
  double left = duration;
  while (true) {
    const Event e = next_event(o, state, x, v);
    if (!(e.dt <= left) || events.size() > 10) return events;
    x += e.dt * v;
    left -= e.dt;
    state = apply(state, e);
    events.push_back(e);
  }
}

// Guards against: an exactly tangent flight producing a spurious crossing.
TEST(Events, ExactTangentChangesNothing) {
  // |(-5 + t, 1, 0)| >= 1 with equality at t = 5; the discriminant is exactly 0.
  const Object o(ball({0, 0, 0}, 1.0), true);
  State s = o.classify({-5, 1, 0});
  EXPECT_TRUE(follow(o, s, {-5, 1, 0}, {1, 0, 0}, 10.0).empty());
  EXPECT_EQ(s, 0u);
}

// Guards against: a grazing hit giving an entry without its exit (state left inside).
TEST(Events, GrazingGivesAConsistentPair) {
  const Object o(ball({0, 0, 0}, 1.0), true);
  const double y = 1.0 - 1e-12;
  State s = o.classify({-5, y, 0});
  const auto events = follow(o, s, {-5, y, 0}, {1, 0, 0}, 10.0);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_TRUE(events[0].enters && events[0].boundary && events[0].into_object);
  EXPECT_TRUE(!events[1].enters && events[1].boundary && !events[1].into_object);
  const double half = std::sqrt(1.0 - y * y);
  EXPECT_NEAR(events[0].dt, 5.0 - half, 1e-12);
  EXPECT_NEAR(events[0].dt + events[1].dt, 5.0 + half, 1e-12);
  EXPECT_EQ(s, 0u);
}

// Guards against: a particle exactly on the surface getting no event, or one with the wrong sign.
TEST(Events, ParticleOnTheSurfaceGetsAConsistentEvent) {
  const Object o(ball({0, 0, 0}, 1.0), true);
  const Eigen::Vector3d x(1, 0, 0);
  ASSERT_EQ(o.classify(x), 0u);  // the surface counts as outside
  {
    SCOPED_TRACE("moving in");
    State s = 0;
    const auto events = follow(o, s, x, {-1, 0, 0}, 1.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].dt, 0.0);
    EXPECT_TRUE(events[0].enters);
    EXPECT_EQ(s, 1u);
    EXPECT_NEAR(events[0].normal.x(), 1.0, 1e-15);
  }
  {
    SCOPED_TRACE("moving out, state outside");
    State s = 0;
    EXPECT_TRUE(follow(o, s, x, {1, 0, 0}, 1.0).empty());
    EXPECT_EQ(s, 0u);
  }
  {
    SCOPED_TRACE("moving out, state inside");
    State s = 1;
    const auto events = follow(o, s, x, {1, 0, 0}, 1.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].dt, 0.0);
    EXPECT_EQ(s, 0u);
  }
  {
    SCOPED_TRACE("moving in, state inside: leaves on the far side");
    State s = 1;
    const auto events = follow(o, s, x, {-1, 0, 0}, 3.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_DOUBLE_EQ(events[0].dt, 2.0);
    EXPECT_EQ(s, 0u);
  }
}

// Guards against: a particle below the surface by round-off getting a negative time of flight.
TEST(Events, SlightlyOnTheWrongSideIsClampedNeverNegative) {
  const Object o(half_space({0, 0, 0}, {0, 0, 1}));
  // Above the plane by round-off, state inside, moving up: leave now.
  Event e = next_event(o, 1, {0, 0, 1e-17}, {0, 0, 1});
  EXPECT_EQ(e.dt, 0.0);
  EXPECT_FALSE(e.enters);
  // Below by round-off, state outside, moving down: enter now (a wall: reflect).
  e = next_event(o, 0, {0, 0, -1e-17}, {0, 0, -1});
  EXPECT_EQ(e.dt, 0.0);
  EXPECT_TRUE(e.reflects());
  EXPECT_NEAR(e.normal.z(), 1.0, 1e-15);
  // Below by round-off, state outside, moving up: already leaving, no event.
  EXPECT_FALSE(next_event(o, 0, {0, 0, -1e-17}, {0, 0, 1}).happens());
}

// Guards against: a particle that just left a ball re-entering it through round-off.
TEST(Events, JustLeftABallDoesNotReenter) {
  const Object o(ball({0.3, 0.1, 0}, 0.7), true);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 10000; ++k) {
    const Eigen::Vector3d v(u(rng), u(rng), u(rng));
    State s = 1;
    Eigen::Vector3d x(0.3, 0.1, 0);
    const auto events = follow(o, s, x, v, 100.0);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(s, 0u);
  }
}

TEST(Events, ComplementedLiteralHasTheInwardNormal) {
  // A box with a spherical cavity: leaving the ball is entering the object.
  const Object o(box({0, 0, 0}, {2, 2, 2}) - ball({0, 0, 0}, 1.0));
  const Event e = next_event(o, o.classify({0, 0, 0}), {0, 0, 0}, {0, 0, 2});
  EXPECT_DOUBLE_EQ(e.dt, 0.5);
  EXPECT_TRUE(e.reflects() && e.into_object && !e.enters);
  EXPECT_NEAR(e.normal.z(), -1.0, 1e-15);
}

}  // namespace
}  // namespace cosim::tracker::csg
