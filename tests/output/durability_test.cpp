// The file keeps every committed window: after the writer is gone, and after it is killed
// without any chance to close the file.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <optional>
#include <random>

#include "tests/output/h5_read.hpp"
#include "coupler/output/journal_driver.hpp"
#include "coupler/output/run_file.hpp"
#include "tests/output/sample_run.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using DurabilityTest = TempDirTest;

const std::vector<std::string> kBodies{"ball", "box"};
const std::vector<std::string> kParticipants{"fluid"};
constexpr char kPython[] = "/usr/bin/python3";

bool python_has_h5py() { return std::system((std::string(kPython) + " -c 'import h5py' 2>/dev/null").c_str()) == 0; }

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
  // scripts/setup installs python3-h5py: its absence is a broken set-up, not a reason to skip.
  ASSERT_TRUE(python_has_h5py()) << kPython << " has no h5py";
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 1}, kBodies, kParticipants);
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

// Guards against: a SIGKILL of the coupler losing windows already committed to the run file.
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
  EXPECT_EQ(h5py_check(path, "assert f['bodies/ball/force'].shape == (5, 3)\n"), 0);
}

// Guards against: a run file killed mid-run not resuming.
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
    RunFile run = RunFile::resume(path, "d1e2f3");
    EXPECT_EQ(run.checkpoint().next_window, 4u);
    run.append(sample_window(4, 0.5, kBodies.size(), kParticipants));
  }
  EXPECT_EQ(ReadFile(path).doubles("/coupling/time"), (std::vector<double>{0.5, 1.0, 1.5, 2.0, 2.5}));
}

// Checkpoint `seq` of the stress test: a ~1.6 MB state whose length changes from one
// checkpoint to the next (so the slots shrink and grow under the kills) and whose values
// name seq, so the test can tell exactly which checkpoint a file holds.
Checkpoint stress_checkpoint(std::uint64_t seq) {
  const WindowRecord w = sample_window(seq, 0.5, kBodies.size(), kParticipants);
  std::vector<double> state(195000 + (seq * 7919) % 10000);
  for (std::size_t i = 0; i < state.size(); ++i) {
    state[i] = static_cast<double>(seq) + 1e-6 * static_cast<double>(i);
  }
  return Checkpoint{seq, w.time, w.poses, w.forces, {{"fluid", std::move(state)}}};
}

// The child of the stress test: resumes the file, then writes checkpoints forever, sending
// each seq down `report` once write_checkpoint has returned.
[[noreturn]] void checkpoint_forever(const std::filesystem::path& path, int report) {
  try {
    RunFile run = RunFile::resume(path, "d1e2f3");
    for (std::uint64_t seq = run.checkpoint().next_window + 1;; ++seq) {
      run.write_checkpoint(stress_checkpoint(seq));
      if (write(report, &seq, sizeof seq) != sizeof seq) _exit(5);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stress child: %s\n", e.what());
  }
  _exit(3);
}

// Forks a child that runs checkpoint_forever(path); `from_child` reads its numbers.
void start_checkpointing(const std::filesystem::path& path, pid_t& child, int& from_child) {
  int pipe_fds[2];
  ASSERT_EQ(pipe(pipe_fds), 0);
  child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    close(pipe_fds[0]);
    checkpoint_forever(path, pipe_fds[1]);
  }
  close(pipe_fds[1]);
  from_child = pipe_fds[0];
}

