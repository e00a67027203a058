// `cosim run`: start the participants a scene needs, run its windows, write the run file,
// and end cleanly whatever happens (a participant failing, Ctrl-C).
#pragma once

#include <filesystem>
#include <optional>

namespace cosim::run {

struct RunRequest {
  std::filesystem::path scene;                  // a fresh run reads this scene
  std::optional<std::filesystem::path> resume;  // or continues this run file
  std::filesystem::path output;                 // fresh runs: overrides output.file if set
  bool progress = true;
};

// Returns the exit code: 0 finished, 1 failed (the reason is printed), 130 interrupted.
int run(const RunRequest& request);

}  // namespace cosim::run
