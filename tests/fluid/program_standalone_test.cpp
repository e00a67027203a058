// The real cosim-fluid: the shipped DFG and Hasimoto scenes standalone against their
// references, exit codes, and `cosim run` starting cosim-fluid for a scene whose only effect
// is hydrodynamics.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <utility>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/fluid/program_scenes.hpp"
#include "tests/integration/standalone_run.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

TEST(FluidProgram, DfgCylinderStandaloneWritesTheDragHistory) {
  const auto dir = scratch_dir("fluid_dfg");
  ASSERT_EQ(run_standalone("cosim-fluid", fs::path(COSIM_CONFIGS_DIR) / "dfg-cylinder.yaml", dir / "dfg.h5"), 0);
  EXPECT_EQ(read_string_attribute(dir / "dfg.h5", "/run", "status"), "finished");
  const Series force = read_series(dir / "dfg.h5", "/bodies/cylinder/force");
  ASSERT_EQ(force.rows, 11u);  // t = 0 and 10 windows
  // C = 2 F / (rho U_mean^2 D T); at 10 cells per diameter the immersed boundary gives
  // C_D = 5.549 (reference 5.5795) and C_L = 0.041 (reference 0.0106: the lift, a 0.2 %
  // part of the force, needs the finer grids of the accuracy study).
  const double scale = 2 / (0.2 * 0.2 * 0.1 * 0.01);
  const std::size_t last = force.rows - 1;
  EXPECT_NEAR(scale * force.at(last, 0), 5.549, 0.01);
  EXPECT_NEAR(scale * force.at(last, 1), 0.040, 0.004);
  EXPECT_NEAR(scale * force.at(last - 1, 0), scale * force.at(last, 0), 1e-3);  // steady
  const Series substeps = read_series(dir / "dfg.h5", "/coupling/participants/fluid/substeps");
  EXPECT_GT(substeps.at(1), 10.0);
}

// The shipped scene on 12^3 cells (a/h = 2.4) instead of 20^3, to t = `end`, with the given
// fluid options added; returns the relative error against Hasimoto's drag.
double hasimoto_error(const std::string& name, const std::string& extra_options, const std::string& end,
                      std::size_t windows) {
  const auto dir = scratch_dir(name);
  std::string scene = read_file(fs::path(COSIM_CONFIGS_DIR) / "hasimoto-sphere.yaml");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"cells: [20, 20, 20]", "cells: [12, 12, 12]"},
                                 {"end: 3.0", "end: " + end},
                                 {"      density: 1.0\n", "      density: 1.0\n" + extra_options}})
    scene.replace(scene.find(from), from.size(), to);
  write_file(dir / "hasimoto.yaml", scene);
  EXPECT_EQ(run_standalone("cosim-fluid", dir / "hasimoto.yaml", dir / "hasimoto.h5"), 0);
  const Series force = read_series(dir / "hasimoto.h5", "/bodies/sphere/force");
  EXPECT_EQ(force.rows, windows + 1);
  if (force.rows < 2) return std::nan("");  // the run failed: reported above
  const std::size_t last = force.rows - 1;
  EXPECT_NEAR(force.at(last - 1, 0), force.at(last, 0), 1e-3 * force.at(last, 0));  // steady
  // U: the mean over the cells of the last field (uniform and periodic: the face mean).
  const Array u = read_array(dir / "hasimoto.h5", fmt::format("/fields/fluid/{:06}/velocity", last));
  double sum = 0;
  for (std::size_t i = 0; i < u.values.size(); i += 3) sum += u.values[i];
  const double mean_u = sum / double(u.values.size() / 3);
  constexpr double a = 0.2, mu = 10, rho_f = 10, pi = std::numbers::pi;
  const double c = 4.0 / 3.0 * pi * a * a * a;
  const double hasimoto = 6 * pi * mu * a * mean_u / (1 - 1.7601 * std::cbrt(c) + c - 1.5593 * c * c);
  return (rho_f - hasimoto) / hasimoto;  // the drive over the whole cell (the scene's header)
}

// The immersed boundary by default: at d/h 4.8, below the two grids its retraction was
// calibrated on (8 and 12), measured +0.55 %. The staircase's surface is grown by its
// calibrated offset (+0.55 %), and with none its sphere is a quarter cell small (-26.3 %),
// as the library test FbmHasimoto finds at 12^3.
TEST(FluidProgram, HasimotoSphereStandaloneMatchesTheLibrarysErrors) {
  const double ibm = hasimoto_error("fluid_hasimoto", "", "1.0", 10);
  const double staircase = hasimoto_error("fluid_hasimoto_staircase", "      bodies: {method: staircase}\n", "0.4", 4);
  const double raw =
      hasimoto_error("fluid_hasimoto_raw", "      bodies: {method: staircase, surface_offset: 0}\n", "0.4", 4);
  std::printf(
      "Hasimoto sphere at d/h 4.8 standalone: immersed boundary %+.2f %%, staircase %+.2f %%, without its "
      "offset %+.2f %%\n",
      100 * ibm, 100 * staircase, 100 * raw);
  EXPECT_NEAR(ibm, 0.0055, 0.01);
  EXPECT_NEAR(staircase, 0.0055, 0.01);
  EXPECT_NEAR(raw, -0.263, 0.01);
}

TEST(FluidProgram, StandaloneReportsSceneErrorsWithExitCode2) {
  const auto dir = scratch_dir("fluid_bad_option");
  write_file(dir / "bad.yaml", oscillating_cylinder_scene("      viscosity_model: carreau\n"));
  EXPECT_EQ(run_standalone("cosim-fluid", dir / "bad.yaml", dir / "bad.h5"), 2);
}

// Only the fluid starts (the cylinder is fixed): the coupled rows equal the standalone ones.
TEST(FluidProgram, CosimRunStartsTheFluidAndMatchesStandalone) {
  const auto dir = scratch_dir("fluid_coupled");
  std::string scene = oscillating_cylinder_scene("      initial_velocity: [0.01, 0, 0]\n");
  scene.replace(scene.find("type: sinusoidal, amplitude: [0.05, 0, 0], frequency: 2"), 55, "type: fixed");
  const auto run = run_scene_text(dir, scene);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("participants: fluid"), std::string::npos) << run.output;

  ASSERT_EQ(run_standalone("cosim-fluid", dir / "scene.yaml", dir / "alone.h5"), 0);
  const Series coupled = read_series(dir / "scene.h5", "/bodies/cyl/force");
  const Series alone = read_series(dir / "alone.h5", "/bodies/cyl/force");
  ASSERT_EQ(coupled.rows, 5u);
  ASSERT_EQ(alone.rows, coupled.rows);
  EXPECT_NE(alone.at(4, 0), 0.0);
  for (std::size_t i = 0; i < alone.values.size(); ++i) EXPECT_EQ(alone.values[i], coupled.values[i]) << i;
}

}  // namespace
}  // namespace cosim::testing
