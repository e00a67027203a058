// The XDMF sidecar for cell fields on the tracker's meshes: any convex polyhedra, as an
// XDMF "Mixed" topology of Polyhedron cells (type 16, then the face count, then per face
// its vertex count and vertices, counter-clockwise from outside). ParaView reads it with
// its "XDMF Reader (Xdmf3ReaderS)"; the older Xdmf2 reader of ParaView 5.11 has no
// polyhedra.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "output/xdmf.hpp"
#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker {

// The mesh's cells in the Mixed layout above.
std::vector<std::int64_t> mixed_topology(const Mesh& mesh);

struct PolyhedraSeries {
  std::string name;        // the temporal collection
  std::string mesh_group;  // HDF5 group holding `vertices` (v x 3) and `topology` (mixed)
  std::size_t cells = 0, vertices = 0, topology_size = 0;
  std::vector<output::XdmfStep> steps;  // cell fields, one value (or components) per cell
};

// Datasets referenced as "<h5_file>:<path>", h5_file relative to the sidecar.
std::string polyhedra_xdmf(const std::string& h5_file, const PolyhedraSeries& series);

}  // namespace cosim::tracker
