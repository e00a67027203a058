#pragma once
// Planes, volumes and centroids from the vertices.

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::mesh {

// Each face's plane goes through the mean of its vertices with Newell's normal (the
// exact area vector of a non-planar polygon); volume and centroid come from the
// triangle fans of the faces around their vertex means, so they are those of the closed
// triangulated surface even when faces are not planar.
void fit_geometry(Mesh& mesh);

// Outward area vector of a face (Newell): its length is the area of a planar face.
Vec3 area_vector(const Mesh& mesh, Index face);
Vec3 vertex_mean(const Mesh& mesh, Index face);
// The box around a cell's vertices (its planes' intersection pokes out of it by the order
// of the faces' non-planarity).
Eigen::AlignedBox3d cell_box(const Mesh& mesh, Index cell);
// The diagonal of the box around the whole mesh's vertices (Mesh::whole_diagonal for a part).
double whole_diagonal(const Mesh& mesh);

}  // namespace cosim::tracker::mesh
