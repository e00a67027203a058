// What a run will take here, before it starts: wall time, memory per program and the run
// file's size, from each program's work report and the cost models fitted to what runs on
// this machine measured (cost_store.hpp). `cosim check` and `cosim run` print it as one
// line that starts "estimate:".
#pragma once

#include <map>
#include <string>
#include <vector>

#include "coupler/estimate/cost_store.hpp"
#include "coupler/estimate/work.hpp"
#include "coupler/scene/scene.hpp"

namespace cosim::estimate {

struct ProgramEstimate {
  std::string name;
  double steps = 0;          // over the run, every coupling iteration's counted
  double seconds = 0;        // inside its steps
  double peak_bytes = 0;     // its largest process
  std::string largest_unit;  // what its step's cost grows with most ("cells"), empty if nothing
  double largest_count = 0;
  bool modelled = true;  // false: nothing measured and no prior (an external program)
  bool grows = false;    // an inflow adds to the counts it was estimated from
};

struct Estimate {
  double wall_seconds = 0;
  double disk_bytes = 0;
  double iterations_per_window = 1;
  bool iterations_measured = false;       // from this scene's last run, not assumed
  std::vector<ProgramEstimate> programs;  // the participants the run starts
  std::size_t runs_measured = 0;          // records of this build the models were fitted to
  std::size_t runs_other_builds = 0;      // records of other builds, used where this build has none
  bool scene_measured = false;            // scaled by this scene's own last run
};

// Coupling iterations per window assumed for an implicit scheme before a scene has run:
// the shipped implicit scenes take 2.2 to 3.0 (configs/README.md's results).
inline constexpr double kAssumedIterations = 3.0;

Estimate estimate(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                  const std::map<std::string, ProgramWork>& work, const CostStore& store, const std::string& build);

// "estimate: 2.1 min here (fluid 82 %: 102 k cells x 2400 steps); memory fluid 180 MB, ...;
// run file 45 MB; fitted to 12 runs of this build here"
std::string estimate_line(const Estimate& e);

// estimate_line() from this host's measured costs (CostStore::default_path()). A store that
// cannot be read gives a line saying so: an estimate is not worth failing a check or a run.
std::string estimate_here(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                          const std::map<std::string, ProgramWork>& work, const std::string& build);

// The model of each program as fitted (for `cosim calibrate`'s report).
Coefficients model_of(const std::string& program, const CostStore& store, const std::string& build);

// What the coupler's own share grows with: the exchanges (windows x iterations), the body
// rows it writes (bodies x rows), the bytes of the field frames it writes, and one start-up
// of each program ("start:fluid").
Units coupler_work(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                   const std::map<std::string, ProgramWork>& work, double exchanges);

// Disk bytes of a run file: body and coupling series, field frames.
double run_file_bytes(const scene::Scene& scene, const std::vector<scene::Participant>& start,
                      const std::map<std::string, ProgramWork>& work);

}  // namespace cosim::estimate
