// The 10-box stack of tests/rigidbody/world/stack_test.cpp over 10,000 steps (or argv[1]) with at most argv[2] solver
// iterations per step (default: the preset's), with timings.
#include <cstdio>
#include <cstdlib>

#include "tests/rigidbody/world/stack_check.hpp"

int main(int argc, char** argv) {
  using namespace cosim::rigidbody::world::test;
  const int steps = argc > 1 ? std::atoi(argv[1]) : 10000;
  const StackResult r = run_box_stack(steps, argc > 2 ? std::atoi(argv[2]) : 0);
  std::printf("boxes %d  steps %d  box %.3g m\n", kStackBoxes, steps, r.box_size);
  std::printf("horizontal drift %.3e m (%.3e of box)  vertical shift %.3e m  max speed %.3e m/s\n", r.horizontal_drift,
              r.horizontal_drift / r.box_size, r.vertical_shift, r.max_speed);
  std::printf("converged in %d of %d steps  iterations: worst %d, mean %.1f  wall %.3f s (%.1f us/step)\n",
              r.converged_steps, steps, r.worst_iterations, r.mean_iterations, r.wall_seconds,
              1e6 * r.wall_seconds / steps);
  return r.horizontal_drift < 0.01 * r.box_size ? 0 : 1;
}
