// cosim-fluid --standalone: the scene's windows with the bodies in prescribed motion,
// written to the same run-file layout as `cosim run`, forces per body included; at the end
// rank 0 prints its steps and the seconds of each stage of them.
#pragma once

#include <filesystem>

namespace cosim::fluid::program {

// Writes `output` (empty: the scene's output.file) from rank 0; on the ranks of
// PETSC_COMM_WORLD together. Returns the exit code (0 on rank 0: the lead throws instead).
// Throws SceneError for a bad scene, std::runtime_error otherwise. PETSc must be
// initialised.
int run_fluid_standalone(const std::filesystem::path& scene_file, std::filesystem::path output);

}  // namespace cosim::fluid::program
