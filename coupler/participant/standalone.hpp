// A program's scene without a coupler: the coupler's windows one after another, each
// recorded by the program's Recorder, by default in the same run-file layout as `cosim run`
// so tools read both alike. Every program's --standalone.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "coupler/participant/solver.hpp"

namespace cosim::participant {

// What a standalone run writes, and when.
class Recorder {
 public:
  virtual ~Recorder() = default;
  // After `done` of the scene's windows (0: the initial state) at `time`: the solver's
  // outputs then, and the wall seconds that window took.
  virtual void record(std::uint64_t done, double time, const Outputs& out, double seconds) = 0;
  // At the end: "finished", or "failed: " and why; the run's wall seconds.
  virtual void set_status(const std::string& status, double seconds) = 0;
  // What the progress line shows after the window, e.g. the particles.
  virtual std::string progress() const { return {}; }
};

// A program's recorder of the run file `output`, made once the solver is initialised.
using MakeRecorder = std::function<std::unique_ptr<Recorder>(const std::filesystem::path& output)>;

// Initialises `solver` as participant `name` and runs all windows of the scene without
// inputs (a solver that needs poses must move its bodies itself and report their poses),
// with a progress line on stderr when that is a terminal. Records into `output` (empty:
// the scene's output.file) what `make`'s recorder writes, or without one the coupler's run
// file: rows as the coupler writes them, the initial state as window 0 (0 iterations),
// then every output.every-th window and the last, with 1 iteration; poses and forces as
// the solver reports them, zeros where it reports none; and the solver's fields(), if it
// has any, at the scene's fields times (output.fields_every, run_file.hpp).
// Over several ranks rank 0 runs it with a LeadSolver (mpi_team.hpp; cosim-fluid), or every
// rank runs it with collective solver calls and the recorder writes on one (cosim-tracker).
// Throws SceneError for a bad scene, std::runtime_error otherwise; what a window throws,
// after the recorder's set_status("failed: ...").
void run_standalone(const scene::Scene& scene, Solver& solver, const std::string& name, std::filesystem::path output,
                    const MakeRecorder& make = {});

}  // namespace cosim::participant
