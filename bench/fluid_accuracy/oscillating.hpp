// The oscillating cylinder in the DFG channel (Wan & Turek; docs/references.md): how large the
// force oscillations are that the staircase FBM adds when grid points switch between solid
// and fluid, per grid level.
#pragma once

#include <string>
#include <vector>

#include "fluid/body_methods.hpp"

namespace cosim::bench {

// x(t) = 1.1 + A sin(2 pi f t), y = 0.2, fluid at rest at t = 0, nu 1e-3, rho 1, no-slip.
constexpr double kOscillationAmplitude = 0.25, kOscillationFrequency = 0.25;  // m, Hz

struct ForceSample {
  double time, drag, lift;  // coefficients 2 F / (rho U^2 D T), U = 2 pi f A
};

struct OscillatingRun {
  std::string level, method;
  long cells = 0;
  int steps = 0;
  double seconds = 0;
  std::vector<ForceSample> history;  // after every step
};

// `periods` periods of the motion on D / h = cells_per_diameter (uniform cells).
OscillatingRun oscillating_cylinder(int cells_per_diameter, double periods, const fluid::BodyOptions& method);

// The study: D/h = 5, 10, 20 over two periods (quick: 5, 10 over 1.25) per method; prints per
// level the means over the last period and the spurious oscillations; csv (if not empty)
// gets every level's history with its smooth part.
void oscillating_study(bool quick, const std::string& csv, const std::vector<fluid::BodyOptions>& methods);

}  // namespace cosim::bench
