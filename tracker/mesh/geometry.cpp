#include "tracker/mesh/geometry.hpp"

#include <algorithm>

namespace cosim::tracker::mesh {

Index Mesh::cell_of_face(Index face) const {
  const auto it = std::upper_bound(cell_faces.begin(), cell_faces.end(), face);
  return static_cast<Index>(it - cell_faces.begin()) - 1;
}

Vec3 area_vector(const Mesh& mesh, Index face) {
  const Index n = mesh.vertex_count(face);
  // Relative to the first vertex, so meshes far from the origin lose no digits.
  const Vec3& origin = mesh.face_vertex(face, 0);
  Vec3 sum = Vec3::Zero();
  for (Index k = 1; k + 1 < n; ++k)
    sum += (mesh.face_vertex(face, k) - origin).cross(mesh.face_vertex(face, k + 1) - origin);
  return 0.5 * sum;
}

Vec3 vertex_mean(const Mesh& mesh, Index face) {
  const Index n = mesh.vertex_count(face);
  Vec3 sum = Vec3::Zero();
  for (Index k = 0; k < n; ++k) sum += mesh.face_vertex(face, k);
  return sum / n;
}

void fit_geometry(Mesh& mesh) {
  const Index cells = mesh.cell_count();
  mesh.volume.assign(cells, 0.0);
  mesh.centroid.assign(cells, Vec3::Zero());
  for (Index c = 0; c < cells; ++c) {
    const Index first = mesh.cell_faces[c], last = mesh.cell_faces[c + 1];
    Vec3 reference = Vec3::Zero();
    for (Index f = first; f < last; ++f) {
      Face& face = mesh.faces[f];
      face.point = vertex_mean(mesh, f);
      // A zero-area face keeps a zero normal; validation reports it.
      const Vec3 area = area_vector(mesh, f);
      const double norm = area.norm();
      face.normal = norm > 0.0 ? Vec3(-area / norm) : Vec3::Zero();
      reference += face.point;
    }
    reference /= std::max<Index>(1, last - first);

    double volume = 0.0;
    Vec3 moment = Vec3::Zero();
    for (Index f = first; f < last; ++f) {
      const Vec3 middle = mesh.faces[f].point - reference;
      const Index n = mesh.vertex_count(f);
      for (Index k = 0; k < n; ++k) {
        const Vec3 a = mesh.face_vertex(f, k) - reference;
        const Vec3 b = mesh.face_vertex(f, (k + 1) % n) - reference;
        const double v = middle.dot(a.cross(b)) / 6.0;
        volume += v;
        moment += v * (middle + a + b) / 4.0;
      }
    }
    mesh.volume[c] = volume;
    mesh.centroid[c] = reference + (volume != 0.0 ? Vec3(moment / volume) : Vec3::Zero());
  }
}

Eigen::AlignedBox3d cell_box(const Mesh& mesh, Index cell) {
  Eigen::AlignedBox3d box;
  for (Index f = mesh.cell_faces[cell]; f < mesh.cell_faces[cell + 1]; ++f)
    for (Index k = 0; k < mesh.vertex_count(f); ++k) box.extend(mesh.face_vertex(f, k));
  return box;
}

double whole_diagonal(const Mesh& mesh) {
  if (mesh.whole_diagonal > 0.0) return mesh.whole_diagonal;
  Eigen::AlignedBox3d box;
  for (const Vec3& x : mesh.vertices) box.extend(x);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

}  // namespace cosim::tracker::mesh
