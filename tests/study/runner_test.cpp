// The levels' runs as child processes: side by side on their own CPUs.
#include "coupler/study/runner.hpp"

#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace cosim::study {
namespace {

namespace fs = std::filesystem;

// What a job's log (or /proc/self/status) says of the CPUs it was allowed: the kernel's Cpus_allowed_list line.
std::string allowed_list(const fs::path& log) {
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("Cpus_allowed_list:", 0) == 0) return line.substr(line.find_first_not_of(" \t", 18));
  return "";
}

std::vector<Job> jobs(const fs::path& dir, int n) {
  fs::create_directories(dir);
  std::vector<Job> out;
  // Long enough that the runs overlap.
  for (int k = 0; k < n; ++k)
    out.push_back({{"/bin/sh", "-c", "grep Cpus_allowed_list /proc/self/status; sleep 0.3"},
                   dir / ("job" + std::to_string(k) + ".log")});
  return out;
}

int allowed_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  return sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
}

TEST(Runner, SideBySideRunsHaveCpusOfTheirOwn) {
  if (allowed_cpus() < 2) GTEST_SKIP() << "one CPU: nothing to share out";
  const fs::path dir = fs::temp_directory_path() / ("cosim-runner-" + std::to_string(getpid()));
  const auto list = jobs(dir, 3);
  const std::vector<Usage> usage = run_all(list, 2, {}, {});
  ASSERT_EQ(usage.size(), 3u);
  for (const Usage& u : usage) EXPECT_EQ(u.ended, "");
  const std::string first = allowed_list(list[0].log), second = allowed_list(list[1].log);
  EXPECT_NE(first, "");
  EXPECT_NE(second, "");
  EXPECT_NE(first, second);  // the two that ran together
  // The third took the slot the first one freed: one of the two shares again.
  const std::string third = allowed_list(list[2].log);
  EXPECT_TRUE(third == first || third == second) << third;
  fs::remove_all(dir);
}

TEST(Runner, OneAtATimeRunsOnEveryCpu) {
  const fs::path dir = fs::temp_directory_path() / ("cosim-runner-one-" + std::to_string(getpid()));
  const auto list = jobs(dir, 1);
  const std::vector<Usage> usage = run_all(list, 1, {}, {});
  EXPECT_EQ(usage[0].ended, "");
  EXPECT_EQ(allowed_list(list[0].log), allowed_list("/proc/self/status"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::study
