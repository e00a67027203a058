// A box's volume per cell, from its nodes alone, in box_mesh's cell order: what the
// per-cell moments are divided by on rank 0 when no rank holds the whole box (Simulation),
// and the output grid's volumes.
#pragma once

#include <vector>

#include "tracker/mesh/box_mesh.hpp"

namespace cosim::tracker {

std::vector<double> cell_volumes(const BoxSpec& box);

}  // namespace cosim::tracker
