// cosim-tracker's participant adapter driven as the coupler drives it: a ball bound to a
// body that the inputs move through gas at rest feels the free-molecular drag, a repeated
// window after restore() gives the same forces to the bit, and bodies without an obstacle
// feel nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "coupler/scene/scene.hpp"
#include "tracker/constants.hpp"
#include "tracker/dsmc/free_molecular.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/step/state_array.hpp"

namespace cosim::tracker::program {
namespace {

// Gas at 1 K with mass 2 k_B (most probable speed 1 m/s), at rest in a periodic box of
// 16 x 10 x 10 cells of 0.5 m, 100 simulators per cell; no collisions (free-molecular). The
// ball (radius 0.8, diffuse at 1 K) is bound to body `ball`; `idle` has no obstacle.
scene::Scene moving_ball_scene() {
  return scene::load_scene_from_string(R"(
time: {end: 1.5}
coupling: {window: 0.25}
domain: {min: [-4, -2.5, -2.5], max: [4, 2.5, 2.5]}
effects: [rarefied_gas]
bodies:
  - {name: idle, shape: {type: sphere, radius: 0.1}, fixed: true, position: [3, 2, 2]}
  - {name: ball, shape: {type: sphere, radius: 0.8}, fixed: true, position: [-2, 0, 0]}
participants:
  tracker:
    dt: 0.05
    options:
      mesh: {type: box, cells: [16, 10, 10], periodic: [true, true, true]}
      obstacles:
        - {name: ball, body: ball, wall: {kind: diffuse, temperature: 1}}
      particles: {per_cell: 100, temperature: 1, mass: 2.761298e-23, seed: 3}
)",
                                       "moving_ball.yaml");
}

// Both bodies' poses with the ball's centre at x along the x axis, moving at u, turned by
// `angle` about (1, 2, 3) (a ball looks the same turned, but its pose does not).
std::vector<participant::PoseRow> poses(double x, double u, double angle = 0) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  return {{{3, 2, 2}, Eigen::Quaterniond::Identity(), zero, zero}, {{x, 0, 0}, q, {u, 0, 0}, zero}};
}

// `turn` rad/s about that axis too (a turning diffuse ball feels a torque and a side force).
participant::Inputs window_inputs(const participant::Window& w, double x0, double u, double turn = 0) {
  participant::Inputs in;
  in.poses_start = poses(x0 + u * w.t0, u, turn * w.t0);
  in.poses_end = poses(x0 + u * w.t1, u, turn * w.t1);
  return in;
}

TEST(TrackerAdapter, BallMovedThroughGasAtRestFeelsTheFreeMolecularDrag) {
  const scene::Scene scene = moving_ball_scene();
  TrackerSolver solver;
  const double x0 = -2.0, u = 2.0;  // speed ratio 2
  solver.initialise(scene, "tracker", poses(x0, u), {});
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  const int windows = 6;
  for (int k = 0; k < windows; ++k) {
    const participant::Window w{static_cast<std::uint64_t>(k), 1, 0.25 * k, 0.25 * (k + 1)};
    const participant::Outputs out = solver.advance(w, window_inputs(w, x0, u));
    ASSERT_EQ(out.forces.size(), 2u);
    EXPECT_EQ(out.substeps, 5);
    EXPECT_EQ(out.forces[0].force, Eigen::Vector3d::Zero()) << "idle body";
    EXPECT_EQ(out.forces[0].torque, Eigen::Vector3d::Zero()) << "idle body";
    force += out.forces[1].force / windows;
    torque += out.forces[1].torque / windows;
  }
  const double mass = 2.761298e-23, density = 100 / 0.125, radius = 0.8;
  const double expected = dsmc::sphere_drag(density, mass, u, 1.0, radius);  // speed ratio u: c_mp = 1
  std::printf(
      "ball at speed ratio 2 through gas at rest: drag %.4g N, Bird %.4g N (%+.2f %%), side %.3g N, torque %.3g N m\n",
      -force.x(), expected, 100 * (-force.x() / expected - 1), force.tail<2>().norm(), torque.norm());
  // About 3e4 hits, so a statistical error near 1 %.
  EXPECT_NEAR(-force.x() / expected, 1.0, 0.04);
  EXPECT_LT(force.tail<2>().norm(), 0.04 * expected);
  EXPECT_LT(torque.norm(), 0.04 * expected * radius);
  EXPECT_EQ(solver.gas().moves().lost, 0);
  for (const tracking::ObstacleTally& t : solver.gas().tallies()) EXPECT_EQ(t.released, 0);
}

// Guards against: an implicit window repeated after a restore giving other forces (state or random stream not
// restored).
TEST(TrackerAdapter, RepeatedWindowAfterRestoreGivesTheSameForcesToTheBit) {
  // The ball moves and turns: the restored pose must be the saved one to the bit.
  const scene::Scene scene = moving_ball_scene();
  TrackerSolver solver;
  solver.initialise(scene, "tracker", poses(-2, 2), {});
  const participant::Window first{0, 1, 0.0, 0.25}, second{1, 1, 0.25, 0.5};
  solver.advance(first, window_inputs(first, -2, 2, 1));
  const std::vector<double> start = solver.state();
  const participant::Outputs once = solver.advance(second, window_inputs(second, -2, 2, 1));
  const std::vector<double> end = solver.state();
  solver.restore(start);
  EXPECT_EQ(solver.state(), start);
  const participant::Window again{1, 2, 0.25, 0.5};
  const participant::Outputs twice = solver.advance(again, window_inputs(again, -2, 2, 1));
  EXPECT_EQ(participant::values_of(twice.forces), participant::values_of(once.forces));
  EXPECT_EQ(solver.state(), end);
  EXPECT_NE(once.forces[1].force.x(), 0.0);

  // A fresh solver resumed from the state continues the same way (a checkpoint).
  TrackerSolver resumed;
  resumed.initialise(scene, "tracker", poses(-2, 2), start);
  EXPECT_EQ(participant::values_of(resumed.advance(second, window_inputs(second, -2, 2, 1)).forces),
            participant::values_of(once.forces));
}

TEST(TrackerAdapter, StateOfAnotherSceneIsRefused) {
  TrackerSolver solver;
  solver.initialise(moving_ball_scene(), "tracker", poses(-2, 0), {});
  std::vector<double> state = solver.state();
  state.pop_back();
  EXPECT_THROW(solver.restore(state), std::runtime_error);
  state.push_back(0.0);
  state[0] = 99;  // layout version
  EXPECT_THROW(solver.restore(state), std::runtime_error);
}

// Guards against: a damaged checkpoint's count or cell (negative, fractional, NaN, out of
// range) cast to an integer instead of refused.
TEST(TrackerState, ANumberThatNoIntegerHoldsIsRefused) {
  const auto read = [](double x) {
    const std::vector<double> values{x};
    step::StateReader reader(values);
    return reader.get<std::int32_t>();
  };
  EXPECT_EQ(read(-7.0), -7);
  EXPECT_EQ(read(2147483647.0), 2147483647);
  for (const double bad : {0.5, 2147483648.0, -2147483649.0, std::nan(""), 1e300})
    EXPECT_THROW(read(bad), std::runtime_error) << bad;
  const std::vector<double> negative{-1.0};
  step::StateReader reader(negative);
  EXPECT_THROW(reader.get<std::size_t>(), std::runtime_error);
}

}  // namespace
}  // namespace cosim::tracker::program
