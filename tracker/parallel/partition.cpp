#include "tracker/parallel/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace cosim::tracker::parallel {
namespace {

static_assert(std::is_same_v<idx_t, int>, "CellGraph hands its arrays to METIS as they are: idx_t must be int");

// Any fixed value: what matters is that every rank and every run uses the same.
constexpr int kSeed = 1;

}  // namespace

CellGraph cell_graph(const mesh::Mesh& mesh) {
  CellGraph graph;
  graph.start.push_back(0);
  std::vector<int> row;
  for (Index c = 0; c < mesh.cell_count(); ++c) {
    row.clear();
    for (Index f = mesh.cell_faces[c]; f < mesh.cell_faces[c + 1]; ++f)
      if (const Index n = mesh.faces[f].neighbour; n >= 0 && n != c) row.push_back(n);
    // A cell meets a neighbour through several faces when a periodic axis has two cells.
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    graph.neighbours.insert(graph.neighbours.end(), row.begin(), row.end());
    graph.start.push_back(static_cast<int>(graph.neighbours.size()));
  }
  return graph;
}

std::vector<int> partition_cells(const mesh::Mesh& mesh, int parts, std::span<const int> weight) {
  const Index cells = mesh.cell_count();
  if (parts < 1 || parts > cells)
    throw std::invalid_argument("cannot split " + std::to_string(cells) + " cells into " + std::to_string(parts) +
                                " parts");
  if (!weight.empty()) {
    long long total = 0;
    for (const int w : weight) total += w;
    if (weight.size() != static_cast<std::size_t>(cells) || *std::min_element(weight.begin(), weight.end()) < 1 ||
        total > (1LL << 31) - 1)
      throw std::invalid_argument("cell weights: one of at least 1 per cell, at most 2^31 in all");
  }
  std::vector<int> part(static_cast<std::size_t>(cells), 0);
  if (parts == 1) return part;
  CellGraph graph = cell_graph(mesh);
  idx_t vertices = cells, constraints = 1, nparts = parts, cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = kSeed;
  // METIS does not write through its weights.
  idx_t* vertex_weights = weight.empty() ? nullptr : const_cast<idx_t*>(weight.data());
  const int status =
      METIS_PartGraphKway(&vertices, &constraints, graph.start.data(), graph.neighbours.data(), vertex_weights, nullptr,
                          nullptr, &nparts, nullptr, nullptr, options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error(mesh.source + ": METIS could not split the cells into " + std::to_string(parts) +
                             " parts (status " + std::to_string(status) + ")");
  return part;
}

}  // namespace cosim::tracker::parallel
