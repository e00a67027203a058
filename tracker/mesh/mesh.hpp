#pragma once
// The tracking mesh: convex polyhedral cells, each with its own face planes. See README.md.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tracker/types.hpp"

namespace cosim::tracker::mesh {

// A face as its cell sees it. The tracking loop reads only these records, and a cell's
// records are contiguous, so one cell's planes are a few adjacent cache lines (64 bytes
// each).
struct Face {
  Vec3 normal;      // unit, pointing into the cell
  Vec3 point;       // on the plane: the cell is where normal . (x - point) >= 0
  Index neighbour;  // the cell across, or boundary_code(patch) < 0
  Index twin;       // the same face in the neighbour's list (global index), -1 on a boundary
  Index shift;      // index into Mesh::shifts: x here is x + shifts[shift] in the neighbour
};

static_assert(sizeof(Face) == 64);

constexpr Index boundary_code(Index patch) { return -1 - patch; }
// The neighbour of a part's ghost across a face to a cell outside the part: no particle
// moves in a ghost, so none reaches such a face.
constexpr Index kBeyondPart = std::numeric_limits<Index>::min();
constexpr Index patch_of(Index code) { return -1 - code; }

struct Mesh {
  std::vector<Index> cell_faces;  // cell c owns faces [cell_faces[c], cell_faces[c + 1])
  std::vector<Face> faces;
  std::vector<double> volume;  // per cell
  std::vector<Vec3> centroid;  // per cell

  // The vertices define the geometry; the planes above are fitted to them (fit_geometry).
  // Face f's vertices are face_vertex_index[face_vertex_begin[f] .. face_vertex_begin[f+1]),
  // counter-clockwise seen from outside its cell.
  std::vector<Vec3> vertices;
  std::vector<Index> face_vertex_begin;
  std::vector<Index> face_vertex_index;

  std::vector<std::string> patches;        // boundary patch names, by patch index
  std::vector<Vec3> shifts{Vec3::Zero()};  // periodic translations; 0 is "none"
  std::string source;                      // file or generator, for messages

  // A rank's part of a larger mesh (part.hpp, `partial`): its last `ghosts` cells surround
  // the others and belong to other ranks, global[c] is cell c's index in the whole mesh, and
  // faces beyond the part have the neighbour kBeyondPart. A whole mesh has none of these.
  bool partial = false;
  std::vector<Index> global;
  Index ghosts = 0;
  double whole_diagonal = 0.0;  // the whole mesh's bounding-box diagonal (0: this one's)

  Index cell_count() const { return static_cast<Index>(cell_faces.size()) - 1; }
  // The cells whose particles are tracked here: all but the ghosts.
  Index own_cells() const { return cell_count() - ghosts; }
  Index global_cell(Index cell) const { return global.empty() ? cell : global[static_cast<std::size_t>(cell)]; }
  Index face_count() const { return static_cast<Index>(faces.size()); }
  Index vertex_count(Index face) const { return face_vertex_begin[face + 1] - face_vertex_begin[face]; }
  const Vec3& face_vertex(Index face, Index k) const {
    return vertices[face_vertex_index[face_vertex_begin[face] + k]];
  }
  Index cell_of_face(Index face) const;  // binary search over cell_faces
};

// Inside by the cell's own planes (boundary included).
inline bool contains(const Mesh& mesh, Index cell, const Vec3& x) {
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f) {
    const Face& face = mesh.faces[f];
    if (face.normal.dot(x - face.point) < 0.0) return false;
  }
  return true;
}

}  // namespace cosim::tracker::mesh
