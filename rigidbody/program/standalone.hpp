// cosim-rigidbody --standalone: the scene's windows without a coupler, written to the same
// run-file layout as `cosim run`, so tools read both alike.
#pragma once

#include <filesystem>

namespace cosim::rigidbody::program {

// Runs the scene with no external forces and writes `output` (empty: the scene's
// output.file). Throws SceneError for a bad scene, std::runtime_error otherwise.
void run_standalone(const std::filesystem::path& scene_file, std::filesystem::path output);

}  // namespace cosim::rigidbody::program
