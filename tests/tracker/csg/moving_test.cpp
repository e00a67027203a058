// Objects moving rigidly between steps: sweep() keeps every particle's state equal to direct
// evaluation after the move, including particles the surface passes close to.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/tracker/csg/flight.hpp"
#include "tracker/csg/shapes.hpp"

namespace cosim::tracker::csg {
namespace {

TEST(Moving, SweptStatesMatchTheNewPose) {
  Object o(box({0, 0, 0}, {0.3, 0.2, 0.1}) - ball({0.1, 0, 0}, 0.15), true);
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::vector<Eigen::Vector3d> xs;
  std::vector<State> states;
  for (int k = 0; k < 20000; ++k) {
    xs.emplace_back(u(rng), u(rng), u(rng));
    states.push_back(o.classify(xs.back()));
  }
  int close = 0;
  for (int step = 1; step <= 20; ++step) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translate(Eigen::Vector3d(0.01 * step, -0.005 * step, 0.002 * step));
    for (std::size_t k = 0; k < xs.size(); ++k) states[k] = sweep(o, states[k], xs[k], pose);
    o.set_pose(pose);
    for (std::size_t k = 0; k < xs.size(); ++k) close += testing::expect_state_matches(o, states[k], xs[k], 1e-9);
  }
  EXPECT_LT(close, 5);
}

TEST(Moving, SmallRotationsKeepStatesAwayFromTheSurface) {
  Object o(capped_cylinder({0, 0, -0.3}, {0, 0, 0.3}, 0.2));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<Eigen::Vector3d> xs;
  std::vector<State> states;
  for (int k = 0; k < 20000; ++k) {
    xs.emplace_back(u(rng), u(rng), u(rng));
    states.push_back(o.classify(xs.back()));
  }
  // Sweeping along the chord of a rotation is first order in the angle: bits may differ only
  // within that error (angle^2 times the lever arm) of a surface.
  const double angle = 1e-4;
  for (int step = 1; step <= 20; ++step) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.rotate(Eigen::AngleAxisd(angle * step, Eigen::Vector3d(1, 1, 0).normalized()));
    for (std::size_t k = 0; k < xs.size(); ++k) states[k] = sweep(o, states[k], xs[k], pose);
    o.set_pose(pose);
  }
  for (std::size_t k = 0; k < xs.size(); ++k) testing::expect_state_matches(o, states[k], xs[k], 1e-7);
}

}  // namespace
}  // namespace cosim::tracker::csg
