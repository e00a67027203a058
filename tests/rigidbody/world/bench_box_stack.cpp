// The 10-box stack over 10,000 steps (or argv[1]), with timings.
#include <cstdio>
#include <cstdlib>

#include "stack_check.hpp"

int main(int argc, char** argv) {
  using namespace cosim::world::test;
  const int steps = argc > 1 ? std::atoi(argv[1]) : 10000;
  const StackResult r = run_box_stack(steps);
  std::printf("boxes %d  steps %d  box %.3g m\n", kStackBoxes, steps, r.box_size);
  std::printf("horizontal drift %.3e m (%.3e of box)  vertical shift %.3e m  max speed %.3e m/s\n",
              r.horizontal_drift, r.horizontal_drift / r.box_size, r.vertical_shift, r.max_speed);
  std::printf("converged %s  worst iterations %d  wall %.3f s (%.1f us/step)\n", r.converged ? "yes" : "no",
              r.worst_iterations, r.wall_seconds, 1e6 * r.wall_seconds / steps);
  return r.horizontal_drift < 0.01 * r.box_size ? 0 : 1;
}
