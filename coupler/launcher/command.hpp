// The command line that starts a participant.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::launcher {

// The scene's `command`, or `cosim-<name>` for a built-in. A bare program name is looked
// up next to the cosim executable first (a build or install tree keeps its programs
// together), then on PATH. With ranks > 1 the command runs under `mpirun -n ranks`; placed
// on other hosts, under mpirun or srun as placed_command() says.
// Throws scene::SceneError naming participants.<name>.command when it cannot be found,
// so a wrong scene fails before any process starts.
std::vector<std::string> participant_command(const scene::Scene& scene, const scene::Participant& p,
                                             const std::filesystem::path& programs_dir);

// `program` as found next to cosim (programs_dir) or on PATH; a path with a '/' is taken as
// is. nullopt when there is no such executable.
std::optional<std::filesystem::path> find_program(const std::string& program,
                                                  const std::filesystem::path& programs_dir);

// Variables Open MPI needs to run as root and on one host, added to what the child
// inherits (never overriding what the user set). Across hosts the ranks must also be free
// to talk over the network, so shared memory is not made the only transport.
std::map<std::string, std::string> mpi_environment(bool across_hosts = false);

// True for a variable by which Open MPI tells a process it is a rank (or singleton) of a
// job: PMIX_*, OMPI_* but for the user's OMPI_MCA_* and OMPI_ALLOW_* settings, and the MCA
// settings of a launched job (ess, orte_*, pmix). An mpirun that inherits them (cosim
// started from an MPI program, such as a test that initialised PETSc) tries to join that
// job and fails, so participants are started without them.
bool describes_enclosing_mpi_job(std::string_view variable);

// Folder holding the running executable.
std::filesystem::path own_directory();

}  // namespace cosim::launcher
