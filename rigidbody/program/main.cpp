// cosim-rigidbody: the rigid-body program.
//   started by `cosim run` (COSIM_ENDPOINT set)     a coupled participant
//   cosim-rigidbody --standalone scene.yaml [-o f.h5]  the scene alone, no external forces
#include <CLI/CLI.hpp>

#include <spdlog/spdlog.h>

#include "participant/run_participant.hpp"
#include "rigidbody/program/adapter.hpp"
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
  std::string scene, output;
  app.add_option("--standalone", scene, "Run this scene without a coupler")->required();
  app.add_option("-o,--output", output, "Run file to write (default: the scene's output.file)");
  CLI11_PARSE(app, argc, argv);

  return cosim::scene::exit_code("cosim-rigidbody", [&] {
    cosim::program::run_standalone(scene, output);
    return 0;
  });
}
