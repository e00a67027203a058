#include "tests/integration/cosim_process.hpp"

#include <fcntl.h>
#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace cosim::testing {
namespace fs = std::filesystem;

fs::path scratch_dir(const std::string& test_name) {
  // One folder per test process, removed when it exits.
  static const struct Root {
    fs::path path = fs::temp_directory_path() / ("cosim-test-" + std::to_string(getpid()));
    ~Root() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } root;
  const auto dir = root.path / test_name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

pid_t child_pid(pid_t parent, const std::string& program) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream cmdline(entry.path() / "cmdline");
    std::string command;
    std::getline(cmdline, command, '\0');
    std::ifstream stat(entry.path() / "stat");
    std::string pid, name, state;
    pid_t parent_of = 0;
    stat >> pid >> name >> state >> parent_of;
    if (parent_of == parent && command.ends_with(program)) return std::stoi(pid);
  }
  return 0;
}

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string read_file(const fs::path& path) {
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

std::vector<std::string> run_args(const fs::path& dir, const std::string& stem) {
  return {"run", (dir / (stem + ".yaml")).string(), "-o", (dir / (stem + ".h5")).string(), "-q"};
}

Finished run_scene_text(const fs::path& dir, const std::string& yaml, const std::string& stem) {
  write_file(dir / (stem + ".yaml"), yaml);
  return run_cosim(run_args(dir, stem));
}

CosimProcess::CosimProcess(const std::vector<std::string>& args, const std::string& network_namespace) {
  static int counter = 0;
  log_ =
      fs::temp_directory_path() / ("cosim-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".log");
  const auto cosim = fs::read_symlink("/proc/self/exe").parent_path() / "cosim";
  std::vector<std::string> argv{cosim.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> cargs;
  for (auto& a : argv) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  pid_ = fork();
  if (pid_ == 0) {
    const int fd = open(log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    if (!network_namespace.empty()) {
      const int ns = open(network_namespace.c_str(), O_RDONLY | O_CLOEXEC);
      if (ns < 0 || setns(ns, CLONE_NEWNET) != 0) _exit(126);
    }
    execv(cargs[0], cargs.data());
    _exit(127);
  }
}

CosimProcess::~CosimProcess() {
  if (pid_ <= 0) return;
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  fs::remove(log_);
}

std::string CosimProcess::output() const { return read_file(log_); }

Finished CosimProcess::wait(std::chrono::seconds limit) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (waitpid(pid_, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      pid_ = -1;
      throw std::runtime_error("cosim did not finish within " + std::to_string(limit.count()) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  pid_ = -1;
  Finished f;
  f.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::stringstream text;
  text << std::ifstream(log_).rdbuf();
  f.output = text.str();
  fs::remove(log_);
  return f;
}

}  // namespace cosim::testing
