// The measures of a study: the scene's `study.measure` and the command line's `--measure`,
// parsed and checked against the scene before anything runs.
#pragma once

#include <string>
#include <vector>

#include "coupler/scene/scene.hpp"
#include "coupler/study/measure.hpp"

namespace cosim::study {

// The scene's measures in file order, then each NAME=EXPRESSION of `arguments` (one with
// the name of a scene's measure replaces it). Every body named must be the scene's, and a
// mean() must end by time.end. A bad scene measure throws scene::SceneError (file, line,
// study.measure.NAME), a bad argument ArgumentError ("--measure NAME=EXPRESSION: ...").
std::vector<Measure> measures_of(const scene::Scene& scene, const std::vector<std::string>& arguments);

// Why `m` cannot be measured on a run of `scene` (a body it lacks, a mean past its end), or "".
std::string mismatch(const Measure& m, const scene::Scene& scene);

}  // namespace cosim::study
