// cosim-fluid: the fluid program.
//   started by `cosim run` (COSIM_ENDPOINT set)       a coupled participant
//   cosim-fluid --standalone scene.yaml [-o f.h5]      bodies in prescribed motion
//   cosim-fluid --check scene.yaml [--work FILE]       read the fluid section only (cosim check),
//                                                      and write the work it gives (fluid_work.hpp)
// Arguments CLI11 does not know (-ksp_*, -pc_*, -log_view ...) go to PETSc. Under mpirun
// rank 0 talks to the coupler or writes the run file, the others follow (mpi_team.hpp).
#include <CLI/CLI.hpp>
#include <petscsys.h>

#include <cstdlib>
#include <functional>

#include <spdlog/spdlog.h>

#include "fluid/program/adapter.hpp"
#include "fluid/program/fluid_work.hpp"
#include "fluid/program/scene_fluid.hpp"
#include "fluid/program/standalone.hpp"
#include "coupler/participant/mpi_team.hpp"
#include "coupler/participant/program_args.hpp"
#include "coupler/participant/run_participant.hpp"
#include "coupler/scene/error.hpp"

namespace {

int coupled() {
  cosim::fluid::program::FluidSolver solver;
  return cosim::participant::run_on_ranks(solver, PETSC_COMM_WORLD, [](cosim::participant::Solver& lead) {
    using cosim::scene::Data;
    int ranks = 1;
    MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
    auto client = cosim::protocol::Client::from_environment();
    // Able to take poses and give forces and fields; the coupler's plan decides what flows.
    return cosim::participant::run_participant(
        *client, lead, static_cast<std::uint32_t>(Data::Forces) | static_cast<std::uint32_t>(Data::Fields),
        static_cast<std::uint32_t>(Data::Poses), static_cast<std::uint32_t>(ranks));
  });
}

// PETSc sees only the arguments meant for it, and is finalised after every solver is gone.
int with_petsc(std::vector<std::string> args, const std::function<int()>& body) {
  args.insert(args.begin(), "cosim-fluid");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int argc = static_cast<int>(args.size());
  char** p = argv.data();
  if (PetscInitialize(&argc, &p, nullptr, nullptr) != 0) return 1;
  const int code = body();
  PetscFinalize();
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // The coupler prints participants' output among its own: say whose a warning is.
  spdlog::set_pattern("cosim-fluid: %^%l%$: %v");
  if (std::getenv(cosim::protocol::kEndpointEnv) != nullptr) return with_petsc({argv + 1, argv + argc}, coupled);

  CLI::App app{
      "cosim-fluid: Navier-Stokes with rigid bodies inside (immersed boundary or staircase); coupled through cosim run, or --standalone"};
  app.allow_extras();
  cosim::participant::ProgramArgs args;
  cosim::participant::add_program_args(app, args, "Run this scene with the bodies in prescribed motion",
                                       "fluid section");
  CLI11_PARSE(app, argc, argv);
  return with_petsc(app.remaining(), [&] {
    return cosim::scene::exit_code("cosim-fluid", [&] {
      if (!args.check.empty()) {
        const cosim::scene::Scene scene = cosim::scene::load_scene(args.check);
        const cosim::fluid::program::FluidSetup setup = cosim::fluid::program::fluid_setup(scene);
        if (!args.work.empty())
          cosim::participant::write_work(args.work, cosim::fluid::program::fluid_work(setup, scene));
        return 0;
      }
      return cosim::fluid::program::run_fluid_standalone(args.standalone, args.output);
    });
  });
}
