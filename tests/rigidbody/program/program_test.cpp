// The real programs: `cosim run` starting only cosim-rigidbody, and the standalone mode.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/integration/standalone_run.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

const double radius = 0.1;

const std::string sphere_on_plane =
    "time: {end: 1.0}\n"
    "coupling: {window: 0.01, scheme: serial-explicit}\n"
    "output: {file: unused.h5, every: 1, checkpoint_every: 50}\n"
    "domain: {min: [-1, -1, -1], max: [1, 1, 1]}\n"
    "effects: [gravity, contact]\n"
    "bodies:\n"
    "  - {name: floor, shape: {type: plane, normal: [0, 0, 1]}, fixed: true, position: [0, 0, 0]}\n"
    "  - {name: ball, shape: {type: sphere, radius: 0.1}, material: {density: 2500}, position: [0, 0, 0.3]}\n"
    "participants:\n"
    "  rigidbody: {dt: 1.0e-3}\n";

TEST(RigidProgram, CoupledAndStandaloneRestTheSphereAtItsRadius) {
  const auto dir = scratch_dir("sphere_on_plane");
  const auto run = run_scene_text(dir, sphere_on_plane);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("participants: rigidbody"), std::string::npos) << run.output;

  const auto coupled = read_series(dir / "scene.h5", "/bodies/ball/position");
  ASSERT_EQ(coupled.rows, 101u);  // t = 0 and 100 windows
  EXPECT_NEAR(coupled.at(coupled.rows - 1, 2), radius, 0.01 * radius);

  ASSERT_EQ(run_standalone("cosim-rigidbody", dir / "scene.yaml", dir / "alone.h5"), 0);
  const auto alone = read_series(dir / "alone.h5", "/bodies/ball/position");
  ASSERT_EQ(alone.rows, coupled.rows);
  for (std::size_t i = 0; i < alone.values.size(); ++i) EXPECT_NEAR(alone.values[i], coupled.values[i], 1e-12) << i;
  EXPECT_EQ(read_string_attribute(dir / "alone.h5", "/run", "status"), "finished");
}

TEST(RigidProgram, StandaloneReportsSceneErrorsWithExitCode2) {
  const auto dir = scratch_dir("bad_option");
  auto bad = sphere_on_plane;
  bad.replace(bad.find("{dt: 1.0e-3}"), 12, "{dt: 1.0e-3, options: {solver: newton}}");
  write_file(dir / "bad.yaml", bad);
  EXPECT_EQ(run_standalone("cosim-rigidbody", dir / "bad.yaml", dir / "bad.h5"), 2);
}

// Guards against: the standalone program running a scene frictionless without saying so.
TEST(RigidProgram, StandaloneWarnsAboutFrictionNoEffectUses) {
  const auto dir = scratch_dir("unused_friction");
  auto scene = sphere_on_plane;
  scene.replace(scene.find("{density: 2500}"), 15, "{density: 2500, friction: 0.4}");
  write_file(dir / "scene.yaml", scene);
  ASSERT_EQ(run_standalone("cosim-rigidbody", dir / "scene.yaml", dir / "alone.h5", 1, dir / "log"), 0);
  EXPECT_NE(read_file(dir / "log")
                .find("cosim-rigidbody: warning: " + (dir / "scene.yaml").string() +
                      ":8: bodies[1].material.friction = 0.4: ignored for body 'ball': "
                      "the scene's effects do not include 'friction'"),
            std::string::npos)
      << read_file(dir / "log");
}

}  // namespace
}  // namespace cosim::testing
