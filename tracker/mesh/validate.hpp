#pragma once
// Checks a mesh and says what is wrong, cell by cell and face by face.

#include "tracker/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace cosim::tracker::mesh {

enum class Defect {
  open_cell,             // outward area vectors do not sum to zero
  degenerate,            // zero-area face (no wider than the tolerance) or non-positive volume
  missing_twin,          // the neighbour has no face back, or an index is out of range
  normals_not_opposite,  // the two sides of a face do not see opposite normals
  inverted_face,         // the normal points out of the cell
  non_convex,            // a vertex of the cell is outside one of its face planes
  non_planar_face,       // warning only: a vertex is off its face's plane
};

struct Problem {
  bool error;  // false: a warning (non-planar faces are expected after perturbation)
  Defect defect;
  Index cell;
  Index face;  // global face index, -1 for the whole cell
  std::string what;
};

// Lengths are compared with a tolerance of 1e-9 of the cell's size; a cell whose faces
// are non-planar by up to d (a warning) is allowed vertices up to 2 d outside its planes,
// the most that moving its vertices by d can do to a convex cell.
std::vector<Problem> validate(const Mesh& mesh);

bool has_errors(const std::vector<Problem>& problems);
// One line per problem, the first `limit` of them, then how many more.
std::string describe(const std::vector<Problem>& problems, std::size_t limit = 20);
// Throws std::invalid_argument naming mesh.source with the errors if there are any.
void require_valid(const Mesh& mesh);

}  // namespace cosim::tracker::mesh
