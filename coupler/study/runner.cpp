#include "coupler/study/runner.hpp"

#include <fcntl.h>
#include <sched.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <stdexcept>

namespace cosim::study {
namespace {

using clock = std::chrono::steady_clock;

// The CPUs this process may run on, in order.
std::vector<int> allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return {};
  std::vector<int> cpus;
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &set)) cpus.push_back(c);
  return cpus;
}

// Slot `slot` of `slots`: its even share of `cpus`, whole CPUs each.
cpu_set_t slot_cpus(const std::vector<int>& cpus, std::size_t slot, std::size_t slots) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (std::size_t k = slot * cpus.size() / slots; k < (slot + 1) * cpus.size() / slots; ++k) CPU_SET(cpus[k], &set);
  return set;
}

// The child inherits the affinity of the thread that spawns it: this thread takes the
// slot's CPUs for the spawn and its own back after.
pid_t spawn(const Job& job, const cpu_set_t* pinned) {
  cpu_set_t own;
  const bool pin = pinned != nullptr && sched_getaffinity(0, sizeof own, &own) == 0 &&
                   sched_setaffinity(0, sizeof *pinned, pinned) == 0;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv;
  for (const auto& a : job.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (pin) sched_setaffinity(0, sizeof own, &own);
  if (rc != 0) throw std::runtime_error("cannot start " + job.argv[0] + ": " + std::strerror(rc));
  return pid;
}

std::string describe(int status) {
  if (WIFEXITED(status))
    return WEXITSTATUS(status) == 0 ? "" : "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status))
    return "killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  return "ended (status " + std::to_string(status) + ")";
}

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

}  // namespace

std::vector<Usage> run_all(const std::vector<Job>& jobs, int parallel, const std::function<void(std::size_t)>& started,
                           const std::function<void(std::size_t, const Usage&)>& finished) {
  std::vector<Usage> usage(jobs.size());
  struct Running {
    std::size_t job;
    std::size_t slot;
    clock::time_point start;
  };
  // Side-by-side runs each on their own share of the CPUs, so that one run's ranks do not
  // take another's cores; with fewer CPUs than runs, or one run at a time, none is pinned.
  const auto slots = static_cast<std::size_t>(std::max(parallel, 1));
  const std::vector<int> cpus = allowed_cpus();
  const bool pin = slots > 1 && cpus.size() >= slots;
  std::vector<std::size_t> free_slots;
  for (std::size_t s = slots; s-- > 0;) free_slots.push_back(s);
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < slots) {
      if (started) started(next);
      const std::size_t slot = free_slots.back();
      free_slots.pop_back();
      const cpu_set_t share = pin ? slot_cpus(cpus, slot, slots) : cpu_set_t{};
      running.emplace(spawn(jobs[next], pin ? &share : nullptr), Running{next, slot, clock::now()});
      ++next;
    }
    int status = 0;
    rusage ru{};
    const pid_t pid = wait4(-1, &status, 0, &ru);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("waiting for the runs: ") + std::strerror(errno));
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    Usage& u = usage[it->second.job];
    u.wall_seconds = std::chrono::duration<double>(clock::now() - it->second.start).count();
    u.cpu_seconds = seconds(ru.ru_utime) + seconds(ru.ru_stime);
    u.peak_mb = static_cast<double>(ru.ru_maxrss) * 1024 / 1e6;  // Linux counts ru_maxrss in KiB
    u.ended = describe(status);
    if (finished) finished(it->second.job, u);
    free_slots.push_back(it->second.slot);
    running.erase(it);
  }
  return usage;
}

}  // namespace cosim::study
