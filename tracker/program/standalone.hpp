// cosim-tracker --standalone: the scene's gas without a coupler, window by window as
// `cosim run` steps it (Simulation::advance), written to the tracker's run file
// (tracker_file.hpp) at the start, every output.fields_every windows and the last.
#pragma once

#include <filesystem>

#include "scene/scene.hpp"
#include "tracker/tracking/move.hpp"

namespace cosim::tracker {

struct RunSummary {
  std::uint64_t steps = 0;
  std::size_t seeded = 0, remaining = 0;  // particles at the start and the end
  std::size_t injected = 0;               // entered through inflow patches: remaining =
                                          // seeded + injected - moves.removed
  std::int64_t collisions = 0;            // DSMC collisions, if the scene has them
  MoveTally moves;
  double wall_seconds = 0.0;
};

// Writes `output` (empty: the scene's output.file). Throws scene::SceneError for a bad
// scene, std::runtime_error otherwise (the file then says "failed: ..." in /run status).
RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output);

}  // namespace cosim::tracker
