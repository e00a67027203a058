#include "tracker/program/mixed_topology.hpp"

#include "output/field_frame.hpp"

namespace cosim::tracker {

std::vector<std::int64_t> mixed_topology(const Mesh& mesh) {
  std::vector<std::int64_t> out;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    out.push_back(output::kXdmfPolyhedron);
    out.push_back(mesh.cell_faces[c + 1] - mesh.cell_faces[c]);
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f) {
      out.push_back(mesh.vertex_count(f));
      for (Index k = mesh.face_vertex_begin[f]; k < mesh.face_vertex_begin[f + 1]; ++k)
        out.push_back(mesh.face_vertex_index[k]);
    }
  }
  return out;
}

}  // namespace cosim::tracker
