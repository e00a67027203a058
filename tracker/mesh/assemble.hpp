#pragma once
// From a list of polyhedra (faces as vertex loops) to a Mesh with connectivity.

#include "tracker/mesh/mesh.hpp"

#include <array>
#include <initializer_list>
#include <span>

namespace cosim::tracker::mesh {

// What every source produces: cells as lists of faces, faces as vertex loops
// counter-clockwise seen from outside the cell.
struct Polyhedra {
  std::vector<Vec3> vertices;
  std::vector<Index> cell_faces{0};         // cell c: faces [cell_faces[c], cell_faces[c+1])
  std::vector<Index> face_vertex_begin{0};  // face f: face_vertex_index[begin[f] .. begin[f+1])
  std::vector<Index> face_vertex_index;
  // Per face: the patch of a face that lies on the boundary, -1 if it does not or the
  // source does not know. Faces without a partner and without a patch land on a patch
  // called "boundary".
  std::vector<Index> face_patch;
  // Optional, per face: the neighbour cell or a boundary code. Empty: faces are paired
  // by their sets of vertex ids. Given: the partner face is the neighbour's face back
  // whose vertex mean matches up to a multiple of `period` (0 on non-periodic axes).
  std::vector<Index> face_neighbour;
  std::array<double, 3> period{0.0, 0.0, 0.0};
  std::vector<std::string> patches;
  std::string source;

  // Appends a face to the current (last, open) cell; close the cell with end_cell().
  void add_face(std::span<const Index> loop, Index patch = -1);
  void add_face(std::initializer_list<Index> loop, Index patch = -1) {
    add_face(std::span<const Index>(loop.begin(), loop.size()), patch);
  }
  void end_cell() { cell_faces.push_back(static_cast<Index>(face_vertex_begin.size()) - 1); }
};

// Connectivity and geometry; no validation (the sources validate what they return).
// Throws std::invalid_argument if a face is shared by more than two cells.
Mesh assemble(Polyhedra polyhedra);

}  // namespace cosim::tracker::mesh
