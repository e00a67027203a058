// The throughput case: lid-driven cavity in the unit cube, lid z = 1 moving at (1, 0, 0),
// Re = 100, N^3 uniform cells, a fixed step of Courant number 0.5 with respect to the lid
// velocity, so that another solver can be given exactly the same steps.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bench/fluid_throughput/memory.hpp"

namespace cosim::bench {

// A body in the cavity: none, or a sphere a quarter of the side across moving through it
// at a quarter of the lid's speed, held by the immersed boundary or the staircase.
enum class CavityBody { none, ibm, staircase };

struct Cavity {
  static constexpr double kLidVelocity = 1, kReynolds = 100, kCourant = 0.5;
  int n = 64;     // cells per side; even, so that x = y = 0.5 lies on faces
  int steps = 5;  // the first is the warm-up (assembly, multigrid setup)
  CavityBody body = CavityBody::none;
  // nu dt / h^2 where given (> 0), for the viscous solve's cost at a chosen stiffness;
  // otherwise nu from Re = 100.
  double viscous_number = 0;
  double viscosity() const {  // the side is 1
    return viscous_number > 0 ? viscous_number / (static_cast<double>(n) * n * dt()) : kLidVelocity / kReynolds;
  }
  double dt() const { return kCourant / (n * kLidVelocity); }
  double end_time() const { return steps * dt(); }
  long cells() const { return static_cast<long>(n) * n * n; }
  double centre(int k) const { return (k + 0.5) / n; }  // height of cell layer k
  // Stokes' first problem, u(z) under an impulsively started plate: the centre line while
  // the lid's layer is thin, up to the return flow the side walls drive (of the order of
  // the layer's thickness over the side: a few per cent of the lid velocity here).
  double stokes_layer(double z) const {
    return kLidVelocity * std::erfc((1 - z) / (2 * std::sqrt(viscosity() * end_time())));
  }
};

struct ThroughputRun {
  static constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();
  std::string solver;
  int ranks = 0;
  Cavity cavity;
  int timed_steps = 0;  // the steps after the warm-up that the per-step figures average over
  // The warm-up step, CPU time like cpu_seconds_per_step (OpenFOAM: from its start-up on).
  double first_step_seconds = 0;
  double seconds_per_step = kNotMeasured;  // wall clock
  // Process CPU time (slowest rank; OpenFOAM: its rank 0's ExecutionTime), which, unlike
  // the wall clock, other work on a shared machine hardly changes.
  double cpu_seconds_per_step = 0;
  double pressure_seconds_per_step = kNotMeasured;  // wall, slowest rank
  double pressure_iterations_per_step = kNotMeasured;
  double forcing_seconds_per_step = kNotMeasured;  // the immersed boundary's, wall, slowest rank
  double max_divergence = kNotMeasured;            // over all steps
  MemoryUse memory{kNotMeasured, kNotMeasured};
  std::vector<double> centre_line;  // u(0.5, 0.5, z) at the n cell-centre heights, at the end
  double cell_updates_per_second() const { return static_cast<double>(cavity.cells()) / seconds_per_step; }
  double cell_updates_per_cpu_second() const { return static_cast<double>(cavity.cells()) / cpu_seconds_per_step; }
};

// Runs the cavity with cosim_fluid on PETSC_COMM_WORLD (collective). Needs PETSc's
// default logging on (PetscLogDefaultBegin) for the pressure-solve time.
ThroughputRun run_cavity(const Cavity& cavity);

}  // namespace cosim::bench
