// The DFG channel (Schaefer & Turek 1996), shared by the fixed (DFG 2D-1) and the
// oscillating (Wan & Turek) cylinder: 2.2 x 0.41 m, cylinder D = 0.1 m, two-dimensional as
// one periodic cell layer of thickness T in z.
#pragma once

#include <cmath>

#include "fluid/grid/axis.hpp"

namespace cosim::bench::channel {

constexpr double L = 2.2, H = 0.41, D = 0.1, T = 0.01;

// Uniform cells across the channel, D / cells_per_diameter as near as a whole number allows.
inline fluid::grid::Axis across(int cells_per_diameter) {
  return fluid::grid::Axis::uniform(static_cast<int>(std::lround(cells_per_diameter * H / D)), 0, H, false);
}

inline fluid::grid::Axis layer() { return fluid::grid::Axis::uniform(1, 0, T, true); }

}  // namespace cosim::bench::channel
