#include "tracker/program/standalone.hpp"

#include <chrono>
#include <cstdio>
#include <optional>

#include "coupler/participant/seconds_since.hpp"
#include "coupler/participant/standalone.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/program/tracker_file.hpp"

namespace cosim::tracker::program {
namespace {

// The tracker's run file at the start, every output.fields_every windows and the last:
// every rank gathers (the sums and the particles are collective), rank 0 writes, once it
// has said that the scene's bodies stay put.
class TrackerRecorder final : public participant::Recorder {
 public:
  TrackerRecorder(const std::filesystem::path& path, const scene::Scene& scene, const TrackerSolver& solver,
                  const parallel::Ranks& ranks)
      : scene_(scene), solver_(solver) {
    if (!ranks.lead()) return;
    if (!scene.bodies.empty())
      std::fprintf(stderr,
                   "cosim-tracker: note: --standalone keeps the scene's %zu bodies (and the obstacles bound to "
                   "them) where the scene puts them; in coupled runs the rigid-body program moves them\n",
                   scene.bodies.size());
    const tracking::Obstacles& obstacles = solver.gas().setup().obstacles;
    std::vector<std::string> names;
    for (int i = 0; i < obstacles.count(); ++i) names.push_back(obstacles.object(i).name);
    file_.emplace(path, scene, solver.grid(), names);
  }

  void record(std::uint64_t done, double time, const participant::Outputs&, double) override {
    const std::uint64_t windows = scene_.windows();
    // The start and the end always: the file is the run's only record.
    if (done != 0 && done != windows && !scene_.output.fields_at(done, windows)) return;
    const step::Simulation& gas = solver_.gas();
    Sample sample{.step = gas.steps(),
                  .time = time,
                  .particles = gas.particles(),
                  .fields = {},
                  .objects = gas.tallies(),
                  .patches = gas.patch_tallies(),
                  .moves = gas.moves()};
    // A box over several ranks is written rank by rank: no rank holds every cell's values.
    if (std::optional<TrackerSolver::FieldBlocks> blocks = solver_.field_blocks()) {
      sample.fields = std::move(blocks->frame);
      if (file_)
        file_->write(sample, blocks->each);
      else
        blocks->each({});
      return;
    }
    sample.fields = solver_.fields();
    if (file_) file_->write(sample);
  }

  void set_status(const std::string& status, double seconds) override {
    if (file_) file_->set_status(status, seconds);
  }

  std::string progress() const override { return std::to_string(solver_.gas().swarm().size()) + " particles"; }

 private:
  const scene::Scene& scene_;
  const TrackerSolver& solver_;
  std::optional<TrackerFile> file_;
};

}  // namespace

RunSummary run_tracker(const scene::Scene& scene, std::filesystem::path output, parallel::Ranks ranks) {
  const auto started = std::chrono::steady_clock::now();
  TrackerSolver solver(ranks, TrackerSolver::Draws::one_stream);
  double setup_seconds = 0.0;
  participant::run_standalone(scene, solver, "tracker", std::move(output), [&](const std::filesystem::path& file) {
    auto recorder = std::make_unique<TrackerRecorder>(file, scene, solver, ranks);
    setup_seconds = participant::seconds_since(started);
    return recorder;
  });
  const step::Simulation& gas = solver.gas();
  return {.steps = gas.steps(),
          .seeded = gas.seeded(),
          .remaining = gas.particles(),
          .injected = gas.injected(),
          .collisions = gas.collisions(),
          .migrated = gas.migrated(),
          .rebalances = gas.rebalances(),
          .moves = gas.moves(),
          .wall_seconds = participant::seconds_since(started),
          .setup_seconds = setup_seconds,
          .stages = gas.stages()};
}

}  // namespace cosim::tracker::program
