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

// --set KEY=VALUE: one value, the same on every level (a method, an end time). Throws
// ArgumentError.
struct Setting {
  std::string key;
  YAML::Node value;
  std::string argument;  // "--set time.end=1.0"
};
Setting parse_set(const std::string& argument);

// The scene at each resolution scale s of `scales` (1: as written; 2: twice as fine), from
// its own values: the number of windows multiplied by s and rounded to a whole number (so
// that time.end stays a whole number of windows), each participant's dt and the fluid's
// dt_initial shrunk with the window (so that a window stays the same whole number of
// steps), participants.fluid.options.grid.cells (when the scene sets it) multiplied by the
// windows' ratio and rounded to whole cells, the tracker's box or Voronoi mesh refined alike
// with its particles per cell kept and the gas the same (each simulator's weight divided by
// the cells' growth), and the coupling's (implicit schemes), the rigid bodies' and the fluid
// forcing's tolerance, where the scene writes them, divided by the ratio's square where the
// ratio is above 1, down to 1e-12. The window comes first, so the refinement ratio is the windows'.
// `argument` names what asked for it, for messages.
std::vector<Varied> scaled(const scene::Scene& scene, const std::vector<double>& scales, const std::string& argument);

// --refine F over `levels` levels: scaled() at 1, F, F^2, ...
std::vector<Varied> refine(const scene::Scene& scene, double factor, int levels);

// The resolution scale of each level of scaled(): its windows over the scene's.
std::vector<double> scales_of(const scene::Scene& scene, const std::vector<Varied>& varied);

// The number of levels, the same for every key; throws ArgumentError naming two that differ.
std::size_t level_count(const std::vector<Varied>& varied);

// A copy of the scene document with level `level`'s values (0-based). Throws ArgumentError
// for a key path that is not in the scene.
YAML::Node variant(const YAML::Node& scene, const std::vector<Varied>& varied, std::size_t level);

// A value as the report shows it: 0.005, [20, 20, 40].
std::string text(const YAML::Node& value);

}  // namespace cosim::study
