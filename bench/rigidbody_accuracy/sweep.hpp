// Which runs the benchmark makes: the full grid, the one-row-per-solver smoke version, and
// the pyramid's reference.
#pragma once

#include <vector>

#include "bench/rigidbody_accuracy/run.hpp"

namespace cosim::bench {

// Per scene: the soft step over sweeps x dt, PGS, SI and Jacobi over iterations x dt, DEM
// over stiffness x dt.
std::vector<RunSpec> full_sweep(SceneBuilder scene);
// Per scene: each solver once at dt 1e-3, the soft step and SI at their default iterations
// (DEM at a stable dt).
std::vector<RunSpec> quick_sweep(SceneBuilder scene);
// A hard case: the soft step at its defaults, SI and PGS at 50 iterations, DEM k = 1e5 at
// its stable dt, all at once side by side.
std::vector<RunSpec> hard_sweep(SceneBuilder scene);
// Sequential impulses with a tight tolerance, many iterations and a small dt: the best
// estimate of the settled state this library can give, for scenes not at rest.
RunSpec reference(SceneBuilder scene);

}  // namespace cosim::bench
