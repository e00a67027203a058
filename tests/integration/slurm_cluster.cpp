#include "tests/integration/slurm_cluster.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <thread>
#include <vector>

namespace cosim::testing {
namespace {

namespace fs = std::filesystem;

// Starts `argv` with its output into `log`; the pid.
pid_t spawn(const std::vector<std::string>& argv, const fs::path& log) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::FILE* out = std::freopen(log.c_str(), "w", stdout);
    if (out == nullptr) _exit(126);
    dup2(STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

std::string output_of(const std::string& command) {
  std::string out;
  if (std::FILE* p = popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, p) != nullptr) out += buffer;
    pclose(p);
  }
  return out;
}

void stop(pid_t& pid) {
  if (pid <= 0) return;
  kill(pid, SIGTERM);
  for (int i = 0; i < 100 && waitpid(pid, nullptr, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  pid = -1;
}

}  // namespace

SlurmCluster::SlurmCluster() {
  for (const char* program : {"/usr/sbin/munged", "/usr/sbin/slurmctld", "/usr/sbin/slurmd", "/usr/bin/sbatch"})
    if (access(program, X_OK) != 0) {
      why_ = std::string(program) + " is missing (Debian's slurm-wlm and munge: scripts/setup installs them)";
      return;
    }
  if (geteuid() != 0) {
    why_ = "not root: slurmd must start job steps as any user";
    return;
  }
  if (access("/etc/munge/munge.key", R_OK) != 0) {
    why_ = "no readable /etc/munge/munge.key (the munge package makes it)";
    return;
  }
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  const std::string host = std::string(name).substr(0, std::string(name).find('.'));
  dir_ = fs::temp_directory_path() / ("cosim-slurm-" + std::to_string(getpid()));
  fs::create_directories(dir_ / "state");
  fs::copy_file("/etc/munge/munge.key", dir_ / "munge.key", fs::copy_options::overwrite_existing);
  fs::permissions(dir_ / "munge.key", fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  // Ports of this process's own (several test processes may each run a cluster), above
  // Linux's ephemeral range (32768-60999), where couplers bound to port 0 land.
  const int port = 61000 + static_cast<int>(getpid() % 1400) * 3;
  const std::string d = dir_.string();
  // Two nodes on this host, each with its own slurmd: the components of a heterogeneous
  // job do not start side by side on one node (the backfill scheduler plans whole nodes).
  nodes_ = {"cosim1", "cosim2"};
  std::ofstream conf_file(conf());
  conf_file << "ClusterName=cosimtest\nSlurmctldHost=" << host << "\nSlurmUser=root\nSlurmdUser=root\n"
            << "AuthType=auth/munge\nCredType=cred/munge\nAuthInfo=socket=" << d << "/munge.sock\n"
            << "StateSaveLocation=" << d << "/state\nSlurmdSpoolDir=" << d << "/spool/%n\n"
            << "SlurmctldPidFile=" << d << "/slurmctld.pid\nSlurmdPidFile=" << d << "/slurmd-%n.pid\n"
            << "SlurmctldPort=" << port << "\n"
            << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\nSelectType=select/cons_tres\n"
            // Heterogeneous jobs start only from the backfill scheduler; it runs every second
            // (default 30 s) so that they start at once.
            << "SchedulerType=sched/backfill\nSchedulerParameters=bf_interval=1\n"
            << "SelectTypeParameters=CR_Core\nSlurmdParameters=config_overrides\nReturnToService=2\n"
            << "MpiDefault=none\nJobAcctGatherType=jobacct_gather/none\nKillWait=5\n";
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    fs::create_directories(dir_ / "spool" / nodes_[i]);
    conf_file << "NodeName=" << nodes_[i] << " NodeHostname=" << host << " NodeAddr=127.0.0.1 Port=" << port + 1 + i
              << " CPUs=4 State=UNKNOWN\n";
  }
  conf_file << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP OverSubscribe=FORCE\n";
  conf_file.close();
  munged_ = spawn({"/usr/sbin/munged", "--foreground", "--force", "--socket=" + d + "/munge.sock",
                   "--key-file=" + d + "/munge.key", "--pid-file=" + d + "/munged.pid", "--seed-file=" + d + "/seed"},
                  dir_ / "munged.log");
  for (int i = 0; i < 100 && !fs::exists(dir_ / "munge.sock"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  slurmctld_ = spawn({"/usr/sbin/slurmctld", "-D", "-i", "-f", conf().string()}, dir_ / "slurmctld.log");
  for (const auto& node : nodes_)
    slurmd_.push_back(
        spawn({"/usr/sbin/slurmd", "-D", "-N", node, "-f", conf().string()}, dir_ / ("slurmd-" + node + ".log")));
  const std::string sinfo = "SLURM_CONF=" + conf().string() + " timeout 2 sinfo -h -t idle -o %D 2>&1";
  for (int i = 0; i < 150; ++i) {
    const std::string state = output_of(sinfo);
    if (state == std::to_string(nodes_.size()) + "\n") return;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  why_ = "the nodes did not come up within 15 s (logs in " + d + ")";
}

SlurmCluster::~SlurmCluster() {
  // A job a failed test left running would outlive slurmd (its slurmstepd does).
  if (running()) (void)output_of("SLURM_CONF=" + conf().string() + " timeout 5 scancel --full -u root 2>&1");
  for (pid_t& pid : slurmd_) stop(pid);
  stop(slurmctld_);
  stop(munged_);
  if (running() && !dir_.empty()) {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
}

}  // namespace cosim::testing
