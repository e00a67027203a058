// cosim-rigidbody --check --work: the bodies that move per step, every body it holds.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

#include "rigidbody/program/rigid_work.hpp"
#include "tests/integration/cosim_process.hpp"
#include "tests/integration/standalone_run.hpp"

namespace cosim::rigidbody::program {
namespace {

namespace fs = std::filesystem;

// Three bodies, the floor fixed; `options` is the rigidbody section's options.
std::string three_bodies(const std::string& options = "{}") {
  return "time: {end: 0.1}\n"
         "coupling: {window: 0.01, scheme: serial-explicit}\n"
         "domain: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
         "effects: [gravity, contact]\n"
         "bodies:\n"
         "  - {name: floor, shape: {type: plane, normal: [0, 0, 1]}, fixed: true, position: [0, 0, 0]}\n"
         "  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500}, position: [0, 0, 0.3]}\n"
         "  - {name: brick, shape: {type: box, half_extents: [0.1, 0.1, 0.1]}, material: {density: 2500}, "
         "position: [0.5, 0, 0.3]}\n"
         "participants:\n"
         "  rigidbody: {dt: 1.0e-3, options: " +
         options + "}\n";
}

participant::WorkReport work_of(const std::string& text) {
  const scene::Scene scene = scene::load_scene_from_string(text, "s.yaml");
  return rigid_work(scene, program_options(scene));
}

TEST(RigidWork, StepsTheBodiesThatMoveAndHoldsThemAll) {
  const participant::WorkReport w = work_of(three_bodies());
  EXPECT_EQ(w.program, "rigidbody");
  EXPECT_EQ(w.per_step, (participant::WorkUnits{{"bodies", 2}}));
  EXPECT_EQ(w.held, (participant::WorkUnits{{"bodies", 3}}));
  EXPECT_EQ(w.frame_bytes, 0u);
  EXPECT_FALSE(w.grows);
}

// The soft step's substeps are its steps where bodies can touch; the other solvers step by dt.
TEST(RigidWork, TheSoftStepsSubstepsAreItsSteps) {
  EXPECT_DOUBLE_EQ(work_of(three_bodies()).dt, 1e-3 / 2);  // two substeps by default
  EXPECT_DOUBLE_EQ(work_of(three_bodies("{substeps: 4}")).dt, 1e-3 / 4);
  EXPECT_EQ(work_of(three_bodies("{solver: pgs}")).dt, 0.0);
}

// The domain's faces made walls are fixed bodies of the world: held, not stepped.
TEST(RigidWork, WallsAreHeldNotStepped) {
  const participant::WorkReport w = work_of(three_bodies("{walls: [x_min, x_max, y_min]}"));
  EXPECT_EQ(w.per_step, (participant::WorkUnits{{"bodies", 2}}));
  EXPECT_EQ(w.held, (participant::WorkUnits{{"bodies", 6}}));
}

TEST(RigidWork, TheProgramWritesTheReportWithCheck) {
  const fs::path dir = testing::scratch_dir("rigid_work");
  testing::write_file(dir / "scene.yaml", three_bodies());
  ASSERT_EQ(testing::run_check("cosim-rigidbody", dir / "scene.yaml", dir / "work.yaml", dir / "log"), 0)
      << testing::read_file(dir / "log");
  // The checkpoint's state: the time, and each body's position, orientation and velocities.
  EXPECT_THAT(testing::read_file(dir / "work.yaml"),
              ::testing::StartsWith("program: rigidbody\nper_step:\n  bodies: 2\nheld:\n  bodies: 3\nframe_bytes: "
                                    "0\nstate_bytes: " +
                                    std::to_string((1 + 13 * 3) * 8) + "\ndt: "));
  const YAML::Node doc = YAML::LoadFile((dir / "work.yaml").string());
  EXPECT_EQ(doc["per_step"]["bodies"].as<double>(), 2);
  EXPECT_DOUBLE_EQ(doc["dt"].as<double>(), 5e-4);  // the soft step's two substeps

  // Without --work, --check writes nothing; --work needs --check.
  ASSERT_EQ(testing::run_check("cosim-rigidbody", dir / "scene.yaml", ""), 0);
  EXPECT_NE(testing::run_program("cosim-rigidbody", "--standalone " + (dir / "scene.yaml").string() + " -o " +
                                                        (dir / "run.h5").string() + " --work " +
                                                        (dir / "alone.yaml").string()),
            0);
  EXPECT_FALSE(fs::exists(dir / "run.h5"));
  EXPECT_FALSE(fs::exists(dir / "alone.yaml"));
}

}  // namespace
}  // namespace cosim::rigidbody::program