// SIGKILL at random moments of a loop that does nothing but write checkpoints: after every
// kill the file opens and holds the last checkpoint the child finished, or the one it was
// writing if the kill came after its commit point, never anything else.
// Guards against: a SIGKILL during a checkpoint write corrupting the file or the last checkpoint.
TEST_F(DurabilityTest, SigkillDuringCheckpointWritesKeepsTheLastCheckpoint) {
  constexpr int kKills = 100;
  const auto path = file("run.h5");
  { RunFile::create(path, RunInfo{}, kBodies, kParticipants).write_checkpoint(stress_checkpoint(1)); }
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> delay_us(0, 4000);
  std::uint64_t written = 0;
  int after_commit = 0;  // kills between the commit point and write_checkpoint returning
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < kKills; ++k) {
    pid_t child = -1;
    int from_child = -1;
    ASSERT_NO_FATAL_FAILURE(start_checkpointing(path, child, from_child));
    std::uint64_t last = 0;
    std::uint64_t seq = 0;
    // Waits for the first checkpoint, so the kill lands inside the loop, not in resume().
    ASSERT_EQ(read(from_child, &last, sizeof last), static_cast<ssize_t>(sizeof last))
        << "child died before its first checkpoint (kill " << k << ")";
    const std::uint64_t first = last;
    usleep(static_cast<useconds_t>(delay_us(rng)));
    kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "kill " << k;
    while (read(from_child, &seq, sizeof seq) == static_cast<ssize_t>(sizeof seq)) last = seq;
    close(from_child);
    written += last - first + 1;

    std::optional<RunFile> run;
    try {
      run.emplace(RunFile::resume(path, "d1e2f3"));
    } catch (const std::exception& e) {
      FAIL() << "kill " << k << " left a file that cannot be resumed: " << e.what();
    }
    const Checkpoint& c = run->checkpoint();
    ASSERT_TRUE(c.next_window == last || c.next_window == last + 1)
        << "kill " << k << ": file holds checkpoint " << c.next_window << ", child finished " << last;
    if (c.next_window == last + 1) ++after_commit;
    const Checkpoint expected = stress_checkpoint(c.next_window);
    ASSERT_EQ(c.time, expected.time);
    ASSERT_EQ(c.poses, expected.poses);
    ASSERT_EQ(c.forces, expected.forces);
    ASSERT_TRUE(c.states == expected.states) << "kill " << k << ": state of checkpoint " << c.next_window << " differs";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "[ stress   ] %d kills, %llu checkpoints completed, %d kills after the commit "
      "point, %.2f s\n",
      kKills, static_cast<unsigned long long>(written), after_commit, seconds);
}

// A journal without a commit in it (a kill after the journal was made, before its first
// header, or after the commit's end) is no reason to refuse the file, and resume() removes it.
TEST_F(DurabilityTest, AJournalWithoutACommitIsIgnored) {
  const auto path = file("run.h5");
  {
    RunFile run = RunFile::create(path, RunInfo{}, kBodies, kParticipants);
    const WindowRecord w = sample_window(0, 0.5, kBodies.size(), kParticipants);
    run.append(w);
    run.write_checkpoint(Checkpoint{1, w.time, w.poses, w.forces, {}, {}});
  }
  for (const std::string& text : {std::string(), std::string(40, '\0') + "rest of an earlier commit"}) {
    std::ofstream(journal_of(path), std::ios::binary) << text;
    EXPECT_EQ(RunFile::peek(path).checkpoint_window, 1u);
    EXPECT_EQ(RunFile::resume(path, "d1e2f3").checkpoint().next_window, 1u);
    EXPECT_FALSE(std::filesystem::exists(journal_of(path)));
  }
}

// Whether a commit is under way or was cut off: the journal's header carries the magic.
bool commit_pending(int journal) {
  char magic[8] = {};
  return pread(journal, magic, sizeof magic, 0) == sizeof magic && std::string(magic, 8) == "cosimjl1";
}

