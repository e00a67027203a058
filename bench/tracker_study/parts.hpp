#pragma once
// The parts of the tracker study; main selects them with --part.

#include <string>

namespace cosim::bench {

// How big a run is: the references' sizes; small meshes and counts (--quick, the ctest);
// smaller still and timed once (--tiny, the ctest of the sanitizer build, whose checks
// make --quick time out), every path still taken.
enum class Size { full, quick, tiny };

// The value for a run of `size`.
template <class T>
T sized(Size size, T full, T quick, T tiny) {
  return size == Size::full ? full : size == Size::quick ? quick : tiny;
}

struct StudyOptions {
  Size size = Size::full;
  std::string csv;  // a part writes its rows to <csv>_<part>.csv if not empty
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
