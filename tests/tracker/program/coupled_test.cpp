// cosim-tracker through `cosim run`, as a user runs it: the tracker alone with a fixed
// sphere in a free-molecular stream (the force in the run file against Bird's drag), and
// with the rigid-body program, which the gas's force then pushes downstream.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <numbers>

#include "cosim_process.hpp"
#include "h5_read.hpp"
#include "tracker/dsmc/free_molecular.hpp"

namespace cosim::tracker {
namespace {

// Argon at 300 K streaming at 2500 m/s (speed ratio 7.1) through an open box of 11^3 cells
// at 7.03e18 m^-3, seeded as the stream and fed on every side, so the flow is steady from
// the start; no collisions (free-molecular); the sphere re-emits diffusely at 300 K.
std::string stream_scene(bool fixed) {
  return std::string(R"(
time: {end: 1.0e-3}
coupling: {window: 2.5e-4, scheme: serial-explicit}
domain: {min: [-2.5, -2.5, -2.5], max: [2.5, 2.5, 2.5]}
effects: [rarefied_gas]
bodies:
  - name: sphere
    shape: {type: sphere, radius: 1}
    position: [0, 0, 0]
    material: {density: 1.0e-4}
)") + (fixed ? "    fixed: true\n" : "") + R"(
participants:
  rigidbody:
    dt: 2.5e-5
  tracker:
    dt: 1.0e-5
    options:
      mesh: {type: box, cells: [11, 11, 11]}
      boundaries: {default: {kind: open}}
      inflow:
        - patches: [x_min, x_max, y_min, y_max, z_min, z_max]
          number_density: 7.03e18
          velocity: [2500, 0, 0]
          temperature: 300
      obstacles:
        - {name: sphere, body: sphere, wall: {kind: diffuse, temperature: 300}}
      particles: {per_cell: 40, temperature: 300, drift: [2500, 0, 0], mass: 6.63e-26, weight: 1.6595e16, seed: 5}
)";
}

double bird_drag() {
  const double mass = 6.63e-26, n = 7.03e18, u = 2500, boltzmann = 1.380649e-23;
  const double s = u / std::sqrt(2 * boltzmann * 300 / mass);
  return dsmc::sphere_drag_coefficient(s, 1.0) * 0.5 * n * mass * u * u * std::numbers::pi;
}

TEST(TrackerCoupled, FixedSphereAloneInAStreamGetsBirdsDragInTheRunFile) {
  const auto dir = testing::scratch_dir("tracker_alone");
  const testing::Finished run = testing::run_scene_text(dir, stream_scene(true));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("participants: tracker"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("rigidbody ("), std::string::npos) << "a fixed body needs no rigid-body program";
  const testing::Series force = testing::read_series(dir / "scene.h5", "/bodies/sphere/force");
  ASSERT_EQ(force.rows, 5u);  // the start and 4 windows
  double drag = 0;
  for (std::size_t k = 1; k < force.rows; ++k) drag += force.at(k, 0) / 4;
  std::printf("fixed sphere in the stream through cosim run: drag %.3f N, Bird %.3f N (%+.2f %%)\n", drag, bird_drag(),
              100 * (drag / bird_drag() - 1));
  // About 3500 hits in all: 2 % statistical error.
  EXPECT_NEAR(drag / bird_drag(), 1.0, 0.08);
  EXPECT_LT(std::abs(force.at(4, 1)) + std::abs(force.at(4, 2)), 0.1 * bird_drag());
}

TEST(TrackerCoupled, FreeSpherePushedByTheGasGainsTheMomentumOfItsForces) {
  const auto dir = testing::scratch_dir("tracker_rigidbody");
  const testing::Finished run = testing::run_scene_text(dir, stream_scene(false));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("rigidbody"), std::string::npos) << run.output;
  const testing::Series force = testing::read_series(dir / "scene.h5", "/bodies/sphere/force");
  const testing::Series velocity = testing::read_series(dir / "scene.h5", "/bodies/sphere/velocity");
  const testing::Series position = testing::read_series(dir / "scene.h5", "/bodies/sphere/position");
  ASSERT_EQ(force.rows, 5u);
  // Serial-explicit: each window's force, held, moves the body in the next one.
  const double mass = 1.0e-4 * 4.0 / 3.0 * std::numbers::pi;
  double momentum = 0;
  for (std::size_t k = 0; k + 1 < force.rows; ++k) momentum += force.at(k, 0) * 2.5e-4;
  std::printf("free sphere: velocity %.4g m/s from the forces %.4g m/s, moved %.3g m\n", velocity.at(4, 0),
              momentum / mass, position.at(4, 0));
  EXPECT_GT(velocity.at(4, 0), 0.5 * bird_drag() * 7.5e-4 / mass);
  EXPECT_NEAR(velocity.at(4, 0), momentum / mass, 1e-6 * momentum / mass + 0.02 * std::abs(momentum / mass));
  EXPECT_GT(position.at(4, 0), 0.0);
}

TEST(TrackerCoupled, CouetteAloneWritesTheShearedProfileAsFields) {
  // configs/tracker-couette.yaml for 0.1 ms through `cosim run`: no bodies, only the
  // tracker; its sampled velocity per cell lands in the coupler's run file.
  std::ifstream in(std::filesystem::path(COSIM_CONFIGS_DIR) / "tracker-couette.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = std::regex_replace(text.str(), std::regex(R"(end: [^\n]+)"), "end: 1.0e-4");
  scene = std::regex_replace(scene, std::regex(R"(file: [^\n]+)"), "file: scene.h5");
  const auto dir = testing::scratch_dir("tracker_couette");
  const testing::Finished run = testing::run_scene_text(dir, scene);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("participants: tracker (provides forces, fields"), std::string::npos) << run.output;
  // 50 cells along y, the last frame (5 windows): u_x from -150 to +150 m/s with slip.
  const testing::Array u = testing::read_array(dir / "scene.h5", "/fields/tracker/000005/velocity");
  ASSERT_EQ(u.values.size(), 150u);
  const auto ux = [&](std::size_t cell) { return u.values[3 * cell]; };
  std::printf("Couette through cosim run: u_x %.1f, %.1f, %.1f m/s at the lower wall, the middle, the upper wall\n",
              ux(0), 0.5 * (ux(24) + ux(25)), ux(49));
  EXPECT_LT(ux(0), -100);
  EXPECT_GT(ux(49), 100);
  EXPECT_GT(ux(0), -150);  // slip: the gas lags the wall
  EXPECT_NEAR(0.5 * (ux(24) + ux(25)), 0.0, 15.0);
}

TEST(TrackerCoupled, BallReleasedInAFreeMolecularStreamFollowsBirdsDrag) {
  // configs/rarefied-crossflow.yaml as it is (2 ms, 20 windows): the force in each window
  // against Bird's drag at the ball's speed relative to the stream in that window, and the
  // ball's speed against m dv/dt = drag(U - v) integrated (serial-explicit: a window's
  // force moves the ball in the next one, so the run lags the ODE by one window).
  std::ifstream in(std::filesystem::path(COSIM_CONFIGS_DIR) / "rarefied-crossflow.yaml");
  std::stringstream text;
  text << in.rdbuf();
  const std::string scene = std::regex_replace(text.str(), std::regex(R"(file: [^\n]+)"), "file: scene.h5");
  const auto dir = testing::scratch_dir("rarefied_crossflow");
  const testing::Finished run = testing::run_scene_text(dir, scene);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const testing::Series force = testing::read_series(dir / "scene.h5", "/bodies/ball/force");
  const testing::Series velocity = testing::read_series(dir / "scene.h5", "/bodies/ball/velocity");
  ASSERT_EQ(force.rows, 21u);

  const double mass = 6.63e-26, n = 7.03e18, stream = 2500, radius = 0.5, boltzmann = 1.380649e-23;
  const double ball = 3.8e-5 * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const double most_probable = std::sqrt(2 * boltzmann * 300 / mass);
  const auto drag = [&](double v) {
    const double u = stream - v;
    return dsmc::sphere_drag_coefficient(u / most_probable, 1.0) * 0.5 * n * mass * u * u * std::numbers::pi * radius *
           radius;
  };
  double measured = 0, expected = 0;
  for (std::size_t k = 1; k < force.rows; ++k) {
    measured += force.at(k, 0);
    expected += drag(0.5 * (velocity.at(k - 1, 0) + velocity.at(k, 0)));
  }
  double v = 0;  // the ODE to t = 1.9 ms, in steps of 1 us
  for (int step = 0; step < 1900; ++step) v += drag(v) / ball * 1e-6;
  std::printf("ball in a free-molecular stream: force %.3f N per window against Bird's %.3f N (%+.2f %%); "
              "speed after 2 ms %.1f m/s, ODE %.1f m/s (%+.2f %%)\n",
              measured / 20, expected / 20, 100 * (measured / expected - 1), velocity.at(20, 0), v,
              100 * (velocity.at(20, 0) / v - 1));
  EXPECT_NEAR(measured / expected, 1.0, 0.04);  // about 3300 hits: 2 %
  EXPECT_NEAR(velocity.at(20, 0) / v, 1.0, 0.04);
  EXPECT_GT(velocity.at(20, 0), 150.0);
}

}  // namespace
}  // namespace cosim::tracker
