// Runs another program and measures it as the kernel accounts it (wait4): its processor
// time and peak resident set, which the parent's own clocks cannot see.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cosim::bench {

struct ChildUsage {
  int exit_code = 0;  // -1 if it did not exit normally
  double wall_seconds = 0;
  double cpu_seconds = 0;  // user + system
  double peak_rss_bytes = 0;
};

// `name` itself if it holds a '/', else the first executable of that name on PATH.
std::optional<std::filesystem::path> find_executable(const std::string& name);

// Runs `program` with `arguments` in `directory`, its stdout and stderr to `output`,
// and waits for it. Throws std::system_error if it cannot be started.
ChildUsage run_child(const std::filesystem::path& program, const std::vector<std::string>& arguments,
                     const std::filesystem::path& directory, const std::filesystem::path& output);

}  // namespace cosim::bench
