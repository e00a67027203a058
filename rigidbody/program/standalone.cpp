#include "rigidbody/program/standalone.hpp"

#include "participant/standalone.hpp"
#include "rigidbody/program/adapter.hpp"

namespace cosim::program {

void run_standalone(const std::filesystem::path& scene_file, std::filesystem::path output) {
  RigidSolver solver;
  participant::run_standalone(scene::load_scene(scene_file), solver, "rigidbody", std::move(output));
}

}  // namespace cosim::program
