// The engines the benchmark runs on the same scene.
#pragma once

#include "bench/rigidbody_granular/pour.hpp"
#include "bench/rigidbody_granular/result.hpp"

namespace cosim::bench {

RunResult run_cosim(const PourScene& scene);
#ifdef COSIM_BENCH_BULLET
RunResult run_bullet(const PourScene& scene);
#endif

}  // namespace cosim::bench
