// The two FBM accuracy cases: one run is one grid level and one alpha resolution.
#pragma once

#include <string>

namespace cosim::bench {

struct FluidRun {
  std::string scene, level, alpha;
  long cells = 0;
  int steps = 0;
  double seconds = 0, value = 0, reference = 0;
  double error() const { return (value - reference) / reference; }
};

// DFG 2D-1 (Schäfer & Turek 1996), Re 20, steady drag coefficient C_D (reference 5.5795);
// the lift (reference 0.010619) goes into `lift`.
FluidRun dfg_cylinder(int cells_per_diameter, int subsamples, double* lift = nullptr);

// Hasimoto (1959) periodic array of spheres, a/L = 0.2, steady Stokes drag F + rho f V
// against 6 pi mu a U K(c).
FluidRun hasimoto_sphere(int n, int subsamples);

}  // namespace cosim::bench
