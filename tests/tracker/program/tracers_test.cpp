// cosim-tracker in tracer mode: tracers carried by a fluid's velocity field read from a run
// file as cosim-fluid writes it. A solid-body rotation (linear, so the trilinear
// interpolation is exact) brings every tracer back after one period; bad sections are
// refused with the key named.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <numbers>

#include "coupler/output/run_file.hpp"
#include "tests/tracker/program/scene_error.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/step/simulation.hpp"

namespace cosim::tracker::program {
namespace {

// Tracers live in the drum between the post and r = 0.44, inside the grid's outermost
// centres (beyond them the field is held constant, no longer a rotation).
// A fluid run file with one velocity frame: rotation about the z axis through (0.5, 0.5)
// with period 1, at the centres of 10 x 10 x 2 cells over the unit box.
std::filesystem::path rotation_run_file(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "fluid.h5";
  auto file = output::RunFile::create(path, {"", "fluid.yaml", "test", "0", 1}, {}, {"fluid"});
  field::FieldFrame frame;
  const auto nodes = [](int n) {
    std::vector<double> x;
    for (int i = 0; i <= n; ++i) x.push_back(static_cast<double>(i) / n);
    return x;
  };
  frame.grid = field::RectilinearGrid{{nodes(10), nodes(10), nodes(2)}};
  field::CellField velocity{"velocity", 3, {}};
  const double omega = 2 * std::numbers::pi;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const double x = (i + 0.5) / 10 - 0.5, y = (j + 0.5) / 10 - 0.5;
        velocity.values.insert(velocity.values.end(), {-omega * y, omega * x, 0.0});
      }
  frame.fields.push_back(velocity);
  file.write_fields("fluid", 0, 0.0, frame);
  file.write_fields("fluid", 7, 0.7, frame);
  return path;
}

scene::Scene tracer_scene(const std::filesystem::path& dir, const std::string& tracers, const std::string& extra = "") {
  const std::string text = R"(
time: {end: 1.0}
coupling: {window: 0.25}
domain: {min: [0, 0, 0], max: [1, 1, 1]}
effects: [tracers, rarefied_gas]
participants:
  tracker:
    dt: 0.005
    options:
      mesh: {type: box, cells: [8, 8, 2]}
      boundaries: {default: {kind: specular}}
      tracers: )" + tracers +
                           R"(
      obstacles:
        - {name: post, shape: {capped_cylinder: {base: [0.5, 0.5, 0], top: [0.5, 0.5, 1], radius: 0.05}}}
        - {name: drum, shape: {complement: {cylinder: {point: [0.5, 0.5, 0], axis: [0, 0, 1], radius: 0.44}}}}
      particles: {total: 300, temperature: 0, mass: 6.63e-26, seed: 4}
)" + extra;
  const std::filesystem::path scene = dir / "scene.yaml";
  std::ofstream(scene) << text;
  return scene::load_scene(scene);
}

std::filesystem::path scratch(const char* name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

std::vector<std::array<double, 3>> positions(const tracking::Swarm& swarm) {
  std::vector<std::array<double, 3>> out;
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const tracking::Particle p = swarm.particle(i);
    out.push_back({p.x.x(), p.x.y(), p.x.z()});
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(TrackerTracers, SolidBodyRotationFromAFluidRunFileReturnsEveryTracer) {
  const auto dir = scratch("tracers_rotation");
  rotation_run_file(dir);
  step::Simulation gas(read_tracker(tracer_scene(dir, "{velocity: {file: fluid.h5}, substeps: 2}")));
  const auto start = positions(gas.swarm());
  ASSERT_EQ(start.size(), 300u);
  for (int k = 0; k < 4; ++k) gas.advance(0.25 * k, 0.25 * (k + 1));
  const auto end = positions(gas.swarm());
  ASSERT_EQ(end.size(), start.size());
  double worst = 0;
  for (std::size_t i = 0; i < start.size(); ++i)
    for (int a = 0; a < 3; ++a) worst = std::max(worst, std::abs(end[i][a] - start[i][a]));
  std::printf("300 tracers after one period of rotation: furthest %.2e m from the start\n", worst);
  EXPECT_LT(worst, 1e-6);  // RK4 with 400 substeps per period: about 1e-9
  EXPECT_EQ(gas.moves().lost, 0);
  EXPECT_GT(gas.moves().faces_crossed, 1000);
  EXPECT_EQ(gas.tallies()[0].hits, 0);  // on circles about the axis nobody reaches a wall
  EXPECT_EQ(gas.tallies()[1].hits, 0);
}

TEST(TrackerTracers, BadSectionsAreRefusedWithTheKeyNamed) {
  const auto dir = scratch("tracers_errors");
  rotation_run_file(dir);
  const auto error = [&](const std::string& tracers, const std::string& extra = "") {
    return testing::scene_error_of([&] { read_tracker(tracer_scene(dir, tracers, extra)); });
  };
  EXPECT_NE(error("{velocity: {file: nothing.h5}}").find("tracers.velocity.file"), std::string::npos);
  EXPECT_NE(error("{velocity: {file: nothing.h5}}").find("nothing.h5"), std::string::npos);
  EXPECT_NE(error("{response_time: -1}").find("tracers.response_time"), std::string::npos);
  EXPECT_NE(
      error("{velocity: {file: fluid.h5}}", "      collisions: {species: Ar, model: vss}\n").find("no collisions"),
      std::string::npos);
}

TEST(TrackerTracers, WithoutAVelocityFieldTheStepSaysWhatIsMissing) {
  const auto dir = scratch("tracers_no_field");
  step::Simulation gas(read_tracker(tracer_scene(dir, "{response_time: 0.1}")));
  try {
    gas.step(0.01);
    FAIL() << "stepped without a velocity field";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("velocity field"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosim::tracker::program