// Kills a writer of checkpoints into `path` after a commit's commit point but before its
// end (the journal whole, the file half written); returns the last checkpoint the writer
// reported, or nothing when 20 kills all missed a commit.
std::optional<std::uint64_t> cut_off_a_commit(const std::filesystem::path& path) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    pid_t child = -1;
    int from_child = -1;
    start_checkpointing(path, child, from_child);
    if (::testing::Test::HasFatalFailure()) return std::nullopt;
    std::uint64_t last = 0;
    // After the first checkpoint the journal exists; the kill comes as soon as it holds one.
    EXPECT_EQ(read(from_child, &last, sizeof last), static_cast<ssize_t>(sizeof last));
    const int journal = open(journal_of(path).c_str(), O_RDONLY);
    EXPECT_GE(journal, 0);
    if (journal < 0) return std::nullopt;
    // The child commits over and over; should it die instead, the test must not spin.
    for (int status = 0; !commit_pending(journal);)
      if (waitpid(child, &status, WNOHANG) != 0) {
        ADD_FAILURE() << "the writer died";
        return std::nullopt;
      }
    kill(child, SIGKILL);
    int status = 0;
    EXPECT_EQ(waitpid(child, &status, 0), child);
    for (std::uint64_t seq = 0; read(from_child, &seq, sizeof seq) == static_cast<ssize_t>(sizeof seq);) last = seq;
    close(from_child);
    const bool cut_off = commit_pending(journal);
    close(journal);
    if (cut_off) return last;  // else the commit ended between the look and the kill: again
  }
  return std::nullopt;
}

// A commit cut off is finished by the next open: read-only in memory, by resume() in the
// file, so that no kill inside a flush leaves the file between two states.
TEST_F(DurabilityTest, SigkillInsideACommitIsFinishedByTheNextOpen) {
  const auto path = file("run.h5");
  { RunFile::create(path, RunInfo{}, kBodies, kParticipants).write_checkpoint(stress_checkpoint(1)); }
  const std::optional<std::uint64_t> last = cut_off_a_commit(path);
  ASSERT_TRUE(last.has_value()) << "no kill in 20 landed inside a commit";
  // The commit cut off wrote either the slot (the checkpoint stays `last`) or the switch to
  // it (`last + 1`): either way the checkpoint read is whole.
  const std::uint64_t seen = RunFile::peek(path).checkpoint_window;
  EXPECT_TRUE(seen == *last || seen == *last + 1) << seen << " after " << *last;
  EXPECT_TRUE(output::commit_pending(path)) << "a read-only open changed the file";
  {
    RunFile run = RunFile::resume(path, "d1e2f3");
    EXPECT_EQ(run.checkpoint().next_window, seen);
    EXPECT_TRUE(run.checkpoint().states == stress_checkpoint(seen).states);
  }
  EXPECT_FALSE(std::filesystem::exists(journal_of(path)));
  EXPECT_EQ(RunFile::peek(path).checkpoint_window, seen);
}

// `cosim repair`: the commit cut off is finished in the file and the journal goes, so that
// HDF5's own driver (h5py's, ParaView's) reads the same checkpoint; a second repair finds
// nothing to do and leaves the file's bytes as they are.
TEST_F(DurabilityTest, FinishCommitLeavesAFileEveryReaderSeesWhole) {
  const auto path = file("run.h5");
  { RunFile::create(path, RunInfo{}, kBodies, kParticipants).write_checkpoint(stress_checkpoint(1)); }
  ASSERT_TRUE(cut_off_a_commit(path).has_value()) << "no kill in 20 landed inside a commit";
  const std::uint64_t seen = RunFile::peek(path).checkpoint_window;
  EXPECT_TRUE(RunFile::finish_commit(path));
  EXPECT_FALSE(std::filesystem::exists(journal_of(path)));
  const hid_t plain = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(plain, 0);
  EXPECT_GT(H5Lexists(plain, "checkpoint", H5P_DEFAULT), 0);
  H5Fclose(plain);
  EXPECT_EQ(RunFile::peek(path).checkpoint_window, seen);
  const auto bytes = [&] {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string before = bytes();
  EXPECT_FALSE(RunFile::finish_commit(path));
  EXPECT_EQ(bytes(), before);
}

}  // namespace
}  // namespace cosim::output::test
