#include "rigidbody/program/rigid_work.hpp"

#include <algorithm>

namespace cosim::rigidbody::program {

participant::WorkReport rigid_work(const scene::Scene& scene, const ProgramOptions& options) {
  const auto moving =
      std::count_if(scene.bodies.begin(), scene.bodies.end(), [](const scene::Body& b) { return !b.fixed; });
  // The walls are fixed half-spaces in the world like any body: held, never stepped.
  const std::size_t held = scene.bodies.size() + options.walls.size();
  // The soft step splits each dt into its substeps where there is something to touch
  // (world/step.cpp); its cost is per substep.
  const world::Settings& s = options.settings;
  const bool split = s.contact && held > 1 && s.solver == world::SolverKind::soft && s.soft.substeps > 1;
  return {.program = "rigidbody",
          .per_step = {{"bodies", static_cast<std::uint64_t>(moving)}},
          .held = {{"bodies", held}},
          .frame_bytes = 0,
          // RigidSolver::state: the time and each body's pose (13), the contacts' memory aside.
          .state_bytes = (1 + 13 * scene.bodies.size()) * sizeof(double),
          .dt = split ? s.dt / s.soft.substeps : 0.0};
}

}  // namespace cosim::rigidbody::program
