// The bodies' poses inside a window, for programs that move bodies they are sent.
#pragma once

#include <vector>

#include "coupler/participant/solver.hpp"

namespace cosim::participant {

// The poses at s in [w.t0, w.t1] between the window's start and end poses: positions and
// velocities linearly, the orientation by normalised linear interpolation (windows are
// short enough for the difference to slerp not to matter against the first-order hold).
// No end poses: the start ones, held.
std::vector<PoseRow> poses_at(const Inputs& in, const Window& w, double s);

}  // namespace cosim::participant
