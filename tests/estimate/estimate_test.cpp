#include "coupler/estimate/estimate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "coupler/estimate/run_record.hpp"
#include "coupler/scene/plan.hpp"

namespace cosim::estimate {
namespace {
namespace fs = std::filesystem;

// 20 windows of 5 ms; the fluid takes 2 steps per window, the rigid bodies 10.
scene::Scene settling(const std::string& scheme) {
  return scene::load_scene_from_string(R"(time: {end: 0.1}
coupling: {window: 0.005, scheme: )" + scheme +
                                           R"(}
output: {file: run.h5, fields_every: 0}
domain: {min: [0, 0, 0], max: [0.1, 0.1, 0.16]}
effects: [gravity, buoyancy, hydrodynamics]
bodies:
  - {name: s, shape: {type: sphere, radius: 0.0075}, material: {density: 1160}, position: [0.05, 0.05, 0.1]}
participants:
  rigidbody: {dt: 5.0e-4, options: {fluid_density: 960}}
  fluid:
    dt: 0.0025
    options: {density: 960, viscosity: {model: newtonian, mu: 0.058}, grid: {cells: [20, 20, 32]}}
)",
                                       "settling.yaml");
}

std::map<std::string, ProgramWork> work() {
  return {{"fluid",
           {.program = "fluid",
            .per_step = {{"cells", 12800}, {"markers", 100}},
            .held = {{"cells", 12800}, {"markers", 100}},
            .frame_bytes = 5e5,
            .state_bytes = 1000}},
          {"rigidbody",
           {.program = "rigidbody", .per_step = {{"bodies", 1}}, .held = {{"bodies", 1}}, .state_bytes = 200}}};
}

CostStore empty_store() { return CostStore::load(fs::temp_directory_path() / "cosim-estimate-none.yaml"); }

const ProgramEstimate& program(const Estimate& e, const std::string& name) {
  for (const auto& p : e.programs)
    if (p.name == name) return p;
  throw std::runtime_error("no " + name);
}

TEST(Estimate, StepsFollowTheWindowsTheIterationsAndEachProgramsStep) {
  const auto s = settling("serial-implicit");
  const auto e = estimate(s, scene::plan_participants(s).start, work(), empty_store(), "build");
  EXPECT_EQ(e.iterations_per_window, kAssumedIterations);
  EXPECT_FALSE(e.iterations_measured);
  EXPECT_EQ(program(e, "fluid").steps, 20 * kAssumedIterations * 2);
  EXPECT_EQ(program(e, "rigidbody").steps, 20 * kAssumedIterations * 10);
}

TEST(Estimate, AProgramThatChoosesASmallerStepTakesMore) {
  const auto s = settling("serial-implicit");
  auto w = work();
  w["fluid"].dt = 0.001;  // the mean step the fluid expects: 5 steps per window, not 2
  const auto e = estimate(s, scene::plan_participants(s).start, w, empty_store(), "build");
  EXPECT_EQ(program(e, "fluid").steps, 20 * kAssumedIterations * 5);
  w["fluid"].dt = 0.01;  // larger than the scene's: the scene's holds
  EXPECT_EQ(program(estimate(s, scene::plan_participants(s).start, w, empty_store(), "build"), "fluid").steps,
            20 * kAssumedIterations * 2);
}

TEST(Estimate, SerialSchemesAddTheProgramsParallelOnesTakeTheSlowest) {
  const auto serial = settling("serial-explicit"), parallel = settling("parallel-explicit");
  const auto a = estimate(serial, scene::plan_participants(serial).start, work(), empty_store(), "build");
  const auto b = estimate(parallel, scene::plan_participants(parallel).start, work(), empty_store(), "build");
  const double fluid = program(a, "fluid").seconds, rigid = program(a, "rigidbody").seconds;
  ASSERT_GT(fluid, rigid);
  EXPECT_NEAR(a.wall_seconds - b.wall_seconds, rigid, 1e-9 * a.wall_seconds);
  EXPECT_GT(b.wall_seconds, fluid);  // and the coupler's share on top
}

TEST(Estimate, TheScenesLastRunGivesItsIterationsAndItsOwnSpeed) {
  const auto s = settling("serial-implicit");
  const auto start = scene::plan_participants(s).start;
  auto store = empty_store();
  const auto before = estimate(s, start, work(), store, "build");
  // The last run took 1.5 iterations per window, and the fluid's steps twice what the model says.
  RunTotals totals;
  totals.windows = 20;
  totals.iterations = 30;
  totals.wall_seconds = 100;
  totals.steps = {{"fluid", 60}, {"rigidbody", 300}};
  const double modelled_step = program(before, "fluid").seconds / program(before, "fluid").steps;
  totals.seconds = {{"fluid", 60 * 2 * modelled_step}, {"rigidbody", 0.01}};
  store.add(run_record(s, work(), totals, "build"));
  const auto after = estimate(s, start, work(), store, "build");
  EXPECT_TRUE(after.iterations_measured);
  EXPECT_DOUBLE_EQ(after.iterations_per_window, 1.5);
  EXPECT_TRUE(after.scene_measured);
  EXPECT_DOUBLE_EQ(program(after, "fluid").steps, 60.0 / 30 * 20 * 1.5);  // its steps per exchange, 2
  EXPECT_NEAR(program(after, "fluid").seconds / program(after, "fluid").steps, 2 * modelled_step, 1e-3 * modelled_step);
  // The same file edited: its former run no longer speaks for it.
  const auto edited = settling("parallel-implicit");
  EXPECT_FALSE(estimate(edited, scene::plan_participants(edited).start, work(), store, "build").scene_measured);
}

TEST(Estimate, TheLineSaysWhatItRestsOn) {
  const auto s = settling("serial-implicit");
  const auto start = scene::plan_participants(s).start;
  auto store = empty_store();
  EXPECT_THAT(estimate_line(estimate(s, start, work(), store, "new")), ::testing::HasSubstr("not measured here yet"));
  RunTotals totals;
  totals.windows = 20;
  totals.iterations = 40;
  totals.wall_seconds = 10;
  store.add(run_record(s, work(), totals, "old"));
  const auto stale = estimate_line(estimate(s, start, work(), store, "new"));
  EXPECT_THAT(stale, ::testing::HasSubstr("1 run of other builds here (`cosim calibrate` measures this one)"));
  EXPECT_THAT(stale, ::testing::HasSubstr("this scene's last run"));
  EXPECT_THAT(stale, ::testing::Not(::testing::HasSubstr("iterations per window assumed")));
  store.add(run_record(s, work(), totals, "new"));
  EXPECT_THAT(estimate_line(estimate(s, start, work(), store, "new")),
              ::testing::HasSubstr("fitted to 1 run of this build here"));
}

TEST(Estimate, TheLineNamesTheLargestTerm) {
  const auto s = settling("serial-implicit");
  const auto e = estimate(s, scene::plan_participants(s).start, work(), empty_store(), "build");
  const std::string line = estimate_line(e);
  EXPECT_THAT(line, ::testing::StartsWith("estimate: "));
  EXPECT_THAT(line, ::testing::HasSubstr("(fluid "));
  EXPECT_THAT(line, ::testing::HasSubstr("13 k cells x 120 steps"));
  EXPECT_THAT(line, ::testing::HasSubstr("memory rigidbody "));
  EXPECT_THAT(line, ::testing::HasSubstr("3 iterations per window assumed"));
}

TEST(Estimate, RunFileHoldsTheRowsTheCheckpointsAndTheFrames) {
  const auto s = settling("serial-implicit");
  const auto start = scene::plan_participants(s).start;
  // 21 rows (the start and every window) in one chunk of 256 rows; a body's series and its
  // structures; the coupling's five series and three per participant; two checkpoints of
  // the pose, force and response, and both programs' states; no fields.
  const double series = (256 * 160 + 22e3) + 256 * 8 * (5 + 3 * 2);
  const double checkpoints = 2 * (8 * (13 + 6 + 78) + 1000 + 200);
  EXPECT_DOUBLE_EQ(run_file_bytes(s, start, work()), 50e3 + static_cast<double>(s.text.size()) + series + checkpoints);
}

TEST(Estimate, FieldFramesAreWrittenAtTheStartEveryNthWindowAndTheLast) {
  auto s = settling("serial-implicit");
  const double without = run_file_bytes(s, scene::plan_participants(s).start, work());
  s.output.fields_every = 6;  // 20 windows: at 0, 6, 12, 18 and 20; the fluid now provides fields
  const auto start = scene::plan_participants(s).start;
  EXPECT_DOUBLE_EQ(run_file_bytes(s, start, work()) - without, 5 * 5e5);
  const auto exchanges = coupler_work(s, start, work(), 60);
  EXPECT_EQ(exchanges.at("exchanges"), 60);
  EXPECT_EQ(exchanges.at("body_rows"), 21);
  EXPECT_EQ(exchanges.at("field_bytes"), 5 * 5e5);
  EXPECT_EQ(exchanges.at("start:fluid"), 1);
  EXPECT_EQ(exchanges.at("start:rigidbody"), 1);
}

// A store that cannot be read costs the estimate, not the check or the run: the line names it.
TEST(Estimate, AnUnreadableStoreGivesALineThatNamesIt) {
  const fs::path path = fs::temp_directory_path() / "cosim-estimate-broken.yaml";
  std::ofstream(path) << "runs: [ {scene: 1, build";
  const char* before = std::getenv("COSIM_COST_FILE");
  const std::string kept = before != nullptr ? before : "";
  setenv("COSIM_COST_FILE", path.c_str(), 1);
  const auto s = settling("serial-explicit");
  const std::string line = estimate_here(s, scene::plan_participants(s).start, work(), "build");
  if (before != nullptr)
    setenv("COSIM_COST_FILE", kept.c_str(), 1);
  else
    unsetenv("COSIM_COST_FILE");
  fs::remove(path);
  EXPECT_THAT(line, ::testing::StartsWith("estimate: none (" + path.string() + ": cannot read"));
}

}  // namespace
}  // namespace cosim::estimate
