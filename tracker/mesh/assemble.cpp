#include "tracker/mesh/assemble.hpp"

#include "tracker/mesh/geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>

namespace cosim::tracker::mesh {

void Polyhedra::add_face(std::span<const Index> loop, Index patch) {
  face_vertex_index.insert(face_vertex_index.end(), loop.begin(), loop.end());
  face_vertex_begin.push_back(static_cast<Index>(face_vertex_index.size()));
  face_patch.push_back(patch);
}

namespace {

Index patch_index(Mesh& mesh, const std::string& name) {
  const auto it = std::find(mesh.patches.begin(), mesh.patches.end(), name);
  if (it != mesh.patches.end()) return static_cast<Index>(it - mesh.patches.begin());
  mesh.patches.push_back(name);
  return static_cast<Index>(mesh.patches.size()) - 1;
}

void set_boundary(Mesh& mesh, Index face, Index patch) {
  if (patch < 0) patch = patch_index(mesh, "boundary");
  mesh.faces[face].neighbour = boundary_code(patch);
}

// Pairs faces with equal sets of vertex ids: sort the faces by their sorted id lists,
// partners become adjacent.
void pair_by_vertices(Mesh& mesh, const std::vector<Index>& face_patch) {
  const Index faces = mesh.face_count();
  std::vector<Index> keys = mesh.face_vertex_index;
  for (Index f = 0; f < faces; ++f)
    std::sort(keys.begin() + mesh.face_vertex_begin[f], keys.begin() + mesh.face_vertex_begin[f + 1]);
  const auto key = [&](Index f) {
    return std::span<const Index>(keys.data() + mesh.face_vertex_begin[f], mesh.vertex_count(f));
  };
  const auto less = [&](Index a, Index b) {
    const auto ka = key(a), kb = key(b);
    return std::lexicographical_compare(ka.begin(), ka.end(), kb.begin(), kb.end());
  };
  std::vector<Index> order(faces);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), less);

  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i + 1;
    while (j < order.size() && !less(order[i], order[j])) ++j;
    if (j - i > 2)
      throw std::invalid_argument(mesh.source + ": face " + std::to_string(order[i]) + " of cell " +
                                  std::to_string(mesh.cell_of_face(order[i])) + " is shared by " +
                                  std::to_string(j - i) + " cells");
    if (j - i == 2) {
      const Index a = order[i], b = order[i + 1];
      mesh.faces[a].neighbour = mesh.cell_of_face(b);
      mesh.faces[a].twin = b;
      mesh.faces[b].neighbour = mesh.cell_of_face(a);
      mesh.faces[b].twin = a;
    } else {
      set_boundary(mesh, order[i], face_patch[order[i]]);
    }
    i = j;
  }
}

// Neighbours given by the source (Voronoi): the partner is the neighbour's face back to
// this cell whose vertex mean is this one's up to a lattice translation.
void pair_by_neighbours(Mesh& mesh, const Polyhedra& input) {
  std::vector<Vec3> middle(mesh.face_count());
  for (Index f = 0; f < mesh.face_count(); ++f) middle[f] = vertex_mean(mesh, f);
  const auto lattice = [&](const Vec3& d) {
    Vec3 s = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      if (input.period[k] > 0.0) s[k] = std::round(d[k] / input.period[k]) * input.period[k];
    return s;
  };
  std::map<std::array<long, 3>, Index> shift_index{{{0, 0, 0}, 0}};

  for (Index f = 0; f < mesh.face_count(); ++f) {
    const Index cell = mesh.cell_of_face(f), other = input.face_neighbour[f];
    if (other < 0) {
      set_boundary(mesh, f, patch_of(other));
      continue;
    }
    mesh.faces[f].neighbour = other;
    if (other >= mesh.cell_count()) continue;  // validation reports it
    double best = std::numeric_limits<double>::infinity();
    for (Index g = mesh.cell_faces[other]; g < mesh.cell_faces[other + 1]; ++g) {
      if (input.face_neighbour[g] != cell || g == f) continue;
      const Vec3 d = middle[g] - middle[f];
      const double miss = (d - lattice(d)).norm();
      if (miss < best) {
        best = miss;
        mesh.faces[f].twin = g;
      }
    }
    if (mesh.faces[f].twin < 0) continue;  // validation reports it
    const Vec3 shift = lattice(middle[mesh.faces[f].twin] - middle[f]);
    std::array<long, 3> key{};
    for (int k = 0; k < 3; ++k) key[k] = input.period[k] > 0.0 ? std::lround(shift[k] / input.period[k]) : 0;
    const auto [it, added] = shift_index.try_emplace(key, static_cast<Index>(mesh.shifts.size()));
    if (added) mesh.shifts.push_back(shift);
    mesh.faces[f].shift = it->second;
  }
}

}  // namespace

Mesh assemble(Polyhedra input) {
  Mesh mesh;
  mesh.source = std::move(input.source);
  mesh.patches = std::move(input.patches);
  mesh.vertices = std::move(input.vertices);
  mesh.cell_faces = std::move(input.cell_faces);
  mesh.face_vertex_begin = std::move(input.face_vertex_begin);
  mesh.face_vertex_index = std::move(input.face_vertex_index);
  mesh.faces.assign(mesh.face_vertex_begin.size() - 1, Face{Vec3::Zero(), Vec3::Zero(), -1, -1, 0});
  if (input.face_neighbour.empty())
    pair_by_vertices(mesh, input.face_patch);
  else
    pair_by_neighbours(mesh, input);
  fit_geometry(mesh);
  return mesh;
}

}  // namespace cosim::tracker::mesh
