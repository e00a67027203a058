#include "fluid/program/standalone.hpp"

#include "fluid/program/adapter.hpp"
#include "participant/standalone.hpp"

namespace cosim::program {

void run_fluid_standalone(const std::filesystem::path& scene_file, std::filesystem::path output) {
  FluidSolver solver(true);
  participant::run_standalone(scene::load_scene(scene_file), solver, "fluid", std::move(output));
}

}  // namespace cosim::program
