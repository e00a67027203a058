// cosim-tracker --check --work: the particles the seeding makes, the mesh's cells and the
// bytes of a field frame, against what the gas and the participant themselves make.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

#include "coupler/scene/scene.hpp"
#include "tests/integration/cosim_process.hpp"
#include "tests/integration/standalone_run.hpp"
#include "tests/integration/work_report_checks.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/tracker_work.hpp"

namespace cosim::tracker::program {
namespace {

namespace fs = std::filesystem;
using testing::unit;

// A unit box of 6 x 5 x 4 cells (120), specular, gas of mass k_B; `options` are appended
// to the tracker's options, `output` to the output section.
std::string box_text(const std::string& options, const std::string& particles = "{per_cell: 5",
                     const std::string& output = "fields_every: 1") {
  return "time: {end: 1.0}\ncoupling: {window: 0.1}\noutput: {" + output +
         "}\n"
         "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\n"
         "participants:\n  tracker:\n    dt: 0.01\n    options:\n"
         "      boundaries: {default: {kind: specular}}\n"
         "      particles: " +
         particles + ", temperature: 1, mass: 1.380649e-23, seed: 7}\n" + options;
}

const std::string kHexahedra = "      mesh: {type: box, cells: [6, 5, 4]}\n";
const std::string kTetrahedra = "      mesh: {type: box, cells: [6, 5, 4], tetrahedra: true}\n";
const std::string kBall =
    "      obstacles:\n        - {name: ball, shape: {ball: {centre: [0.5, 0.5, 0.5], radius: 0.3}}}\n";

scene::Scene scene_of(const std::string& text) { return scene::load_scene_from_string(text, "scene.yaml"); }

participant::WorkReport work_of(const std::string& text) {
  const scene::Scene scene = scene_of(text);
  return tracker_work(scene, read_tracker(scene));
}

// What the gas seeds when it starts.
std::size_t gas_seeded(const std::string& text) {
  TrackerScene setup = read_tracker(scene_of(text));
  return step::Simulation(std::move(static_cast<step::GasSetup&>(setup))).seeded();
}

// The float64 values of the participant's frame at the start, in bytes.
std::uint64_t first_frame_bytes(const std::string& text) {
  TrackerSolver solver;
  solver.initialise(scene_of(text), "tracker", {}, {});
  return testing::frame_bytes(solver.fields());
}

TEST(TrackerWork, ABoxWithoutObstaclesSeedsEveryCell) {
  const std::string text = box_text(kHexahedra);
  const participant::WorkReport w = work_of(text);
  EXPECT_EQ(w.program, "tracker");
  // 600 particles at the mean thermal speed sqrt(8 k T / (pi m)) = sqrt(8 / pi) fly 0.01 of
  // it per step through cells 120^(-1/3) wide: 47 faces crossed.
  EXPECT_EQ(
      w.per_step,
      (participant::WorkUnits{
          {"particles", 600}, {"crossings", 47}, {"cells", 120}, {"primitive_tests", 0}, {"colliding_particles", 0}}));
  EXPECT_EQ(w.held, (participant::WorkUnits{{"particles", 600}, {"cells", 120}}));
  EXPECT_EQ(gas_seeded(text), 600u);
  // count, mean_count, density, velocity (3), temperature, pressure per cell.
  EXPECT_EQ(w.frame_bytes, 120u * 8 * 8);
  EXPECT_EQ(w.frame_bytes, first_frame_bytes(text));
  EXPECT_FALSE(w.grows);
}

// A drift adds to the thermal speed, a longer step to the flight, smaller cells to the faces
// crossed.
TEST(TrackerWork, CrossingsGrowWithTheFlightOverTheCellWidth) {
  const double still = unit(work_of(box_text(kHexahedra)).per_step, "crossings");
  const double drifting =
      unit(work_of(box_text(kHexahedra, "{per_cell: 5, drift: [1.5957691, 0, 0]")).per_step, "crossings");
  EXPECT_NEAR(drifting / still, 2.0, 0.05);
  const double finer =
      unit(work_of(box_text("      mesh: {type: box, cells: [12, 10, 8]}\n", "{per_cell: 5")).per_step, "crossings");
  EXPECT_NEAR(finer / still, 8 * 2, 0.5);  // eight times the particles, each crossing twice as many faces
}

// Each flight is tested against the primitives registered in the cells it passes: one ball
// is one primitive in the cells near its surface (and none elsewhere), a lattice of eight
// smaller balls more primitives in more cells.
TEST(TrackerWork, PrimitiveTestsFollowTheObstaclesPrimitivesPerCell) {
  const auto per_flight = [](const std::string& obstacles) {
    const participant::WorkReport w = work_of(box_text(kHexahedra + obstacles));
    return static_cast<double>(unit(w.per_step, "primitive_tests")) /
           static_cast<double>(unit(w.per_step, "particles") + unit(w.per_step, "crossings"));
  };
  const double ball = per_flight(kBall);
  EXPECT_GT(ball, 0.1);
  EXPECT_LE(ball, 1.0);
  const double lattice = per_flight(
      "      obstacles:\n        - {name: balls, shape: {lattice: {shape: {ball: {centre: [0.25, 0.25, 0.25], "
      "radius: 0.15}}, spacing: [0.5, 0.5, 0.5], count: [2, 2, 2]}}}\n");
  EXPECT_GT(lattice, ball);
  EXPECT_LE(lattice, 8.0);
}

// DSMC collisions cost per particle beside its flight.
TEST(TrackerWork, CollisionsMakeEveryParticleACollidingOne) {
  std::string text =
      box_text(kHexahedra + "      collisions: {species: Ar, model: vss}\n", "{per_cell: 5, weight: 1.0e10");
  text.replace(text.find("1.380649e-23"), 12, "6.63e-26");  // argon's mass
  const participant::WorkReport w = work_of(text);
  EXPECT_EQ(unit(w.per_step, "colliding_particles"), unit(w.per_step, "particles"));
  EXPECT_GT(unit(w.per_step, "particles"), 0u);
}

// Draws inside a wall are dropped: the count is the seeding's own, in the cells the ball
// cuts as well as in those wholly inside or outside it.
TEST(TrackerWork, AWallDropsTheDrawsInsideItAsTheSeedingDoes) {
  for (const std::string& mesh : {kHexahedra, kTetrahedra}) {
    const std::string text = box_text(mesh + kBall);
    const participant::WorkReport w = work_of(text);
    const std::uint64_t cells = unit(w.per_step, "cells");
    EXPECT_EQ(cells, mesh == kHexahedra ? 120u : 720u);
    const std::uint64_t particles = unit(w.per_step, "particles");
    EXPECT_EQ(particles, gas_seeded(text)) << mesh;
    EXPECT_LT(particles, 5 * cells - 5 * cells / 20) << mesh;  // the ball is 11 % of the box
    EXPECT_EQ(w.frame_bytes, cells * 8 * 8);
  }
}

TEST(TrackerWork, ATotalIsSeededExactly) {
  const std::string text = box_text(kHexahedra + kBall, "{total: 1234");
  EXPECT_EQ(unit(work_of(text).held, "particles"), 1234u);
  EXPECT_EQ(gas_seeded(text), 1234u);
}

// Written particles add their point set (x, y, z, velocity, cell, and per obstacle its
// state and inside) to the frames that carry them.
TEST(TrackerWork, ParticleOutputAddsThePointSetToTheFrames) {
  const std::string every_frame = box_text(kHexahedra + kBall + "      particle_output: {}\n");
  const participant::WorkReport w = work_of(every_frame);
  const std::uint64_t particles = unit(w.per_step, "particles");
  EXPECT_EQ(w.frame_bytes, 120u * 8 * 8 + particles * (7 + 3) * 8);
  EXPECT_EQ(w.frame_bytes, first_frame_bytes(every_frame));

  // Half the particles in every other frame: a quarter of the set per frame.
  const participant::WorkReport sampled = work_of(box_text(
      kHexahedra + kBall + "      particle_output: {every: 4, fraction: 0.5}\n", "{per_cell: 5", "fields_every: 2"));
  EXPECT_EQ(sampled.frame_bytes, 120u * 8 * 8 + particles * (7 + 3) * 8 / 4);
}

TEST(TrackerWork, AnInflowGrowsTheGas) {
  const std::string text =
      "time: {end: 1.0}\ncoupling: {window: 0.1}\n"
      "domain: {min: [0, 0, 0], max: [1, 1, 1]}\neffects: [rarefied_gas]\n"
      "participants:\n  tracker:\n    dt: 0.01\n    options:\n" +
      kHexahedra +
      "      boundaries: {default: {kind: specular}, x_min: {kind: open}}\n"
      "      inflow:\n        - {patches: [x_min], number_density: 1.0e3, velocity: [1, 0, 0], temperature: 1}\n"
      "      particles: {per_cell: 2, temperature: 1, mass: 1.380649e-23, seed: 7}\n";
  const participant::WorkReport w = work_of(text);
  EXPECT_TRUE(w.grows);
  EXPECT_EQ(unit(w.per_step, "particles"), 240u);  // the start's
  EXPECT_NE(participant::work_yaml(w).find("grows: true"), std::string::npos);
}

TEST(TrackerWork, TheProgramWritesTheReportWithCheck) {
  const fs::path dir = testing::scratch_dir("tracker_work");
  const std::string text = box_text(kHexahedra + kBall);
  testing::write_file(dir / "scene.yaml", text);
  ASSERT_EQ(testing::run_check("cosim-tracker", dir / "scene.yaml", dir / "work.yaml", dir / "log"), 0)
      << testing::read_file(dir / "log");
  const participant::WorkReport expected = work_of(text);
  EXPECT_EQ(testing::read_file(dir / "work.yaml"), participant::work_yaml(expected));
  const YAML::Node doc = YAML::LoadFile((dir / "work.yaml").string());
  EXPECT_EQ(doc["program"].as<std::string>(), "tracker");
  EXPECT_EQ(doc["per_step"]["particles"].as<std::uint64_t>(), gas_seeded(text));
  EXPECT_EQ(doc["held"]["cells"].as<double>(), 120);
  EXPECT_EQ(doc["frame_bytes"].as<double>(), 120 * 8 * 8);
  EXPECT_FALSE(doc["grows"]);
  EXPECT_NE(
      testing::run_program("cosim-tracker", "--standalone " + (dir / "scene.yaml").string() + " -o " +
                                                (dir / "run.h5").string() + " --work " + (dir / "alone.yaml").string()),
      0);
  EXPECT_FALSE(fs::exists(dir / "alone.yaml"));
}

}  // namespace
}  // namespace cosim::tracker::program
