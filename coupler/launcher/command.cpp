#include "coupler/launcher/command.hpp"

#include <unistd.h>

#include <cstdlib>
#include <optional>
#include <sstream>

#include "coupler/launcher/placement.hpp"
#include "coupler/protocol/client.hpp"
#include "coupler/protocol/curve.hpp"
#include "coupler/scene/error.hpp"
#include "coupler/scene/plan.hpp"

namespace cosim::launcher {
namespace fs = std::filesystem;
namespace {

bool executable(const fs::path& p) { return fs::is_regular_file(p) && access(p.c_str(), X_OK) == 0; }

}  // namespace

std::optional<fs::path> find_program(const std::string& program, const fs::path& programs_dir) {
  if (program.find('/') != std::string::npos)
    return executable(program) ? std::optional<fs::path>(program) : std::nullopt;
  if (executable(programs_dir / program)) return programs_dir / program;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && executable(fs::path(dir) / program)) return fs::path(dir) / program;
  return std::nullopt;
}

std::vector<std::string> participant_command(const scene::Scene& scene, const scene::Participant& p,
                                             const fs::path& programs_dir) {
  std::vector<std::string> command = p.command;
  if (command.empty() && scene::is_builtin(p.name)) command = {"cosim-" + p.name};
  const std::string key = "participants." + p.name + ".command";
  if (command.empty()) throw scene::SceneError(scene.file.string(), p.line, key, "", "no command to start it");
  const auto program = find_program(command[0], programs_dir);
  if (!program)
    throw scene::SceneError(scene.file.string(), p.line, key, command[0],
                            "program not found next to cosim (" + programs_dir.string() + ") nor on PATH");
  command[0] = program->string();
  if (!p.placement.local())
    return placed_command(
        scene, p, std::move(command), programs_dir,
        {protocol::kEndpointEnv, protocol::kParticipantEnv, protocol::kHeartbeatEnv, protocol::curve::kServerKeyEnv,
         protocol::curve::kPublicKeyEnv, protocol::curve::kSecretKeyEnv});
  if (p.ranks > 1)
    command.insert(command.begin(), {launcher_path(scene, p, "mpirun", programs_dir,
                                                   "participants." + p.name + ".ranks", std::to_string(p.ranks)),
                                     "-n", std::to_string(p.ranks)});
  return command;
}

std::map<std::string, std::string> mpi_environment(bool across_hosts) {
  std::map<std::string, std::string> env;
  const auto add = [&env](const char* key, const char* value) {
    if (std::getenv(key) == nullptr) env[key] = value;
  };
  if (geteuid() == 0) {
    add("OMPI_ALLOW_RUN_AS_ROOT", "1");
    add("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1");
  }
  add("OMPI_MCA_rmaps_base_oversubscribe", "1");
  if (!across_hosts) add("OMPI_MCA_btl", "self,vader");
  return env;
}

bool describes_enclosing_mpi_job(std::string_view variable) {
  if (variable.starts_with("PMIX_")) return true;
  if (!variable.starts_with("OMPI_")) return false;
  if (variable == "OMPI_MCA_ess" || variable == "OMPI_MCA_pmix" || variable.starts_with("OMPI_MCA_orte_")) return true;
  return !variable.starts_with("OMPI_MCA_") && !variable.starts_with("OMPI_ALLOW_");
}

fs::path own_directory() { return fs::read_symlink("/proc/self/exe").parent_path(); }

}  // namespace cosim::launcher
