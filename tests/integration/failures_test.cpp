// What the coupler does when things go wrong: a participant killed or hung, Ctrl-C, a
// resumed run, a bad scene.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <filesystem>
#include <regex>
#include <thread>

#include "tests/integration/cosim_process.hpp"
#include "tests/integration/h5_read.hpp"
#include "coupler/launcher/command.hpp"
#include "coupler/launcher/process.hpp"
#include "tests/integration/oscillator_scene.hpp"

namespace cosim::testing {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

OscillatorScene scene_for_failures() {
  OscillatorScene s;
  s.end = 1.0;
  s.window = 0.01;
  s.dt_mass = s.dt_spring = 0.001;
  s.checkpoint_every = 10;
  return s;
}

// Killed at an odd time with checkpoints every 7 windows, so the resume has to replay
// windows past the checkpoint; in every scheme it must end bit-identical.
class KillAndResume : public ::testing::TestWithParam<std::string> {};

// Guards against: a participant crash losing the run, or the resume not ending bit-identical.
TEST_P(KillAndResume, EndsTheRunAndResumeFinishesIdentically) {
  const auto dir = scratch_dir("kill_resume_" + GetParam());
  auto s = scene_for_failures();
  s.scheme = GetParam();
  s.acceleration = "aitken";
  s.checkpoint_every = 7;
  const auto whole = run_scene_text(dir, s.yaml(), "whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.output;

  s.spring_extra = {"kill_at: 0.555", "kill_marker: " + (dir / "killed").string()};
  const auto file = dir / "killed.h5";
  const auto died = run_scene_text(dir, s.yaml(), "killed");
  EXPECT_EQ(died.exit_code, 1);
  EXPECT_THAT(died.output, HasSubstr("participant 'spring' killed by signal 9"));
  EXPECT_THAT(died.output, HasSubstr("in window 56 (t = 0.56"));
  EXPECT_THAT(died.output, HasSubstr("checkpoint at window 56 with: cosim run --resume " + file.string()));
  // Every committed window is in the file, which opens.
  EXPECT_EQ(read_series(file, "/bodies/m1/time").rows, 57u);  // initial row + windows 0..55
  EXPECT_THAT(read_string_attribute(file, "/run", "status"), HasSubstr("failed"));

  const auto resumed = run_cosim({"run", "--resume", file.string(), "-q"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(read_string_attribute(file, "/run", "status"), "finished");
  for (const std::string series : {"/bodies/m1/time", "/bodies/m1/position", "/bodies/m1/force"})
    EXPECT_EQ(read_series(file, series).values, read_series(dir / "whole.h5", series).values) << series;
}

INSTANTIATE_TEST_SUITE_P(Failures, KillAndResume,
                         ::testing::Values("serial-explicit", "parallel-explicit", "serial-implicit",
                                           "parallel-implicit"),
                         [](const auto& info) {
                           auto name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// Guards against: a participant killed from outside hanging the coupler or going unnamed.
TEST(Failures, ParticipantKilledFromOutsideIsNamedWithItsSignal) {
  const auto dir = scratch_dir("external_kill");
  auto s = scene_for_failures();
  s.end = 100.0;
  s.spring_extra = {"delay: 0.002"};  // the coupler mostly waits for the spring
  write_file(dir / "scene.yaml", s.yaml());
  CosimProcess cosim(run_args(dir));
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  // The mass, which the coupler is usually not waiting for when it dies.
  const pid_t mass = child_pid(cosim.pid(), "cosim-test-oscillator-mass");
  ASSERT_GT(mass, 0);
  kill(mass, SIGKILL);
  const auto r = cosim.wait();
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, HasSubstr("participant 'mass' killed by signal 9"));
  // Where it died: in a window, or in the checkpoint every tenth window.
  EXPECT_THAT(r.output, AnyOf(HasSubstr("in window"), HasSubstr("while checkpointing at t =")));
}

TEST(Failures, ParticipantSendingTheWrongSizeIsNamed) {
  const auto dir = scratch_dir("wrong_size");
  auto s = scene_for_failures();
  s.spring_extra = {"extra_force_rows: 1"};
  const auto r = run_scene_text(dir, s.yaml());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, HasSubstr("participant 'spring' sent Forces with 12 values, expected 6 during start-up"));
  EXPECT_THAT(r.output, HasSubstr("no window was committed, so there is nothing to resume"));
}

// Guards against: a hung participant hanging the whole run.
TEST(Failures, HungParticipantTimesOut) {
  const auto dir = scratch_dir("hang");
  auto s = scene_for_failures();
  s.timeout = 1.0;
  s.spring_extra = {"hang_at: 0.2"};
  const auto r = run_scene_text(dir, s.yaml());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, HasSubstr("participant 'spring' did not answer Result within 1"));
  EXPECT_THAT(r.output, HasSubstr("in window 20"));
  EXPECT_GE(read_series(dir / "scene.h5", "/bodies/m1/time").rows, 20u);
}

bool process_gone(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) return true;
  std::string content((std::istreambuf_iterator<char>(stat)), {});
  const auto close = content.rfind(')');
  return close != std::string::npos && content.size() > close + 2 && content[close + 2] == 'Z';
}

// Guards against: Ctrl-C leaving orphan participants or an unreadable run file.
TEST(Failures, CtrlCStopsEverythingAndLeavesAReadableFile) {
  const auto dir = scratch_dir("ctrl_c");
  auto s = scene_for_failures();
  s.end = 100.0;
  s.spring_extra = {"delay: 0.002"};
  write_file(dir / "scene.yaml", s.yaml());
  CosimProcess cosim(run_args(dir));
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  kill(cosim.pid(), SIGINT);
  const auto r = cosim.wait();
  EXPECT_EQ(r.exit_code, 130) << r.output;
  EXPECT_THAT(r.output, HasSubstr("interrupted"));
  EXPECT_EQ(read_string_attribute(dir / "scene.h5", "/run", "status"), "interrupted");
  EXPECT_GT(read_series(dir / "scene.h5", "/bodies/m1/time").rows, 10u);
  // The participants it started are gone.
  const std::regex started(R"(started (\w+) \(pid (\d+)\))");
  int seen = 0;
  for (std::sregex_iterator it(r.output.begin(), r.output.end(), started), end; it != end; ++it) {
    EXPECT_TRUE(process_gone(std::stoi((*it)[2]))) << (*it)[1];
    ++seen;
  }
  EXPECT_EQ(seen, 2) << r.output;
}

// The failure scene with its first `from` replaced by `to`, run in dir.
Finished run_edited(const fs::path& dir, const std::string& from, const std::string& to) {
  auto yaml = scene_for_failures().yaml();
  yaml.replace(yaml.find(from), from.size(), to);
  return run_scene_text(dir, yaml);
}

TEST(Failures, MissingProgramIsASceneErrorBeforeAnythingStarts) {
  const auto dir = scratch_dir("missing_program");
  const auto r = run_edited(dir, "cosim-test-oscillator-spring", "no-such-program-xyz");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.output, HasSubstr("participants.spring.command = no-such-program-xyz: program not found"));
  EXPECT_THAT(r.output, Not(HasSubstr("started")));
  EXPECT_FALSE(fs::exists(dir / "scene.h5"));
}

// The participant's own words are the reason given, not the exit that follows them.
TEST(Failures, AReportedErrorIsWhatTheCouplerSays) {
  const auto r = run_edited(scratch_dir("reported_error"), "stiffness: ", "stiffness: -");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.output, HasSubstr("cosim: error: participant 'spring' reported an error: "));
  EXPECT_THAT(r.output, HasSubstr("stiffness = -"));
  EXPECT_THAT(r.output, Not(HasSubstr("exited with status")));
}

