// cosim-tracker: the tracker program.
//   started by `cosim run` (COSIM_ENDPOINT set)         a coupled participant (adapter.hpp)
//   cosim-tracker --standalone scene.yaml [-o f.h5]     particles among the scene's obstacles
#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>

#include "participant/run_participant.hpp"
#include "protocol/client.hpp"
#include "scene/error.hpp"
#include "tracker/program/adapter.hpp"
#include "tracker/program/standalone.hpp"

int main(int argc, char** argv) {
  if (std::getenv(cosim::protocol::kEndpointEnv) != nullptr) {
    using cosim::scene::Data;
    cosim::tracker::TrackerSolver solver;
    auto client = cosim::protocol::Client::from_environment();
    // Able to take poses and give forces; the coupler's plan decides what flows.
    return cosim::participant::run_participant(*client, solver, static_cast<std::uint32_t>(Data::Forces),
                                               static_cast<std::uint32_t>(Data::Poses));
  }
  CLI::App app{"cosim-tracker: ballistic particles through polyhedral meshes among CSG obstacles"};
  std::string scene, output;
  app.add_option("--standalone", scene, "Run this scene's tracker alone")->required();
  app.add_option("-o,--output", output, "Run file to write (default: the scene's output.file)");
  CLI11_PARSE(app, argc, argv);
  return cosim::scene::exit_code("cosim-tracker", [&] {
    const cosim::tracker::RunSummary s = cosim::tracker::run_tracker(cosim::scene::load_scene(scene), output);
    std::fprintf(stderr, "cosim-tracker: %llu steps, %zu particles seeded, %zu entered, %zu remain, %lld collisions, %.2f s\n  %s\n",
                 static_cast<unsigned long long>(s.steps), s.seeded, s.injected, s.remaining,
                 static_cast<long long>(s.collisions), s.wall_seconds,
                 cosim::tracker::summary(s.moves).c_str());
    if (s.moves.lost > 0) {
      std::fprintf(stderr, "cosim-tracker: %lld particles lost (outside their cells): a tracking bug\n", s.moves.lost);
      return 1;
    }
    return 0;
  });
}
