#include "tracker/program/standalone.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <cstdio>

#include "participant/seconds_since.hpp"
#include "tracker/program/collide.hpp"
#include "tracker/program/progress.hpp"
#include "tracker/program/scene_tracker.hpp"
#include "tracker/program/seeding.hpp"
#include "tracker/program/tracker_file.hpp"

namespace cosim::tracker {
namespace {

using clock = std::chrono::steady_clock;


// Particles per cell at this step.
std::vector<double> counts(const Swarm& swarm, Index cells) {
  std::vector<double> count(static_cast<std::size_t>(cells), 0.0);
  for (std::size_t i = 0; i < swarm.size(); ++i) count[static_cast<std::size_t>(swarm.cell(i))] += 1.0;
  return count;
}

}  // namespace

RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output) {
  const auto started = clock::now();
  const TrackerScene t = read_tracker(scene);
  if (!scene.bodies.empty())
    std::fprintf(stderr, "cosim-tracker: warning: --standalone ignores the scene's %zu bodies (obstacles are the "
                         "tracker's own; bodies move them in coupled runs)\n", scene.bodies.size());
  const Mesh& mesh = *t.mesh;
  const auto objects = static_cast<std::size_t>(t.obstacles.count());

  // One generator for the whole run, so a scene and its seed give the same run.
  Random random(t.particles.seed);
  Swarm swarm = seed_particles(mesh, t.obstacles, t.particles, random);

  if (output.empty()) output = scene.output.file;
  if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
  std::vector<std::string> names;
  for (std::size_t i = 0; i < objects; ++i) names.push_back(t.obstacles.object(static_cast<int>(i)).name);
  TrackerFile file(output, scene, mesh, names);

  RunSummary summary;
  summary.steps = static_cast<std::uint64_t>(std::llround(scene.time.end / t.dt));  // whole: scene validation
  summary.seeded = swarm.size();
  std::vector<ObstacleTally> tallies(objects);
  CellSampler sampler(mesh);
  std::optional<CellCollider> collider;
  if (t.collisions) {
    // The first (sigma g)_max per cell: at the hottest temperature the scene gives.
    double hottest = t.particles.temperature;
    for (const Inflow& inflow : t.inflows) hottest = std::max(hottest, inflow.temperature());
    collider.emplace(mesh, *t.collisions, std::max(hottest, 1.0), t.particles.weight, t.particles.seed);
  }
  const int every = scene.output.fields_every;
  const auto write = [&](std::uint64_t step) {
    std::vector<CellMoments> moments;
    for (Index c = 0; c < mesh.cell_count(); ++c) moments.push_back(sampler.moments(c, t.particles.mass, t.particles.weight));
    sampler.reset();
    file.write({.step = step,
                .time = static_cast<double>(step) * t.dt,
                .particles = swarm.size(),
                .count = counts(swarm, mesh.cell_count()),
                .moments = moments,
                .objects = tallies,
                .moves = summary.moves});
  };
  Progress progress(summary.steps, scene.time.end);
  try {
    sampler.sample(swarm);
    write(0);
    for (std::uint64_t step = 1; step <= summary.steps; ++step) {
      // In cell order, as DSMC codes keep them: a cell's particles then share its faces in cache.
      swarm.sort_by_cell(mesh.cell_count());
      if (collider) summary.collisions += collider->collide(swarm, t.dt);
      swarm.move_all(*t.domain, t.obstacles, t.dt, random, summary.moves, tallies);
      for (const Inflow& inflow : t.inflows)
        summary.injected += static_cast<std::size_t>(inflow.inject(*t.domain, t.obstacles, t.dt, random, swarm, summary.moves, tallies));
      sampler.sample(swarm);
      if ((every > 0 && step % static_cast<std::uint64_t>(every) == 0) || step == summary.steps) write(step);
      progress.update(step, static_cast<double>(step) * t.dt, swarm.size());
    }
  } catch (const std::exception& e) {
    progress.finish();
    file.set_status(std::string("failed: ") + e.what(), participant::seconds_since(started));
    throw;
  }
  progress.finish();
  summary.remaining = swarm.size();
  summary.wall_seconds = participant::seconds_since(started);
  file.set_status("finished", summary.wall_seconds);
  return summary;
}

}  // namespace cosim::tracker
