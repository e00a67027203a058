// The cells of a mesh split into parts of about equal size with few faces between them:
// METIS k-way partitioning (Karypis & Kumar 1998) of the cells' dual graph.
#pragma once

#include <vector>

#include "tracker/mesh/mesh.hpp"

namespace cosim::tracker {

// The dual graph in compressed rows: cell c's neighbours are neighbours[start[c] ..
// start[c + 1]), ascending, each once. Two cells are neighbours when they share an
// interior face or a periodic one (a particle crosses either); a cell is never its own.
struct CellGraph {
  std::vector<int> start;
  std::vector<int> neighbours;
};
CellGraph cell_graph(const Mesh& mesh);

// The part (0 .. parts - 1) of every cell. Deterministic: METIS runs with a fixed seed, so
// the same mesh and part count give the same parts on every rank and every run. One part
// calls no METIS. Parts hold the same number of cells within METIS's default imbalance
// (3 %). Throws std::invalid_argument for parts < 1 or more parts than cells, and
// std::runtime_error if METIS fails.
std::vector<int> partition_cells(const Mesh& mesh, int parts);

}  // namespace cosim::tracker
