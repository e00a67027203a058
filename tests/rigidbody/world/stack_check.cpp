#include "tests/rigidbody/world/stack_check.hpp"

#include <algorithm>

#include "tests/rigidbody/world/scenes.hpp"

namespace cosim::rigidbody::world::test {

StackResult run_box_stack(int steps, int iterations) {
  constexpr double kHalf = 0.1;
  World world({.solver = SolverKind::sequential_impulses, .iterations = iterations});
  add_ground(world);
  const std::vector<std::uint32_t> boxes = add_box_stack(world, kStackBoxes, kHalf);
  std::vector<Eigen::Vector3d> start;
  for (auto b : boxes) start.push_back(world.states()[b].position);
  StackResult r{.box_size = 2 * kHalf};
  for (int i = 0; i < steps; ++i) {
    const StepReport step = world.advance(world.settings().dt);
    r.converged = r.converged && step.converged;
    r.converged_steps += step.converged ? 1 : 0;
    r.worst_iterations = std::max(r.worst_iterations, step.solver_iterations);
    r.mean_iterations += static_cast<double>(step.solver_iterations) / steps;
    r.wall_seconds += step.wall_seconds;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      const auto& s = world.states()[boxes[k]];
      const Eigen::Vector3d shift = s.position - start[k];
      r.horizontal_drift = std::max(r.horizontal_drift, shift.head<2>().norm());
      r.vertical_shift = std::max(r.vertical_shift, std::abs(shift.z()));
      r.max_speed = std::max(r.max_speed, s.velocity.norm());
    }
  }
  return r;
}

}  // namespace cosim::rigidbody::world::test
