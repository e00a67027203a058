#include "tracker/program/standalone.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "participant/seconds_since.hpp"
#include "tracker/program/progress.hpp"
#include "tracker/program/simulation.hpp"
#include "tracker/program/tracker_file.hpp"

namespace cosim::tracker {

RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output) {
  const auto started = std::chrono::steady_clock::now();
  Simulation gas(scene);
  if (!scene.bodies.empty())
    std::fprintf(stderr, "cosim-tracker: note: --standalone keeps the scene's %zu bodies (and the obstacles bound to "
                         "them) where the scene puts them; in coupled runs the rigid-body program moves them\n",
                 scene.bodies.size());
  const double dt = gas.setup().dt;

  if (output.empty()) output = scene.output.file;
  if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
  std::vector<std::string> names;
  for (int i = 0; i < gas.setup().obstacles.count(); ++i) names.push_back(gas.setup().obstacles.object(i).name);
  TrackerFile file(output, scene, gas.mesh(), names);

  RunSummary summary;
  summary.steps = static_cast<std::uint64_t>(std::llround(scene.time.end / dt));  // whole: scene validation
  const int every = scene.output.fields_every;
  const auto write = [&](std::uint64_t step) {
    const std::vector<double> count = gas.counts();
    const std::vector<CellMoments> moments = gas.take_moments();
    file.write({.step = step,
                .time = static_cast<double>(step) * dt,
                .particles = gas.swarm().size(),
                .count = count,
                .moments = moments,
                .objects = gas.tallies(),
                .moves = gas.moves()});
  };
  Progress progress(summary.steps, scene.time.end);
  try {
    write(0);
    for (std::uint64_t step = 1; step <= summary.steps; ++step) {
      gas.step(dt);
      if ((every > 0 && step % static_cast<std::uint64_t>(every) == 0) || step == summary.steps) write(step);
      progress.update(step, static_cast<double>(step) * dt, gas.swarm().size());
    }
  } catch (const std::exception& e) {
    progress.finish();
    file.set_status(std::string("failed: ") + e.what(), participant::seconds_since(started));
    throw;
  }
  progress.finish();
  summary.seeded = gas.seeded();
  summary.injected = gas.injected();
  summary.remaining = gas.swarm().size();
  summary.collisions = gas.collisions();
  summary.moves = gas.moves();
  summary.wall_seconds = participant::seconds_since(started);
  file.set_status("finished", summary.wall_seconds);
  return summary;
}

}  // namespace cosim::tracker
