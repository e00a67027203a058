// Runs the real `cosim` program (next to the test binary) the way a user would, capturing
// what it prints.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace cosim::testing {

struct Finished {
  int exit_code = -1;  // 128 + signal if killed
  std::string output;  // stdout and stderr together
};

class CosimProcess {
 public:
  // With `network_namespace` (a /var/run/netns path) it runs inside that namespace, as on
  // another host.
  explicit CosimProcess(const std::vector<std::string>& args, const std::string& network_namespace = "");
  // A run a failed assertion left behind is killed (its participants follow the coupler).
  ~CosimProcess();
  CosimProcess(const CosimProcess&) = delete;
  CosimProcess& operator=(const CosimProcess&) = delete;
  pid_t pid() const { return pid_; }
  std::string output() const;  // what it printed so far
  // Fails the test (exception) after `limit`.
  Finished wait(std::chrono::seconds limit = std::chrono::seconds(60));

 private:
  pid_t pid_ = -1;
  std::filesystem::path log_;
};

inline Finished run_cosim(const std::vector<std::string>& args, std::chrono::seconds limit = std::chrono::seconds(60)) {
  return CosimProcess(args).wait(limit);
}

// Writes dir/<stem>.yaml and runs `cosim run` on it, writing dir/<stem>.h5.
Finished run_scene_text(const std::filesystem::path& dir, const std::string& yaml, const std::string& stem = "scene");
std::vector<std::string> run_args(const std::filesystem::path& dir, const std::string& stem = "scene");

// The process started by `parent` whose command ends with `program`, or 0.
pid_t child_pid(pid_t parent, const std::string& program);

// A fresh folder for one test's files.
std::filesystem::path scratch_dir(const std::string& test_name);
void write_file(const std::filesystem::path& path, const std::string& text);
std::string read_file(const std::filesystem::path& path);  // "" if it cannot be read

}  // namespace cosim::testing
