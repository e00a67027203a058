// cosim-rigidbody: the rigid-body program.
//   started by `cosim run` (COSIM_ENDPOINT set)     a coupled participant
//   cosim-rigidbody --standalone scene.yaml [-o f.h5]  the scene alone, no external forces
//   cosim-rigidbody --check scene.yaml [--work FILE]   read the bodies and the section only (cosim check),
//                                                     and write the work they give (rigid_work.hpp)
#include <CLI/CLI.hpp>

#include <spdlog/spdlog.h>

#include "coupler/participant/program_args.hpp"
#include "coupler/participant/run_participant.hpp"
#include "rigidbody/program/adapter.hpp"
#include "rigidbody/program/rigid_work.hpp"
#include "rigidbody/program/scene_world.hpp"
#include "rigidbody/program/standalone.hpp"
#include "coupler/scene/error.hpp"

int main(int argc, char** argv) {
  // The coupler prints participants' output among its own: say whose a warning is.
  spdlog::set_pattern("cosim-rigidbody: %^%l%$: %v");
  if (auto client = cosim::protocol::Client::from_environment()) {
    cosim::rigidbody::program::RigidSolver solver;
    using cosim::scene::Data;
    // Able to take forces; the coupler sends them only if some participant produces them.
    return cosim::participant::run_participant(*client, solver, static_cast<std::uint32_t>(Data::Poses),
                                               static_cast<std::uint32_t>(Data::Forces));
  }

  CLI::App app{"cosim-rigidbody: rigid bodies with contacts; coupled through cosim run, or --standalone"};
  cosim::participant::ProgramArgs args;
  cosim::participant::add_program_args(app, args, "Run this scene without a coupler", "bodies and rigidbody section");
  CLI11_PARSE(app, argc, argv);

  return cosim::scene::exit_code("cosim-rigidbody", [&] {
    if (!args.check.empty()) {
      const cosim::scene::Scene scene = cosim::scene::load_scene(args.check);
      const cosim::rigidbody::program::ProgramOptions options = cosim::rigidbody::program::program_options(scene);
      cosim::rigidbody::program::make_world(scene, options);
      if (!args.work.empty())
        cosim::participant::write_work(args.work, cosim::rigidbody::program::rigid_work(scene, options));
    } else {
      cosim::rigidbody::program::run_standalone(args.standalone, args.output);
    }
    return 0;
  });
}
