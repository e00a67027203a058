// One gas over several ranks: which rank owns each cell (partition.hpp, computed on rank 0
// and broadcast), and the step's migration of particles to the owners of their cells
// (migration.hpp). Every rank keeps the whole mesh; a rank holds only the particles in its
// own cells between steps.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tracker/parallel/ranks.hpp"
#include "tracker/tracking/swarm.hpp"

namespace cosim::tracker {

class Decomposition {
 public:
  // Collective. One rank owns every cell (no METIS, no MPI).
  Decomposition(const Mesh& mesh, Ranks ranks);

  const Ranks& ranks() const { return ranks_; }
  std::span<const int> owners() const { return owner_; }
  int owner(Index cell) const { return owner_[static_cast<std::size_t>(cell)]; }
  bool owns(Index cell) const { return owner(cell) == ranks_.rank(); }
  // Collective: sends the swarm's particles in other ranks' cells there (migration.hpp);
  // returns how many left this rank.
  std::size_t migrate(Swarm& swarm);

 private:
  Ranks ranks_;
  std::vector<int> owner_;
  std::uint64_t migrations_ = 0;
};

}  // namespace cosim::tracker
