// The engines the benchmark runs on the same scene.
#pragma once

#include "bench/rigidbody_granular/pour.hpp"
#include "bench/rigidbody_granular/result.hpp"
#include "rigidbody/world/settings.hpp"

namespace cosim::bench {

// solver: the soft step (the world's default, its own sweep counts) or sequential
// impulses (scene.iterations).
RunResult run_cosim(const PourScene& scene, world::SolverKind solver);
#ifdef COSIM_BENCH_BULLET
RunResult run_bullet(const PourScene& scene);
#endif

}  // namespace cosim::bench
