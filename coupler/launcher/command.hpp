// The command line that starts a participant.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace cosim::launcher {

// The scene's `command`, or `cosim-<name>` for a built-in. A bare program name is looked
// up next to the cosim executable first (a build or install tree keeps its programs
// together), then on PATH. With ranks > 1 the command runs under `mpirun -n ranks`.
// Throws scene::SceneError naming participants.<name>.command when it cannot be found,
// so a wrong scene fails before any process starts.
std::vector<std::string> participant_command(const scene::Scene& scene,
                                             const scene::Participant& p,
                                             const std::filesystem::path& programs_dir);

// Variables Open MPI needs to run as root and on one host, added to what the child
// inherits (never overriding what the user set).
std::map<std::string, std::string> mpi_environment();

// Folder holding the running executable.
std::filesystem::path own_directory();

}  // namespace cosim::launcher
