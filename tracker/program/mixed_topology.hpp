// The tracker's meshes as an XDMF "Mixed" topology of Polyhedron cells (type 16, then the
// face count, then per face its vertex count and vertices, counter-clockwise from
// outside): the topology of output::PolyhedralGrid.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker {

// The mesh's cells in the Mixed layout above.
std::vector<std::int64_t> mixed_topology(const Mesh& mesh);

}  // namespace cosim::tracker
