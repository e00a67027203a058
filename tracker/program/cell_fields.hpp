// The tracker's per-cell samples as grid fields on its polyhedral mesh (output::FieldFrame),
// for the run file and the Field message alike.
#pragma once

#include <span>
#include <vector>

#include "output/field_frame.hpp"
#include "tracker/mesh/mesh.hpp"
#include "tracker/tracking/sampling.hpp"

namespace cosim::tracker {

// The mesh's vertices and cells (mixed_topology()).
output::PolyhedralGrid polyhedral_grid(const Mesh& mesh);
// Per cell: count (the particles now, `count`), then the moments averaged since the last
// sample was taken: mean_count, density (1/m^3), velocity (3, m/s), temperature (K),
// pressure (Pa).
std::vector<output::CellField> cell_fields(std::span<const CellMoments> moments, std::span<const double> count);
// Both together: what the tracker hands the run file as its fields.
output::FieldFrame tracker_fields(const Mesh& mesh, std::span<const CellMoments> moments,
                                  std::span<const double> count);

}  // namespace cosim::tracker
