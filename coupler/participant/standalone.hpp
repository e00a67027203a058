// A program's scene without a coupler: the coupler's windows, written to the same run-file
// layout as `cosim run`, so tools read both alike. Shared by every program's --standalone.
#pragma once

#include <filesystem>
#include <string>

#include "coupler/participant/solver.hpp"

namespace cosim::participant {

// Initialises `solver` as participant `name` and runs all windows of the scene without
// inputs (a solver that needs poses must move its bodies itself and report their poses).
// Writes `output` (empty: the scene's output.file): rows as the coupler writes them, the
// initial state as window 0 (0 iterations), then every output.every-th window and the
// last, with 1 iteration; poses and forces as the solver reports them, zeros where it
// reports none; and the solver's fields(), if it has any, at the scene's fields times
// (output.fields_every, run_file.hpp).
// Throws SceneError for a bad scene, std::runtime_error otherwise.
void run_standalone(const scene::Scene& scene, Solver& solver, const std::string& name,
                    std::filesystem::path output);

}  // namespace cosim::participant
