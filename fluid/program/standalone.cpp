#include "fluid/program/standalone.hpp"

#include <petscsys.h>

#include <cstdio>

#include "fluid/program/adapter.hpp"
#include "coupler/participant/mpi_team.hpp"
#include "coupler/participant/stage_summary.hpp"
#include "coupler/participant/standalone.hpp"

namespace cosim::fluid::program {

int run_fluid_standalone(const std::filesystem::path& scene_file, std::filesystem::path output) {
  FluidSolver solver(true);
  return participant::run_on_ranks(solver, PETSC_COMM_WORLD, [&](participant::Solver& lead) {
    participant::run_standalone(scene::load_scene(scene_file), lead, "fluid", std::move(output));
    std::fprintf(stderr, "cosim-fluid: %zu steps: %s\n", solver.steps(),
                 participant::stage_summary(fluid::navier_stokes::kStageNames, solver.stage_seconds().all()).c_str());
    return 0;
  });
}

}  // namespace cosim::fluid::program
