// A box's volume per cell, from its nodes alone, in box_mesh's cell order: what the
// per-cell moments are divided by where no rank holds the whole box (Simulation), and the
// output grid's volumes.
#pragma once

#include <array>
#include <vector>

#include "tracker/mesh/box_mesh.hpp"

namespace cosim::tracker::step {

std::vector<double> cell_volumes(const mesh::BoxSpec& box);
// The cells of the hexahedra [lo, hi) per axis, in box_mesh's order among themselves.
std::vector<double> cell_volumes(const mesh::BoxSpec& box, const std::array<int, 3>& lo, const std::array<int, 3>& hi);

}  // namespace cosim::tracker::step
