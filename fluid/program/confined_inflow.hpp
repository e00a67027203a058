// An inflow face confined to a container's inside: a round column fed through the floor of
// the box around it, the corners outside the column taking nothing.
#pragma once

#include <vector>

#include "fluid/grid/axis.hpp"
#include "fluid/grid/boundary_conditions.hpp"
#include "geometry/container.hpp"

namespace cosim::fluid::program {

// `profile` times, on each cell of the face (axis `axis`, side `side` of the grid `axes`),
// the fraction of that cell's face inside the container at `pose`, sampled on kSamples^2
// points. The flow rate through the face is then the profile's over the container's cross
// section, not over the face cells whose centres lie inside it. Throws std::invalid_argument
// when no part of the face lies inside (a cap across the face, or the face beside it).
fluid::grid::VelocityFunction confined_inflow(fluid::grid::VelocityFunction profile,
                                              const geometry::Container& container, const geometry::Pose& pose,
                                              int axis, fluid::grid::Side side,
                                              const std::vector<fluid::grid::Axis>& axes);

}  // namespace cosim::fluid::program
