// The tracker's meshes as an XDMF "Mixed" topology of Polyhedron cells (type 16, then the
// face count, then per face its vertex count and vertices, counter-clockwise from
// outside): the topology of field::PolyhedralGrid.
#pragma once

#include <cstdint>
#include <vector>

#include "coupler/field/field_frame.hpp"
#include "tracker/mesh/assemble.hpp"
#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::program {

// The cells of a Mesh or of Polyhedra (both list a cell's faces and a face's vertices
// alike) in the Mixed layout above.
template <class Cells>
std::vector<std::int64_t> mixed_topology(const Cells& cells) {
  std::vector<std::int64_t> out;
  const auto count = static_cast<Index>(cells.cell_faces.size()) - 1;
  for (Index c = 0; c < count; ++c) {
    out.push_back(field::kXdmfPolyhedron);
    out.push_back(cells.cell_faces[c + 1] - cells.cell_faces[c]);
    for (Index f = cells.cell_faces[c]; f < cells.cell_faces[c + 1]; ++f) {
      out.push_back(cells.face_vertex_begin[f + 1] - cells.face_vertex_begin[f]);
      for (Index k = cells.face_vertex_begin[f]; k < cells.face_vertex_begin[f + 1]; ++k)
        out.push_back(cells.face_vertex_index[k]);
    }
  }
  return out;
}

}  // namespace cosim::tracker::program
