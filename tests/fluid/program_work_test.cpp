// cosim-fluid --check --work: the cells, the immersed boundary's markers and the bytes of a
// field frame, against what the solver itself makes of the scene.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

#include "fluid/ibm/immersed_boundary.hpp"
#include "fluid/program/adapter.hpp"
#include "fluid/program/fluid_work.hpp"
#include "tests/fluid/program_scenes.hpp"
#include "tests/integration/cosim_process.hpp"
#include "tests/integration/standalone_run.hpp"
#include "tests/integration/work_report_checks.hpp"

namespace cosim::fluid::program {
namespace {

namespace fs = std::filesystem;
using testing::unit;

// A 1 x 1 x 2 box of 16 x 16 x 32 cells (h = 1/16) holding a fixed sphere of radius 0.2 and
// a fixed box, so that the solver measures no responses when it starts.
std::string box_scene(const std::string& body_options = "") {
  return "time: {end: 0.1}\n"
         "coupling: {window: 0.05, scheme: serial-explicit}\n"
         "domain: {min: [0, 0, 0], max: [1, 1, 2]}\n"
         "effects: [hydrodynamics]\n"
         "bodies:\n"
         "  - {name: ball, shape: {type: sphere, radius: 0.2}, fixed: true, position: [0.5, 0.5, 0.6]}\n"
         "  - {name: brick, shape: {type: box, half_extents: [0.2, 0.15, 0.1]}, fixed: true, "
         "position: [0.5, 0.5, 1.4]}\n"
         "participants:\n"
         "  fluid:\n"
         "    dt: 0.01\n"
         "    options:\n"
         "      density: 1000\n"
         "      viscosity: {model: newtonian, mu: 0.01}\n"
         "      grid: {cells: [16, 16, 32]}\n" +
         body_options;
}

scene::Scene scene_of(const std::string& text) { return scene::load_scene_from_string(text, "s.yaml"); }
FluidSetup setup_of(const std::string& text) { return fluid_setup(scene_of(text)); }

// The markers ImmersedBoundary::add() places for each body of the setup, on a real grid.
std::size_t solver_markers(const FluidSetup& s) {
  const fluid::grid::Grid grid(PETSC_COMM_WORLD, {s.axes[0], s.axes[1], s.axes[2]});
  fluid::ibm::ImmersedBoundary bodies(grid, std::get<fluid::ibm::IbmOptions>(s.body_method));
  std::size_t n = 0;
  for (const fluid::bodies::RigidBody& b : s.bodies) n += bodies.markers(bodies.add(b)).size();
  return n;
}

// The float64 values of the frame the solver hands over at the start, in bytes.
std::uint64_t first_frame_bytes(const std::string& text) {
  FluidSolver solver(true);
  solver.initialise(scene::load_scene_from_string(text, "s.yaml"), "fluid", {}, {});
  return testing::frame_bytes(solver.fields());
}

TEST(FluidWork, CellsMarkersAndFrameBytesAreTheSolversOwn) {
  const FluidSetup s = setup_of(box_scene());
  const participant::WorkReport w = fluid_work(s, scene_of(box_scene()));
  EXPECT_EQ(w.program, "fluid");
  EXPECT_EQ(unit(w.per_step, "cells"), 8192u);
  EXPECT_EQ(unit(w.held, "cells"), 8192u);
  const std::size_t markers = solver_markers(s);
  EXPECT_GT(markers, 100u);  // a sphere 6.4 cells across and a box
  EXPECT_EQ(unit(w.per_step, "markers"), markers);
  EXPECT_EQ(unit(w.held, "markers"), markers);
  // velocity (3), pressure and alpha per cell, and the bodies' surface points (x, y, z).
  const std::uint64_t frame = first_frame_bytes(box_scene());
  EXPECT_EQ(w.frame_bytes, frame);
  EXPECT_GT(frame, 8192u * 5 * 8);
  EXPECT_EQ((frame - 8192u * 5 * 8) % 24, 0u);
  EXPECT_FALSE(w.grows);
}

// The sphere's count alone is the immersed boundary's for it, whatever the marker spacing.
TEST(FluidWork, ASpheresMarkersAreWhatTheImmersedBoundaryCreates) {
  for (const char* spacing : {"1.0", "0.7"}) {
    FluidSetup s = setup_of(box_scene(std::string("      bodies: {method: ibm, marker_spacing: ") + spacing + "}\n"));
    s.bodies.erase(s.bodies.begin() + 1, s.bodies.end());
    EXPECT_EQ(unit(fluid_work(s, scene_of(box_scene())).per_step, "markers"), solver_markers(s)) << spacing;
  }
}

// On a two-dimensional grid the markers lie on the cylinder's section by the layer.
TEST(FluidWork, ATwoDimensionalGridCountsTheSectionsMarkers) {
  const std::string text = testing::oscillating_cylinder_scene();
  const FluidSetup s = setup_of(text);
  const participant::WorkReport w = fluid_work(s, scene_of(text));
  EXPECT_EQ(unit(w.per_step, "cells"), 16u * 8u);
  EXPECT_GT(unit(w.per_step, "markers"), 0u);
  EXPECT_EQ(unit(w.per_step, "markers"), solver_markers(s));
  EXPECT_EQ(w.frame_bytes, first_frame_bytes(text));
}

// The staircase has no markers; its frames carry the surfaces all the same.
TEST(FluidWork, TheStaircaseHasNoMarkers) {
  const std::string text = box_scene("      bodies: {method: staircase}\n");
  const participant::WorkReport w = fluid_work(setup_of(text), scene_of(text));
  EXPECT_EQ(unit(w.per_step, "markers"), 0u);
  EXPECT_EQ(unit(w.held, "markers"), 0u);
  EXPECT_EQ(w.frame_bytes, first_frame_bytes(text));
}

TEST(FluidWork, TheProgramWritesTheReportWithCheck) {
  const fs::path dir = testing::scratch_dir("fluid_work");
  testing::write_file(dir / "scene.yaml", box_scene());
  ASSERT_EQ(testing::run_check("cosim-fluid", dir / "scene.yaml", dir / "work.yaml", dir / "log"), 0)
      << testing::read_file(dir / "log");
  const participant::WorkReport expected = fluid_work(setup_of(box_scene()), scene_of(box_scene()));
  EXPECT_EQ(testing::read_file(dir / "work.yaml"), participant::work_yaml(expected));
  const YAML::Node doc = YAML::LoadFile((dir / "work.yaml").string());
  EXPECT_EQ(doc["program"].as<std::string>(), "fluid");
  EXPECT_EQ(doc["per_step"]["cells"].as<double>(), 8192);
  EXPECT_EQ(doc["held"]["markers"].as<std::uint64_t>(), unit(expected.held, "markers"));
  EXPECT_EQ(doc["frame_bytes"].as<std::uint64_t>(), expected.frame_bytes);
  EXPECT_FALSE(doc["grows"]);

  // --work belongs to --check; a bad scene writes no report.
  EXPECT_NE(
      testing::run_program("cosim-fluid", "--standalone " + (dir / "scene.yaml").string() + " -o " +
                                              (dir / "run.h5").string() + " --work " + (dir / "alone.yaml").string()),
      0);
  EXPECT_FALSE(fs::exists(dir / "run.h5"));
  EXPECT_FALSE(fs::exists(dir / "alone.yaml"));
  fs::remove(dir / "work.yaml");
  testing::write_file(dir / "bad.yaml", box_scene("      grid_cells: 3\n"));
  EXPECT_EQ(testing::run_check("cosim-fluid", dir / "bad.yaml", dir / "work.yaml"), 2);
  EXPECT_FALSE(fs::exists(dir / "work.yaml"));
}

}  // namespace
}  // namespace cosim::fluid::program
