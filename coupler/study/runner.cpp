#include "coupler/study/runner.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <map>
#include <stdexcept>

namespace cosim::study {
namespace {

using clock = std::chrono::steady_clock;

pid_t spawn(const Job& job) {
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
    clock::time_point start;
  };
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  while (next < jobs.size() || !running.empty()) {
    while (next < jobs.size() && running.size() < static_cast<std::size_t>(parallel)) {
      if (started) started(next);
      running.emplace(spawn(jobs[next]), Running{next, clock::now()});
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
    running.erase(it);
  }
  return usage;
}

}  // namespace cosim::study
