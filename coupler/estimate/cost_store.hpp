// What finished runs measured on this machine, kept between runs: the file the cost
// models are fitted to. One file per host (machines differ by up to 2x), by default
// $XDG_CACHE_HOME/cosim/cost-<host>.yaml (~/.cache when unset); COSIM_COST_FILE names
// another. Each record carries the build that ran it: a model fits the records of this
// build where it has any, since a new build may be faster or slower.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "coupler/estimate/cost_model.hpp"

namespace cosim::estimate {

// The coupler's own share of a run: start-up, messages, the run file.
inline constexpr const char* kCoupler = "coupler";

struct RunRecord {
  std::string scene;         // the scene as scene_key() names it (run_record.hpp)
  std::string build;         // git hash of the build that ran it
  bool calibration = false;  // run by `cosim calibrate`
  double windows = 0;
  double iterations = 0;  // over all windows
  double wall_seconds = 0;
  double disk_bytes = 0;  // the run file's size at the end
  // Per program; kCoupler's: steps 1, per_step what coupler_work() counts (estimate.hpp),
  // seconds what the wall time leaves after the programs' steps.
  std::map<std::string, Observation> programs;
};

class CostStore {
 public:
  static std::filesystem::path default_path();
  // An empty store if the file does not exist; throws naming the file if it cannot be read.
  static CostStore load(const std::filesystem::path& path);
  // Writes a temporary file and renames it over the store.
  void save() const;
  // Loads the store at `path`, lets `change` change it, and saves it, holding an exclusive
  // lock (flock on <path>.lock) throughout, so that runs finishing at once (`cosim study`'s
  // levels side by side, tests in parallel) each keep their record.
  static void update(const std::filesystem::path& path, const std::function<void(CostStore&)>& change);

  void add(RunRecord record);  // keeps the newest records, up to a bound
  void drop_calibration();     // before `cosim calibrate` measures anew

  const std::filesystem::path& path() const { return path_; }
  const std::vector<RunRecord>& records() const { return records_; }
  // The program's observations from runs of `build`, or of any build if it has none.
  std::vector<Observation> observations(const std::string& program, const std::string& build) const;
  // The newest record of this scene, if any (for its coupling iterations per window).
  const RunRecord* last_run_of(const std::string& scene) const;

 private:
  std::filesystem::path path_;
  std::vector<RunRecord> records_;  // oldest first
};

}  // namespace cosim::estimate
