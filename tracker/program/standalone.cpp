#include "tracker/program/standalone.hpp"

#include <chrono>
#include <cstdio>
#include <optional>

#include "coupler/participant/seconds_since.hpp"
#include "tracker/program/output_grid.hpp"
#include "tracker/program/particle_dump.hpp"
#include "tracker/program/progress.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/tracker_file.hpp"
#include "tracker/step/simulation.hpp"

namespace cosim::tracker {

RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output, Ranks ranks) {
  const auto started = std::chrono::steady_clock::now();
  TrackerScene setup = read_tracker(scene, ranks);
  const std::optional<ParticleOutput> particle_output = setup.particle_output;
  Simulation gas(std::move(setup), ranks);
  if (!scene.bodies.empty() && ranks.lead())
    std::fprintf(stderr, "cosim-tracker: note: --standalone keeps the scene's %zu bodies (and the obstacles bound to "
                         "them) where the scene puts them; in coupled runs the rigid-body program moves them\n",
                 scene.bodies.size());

  if (output.empty()) output = scene.output.file;
  std::optional<TrackerFile> file;
  if (ranks.lead()) {
    if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
    std::vector<std::string> names;
    for (int i = 0; i < gas.setup().obstacles.count(); ++i) names.push_back(gas.setup().obstacles.object(i).name);
    file.emplace(output, scene, output_grid(gas), names);
  }

  RunSummary summary;
  summary.setup_seconds = participant::seconds_since(started);
  const std::uint64_t windows = scene.windows();
  // Every rank gathers (the sums and the particles are collective), rank 0 writes.
  const auto write = [&](std::uint64_t done, double time) {
    std::vector<field::PointSet> point_sets;
    if (particle_output && particle_output->at(done, windows)) point_sets.push_back(particle_set(gas, *particle_output));
    const std::vector<double> count = gas.counts();
    const std::vector<CellMoments> moments = gas.take_moments();
    const std::vector<ObstacleTally> tallies = gas.tallies();
    const std::vector<SurfaceTally> patches = gas.patch_tallies();
    const MoveTally moves = gas.moves();
    const std::size_t particles = gas.particles();
    if (file)
      file->write({.step = gas.steps(),
                   .time = time,
                   .particles = particles,
                   .count = count,
                   .moments = moments,
                   .objects = tallies,
                   .patches = patches,
                   .moves = moves,
                   .point_sets = std::move(point_sets)});
  };
  // Shown only on a terminal, and no rank's stderr is one under mpirun: its count is the run's.
  Progress progress(windows, scene.time.end);
  try {
    write(0, 0.0);
    for (std::uint64_t k = 0; k < windows; ++k) {
      // Window bounds computed as the coupler does, so both runs take identical steps.
      const double t1 = static_cast<double>(k + 1) * scene.coupling.window;
      gas.advance(static_cast<double>(k) * scene.coupling.window, t1);
      // The start and the end always: the file is the run's only record.
      if (scene.output.fields_at(k + 1, windows) || k + 1 == windows) write(k + 1, t1);
      progress.update(k + 1, t1, gas.swarm().size());
    }
  } catch (const std::exception& e) {
    progress.finish();
    if (file) file->set_status(std::string("failed: ") + e.what(), participant::seconds_since(started));
    throw;
  }
  progress.finish();
  summary.steps = gas.steps();
  summary.seeded = gas.seeded();
  summary.injected = gas.injected();
  summary.remaining = gas.particles();
  summary.migrated = gas.migrated();
  summary.rebalances = gas.rebalances();
  summary.stages = gas.stages();
  summary.collisions = gas.collisions();
  summary.moves = gas.moves();
  summary.wall_seconds = participant::seconds_since(started);
  if (file) file->set_status("finished", summary.wall_seconds);
  return summary;
}

}  // namespace cosim::tracker
