// The levels' runs as child processes, up to N side by side, each measured as the operating
// system accounts it.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cosim::study {

struct Job {
  std::vector<std::string> argv;  // argv[0] a path
  std::filesystem::path log;      // stdout and stderr
};

struct Usage {
  double wall_seconds = 0;
  // getrusage of the child: user + system time of it and of every descendant it waited for
  // (`cosim run` waits for its participants and their ranks).
  double cpu_seconds = 0;
  double peak_mb = 0;  // the largest peak resident set among them, in 10^6 bytes
  std::string ended;   // empty after exit status 0; otherwise "exited with status 1", "killed by signal 9"
};

// Runs every job, `parallel` at a time in order, and returns their usage in the jobs' order;
// `started` and `finished` are told as it happens. With `parallel` above 1 and at least as
// many CPUs allowed to this process, each job runs pinned to its even share of them (the
// slot it took, whole CPUs), inherited by everything it starts.
std::vector<Usage> run_all(const std::vector<Job>& jobs, int parallel, const std::function<void(std::size_t)>& started,
                           const std::function<void(std::size_t, const Usage&)>& finished);

}  // namespace cosim::study
