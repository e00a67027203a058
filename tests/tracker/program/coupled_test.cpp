// cosim-tracker through `cosim run`, as a user runs it: the tracker alone with a fixed
// sphere in a free-molecular stream (the force in the run file against Bird's drag), and
// with the rigid-body program, which the gas's force then pushes downstream; and tracers
// carried by cosim-fluid's velocity, which the coupler forwards every window.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <numbers>
#include <string>
#include <vector>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tracker/dsmc/free_molecular.hpp"

namespace cosim::tracker::program {
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
)") + (fixed ? "    fixed: true\n" : "") +
         R"(
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

double bird_drag() { return dsmc::sphere_drag(7.03e18, 6.63e-26, 2500, 300, 1); }

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
  // tracker; its sampled velocity per cell lands in the coupler's run file, and its
  // particles at the start and the end with it.
  std::ifstream in(std::filesystem::path(COSIM_CONFIGS_DIR) / "tracker-couette.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string scene = std::regex_replace(text.str(), std::regex(R"(end: [^\n]+)"), "end: 1.0e-4");
  scene = std::regex_replace(scene, std::regex(R"(file: [^\n]+)"), "file: scene.h5");
  scene += "      particle_output: {every: 5}\n";
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

  // Every particle, in the cell the cell fields count it in.
  for (const std::string step : {"000000", "000005"}) {
    const std::string at = "/fields/tracker/" + step + "/";
    const testing::Array count = testing::read_array(dir / "scene.h5", at + "count");
    const testing::Array points = testing::read_array(dir / "scene.h5", at + "points/particles");
    const testing::Array cell = testing::read_array(dir / "scene.h5", at + "point_attributes/particles/cell");
    const testing::Array v = testing::read_array(dir / "scene.h5", at + "point_attributes/particles/velocity");
    ASSERT_EQ(points.dims, (std::vector<std::size_t>{5000, 3})) << step;  // 100 per cell, nothing leaves
    EXPECT_EQ(v.dims, points.dims);
    std::vector<double> per_cell(count.values.size(), 0.0);
    for (const double c : cell.values) per_cell.at(static_cast<std::size_t>(c)) += 1;
    EXPECT_EQ(per_cell, count.values) << step;
  }
  std::ifstream sidecar(dir / "scene.xmf");
  const std::string xmf{std::istreambuf_iterator<char>(sidecar), {}};
  EXPECT_NE(xmf.find("<Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">"), std::string::npos);
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

  const double radius = 0.5, ball = 3.8e-5 * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  const auto drag = [&](double v) { return dsmc::sphere_drag(7.03e18, 6.63e-26, 2500 - v, 300, radius); };
  double measured = 0, expected = 0;
  for (std::size_t k = 1; k < force.rows; ++k) {
    measured += force.at(k, 0);
    expected += drag(0.5 * (velocity.at(k - 1, 0) + velocity.at(k, 0)));
  }
  double v = 0;  // the ODE to t = 1.9 ms, in steps of 1 us
  for (int step = 0; step < 1900; ++step) v += drag(v) / ball * 1e-6;
  std::printf(
      "ball in a free-molecular stream: force %.3f N per window against Bird's %.3f N (%+.2f %%); "
      "speed after 2 ms %.1f m/s, ODE %.1f m/s (%+.2f %%)\n",
      measured / 20, expected / 20, 100 * (measured / expected - 1), velocity.at(20, 0), v,
      100 * (velocity.at(20, 0) / v - 1));
  EXPECT_NEAR(measured / expected, 1.0, 0.04);  // about 3300 hits: 2 %
  EXPECT_NEAR(velocity.at(20, 0) / v, 1.0, 0.04);
  EXPECT_GT(velocity.at(20, 0), 150.0);
}

// A uniform stream of 0.1 m/s along a 0.4 m channel (inflow and outflow along x, periodic
// across), cosim-fluid on 16 x 8 x 1 cells; with `tracers`, 400 massless tracers seeded
// uniformly in the tracker's 8 x 4 x 1 box cells, leaving through x_max. 1 s: the stream
// carries every tracer 0.1 m downstream, a quarter of the channel. A free cylinder in the
// stream closes a loop with the rigid-body program: serial-implicit iterates the windows.
std::string channel_scene(bool tracers, bool free_cylinder = false) {
  const std::string effects = tracers && free_cylinder ? "tracers, hydrodynamics"
                              : tracers                ? "tracers"
                                                       : "hydrodynamics";
  std::string text = R"(
time: {end: 1.0}
coupling: {window: 0.05, scheme: )" +
                     std::string(free_cylinder ? "serial-implicit" : "serial-explicit") + R"(}
output: {fields_every: 20}
domain: {min: [0, 0, 0], max: [0.4, 0.2, 0.01]}
effects: [)" + effects +
                     R"(]
participants:
  fluid:
    dt: 0.01
    options:
      density: 1000
      viscosity: {model: newtonian, mu: 0.01}
      grid: {cells: [16, 8, 1]}
      boundaries:
        x_min: {type: inflow, velocity: [0.1, 0, 0]}
        x_max: {type: outflow}
        y_min: {type: periodic}
        y_max: {type: periodic}
        z_min: {type: periodic}
        z_max: {type: periodic}
      initial_velocity: [0.1, 0, 0]
)";
  if (tracers)
    text += R"(  tracker:
    dt: 0.01
    options:
      mesh: {type: box, cells: [8, 4, 1]}
      boundaries: {default: {kind: specular}, x_max: {kind: open}}
      tracers: {response_time: 0}
      particles: {total: 400, temperature: 0, mass: 1.0e-12, seed: 3}
)";
  if (free_cylinder)
    text += R"(  rigidbody:
    dt: 0.01
bodies:
  - {name: cyl, shape: {type: cylinder, radius: 0.03, height: 0.01}, position: [0.2, 0.1, 0.005], material: {density: 1000}}
)";
  return text;
}

