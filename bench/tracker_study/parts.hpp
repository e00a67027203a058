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

}  // namespace cosim::bench
