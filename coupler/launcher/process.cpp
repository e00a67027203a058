#include "coupler/launcher/process.hpp"

#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "coupler/launcher/command.hpp"

namespace cosim::launcher {
namespace {

std::string describe(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return "killed by signal " + std::to_string(sig) + " (" + strsignal(sig) + ")";
  }
  return "ended (status " + std::to_string(status) + ")";
}

}  // namespace

Process::Process(std::string name, const std::vector<std::string>& argv, const std::map<std::string, std::string>& env)
    : name_(std::move(name)) {
  if (argv.empty()) throw std::invalid_argument("participant '" + name_ + "': empty command");
  // Everything the child needs is prepared before fork: after it only async-signal-safe
  // calls are allowed.
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string entry = *e;
    const auto key = entry.substr(0, entry.find('='));
    if (!env.contains(key) && !describes_enclosing_mpi_job(key)) env_strings.push_back(entry);
  }
  for (const auto& [k, v] : env) env_strings.push_back(k + "=" + v);
  std::vector<char*> envp;
  for (auto& e : env_strings) envp.push_back(e.data());
  envp.push_back(nullptr);

  const pid_t parent = getpid();
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("cannot start '" + name_ + "': " + std::strerror(errno));
  if (pid_ == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the coupler died before prctl took effect
    execvpe(args[0], args.data(), envp.data());
    const char msg[] = "cosim: cannot execute participant command\n";
    [[maybe_unused]] auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
    _exit(127);
  }
  setpgid(pid_, pid_);  // also from the parent, so kill(-pid) works without a race
}

Process::Process(Process&& o) noexcept
    : name_(std::move(o.name_)),
      pid_(o.pid_),
      ended_(std::move(o.ended_)),
      exit_status_(o.exit_status_),
      peak_bytes_(o.peak_bytes_),
      group_ended_(o.group_ended_) {
  o.pid_ = -1;
}

Process::~Process() {
  if (pid_ > 0) stop(std::chrono::milliseconds(0));
}

std::optional<std::string> Process::poll() {
  if (ended_ || pid_ <= 0) return ended_;
  int status = 0;
  rusage usage{};
  if (wait4(pid_, &status, WNOHANG, &usage) == pid_) ended(status, usage);
  return ended_;
}

void Process::ended(int status, const rusage& usage) {
  ended_ = describe(status);
  peak_bytes_ = static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux counts kB
  if (WIFEXITED(status)) exit_status_ = WEXITSTATUS(status);
}

void Process::stop(std::chrono::milliseconds grace) {
  using clock = std::chrono::steady_clock;
  const auto wait_until = [this](clock::time_point deadline) {
    while (!poll() && clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    return poll().has_value();
  };
  if (pid_ <= 0) return;
  if (!wait_until(clock::now() + grace)) {
    kill(-pid_, SIGTERM);
    kill(-pid_, SIGCONT);  // a stopped process acts on SIGTERM only once it runs again
    // mpirun needs a moment to pass SIGTERM on to its ranks and collect them.
    if (!wait_until(clock::now() + std::chrono::seconds(5))) {
      kill(-pid_, SIGKILL);
      int status = 0;
      rusage usage{};
      if (wait4(pid_, &status, 0, &usage) == pid_) ended(status, usage);
    }
  }
  // Helpers the participant forked into its group may outlive its main process. Once
  // only: after that the group id could in principle be reused.
  if (!group_ended_) kill(-pid_, SIGKILL);
  group_ended_ = true;
}

void adopt_orphans() { prctl(PR_SET_CHILD_SUBREAPER, 1); }

void end_orphans() {
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream children(task.path() / "children");
    for (pid_t pid = 0; children >> pid;) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
  }
}

}  // namespace cosim::launcher
