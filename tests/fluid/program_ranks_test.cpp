// cosim-fluid on two MPI ranks as users start it: `mpirun -n 2 cosim-fluid --standalone`
// and `ranks: 2` under cosim run. Two ranks give one rank's answer to the solvers'
// tolerance, the fields arrive whole, and implicit coupling restores the state every rank
// holds a part of.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "tests/fluid/program_scenes.hpp"
#include "tests/integration/standalone_run.hpp"

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

std::string with_ranks(std::string scene, int ranks) {
  const std::string at = "  fluid:\n    dt: 0.01\n";
  scene.insert(scene.find(at) + at.size(), "    ranks: " + std::to_string(ranks) + "\n");
  return scene;
}

// Largest difference relative to the largest magnitude in `a`.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    diff = std::max(diff, std::abs(a[i] - b[i]));
  }
  return diff / scale;
}

TEST(FluidRanks, TwoRanksStandaloneMatchOneRank) {
  const auto dir = scratch_dir("fluid_ranks_standalone");
  write_file(dir / "channel.yaml", channel_scene());
  ASSERT_EQ(run_standalone("cosim-fluid", dir / "channel.yaml", dir / "one.h5"), 0);
  ASSERT_EQ(run_standalone("cosim-fluid", dir / "channel.yaml", dir / "two.h5", 2), 0);
  EXPECT_EQ(read_string_attribute(dir / "two.h5", "/run", "status"), "finished");
  // The pressure solve stops at a relative residual of 1e-10 (fluid/README.md); the rank
  // partition changes the order of the sums and GAMG's aggregates.
  EXPECT_LT(relative_difference(read_series(dir / "one.h5", "/bodies/cyl/force").values,
                                read_series(dir / "two.h5", "/bodies/cyl/force").values),
            1e-6);
  for (const char* field : {"velocity", "pressure"}) {
    const std::string dataset = std::string("/fields/fluid/000002/") + field;
    const Array one = read_array(dir / "one.h5", dataset), two = read_array(dir / "two.h5", dataset);
    EXPECT_EQ(one.dims, two.dims) << field;
    EXPECT_LT(relative_difference(one.values, two.values), 1e-6) << field;
  }
  EXPECT_EQ(read_array(dir / "one.h5", "/fields/fluid/000002/alpha").values,
            read_array(dir / "two.h5", "/fields/fluid/000002/alpha").values);
}

// The ranks as the scene lays them out: across y, where PETSc would cut the longer x.
TEST(FluidRanks, RanksAcrossTheAxisTheSceneAsksMatchOneRank) {
  const auto dir = scratch_dir("fluid_ranks_across_y");
  write_file(dir / "channel.yaml", channel_scene());
  std::string across = with_ranks(channel_scene(), 2);
  const std::string grid = "cells: [16, 8, 1], stretching: [1, 0, 0]";
  across.replace(across.find(grid), grid.size(), grid + ", ranks: [1, 2, 1]");
  write_file(dir / "across.yaml", across);
  ASSERT_EQ(run_standalone("cosim-fluid", dir / "channel.yaml", dir / "one.h5"), 0);
  ASSERT_EQ(run_standalone("cosim-fluid", dir / "across.yaml", dir / "two.h5", 2), 0);
  EXPECT_LT(relative_difference(read_series(dir / "one.h5", "/bodies/cyl/force").values,
                                read_series(dir / "two.h5", "/bodies/cyl/force").values),
            1e-6);
  const Array one = read_array(dir / "one.h5", "/fields/fluid/000002/velocity"),
              two = read_array(dir / "two.h5", "/fields/fluid/000002/velocity");
  EXPECT_LT(relative_difference(one.values, two.values), 1e-6);
  // The layout needs as many ranks as it names.
  EXPECT_NE(run_standalone("cosim-fluid", dir / "across.yaml", dir / "one_of_two.h5"), 0);
}

// Only the fluid starts (the cylinder is fixed); the coupler asks for the fields every window.
TEST(FluidRanks, CosimRunOnTwoRanksWritesWhatStandaloneWrites) {
  const auto dir = scratch_dir("fluid_ranks_coupled");
  const std::string scene = with_ranks(channel_scene(), 2);
  const auto run = run_scene_text(dir, scene);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ASSERT_EQ(run_standalone("cosim-fluid", dir / "scene.yaml", dir / "alone.h5", 2), 0);
  EXPECT_EQ(read_series(dir / "scene.h5", "/bodies/cyl/force").values,
            read_series(dir / "alone.h5", "/bodies/cyl/force").values);
  for (const char* step : {"000000", "000001", "000002"})
    for (const char* field : {"velocity", "pressure", "alpha"}) {
      const std::string dataset = std::string("/fields/fluid/") + step + "/" + field;
      EXPECT_EQ(read_array(dir / "scene.h5", dataset).values, read_array(dir / "alone.h5", dataset).values) << dataset;
    }
  EXPECT_TRUE(fs::exists(dir / "scene.xmf"));
}

// A cylinder 1.2 times as dense as the fluid sinks (the rigid bodies add the buoyancy); serial-implicit with
// Aitken repeats windows, so the fluid restores its state, gathered from and scattered to
// both ranks. The path matches one rank's.
// Guards against: a restore on two ranks losing part of the state gathered from the other rank.
TEST(FluidRanks, ImplicitCouplingOnTwoRanksMatchesOneRank) {
  std::string scene = oscillating_cylinder_scene();
  const auto replace = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(scene.find(from), std::string::npos) << from;
    scene.replace(scene.find(from), from.size(), to);
  };
  replace("fixed: true,", "material: {density: 1200},");
  replace("      motion: {cyl: {type: sinusoidal, amplitude: [0.05, 0, 0], frequency: 2}}\n", "");
  replace("scheme: serial-explicit}", "scheme: serial-implicit, acceleration: aitken, tolerance: 1.0e-8}");
  replace("effects: [hydrodynamics]", "gravity: [0, -9.81, 0]\neffects: [gravity, buoyancy, hydrodynamics]");
  scene += "      bodies: {tolerance: 1.0e-9}\n  rigidbody: {dt: 0.01, options: {fluid_density: 1000}}\n";

  std::vector<Series> poses;
  for (int ranks : {1, 2}) {
    const auto dir = scratch_dir("fluid_ranks_implicit_" + std::to_string(ranks));
    const auto run = run_scene_text(dir, with_ranks(scene, ranks));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const Series iterations = read_series(dir / "scene.h5", "/coupling/iterations");
    EXPECT_GT(*std::max_element(iterations.values.begin(), iterations.values.end()), 1.0);
    poses.push_back(read_series(dir / "scene.h5", "/bodies/cyl/position"));
  }
  const std::size_t last = poses[0].rows - 1;
  EXPECT_LT(poses[0].at(last, 1), 0.1 - 1e-3);  // it sank
  EXPECT_NEAR(poses[1].at(last, 1), poses[0].at(last, 1), 1e-8);
}

}  // namespace
}  // namespace cosim::testing
