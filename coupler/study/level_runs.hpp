// The levels of a study on disk and in flight: each level's scene written beside its run
// file and log, checked as `cosim check` would before anything runs, run by `cosim run` as
// a child, and its quantities read back with the order, extrapolate and GCI of each level
// and the two before it. `cosim study` and `cosim run --target` share them.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "coupler/study/levels.hpp"
#include "coupler/study/measure.hpp"
#include "coupler/study/study.hpp"

namespace cosim::study {

// The scene as a document for its levels, which live in another folder: `folder` set to
// the scene's own (absolute), so that the files it names by relative path are found.
YAML::Node level_document(const scene::Scene& scene);

// Level `k` (0-based) of `varied`: DIR/level_<k+1>.yaml written from the scene `document`
// with the level's values, and checked (the scene loader, every measure, each built-in
// program's own section). Throws ArgumentError naming `arguments` and the level.
Level write_level(const std::filesystem::path& dir, const YAML::Node& document, const std::vector<Varied>& varied,
                  std::size_t k, const std::vector<Measure>& measures, const std::string& arguments);

// Runs `levels[first..]` by `cosim run`, `jobs` side by side, telling stdout as each starts
// and ends ("<who>: level 2/3 done: ..."), and keeps each one's usage. Returns whether all
// of them succeeded.
bool run_levels(std::vector<Level>& levels, std::size_t first, const std::vector<std::string>& keys, int jobs,
                const std::string& who);

// The measure on every level of `r`, with the estimate of each level from the two before it.
Quantity measure_quantity(const Measure& m, const Results& r);

// Draws results.csv's plots and points each quantity at its own (or says why there is none).
void set_plots(Results& r, const std::filesystem::path& csv);

}  // namespace cosim::study
