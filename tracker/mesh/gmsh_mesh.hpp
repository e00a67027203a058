#pragma once
// Gmsh .msh import.

#include "tracker/mesh/mesh.hpp"

#include <filesystem>

namespace cosim::tracker::mesh {

// Reads the volume elements (tetrahedra, hexahedra, prisms, pyramids; of higher order
// only the corner nodes are used, so curved cells become straight ones) of any .msh
// version Gmsh reads. Boundary faces take the name of the physical group of the surface
// elements on them (the group's tag as a name if it has none); the rest form the patch
// "boundary". Runs its own Gmsh session: do not call it while the caller has one open.
// Throws std::invalid_argument naming the file if it cannot be read, holds unsupported
// elements or fails validation.
Mesh load_gmsh(const std::filesystem::path& path);

}  // namespace cosim::tracker::mesh
