// The box-stack scene and its measurements, shared by the test and bench_box_stack.
#pragma once

namespace cosim::rigidbody::world::test {

inline constexpr int kStackBoxes = 10;
inline constexpr int kStackTestSteps = 10000;

struct StackResult {
  double box_size = 0.0;
  double horizontal_drift = 0.0;  // largest over boxes and steps
  double vertical_shift = 0.0;    // largest over boxes and steps
  double max_speed = 0.0;         // largest over boxes and steps
  bool converged = true;          // the solver met its tolerance in every step
  int converged_steps = 0;        // steps in which it did
  int worst_iterations = 0;
  double mean_iterations = 0.0;  // over the steps
  double wall_seconds = 0.0;
};

// Ten boxes of 0.2 m, exactly touching at t = 0, sequential impulses, dt 1e-3, at most
// `iterations` per step (0: the preset's).
StackResult run_box_stack(int steps, int iterations = 0);

}  // namespace cosim::rigidbody::world::test
