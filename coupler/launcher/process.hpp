// Child processes of the launcher. Each participant runs in its own process group, so a
// Ctrl-C at the terminal reaches only the coupler, which then shuts the participants down
// in order; and it gets SIGTERM when the coupler dies (PR_SET_PDEATHSIG), so it does not
// outlive even a killed coupler (mpirun forwards the SIGTERM to its ranks).
#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace cosim::launcher {

class Process {
 public:
  // Starts argv[0] (resolved with PATH) with `env` added to this process's environment.
  Process(std::string name, const std::vector<std::string>& argv, const std::map<std::string, std::string>& env);
  Process(Process&&) noexcept;
  Process& operator=(Process&&) = delete;
  ~Process();  // kills the group if still running

  const std::string& name() const { return name_; }
  pid_t pid() const { return pid_; }

  // nullopt while running; otherwise how it ended ("exited with status 3",
  // "killed by signal 9 (Killed)").
  std::optional<std::string> poll();
  // Its exit status once it has exited; nullopt while running or when a signal ended it.
  std::optional<int> exit_status() const { return exit_status_; }
  // Once it has ended: the peak resident set of it or of the largest descendant it waited
  // for (mpirun: its largest rank), in bytes; 0 before.
  double peak_bytes() const { return peak_bytes_; }
  // Waits up to `grace` for a voluntary exit, then SIGTERM, then SIGKILL to the group.
  void stop(std::chrono::milliseconds grace);

 private:
  void ended(int status, const rusage& usage);

  std::string name_;
  pid_t pid_ = -1;
  std::optional<std::string> ended_;
  std::optional<int> exit_status_;
  double peak_bytes_ = 0;
  bool group_ended_ = false;
};

// Makes this process adopt its descendants orphaned below it (PR_SET_CHILD_SUBREAPER):
// mpirun puts every rank in a process group of its own, so if mpirun dies the ranks would
// otherwise escape to init.
void adopt_orphans();
// Kills and reaps every child of this process still alive: orphans adopted as above.
void end_orphans();

}  // namespace cosim::launcher
