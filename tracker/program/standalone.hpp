// cosim-tracker --standalone: the scene's gas without a coupler, window by window through
// its participant (adapter.hpp) as `cosim run` steps it (participant::run_standalone),
// written to the tracker's run file (tracker_file.hpp) at the start, every
// output.fields_every windows and the last, with the particles where particle_output asks
// for them (scene_particle_output.hpp).
// Over several ranks (`mpirun -n N cosim-tracker --standalone`) every rank runs it on its
// cells' particles and rank 0 alone writes the file, of the sums over the ranks.
#pragma once

#include <filesystem>

#include "coupler/scene/scene.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/step/stages.hpp"
#include "tracker/tracking/move.hpp"

namespace cosim::tracker::program {

struct RunSummary {
  std::uint64_t steps = 0;
  std::size_t seeded = 0, remaining = 0;  // particles at the start and the end
  std::size_t injected = 0;               // entered through inflow patches: remaining =
                                          // seeded + injected - moves.removed
  std::int64_t collisions = 0;            // DSMC collisions, if the scene has them
  std::size_t migrated = 0;               // particles sent between ranks
  std::uint64_t rebalances = 0;           // re-partitions by particles (scene_balance.hpp)
  tracking::MoveTally moves;
  double wall_seconds = 0.0;
  double setup_seconds = 0.0;  // of this rank: the mesh built, the gas seeded, the file made
  step::StageSeconds stages;   // of this rank's steps
};

// Writes `output` (empty: the scene's output.file). Throws scene::SceneError for a bad
// scene, std::runtime_error otherwise (the file then says "failed: ..." in /run status),
// lost particles included (a tracking bug). Collective over `ranks`; the summary is the
// totals over them, on every rank.
RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output, parallel::Ranks ranks = {});

}  // namespace cosim::tracker::program
