// cosim-rigidbody: the rigid-body program.
//   started by `cosim run` (COSIM_ENDPOINT set)     a coupled participant
//   cosim-rigidbody --standalone scene.yaml [-o f.h5]  the scene alone, no external forces
//   cosim-rigidbody --check scene.yaml                 read the bodies and the section only (cosim check)
#include <CLI/CLI.hpp>

#include <spdlog/spdlog.h>

#include "participant/run_participant.hpp"
#include "rigidbody/program/adapter.hpp"
#include "rigidbody/program/scene_world.hpp"
#include "rigidbody/program/standalone.hpp"
#include "scene/error.hpp"

int main(int argc, char** argv) {
  // The coupler prints participants' output among its own: say whose a warning is.
  spdlog::set_pattern("cosim-rigidbody: %^%l%$: %v");
  if (auto client = cosim::protocol::Client::from_environment()) {
    cosim::program::RigidSolver solver;
    using cosim::scene::Data;
    // Able to take forces; the coupler sends them only if some participant produces them.
    return cosim::participant::run_participant(*client, solver, static_cast<std::uint32_t>(Data::Poses),
                                               static_cast<std::uint32_t>(Data::Forces));
  }

  CLI::App app{"cosim-rigidbody: rigid bodies with contacts; coupled through cosim run, or --standalone"};
  std::string scene, checked, output;
  auto* mode = app.add_option_group("mode");
  mode->add_option("--standalone", scene, "Run this scene without a coupler");
  mode->add_option("--check", checked, "Read this scene's bodies and rigidbody section as a run would, and say what is wrong");
  mode->require_option(1);
  app.add_option("-o,--output", output, "Run file to write (default: the scene's output.file)");
  CLI11_PARSE(app, argc, argv);

  return cosim::scene::exit_code("cosim-rigidbody", [&] {
    if (!checked.empty()) {
      const auto s = cosim::scene::load_scene(checked);
      cosim::program::make_world(s, cosim::program::program_options(s));
    } else {
      cosim::program::run_standalone(scene, output);
    }
    return 0;
  });
}
