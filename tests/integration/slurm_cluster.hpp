// A real Slurm on this machine, for the tests of runs inside an allocation: munged,
// slurmctld and slurmd (Debian's slurm-wlm and munge) started in the foreground from a
// configuration written into a temporary folder, two nodes on this host (a slurmd each) with
// 4 CPUs that oversubscribe, so that several srun steps and the components of a
// heterogeneous job fit side by side. `why()` says why not where the machine cannot run the
// daemons.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::testing {

class SlurmCluster {
 public:
  SlurmCluster();   // not running if it could not be started: see why()
  ~SlurmCluster();  // stops the daemons
  SlurmCluster(const SlurmCluster&) = delete;
  SlurmCluster& operator=(const SlurmCluster&) = delete;

  bool running() const { return why_.empty(); }
  const std::string& why() const { return why_; }
  const std::vector<std::string>& nodes() const { return nodes_; }
  // slurm.conf, for SLURM_CONF: the clients (sbatch, srun, scancel) find the cluster by it.
  std::filesystem::path conf() const { return dir_ / "slurm.conf"; }

 private:
  std::filesystem::path dir_;
  std::vector<std::string> nodes_;
  std::string why_;
  pid_t munged_ = -1, slurmctld_ = -1;
  std::vector<pid_t> slurmd_;
};

}  // namespace cosim::testing
