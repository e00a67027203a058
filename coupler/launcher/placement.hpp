// Starting a participant's ranks on other hosts, through the engines the cluster already
// has: srun inside a Slurm allocation, mpirun (Open MPI) elsewhere. No remote shell of ours.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::launcher {

// The launcher (mpirun, srun) next to cosim or on PATH; scene::SceneError naming `key`
// and `value` (what asked for it) if there is none.
std::string launcher_path(const scene::Scene& scene, const scene::Participant& p, const std::string& launcher,
                          const std::filesystem::path& programs_dir, const std::string& key, const std::string& value);

// Inside a Slurm allocation: SLURM_JOB_ID is set (sbatch, salloc).
bool inside_slurm();

// `program` (its resolved command line) started where p.placement says, on p.ranks ranks:
//   Slurm:  srun --nodelist=a,b --nodes=2 --ntasks=R --exact program    (hosts: [a, b])
//           srun --nodefile=F --ntasks=R --exact program                (hostfile: F)
//           srun --het-group=K --ntasks=R program                       (het_group: K)
//           srun --ntasks=R --exact program                             (hosts: scheduler)
//   otherwise: mpirun -n R --host a,b | --hostfile F, with -x for each of `forwarded`, the
//           variables the coupler sets for its participants (srun passes the whole
//           environment by default; mpirun passes only what -x names to other hosts).
// Throws scene::SceneError naming the key when the launcher is missing, or the placement
// needs Slurm outside an allocation.
std::vector<std::string> placed_command(const scene::Scene& scene, const scene::Participant& p,
                                        std::vector<std::string> program, const std::filesystem::path& programs_dir,
                                        const std::vector<std::string>& forwarded);

}  // namespace cosim::launcher
