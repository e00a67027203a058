// The engines the benchmark runs on the same scene.
#pragma once

#include "bench/rigidbody_granular/pour.hpp"
#include "bench/rigidbody_granular/result.hpp"
#include "rigidbody/world/settings.hpp"

namespace cosim::bench {

// How cosim's world runs the scene: the solver, and the soft step's settings (the
// world's defaults unless the command line changes them).
struct CosimRun {
  world::SolverKind solver = world::SolverKind::soft;
  solver::SoftOptions soft{};
};

// Sequential impulses take scene.iterations; the soft step its own sweeps (run.soft).
RunResult run_cosim(const PourScene& scene, const CosimRun& run);
#ifdef COSIM_BENCH_BULLET
RunResult run_bullet(const PourScene& scene);
#endif

}  // namespace cosim::bench
