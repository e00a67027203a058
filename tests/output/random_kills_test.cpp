// SIGKILL at random instants of a run file's whole life: resume()'s cut, window appends,
// field steps that grow the file with new groups and datasets, checkpoint writes. After
// every kill the file must open and resume, holding exactly what was committed.
// COSIM_STRESS_KILLS sets the number of kills (300 by default; the ctest label `stress`
// runs 1000).
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "coupler/output/journal_driver.hpp"
#include "coupler/output/run_file.hpp"
#include "tests/output/h5_read.hpp"
#include "tests/output/sample_run.hpp"
#include "tests/output/temp_dir.hpp"

namespace cosim::output::test {
namespace {

using RandomKillTest = TempDirTest;

const std::vector<std::string> kBodies{"ball", "box"};
const std::vector<std::string> kParticipants{"fluid"};
constexpr double kDt = 0.5;
constexpr std::uint64_t kCheckpointEvery = 4;  // windows
constexpr std::uint64_t kFieldsEvery = 3;      // windows
constexpr std::uint64_t kRestartAfter = 300;   // windows (past a series chunk of 256): then a fresh file

// What the child is doing, written to memory it shares with the parent before each step.
enum Phase : int { kForking, kResuming, kAppending, kFields, kCheckpoint, kPhases };
constexpr std::array<const char*, kPhases> kPhaseNames{"before resume", "resume", "append", "field step", "checkpoint"};

struct Shared {
  std::atomic<int> phase;
  std::atomic<std::uint64_t> checkpoint;  // next_window of the last checkpoint completed
};

int kill_count() {
  const char* text = std::getenv("COSIM_STRESS_KILLS");
  return text ? std::atoi(text) : 300;
}

// Checkpoint with next_window n: its state's length changes from one to the next and its
// values name n, so the test tells exactly which checkpoint a file holds.
Checkpoint checkpoint_at(std::uint64_t n) {
  const WindowRecord w = sample_window(n - 1, kDt, kBodies.size(), kParticipants);
  std::vector<double> state(20000 + (n * 7919) % 5000);
  for (std::size_t i = 0; i < state.size(); ++i) state[i] = static_cast<double>(n) + 1e-6 * static_cast<double>(i);
  return Checkpoint{n, w.time, w.poses, w.forces, {{"fluid", std::move(state)}}, {}};
}

// The fields at the start of window `step`: 8 x 8 x 8 cells of values that name the step.
field::FieldFrame frame_at(std::uint64_t step) {
  field::RectilinearGrid grid;
  for (auto& axis : grid.nodes)
    for (int i = 0; i <= 8; ++i) axis.push_back(0.125 * i);
  std::vector<double> p(512), u(3 * 512);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = static_cast<double>(step) + 1e-3 * static_cast<double>(i);
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = -static_cast<double>(step) - 1e-3 * static_cast<double>(i);
  return field::FieldFrame{grid, {{"p", 1, std::move(p)}, {"u", 3, std::move(u)}}};
}

void make_fresh(const std::filesystem::path& path) {
  RunFile run = RunFile::create(path, RunInfo{"scene: 1\n", "s.yaml", "abc", "0.1.0", 1}, kBodies, kParticipants);
  run.write_fields("fluid", 0, 0.0, frame_at(0));
  run.write_checkpoint(checkpoint_at(1));  // a first checkpoint before any window: next_window 1 after window 0
  run.append(sample_window(0, kDt, kBodies.size(), kParticipants));
}

// The child: resumes, then runs windows forever as the coupler does, fields every
// kFieldsEvery windows and a checkpoint every kCheckpointEvery.
[[noreturn]] void run_forever(const std::filesystem::path& path, Shared* shared) {
  try {
    shared->phase = kResuming;
    RunFile run = RunFile::resume(path, "stress");
    for (std::uint64_t k = run.checkpoint().next_window;; ++k) {
      shared->phase = kAppending;
      const WindowRecord w = sample_window(k, kDt, kBodies.size(), kParticipants);
      run.append(w);
      if ((k + 1) % kFieldsEvery == 0) {
        shared->phase = kFields;
        run.write_fields("fluid", k + 1, w.time, frame_at(k + 1));
      }
      if ((k + 1) % kCheckpointEvery == 0) {
        shared->phase = kCheckpoint;
        run.write_checkpoint(checkpoint_at(k + 1));
        shared->checkpoint = k + 1;
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stress child: %s\n", e.what());
  }
  _exit(3);
}

// Whether a kill left a commit half done: a journal whose header carries the magic.
bool journal_pending(const std::filesystem::path& path) {
  std::ifstream journal(journal_of(path), std::ios::binary);
  char magic[8] = {};
  return journal.read(magic, sizeof magic) && std::string(magic, 8) == "cosimjl1";
}

// Why the file, resumed, does not hold exactly what was committed up to a checkpoint at or
// after `committed`; empty if it does. Leaves the file resumed and closed.
std::string resume_problem(const std::filesystem::path& path, std::uint64_t committed, std::uint64_t* next) {
  try {
    (void)RunFile::peek(path);
  } catch (const std::exception& e) {
    return std::string("unreadable: ") + e.what();
  }
  Checkpoint c;
  try {
    c = RunFile::resume(path, "check").checkpoint();
  } catch (const std::exception& e) {
    return std::string("resume failed: ") + e.what();
  }
  *next = c.next_window;
  if (c.next_window < committed || c.next_window > committed + kCheckpointEvery)
    return "checkpoint " + std::to_string(c.next_window) + " after " + std::to_string(committed) + " was completed";
  const Checkpoint expected = checkpoint_at(c.next_window);
  if (c.time != expected.time || c.poses != expected.poses || c.states != expected.states)
    return "checkpoint " + std::to_string(c.next_window) + " holds other values";
  ReadFile f(path);
  const std::vector<double> times = f.doubles("/coupling/time");
  const std::vector<double> position = f.doubles("/bodies/box/position");
  if (times.size() != c.next_window || position.size() != 3 * c.next_window)
    return std::to_string(times.size()) + " windows after the cut to checkpoint " + std::to_string(c.next_window);
  for (std::uint64_t k = 0; k < c.next_window; ++k) {
    const WindowRecord w = sample_window(k, kDt, kBodies.size(), kParticipants);
    if (times[k] != w.time || position[3 * k + 2] != slot(k, 1, 2))
      return "window " + std::to_string(k) + " holds other values";
  }
  for (std::uint64_t step = 0; step <= c.next_window + kFieldsEvery; step += kFieldsEvery) {
    char name[32];
    std::snprintf(name, sizeof name, "/fields/fluid/%06llu", static_cast<unsigned long long>(step));
    if (f.has(name) != (step <= c.next_window)) return std::string(name) + (f.has(name) ? " kept" : " missing");
    if (step <= c.next_window && f.doubles(std::string(name) + "/u") != frame_at(step).fields[1].values)
      return std::string(name) + " holds other values";
  }
  return "";
}

// No kill, wherever it lands, leaves a file that does not open, does not resume, or lost a
// commit.
TEST_F(RandomKillTest, EveryKilledFileOpensAndResumes) {
  const int kills = kill_count();
  const auto path = file("run.h5");
  make_fresh(path);
  auto* shared =
      static_cast<Shared*>(mmap(nullptr, sizeof(Shared), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0));
  ASSERT_NE(shared, MAP_FAILED);
  std::mt19937 rng(20261203);
  std::uint64_t committed = 1;
  double check_us = 2000;  // the last check's duration (a peek, a resume, reads): about a resume's
  std::array<int, kPhases> landed{};
  std::map<std::string, int> problems;
  int broken = 0;
  int journals = 0;  // kills between a commit's commit point and its end, finished on opening
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < kills; ++k) {
    shared->phase = kForking;
    shared->checkpoint = 0;
    // About a third of the kills land in resume(), the rest in the windows after it.
    std::uniform_real_distribution<double> delay(0.0, 3.0 * check_us);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) run_forever(path, shared);
    usleep(static_cast<useconds_t>(delay(rng)));
    kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ++landed[shared->phase];
    journals += journal_pending(path);
    committed = std::max<std::uint64_t>(committed, shared->checkpoint);

    std::uint64_t next = 0;
    const auto before = std::chrono::steady_clock::now();
    // A child that ended by itself found the file it resumed broken (it says why).
    const std::string problem = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL
                                    ? resume_problem(path, committed, &next)
                                    : "the child failed on the file the last kill left";
    check_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - before).count();
    if (!problem.empty()) {
      ++broken;
      if (++problems[problem.substr(0, 60)] == 1)
        std::printf("kill %d (%s): %s\n", k, kPhaseNames[shared->phase], problem.c_str());
      next = 0;
    }
    committed = next;
    if (next == 0 || next > kRestartAfter) {
      make_fresh(path);
      committed = 1;
    }
  }
  munmap(shared, sizeof(Shared));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ stress   ] %d kills in %.1f s, %d files broken, %d left a commit to finish; kills in", kills, seconds,
              broken, journals);
  for (int p = 0; p < kPhases; ++p) std::printf(" %s %d%s", kPhaseNames[p], landed[p], p + 1 < kPhases ? "," : "\n");
  EXPECT_EQ(broken, 0);
}

}  // namespace
}  // namespace cosim::output::test
