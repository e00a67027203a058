// The tracker's per-cell samples as grid fields (field::CellField), for the run file and
// the Field message alike, on its output grid (output_grid.hpp).
#pragma once

#include <span>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "tracker/tracking/sampling.hpp"

namespace cosim::tracker::program {

// Per cell: count (the particles now, `count`), then the moments averaged since the last
// sample was taken: mean_count, density (1/m^3), velocity (3, m/s), temperature (K),
// pressure (Pa).
std::vector<field::CellField> cell_fields(std::span<const tracking::CellMoments> moments,
                                          std::span<const double> count);

}  // namespace cosim::tracker::program
