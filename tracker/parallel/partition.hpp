// The cells of a mesh split into parts of about equal size with few faces between them:
// METIS k-way partitioning (Karypis & Kumar 1998) of the cells' dual graph.
#pragma once

#include <span>
#include <vector>

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker::parallel {

// The dual graph in compressed rows: cell c's neighbours are neighbours[start[c] ..
// start[c + 1]), ascending, each once. Two cells are neighbours when they share an
// interior face or a periodic one (a particle crosses either); a cell is never its own.
struct CellGraph {
  std::vector<int> start;
  std::vector<int> neighbours;
};
CellGraph cell_graph(const mesh::Mesh& mesh);

// The part (0 .. parts - 1) of every cell. Deterministic: METIS runs with a fixed seed, so
// the same mesh, part count and weights give the same parts on every rank and every run.
// One part calls no METIS. Parts hold the same number of cells, or the same weight if
// `weight` gives one per cell (>= 1 each, at most 2^31 in all), within METIS's default
// imbalance (3 %). Throws std::invalid_argument for parts < 1, more parts than cells or bad
// weights, and std::runtime_error if METIS fails.
std::vector<int> partition_cells(const mesh::Mesh& mesh, int parts, std::span<const int> weight = {});

}  // namespace cosim::tracker::parallel
