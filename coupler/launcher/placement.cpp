#include "coupler/launcher/placement.hpp"

#include <cstdlib>

#include "coupler/launcher/command.hpp"
#include "coupler/scene/error.hpp"

namespace cosim::launcher {
namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ",") + s;
  return out;
}

// The key that placed the participant, for errors.
std::string placement_key(const scene::Participant& p) {
  const auto& pl = p.placement;
  return "participants." + p.name + "." +
         (pl.hostfile.empty() ? pl.het_group >= 0 ? "het_group" : "hosts" : "hostfile");
}

std::string placement_value(const scene::Participant& p) {
  const auto& pl = p.placement;
  if (!pl.hostfile.empty()) return pl.hostfile.string();
  if (pl.het_group >= 0) return std::to_string(pl.het_group);
  return pl.scheduler ? "scheduler" : "[" + joined(pl.hosts) + "]";
}

}  // namespace

std::string launcher_path(const scene::Scene& scene, const scene::Participant& p, const std::string& launcher,
                          const std::filesystem::path& programs_dir, const std::string& key, const std::string& value) {
  const auto found = find_program(launcher, programs_dir);
  if (!found) throw scene::SceneError(scene.file.string(), p.line, key, value, launcher + " not found on PATH");
  return found->string();
}

bool inside_slurm() { return std::getenv("SLURM_JOB_ID") != nullptr; }

std::vector<std::string> placed_command(const scene::Scene& scene, const scene::Participant& p,
                                        std::vector<std::string> program, const std::filesystem::path& programs_dir,
                                        const std::vector<std::string>& forwarded) {
  const auto& pl = p.placement;
  const std::string tasks = "--ntasks=" + std::to_string(p.ranks);
  std::vector<std::string> command;
  if (inside_slurm()) {
    // --exact: each participant's step gets only what it asks for, so that the steps of
    // one allocation run side by side instead of waiting for each other.
    command = {launcher_path(scene, p, "srun", programs_dir, placement_key(p), placement_value(p))};
    if (!pl.hosts.empty())
      command.insert(command.end(), {"--nodelist=" + joined(pl.hosts), "--nodes=" + std::to_string(pl.hosts.size()),
                                     tasks, "--exact"});
    else if (!pl.hostfile.empty())
      command.insert(command.end(), {"--nodefile=" + pl.hostfile.string(), tasks, "--exact"});
    else if (pl.het_group >= 0)
      command.insert(command.end(), {"--het-group=" + std::to_string(pl.het_group), tasks});
    else
      command.insert(command.end(), {tasks, "--exact"});
  } else {
    if (pl.het_group >= 0 || pl.scheduler)
      throw scene::SceneError(scene.file.string(), p.line, placement_key(p), placement_value(p),
                              "needs a Slurm allocation (SLURM_JOB_ID is not set): run cosim inside the job "
                              "script given to sbatch");
    command = {launcher_path(scene, p, "mpirun", programs_dir, placement_key(p), placement_value(p)), "-n",
               std::to_string(p.ranks)};
    if (!pl.hosts.empty())
      command.insert(command.end(), {"--host", joined(pl.hosts)});
    else
      command.insert(command.end(), {"--hostfile", pl.hostfile.string()});
    for (const auto& name : forwarded) command.insert(command.end(), {"-x", name});
  }
  command.insert(command.end(), program.begin(), program.end());
  return command;
}

}  // namespace cosim::launcher
