#pragma once
// The parts of the tracker study; main selects them with --part.

#include <string>

namespace cosim::bench {

struct StudyOptions {
  bool quick = false;  // small meshes and counts: the ctest
  std::string csv;     // a part writes its rows to <csv>_<part>.csv if not empty
};

// The three tracking algorithms on the same particles: lost particles on perturbed meshes
// and speed on unperturbed ones, with Stollmeier & Grabe's published speed ratio. Returns
// the exit code: 1 if the event-driven algorithm lost a particle.
int algorithms_part(const StudyOptions& options);

// Table 1 of Strobl, Bannerman & Poeschel: the sphere cluster registered with bounding grids
// from none to the tracking mesh; primitives per cell, events generated and executed and
// the speed-up next to the published rows. Returns 1 if the executed events differ between
// grids or a particle is lost.
int pruning_part(const StudyOptions& options);

}  // namespace cosim::bench
