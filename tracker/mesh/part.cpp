#include "tracker/mesh/part.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "tracker/mesh/geometry.hpp"

namespace cosim::tracker::mesh {
namespace {

// The part's cells in the whole's numbers: the owned ones, then each layer of neighbours.
std::vector<Index> part_cells(const Mesh& whole, const std::function<int(Index)>& owner, int rank, int layers,
                              std::vector<Index>& local) {
  std::vector<Index> cells;
  for (Index c = 0; c < whole.cell_count(); ++c)
    if (owner(c) == rank) {
      local[static_cast<std::size_t>(c)] = static_cast<Index>(cells.size());
      cells.push_back(c);
    }
  std::size_t layer_begin = 0;
  for (int layer = 0; layer < layers; ++layer) {
    const std::size_t layer_end = cells.size();
    std::vector<Index> next;
    for (std::size_t i = layer_begin; i < layer_end; ++i)
      for (Index f = whole.cell_faces[cells[i]]; f < whole.cell_faces[cells[i] + 1]; ++f)
        if (const Index n = whole.faces[static_cast<std::size_t>(f)].neighbour;
            n >= 0 && local[static_cast<std::size_t>(n)] < 0) {
          local[static_cast<std::size_t>(n)] = 0;  // taken; numbered below, in the whole's order
          next.push_back(n);
        }
    std::sort(next.begin(), next.end());
    for (const Index n : next) {
      local[static_cast<std::size_t>(n)] = static_cast<Index>(cells.size());
      cells.push_back(n);
    }
    layer_begin = layer_end;
  }
  return cells;
}

}  // namespace

Mesh extract_part(const Mesh& whole, const std::function<int(Index)>& owner, int rank, int layers) {
  std::vector<Index> local(static_cast<std::size_t>(whole.cell_count()), -1);
  Mesh part;
  part.partial = true;
  part.global = part_cells(whole, owner, rank, layers, local);
  part.ghosts = static_cast<Index>(
      std::count_if(part.global.begin(), part.global.end(), [&](Index c) { return owner(c) != rank; }));
  part.patches = whole.patches;
  part.shifts = whole.shifts;
  part.source = whole.source;
  part.whole_diagonal = whole_diagonal(whole);

  part.cell_faces.push_back(0);
  for (const Index c : part.global)
    part.cell_faces.push_back(part.cell_faces.back() + whole.cell_faces[c + 1] - whole.cell_faces[c]);
  std::vector<Index> vertex(whole.vertices.size(), -1);
  part.face_vertex_begin.push_back(0);
  for (const Index c : part.global) {
    part.volume.push_back(whole.volume[static_cast<std::size_t>(c)]);
    part.centroid.push_back(whole.centroid[static_cast<std::size_t>(c)]);
    for (Index f = whole.cell_faces[c]; f < whole.cell_faces[c + 1]; ++f) {
      Face face = whole.faces[static_cast<std::size_t>(f)];
      if (const Index n = face.neighbour; n >= 0) {
        const Index there = local[static_cast<std::size_t>(n)];
        if (there < 0) {
          face.neighbour = kBeyondPart;
          face.twin = -1;
        } else {
          face.neighbour = there;
          face.twin = part.cell_faces[static_cast<std::size_t>(there)] + face.twin - whole.cell_faces[n];
        }
      }
      part.faces.push_back(face);
      for (Index k = 0; k < whole.vertex_count(f); ++k) {
        const auto v =
            static_cast<std::size_t>(whole.face_vertex_index[static_cast<std::size_t>(whole.face_vertex_begin[f] + k)]);
        if (vertex[v] < 0) {
          vertex[v] = static_cast<Index>(part.vertices.size());
          part.vertices.push_back(whole.vertices[v]);
        }
        part.face_vertex_index.push_back(vertex[v]);
      }
      part.face_vertex_begin.push_back(static_cast<Index>(part.face_vertex_index.size()));
    }
  }
  return part;
}

PartCells::PartCells(const Mesh& part) {
  for (Index c = 0; c < part.cell_count(); ++c) by_global_.emplace_back(part.global_cell(c), c);
  std::sort(by_global_.begin(), by_global_.end());
}

Index PartCells::local(Index global) const {
  const auto it = std::lower_bound(by_global_.begin(), by_global_.end(), std::pair<Index, Index>{global, -1});
  return it != by_global_.end() && it->first == global ? it->second : -1;
}

}  // namespace cosim::tracker::mesh
