#pragma once
// Checks shared by the mesh tests.

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::mesh::test {

double total_volume(const Mesh& mesh);
// Unit inward normals, symmetric neighbours with opposite normals, no validation errors.
void expect_consistent(const Mesh& mesh);
Index boundary_faces(const Mesh& mesh);

}  // namespace cosim::tracker::mesh::test
