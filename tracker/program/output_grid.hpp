// The tracker's mesh as its output shows it (the run file, the Field messages to the
// coupler): built once, on the rank that writes. A box of hexahedra is the rectilinear grid
// of its nodes, so no rank ever holds the whole box's cells (ParaView reads it as XDMF's
// 3DRectMesh; the cells in box_mesh's order, x fastest); a box of tetrahedra and every other
// mesh are XDMF polyhedra (mixed_topology.hpp). With each cell's volume and each boundary
// patch's area, which the moments and the walls' stresses are divided by.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "tracker/mesh/box_mesh.hpp"
#include "tracker/mesh/mesh.hpp"
#include "tracker/step/cell_volumes.hpp"
#include "tracker/step/simulation.hpp"

namespace cosim::tracker::program {

struct OutputGrid {
  field::Grid grid;
  // Per cell (m^3), in the grid's order: of a polyhedral grid. A box of hexahedra's come
  // from `box`, a slab of cells at a time (cell_volumes.hpp), so that its writer never
  // holds every cell's.
  std::vector<double> volume;
  std::optional<mesh::BoxSpec> box;
  std::vector<std::string> patches;  // the boundary patches' names (Mesh::patches)
  std::vector<double> patch_area;    // per patch (m^2): a periodic axis's patches have none
};

// From the box's nodes alone (its tetrahedra from box_polyhedra()).
OutputGrid output_grid(const mesh::BoxSpec& box);
// From the whole mesh.
OutputGrid output_grid(const mesh::Mesh& whole);
// The gas's: of its box, or of its whole mesh. Rank 0 only (std::logic_error on others).
OutputGrid output_grid(const step::Simulation& gas);

}  // namespace cosim::tracker::program
