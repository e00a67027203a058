// The file keeps every committed window: after the writer is gone, and after it is killed
// without any chance to close the file.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <functional>

#include "h5_read.hpp"
#include "output/run_file.hpp"
#include "sample_run.hpp"
#include "temp_dir.hpp"

namespace cosim::output::test {
namespace {

using DurabilityTest = TempDirTest;

const std::vector<std::string> kBodies{"ball", "box"};
const std::vector<std::string> kParticipants{"fluid"};
constexpr char kPython[] = "/usr/bin/python3";

bool python_has_h5py() {
  return std::system((std::string(kPython) + " -c 'import h5py' 2>/dev/null").c_str()) == 0;
}

// Runs a Python snippet with `f` open on path (h5py links its own, serial, HDF5).
int h5py_check(const std::filesystem::path& path, const std::string& body) {
  const std::string script = "import h5py, sys\nf = h5py.File(sys.argv[1], 'r')\n" + body;
  const std::string cmd = std::string(kPython) + " -c \"" + script + "\" " + path.string();
  return std::system(cmd.c_str());
}

// Runs `work` in a child process that then dies by SIGKILL while still holding the RunFile
// that `work` returns: no destructor, no H5Fclose, no atexit handler.
void run_and_kill(const std::function<RunFile()>& work) {
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      const RunFile open_run = work();
      raise(SIGKILL);
    } catch (...) {
      _exit(3);
    }
    _exit(4);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
  ASSERT_EQ(WTERMSIG(status), SIGKILL);
}

TEST_F(DurabilityTest, ReadableByH5pyAfterTheWriterIsGone) {
  if (!python_has_h5py()) GTEST_SKIP() << kPython << " has no h5py";
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 1},
                                  kBodies, kParticipants);
    for (std::uint64_t k = 0; k < 4; ++k) {
      run.append(sample_window(k, 0.5, kBodies.size(), kParticipants));
    }
    run.set_status("finished", 2.0);
  }
  EXPECT_EQ(h5py_check(path,
                       "assert f['coupling/time'].shape == (4,)\n"
                       "assert f['bodies/box/orientation'].shape == (4, 4)\n"
                       "assert f['bodies/box/orientation'][3, 0] == 3100.25 + 3\n"
                       "assert f['run'].attrs['status'] == 'finished'\n"
                       "assert list(f['run'].attrs['body_names']) == ['ball', 'box']\n"
                       "assert f['run/scene_text'][()].decode() == 'scene: 1\\n'\n"),
            0);
}

TEST_F(DurabilityTest, SigkillAfterAppendLosesNothingCommitted) {
  const auto path = file("run.h5");
  run_and_kill([&] {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    for (std::uint64_t k = 0; k < 5; ++k) {
      run.append(sample_window(k, 0.5, kBodies.size(), kParticipants));
    }
    return run;
  });
  ReadFile f(path);
  EXPECT_EQ(f.doubles("/coupling/time"), (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(f.dims("/bodies/box/position"), (std::vector<hsize_t>{5, 3}));
  EXPECT_EQ(f.doubles("/bodies/box/position")[4 * 3 + 2], slot(4, 1, 2));
  EXPECT_EQ(f.doubles("/coupling/participants/fluid/wall_seconds").size(), 5u);
  EXPECT_EQ(f.string_attribute("/run", "status"), "running");
  if (python_has_h5py()) {
    EXPECT_EQ(h5py_check(path, "assert f['bodies/ball/force'].shape == (5, 3)\n"), 0);
  }
}

TEST_F(DurabilityTest, ResumeAfterSigkill) {
  const auto path = file("run.h5");
  run_and_kill([&] {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    for (std::uint64_t k = 0; k < 6; ++k) {
      const WindowRecord w = sample_window(k, 0.5, kBodies.size(), kParticipants);
      run.append(w);
      if (k == 3) run.write_checkpoint(Checkpoint{k + 1, w.time, w.poses, w.forces, {}});
    }
    return run;
  });
  {
    RunFile run = RunFile::resume(path);
    EXPECT_EQ(run.checkpoint().next_window, 4u);
    run.append(sample_window(4, 0.5, kBodies.size(), kParticipants));
  }
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time"),
            (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
}

}  // namespace
}  // namespace cosim::output::test
