// cosim-fluid --standalone: the scene's windows with the bodies in prescribed motion,
// written to the same run-file layout as `cosim run`, forces per body included.
#pragma once

#include <filesystem>

namespace cosim::program {

// Writes `output` (empty: the scene's output.file). Throws SceneError for a bad scene,
// std::runtime_error otherwise. PETSc must be initialised.
void run_fluid_standalone(const std::filesystem::path& scene_file, std::filesystem::path output);

}  // namespace cosim::program
