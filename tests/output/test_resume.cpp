// Checkpoints and --resume: the file is cut back to the checkpoint and continues from it.
#include <gtest/gtest.h>

#include <fstream>

#include "h5_read.hpp"
#include "output/run_file.hpp"
#include "sample_run.hpp"
#include "temp_dir.hpp"

namespace cosim::output::test {
namespace {

using ResumeTest = TempDirTest;

const std::vector<std::string> kBodies{"ball"};
const std::vector<std::string> kParticipants{"fluid", "rigid", "tracer"};
constexpr double kDt = 0.1;  // not exact in binary: times carry rounding, as in a real run

Checkpoint checkpoint_after(std::uint64_t window) {
  const WindowRecord w = sample_window(window, kDt, kBodies.size(), kParticipants);
  Checkpoint c;
  c.next_window = window + 1;
  c.time = w.time;
  c.poses = w.poses;
  c.forces = w.forces;
  c.states = {{"fluid", {1.0, 2.0, 3.0}}, {"rigid", {}}};  // tracer has none
  return c;
}

// Writes windows 0..4 with a checkpoint after window 2, as a run killed after window 4.
void write_interrupted_run(const std::filesystem::path& path) {
  RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 2},
                                kBodies, kParticipants);
  for (std::uint64_t k = 0; k < 5; ++k) {
    run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    if (k == 1 || k == 2) run.write_checkpoint(checkpoint_after(k));
  }
  run.set_status("interrupted", 3.0);
}

TEST_F(ResumeTest, CutsSeriesToTheCheckpointAndContinues) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  {
    RunFile run = RunFile::resume(path);
    EXPECT_EQ(run.info().scene_text, "scene: 1\n");
    EXPECT_EQ(run.info().protocol_version, 2);
    const Checkpoint& c = run.checkpoint();
    const Checkpoint expected = checkpoint_after(2);
    EXPECT_EQ(c.next_window, 3u);
    EXPECT_EQ(c.time, expected.time);
    EXPECT_EQ(c.poses, expected.poses);
    EXPECT_EQ(c.forces, expected.forces);
    EXPECT_EQ(c.states, expected.states);
    for (std::uint64_t k = c.next_window; k < 7; ++k) {
      run.append(sample_window(k, kDt, kBodies.size(), kParticipants));
    }
  }
  ReadFile f(path);
  EXPECT_EQ(f.string_attribute("/run", "status"), "running");
  EXPECT_EQ(f.double_attribute("/run", "wall_seconds"), 3.0);
  EXPECT_FALSE(f.has("/checkpoint_new"));
  std::vector<double> times;
  for (std::uint64_t k = 0; k < 7; ++k) times.push_back(sample_window(k, kDt, 1, {}).time);
  EXPECT_EQ(f.doubles("/coupling/time"), times);
  EXPECT_EQ(f.doubles("/bodies/ball/time"), times);
  EXPECT_EQ(f.values<std::uint64_t>("/coupling/window", H5T_NATIVE_UINT64),
            (std::vector<std::uint64_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(f.dims("/bodies/ball/orientation"), (std::vector<hsize_t>{7, 4}));
  EXPECT_EQ(f.doubles("/bodies/ball/torque")[3 * 3 + 2], slot(3, 0, 18));
  EXPECT_EQ(f.dims("/coupling/participants/tracer/substeps"), (std::vector<hsize_t>{7}));
}

TEST_F(ResumeTest, ResumeTwiceFromTheSameCheckpoint) {
  const auto path = file("run.h5");
  write_interrupted_run(path);
  { RunFile first = RunFile::resume(path); }
  RunFile second = RunFile::resume(path);
  second.append(sample_window(3, kDt, kBodies.size(), kParticipants));
  second = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time").size(), 4u);
}

TEST_F(ResumeTest, CheckpointAtStartKeepsNoRows) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    Checkpoint c = checkpoint_after(0);
    c.next_window = 0;
    c.time = 0.0;
    run.write_checkpoint(c);
    run.append(sample_window(0, kDt, kBodies.size(), kParticipants));
    EXPECT_EQ(run.checkpoint().next_window, 0u);
  }
  RunFile run = RunFile::resume(path);
  run.append(sample_window(0, kDt, kBodies.size(), kParticipants));
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time"), std::vector<double>{kDt});
}

TEST_F(ResumeTest, WithoutCheckpointThrows) {
  const auto path = file("run.h5");
  { RunFile::create(path, RunInfo{}, kBodies, kParticipants).append(
        sample_window(0, kDt, kBodies.size(), kParticipants)); }
  try {
    RunFile::resume(path);
    FAIL() << "resumed a run without checkpoint";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), ("no checkpoint in " + path.string() + ": it cannot be resumed").c_str());
  }
}

TEST_F(ResumeTest, NotARunFileThrowsNamingIt) {
  const auto path = file("scene.yaml");
  std::ofstream(path) << "not hdf5\n";
  try {
    RunFile::resume(path);
    FAIL() << "resumed a text file";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path.string() + ": open file", 0), 0u) << e.what();
  }
}

TEST_F(ResumeTest, MalformedCheckpointKeepsThePreviousOne) {
  const auto path = file("run.h5");
  RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
  run.write_checkpoint(checkpoint_after(0));
  Checkpoint bad = checkpoint_after(1);
  bad.states["solid"] = {1.0};
  EXPECT_THROW(run.write_checkpoint(bad), std::runtime_error);
  bad = checkpoint_after(1);
  bad.forces.pop_back();
  EXPECT_THROW(run.write_checkpoint(bad), std::runtime_error);
  EXPECT_EQ(run.checkpoint().next_window, 1u);
  run = RunFile::create(file("other.h5"), RunInfo{}, {}, {});
  EXPECT_EQ(RunFile::resume(path).checkpoint().next_window, 1u);
}

}  // namespace
}  // namespace cosim::output::test
