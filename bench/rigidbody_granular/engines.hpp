// The engines the benchmark runs on the same scene.
#pragma once

#include <optional>
#include <string>

#include "bench/rigidbody_granular/pour.hpp"
#include "bench/rigidbody_granular/result.hpp"
#include "rigidbody/world/settings.hpp"

namespace cosim::bench {

// How cosim's world runs the scene: the solver, and the soft step's settings (the
// world's defaults unless the command line changes them).
struct CosimRun {
  rigidbody::world::SolverKind solver = rigidbody::world::SolverKind::soft;
  rigidbody::solver::SoftOptions soft{};
};

// Sequential impulses take scene.iterations; the soft step its own sweeps (run.soft); DEM
// scene.hertz in steps of scene.dem_dt.
RunResult run_cosim(const PourScene& scene, const CosimRun& run);

// How LIGGGHTS runs: its executable (a name on PATH or a path) and where its decks go
// (empty: a temporary directory, removed after the run; else kept in a subdirectory per N).
struct LiggghtsRun {
  std::string executable = "liggghts";
  std::string directory;
};

// LIGGGHTS on scene.hertz in steps of scene.dem_dt, serial; nullopt, with the reason
// printed, if the executable is not there. Throws std::runtime_error if it fails.
std::optional<RunResult> run_liggghts(const PourScene& scene, const LiggghtsRun& run);
#ifdef COSIM_BENCH_BULLET
RunResult run_bullet(const PourScene& scene);
#endif

}  // namespace cosim::bench
