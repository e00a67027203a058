// Runs the real cosim-rigidbody (next to the test binary) with --standalone.
#pragma once

#include <filesystem>

namespace cosim::testing {

// Its exit code, or -1 if it did not exit normally. Output is discarded.
int run_standalone(const std::filesystem::path& scene, const std::filesystem::path& out);

}  // namespace cosim::testing
