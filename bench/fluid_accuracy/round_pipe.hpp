// Poiseuille's flow in a round pipe made by a container (the solid outside a cylinder) on
// the Cartesian grid: u = G (R^2 - r^2) / (4 nu), along a periodic z.
#pragma once

#include <Eigen/Core>

#include "fluid/ibm/delta_kernel.hpp"

namespace cosim::bench {

struct PipeFlow {
  double profile_error = 0;    // largest |u - exact| over the core r <= R - 2 h, of u_max
  double flow_rate_error = 0;  // over the cross-section r < R, of the exact pi G R^4 / (8 nu)
  long cells = 0;
  int steps = 0;
  double seconds = 0;
};

// A pipe of D/h = `cells_across` whose axis lies `offset` cell widths off the grid's centre
// lines, in a box `margin` cells wider than it, with the immersed boundary's `kernel`; steps
// of nu dt / h^2 = 1 from rest to the steady state.
PipeFlow round_pipe(int cells_across, const Eigen::Vector2d& offset, int margin, fluid::ibm::DeltaKernel kernel);

}  // namespace cosim::bench
