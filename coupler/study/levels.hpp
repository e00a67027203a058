// What `cosim study` varies: keys of the scene and their value at each level, level 1 the
// coarsest. Several keys vary together, level by level.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"

namespace cosim::study {

struct Varied {
  std::string key;                 // a dotted path into the scene (key_path.hpp)
  std::vector<YAML::Node> values;  // one per level
  std::string argument;            // what gave it, for messages: "--vary coupling.window=0.01,0.005"
};

// --vary KEY=V1,V2,...: each value a YAML flow node ("0.005", "[20, 20, 40]"). Throws
// ArgumentError.
Varied parse_vary(const std::string& argument);

// --refine F over `levels` levels, from the scene's own values: coupling.window and each
// participant's dt divided by F per level, participants.fluid.options.grid.cells (when the
// scene sets it) multiplied by F and rounded to whole cells. The window comes first, so the
// refinement ratio is F.
std::vector<Varied> refine(const scene::Scene& scene, double factor, int levels);

// The number of levels, the same for every key; throws ArgumentError naming two that differ.
std::size_t level_count(const std::vector<Varied>& varied);

// A copy of the scene document with level `level`'s values (0-based). Throws ArgumentError
// for a key path that is not in the scene.
YAML::Node variant(const YAML::Node& scene, const std::vector<Varied>& varied, std::size_t level);

// A value as the report shows it: 0.005, [20, 20, 40].
std::string text(const YAML::Node& value);

}  // namespace cosim::study