TEST(Failures, CheckValidatesWithoutRunning) {
  const auto dir = scratch_dir("check");
  write_file(dir / "good.yaml", scene_for_failures().yaml());
  const auto good = run_cosim({"check", (dir / "good.yaml").string()});
  EXPECT_EQ(good.exit_code, 0) << good.output;
  EXPECT_THAT(good.output, HasSubstr("valid; 1 bodies, 100 windows"));
  EXPECT_THAT(good.output, HasSubstr("starts spring (dt 0.001 s): /"));
  EXPECT_FALSE(fs::exists(dir / "run.h5"));

  auto yaml = scene_for_failures().yaml();
  const auto at = yaml.find("radius: 0.1");
  yaml.replace(at, 11, "radius: -0.1");
  const auto line = 1 + std::count(yaml.begin(), yaml.begin() + static_cast<long>(at), '\n');
  write_file(dir / "bad.yaml", yaml);
  const auto bad = run_cosim({"check", (dir / "bad.yaml").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.output, HasSubstr((dir / "bad.yaml").string() + ":" + std::to_string(line) +
                                    ": bodies[0].shape.radius = -0.1: must be > 0"));
}

TEST(Launcher, MpirunWorksAsRootWithoutExportedVariables) {
  // What a user's shell would have: none of the variables Open MPI needs as root.
  for (const char* v : {"OMPI_ALLOW_RUN_AS_ROOT", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "OMPI_MCA_rmaps_base_oversubscribe",
                        "OMPI_MCA_btl"})
    unsetenv(v);
  launcher::Process p("mpi", {"mpirun", "-n", "2", "true"}, launcher::mpi_environment());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!p.poll() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(p.poll().value_or("still running"), "exited with status 0");
}

}  // namespace
}  // namespace cosim::testing
