#include "fluid/program/standalone.hpp"

#include <petscsys.h>

#include "fluid/program/adapter.hpp"
#include "participant/mpi_team.hpp"
#include "participant/standalone.hpp"

namespace cosim::program {

int run_fluid_standalone(const std::filesystem::path& scene_file, std::filesystem::path output) {
  FluidSolver solver(true);
  return participant::run_on_ranks(solver, PETSC_COMM_WORLD, [&](participant::Solver& lead) {
    participant::run_standalone(scene::load_scene(scene_file), lead, "fluid", std::move(output));
    return 0;
  });
}

}  // namespace cosim::program
