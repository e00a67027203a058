#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tracker/csg/events.hpp"

namespace cosim::tracker::csg::testing {

// A particle flying ballistically in the box [lo, hi]^3 with specular box walls, reflected
// specularly by the object's wall boundaries and counted through permeable ones.
struct Flight {
  Eigen::Vector3d x;
  Eigen::Vector3d v;
  State state;
  long events = 0;
  long boundaries = 0;
};

inline void fly(const Object& object, Flight& p, double duration, double lo, double hi) {
  double left = duration;
  while (true) {
    const Event e = next_event(object, p.state, p.x, p.v);
    double wall = Chord::inf;
    int axis = 0;
    for (int i = 0; i < 3; ++i) {
      if (p.v[i] == 0.0) continue;
      const double t = std::max(0.0, ((p.v[i] > 0.0 ? hi : lo) - p.x[i]) / p.v[i]);
      if (t < wall) {
        wall = t;
        axis = i;
      }
    }
    if (std::min(e.dt, wall) > left) {
      p.x += left * p.v;
      return;
    }
    if (wall < e.dt) {
      p.x += wall * p.v;
      p.x[axis] = p.v[axis] > 0.0 ? hi : lo;
      p.v[axis] = -p.v[axis];
      left -= wall;
      continue;
    }
    p.x += e.dt * p.v;
    left -= e.dt;
    ++p.events;
    if (e.boundary) ++p.boundaries;
    if (e.reflects()) p.v -= 2.0 * p.v.dot(e.normal) * e.normal;
    p.state = apply(p.state, e);
    ASSERT_LT(p.events, 100000) << "events do not advance";
  }
}

inline Eigen::Vector3d random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

// Every bit agrees with direct evaluation, except where round-off may decide it: within
// `margin` (in indicator units) of a surface. Returns how many bits were too close to tell.
inline int expect_state_matches(const Object& object, State state, const Eigen::Vector3d& x, double margin) {
  int close = 0;
  for (int i = 0; i < object.primitive_count(); ++i) {
    const double f = object.tree().primitives()[i].indicator(x);
    if (std::abs(f) < margin) {
      ++close;
      continue;
    }
    EXPECT_EQ(test(state, i), f < 0.0) << "primitive " << i << " at " << x.transpose() << ", f = " << f;
  }
  return close;
}

}  // namespace cosim::tracker::csg::testing
