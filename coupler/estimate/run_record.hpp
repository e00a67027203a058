// A finished run as the cost models learn from it: each program's counts (its work report)
// beside what its steps took, and the coupler's share as what the wall time leaves.
#pragma once

#include <map>
#include <string>

#include "coupler/estimate/cost_store.hpp"
#include "coupler/estimate/work.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::estimate {

// What the coupler counted over a run's windows.
struct RunTotals {
  double windows = 0;
  double iterations = 0;
  double wall_seconds = 0;
  double disk_bytes = 0;
  std::map<std::string, double> seconds;     // per participant, inside its steps
  std::map<std::string, double> steps;       // per participant, over all iterations
  std::map<std::string, double> peak_bytes;  // per participant, its largest process
};

// Set by `cosim calibrate` for the runs it starts, so that their records say so.
inline constexpr const char* kCalibrationEnv = "COSIM_CALIBRATION";

// A scene's name in the records: its file's absolute path and a hash of its text, so that
// an edited scene (another grid, step or window) is not estimated from its former runs.
std::string scene_key(const scene::Scene& scene);

RunRecord run_record(const scene::Scene& scene, const std::map<std::string, ProgramWork>& work, const RunTotals& totals,
                     const std::string& build);

}  // namespace cosim::estimate