// The channel's velocity frame on the wire: the grid's 17 + 9 + 2 nodes and 128 x 3
// values, and the names x, y, z and velocity.
constexpr double kVelocityBytes = 8.0 * (17 + 9 + 2 + 128 * 3) + 11;

// The x of each cell's centre in the run file's rectilinear grid (the tracker's box of
// hexahedra), cells x fastest.
std::vector<double> cell_centres_x(const std::filesystem::path& file, const std::string& grid) {
  const std::vector<double> x = testing::read_array(file, grid + "/x").values;
  const std::size_t rows = (testing::read_array(file, grid + "/y").values.size() - 1) *
                           (testing::read_array(file, grid + "/z").values.size() - 1);
  std::vector<double> out;
  for (std::size_t row = 0; row < rows; ++row)
    for (std::size_t i = 0; i + 1 < x.size(); ++i) out.push_back(0.5 * (x[i] + x[i + 1]));
  return out;
}

TEST(TrackerCoupled, TracersRideTheFluidsVelocityForwardedByTheCoupler) {
  const auto dir = testing::scratch_dir("tracker_tracers");
  const testing::Finished run = testing::run_scene_text(dir, channel_scene(true));
  ASSERT_EQ(run.exit_code, 0) << run.output;  // the tracker fails the run if a tracer is lost
  EXPECT_NE(run.output.find("tracker (provides fields, needs fields)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("forwarded"), std::string::npos) << run.output;
  const auto file = dir / "scene.h5";

  // Only the velocity crosses, not the fluid's pressure and alpha.
  const testing::Series forwarded = testing::read_series(file, "/coupling/participants/tracker/field_bytes");
  const testing::Series to_fluid = testing::read_series(file, "/coupling/participants/fluid/field_bytes");
  ASSERT_EQ(forwarded.rows, 21u);  // the start and 20 windows
  EXPECT_EQ(forwarded.at(0), 0.0);
  for (std::size_t k = 1; k < forwarded.rows; ++k) {
    EXPECT_EQ(forwarded.at(k), kVelocityBytes) << "window " << k;
    EXPECT_EQ(to_fluid.at(k), 0.0);
  }

  const std::vector<double> x = cell_centres_x(file, "/fields/tracker/grid");
  const std::vector<double> start = testing::read_array(file, "/fields/tracker/000000/count").values;
  const std::vector<double> end = testing::read_array(file, "/fields/tracker/000020/count").values;
  const std::vector<double> velocity = testing::read_array(file, "/fields/tracker/000020/velocity").values;
  ASSERT_EQ(start.size(), x.size());
  double seeded = 0, remaining = 0, x_start = 0, x_end = 0, upstream = 0, u = 0;
  for (std::size_t c = 0; c < x.size(); ++c) {
    seeded += start[c];
    remaining += end[c];
    x_start += start[c] * x[c];
    x_end += end[c] * x[c];
    if (x[c] < 0.1) upstream += end[c];
    if (end[c] > 0) u += end[c] * velocity[3 * c];  // a cell never sampled has no velocity
  }
  x_start /= seeded;
  x_end /= remaining;
  u /= remaining;
  std::printf("tracers in a 0.1 m/s stream: %g seeded, %g remain after 1 s, mean x %.3f -> %.3f m, mean u %.4f m/s\n",
              seeded, remaining, x_start, x_end, u);
  EXPECT_EQ(seeded, 400);
  // Those seeded in the last quarter have left: 300 expected, binomial spread 9.
  EXPECT_NEAR(remaining, 300, 30);
  EXPECT_EQ(upstream, 0) << "the first 0.1 m is behind every tracer";
  EXPECT_NEAR(x_end - x_start, 0.05, 0.02);  // uniform in [0.1, 0.4] from uniform in [0, 0.4]
  EXPECT_NEAR(u, 0.1, 1e-3);
}

// Every iteration of an implicit window takes the fluid's fields of the window's start again.
TEST(TrackerCoupled, AnImplicitWindowForwardsTheFieldsInEveryIteration) {
  const auto dir = testing::scratch_dir("tracker_tracers_implicit");
  const testing::Finished run = testing::run_scene_text(dir, channel_scene(true, true));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const testing::Series iterations = testing::read_series(dir / "scene.h5", "/coupling/iterations");
  const testing::Series forwarded =
      testing::read_series(dir / "scene.h5", "/coupling/participants/tracker/field_bytes");
  ASSERT_EQ(forwarded.rows, 21u);
  double most = 0;
  for (std::size_t k = 1; k < forwarded.rows; ++k) {
    EXPECT_EQ(forwarded.at(k), iterations.at(k) * kVelocityBytes) << "window " << k;
    most = std::max(most, iterations.at(k));
  }
  EXPECT_GT(most, 1) << "no window was repeated";
}

TEST(TrackerCoupled, WithoutTracersNoFieldsAreForwarded) {
  const auto dir = testing::scratch_dir("fluid_no_tracers");
  const testing::Finished run = testing::run_scene_text(dir, channel_scene(false));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.find("forwarded"), std::string::npos) << run.output;
  const testing::Series forwarded = testing::read_series(dir / "scene.h5", "/coupling/participants/fluid/field_bytes");
  ASSERT_EQ(forwarded.rows, 21u);
  for (std::size_t k = 0; k < forwarded.rows; ++k) EXPECT_EQ(forwarded.at(k), 0.0) << "window " << k;
}

}  // namespace
}  // namespace cosim::tracker::program
