// One gas over several ranks: which rank owns each cell (partition.hpp, computed on rank 0
// and broadcast, again with the particles as weights when the loads drift apart), and the
// step's migration of particles to the owners of their cells (migration.hpp). Every rank keeps the whole mesh; a rank holds only the particles in its
// own cells between steps.
#pragma once

#include <cstdint>
#include <functional>
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
  // Collective: a new partition with every cell weighted by 1 + its particles (`particles`:
  // per cell, the same on every rank), as rank 0's METIS gives it. The particles stay where
  // they are until the next migrate().
  void repartition(const Mesh& mesh, std::span<const double> particles);
  // Owners as a state saved them (the same on every rank): std::invalid_argument unless one
  // rank in range per cell.
  void set_owners(std::vector<int> owners);

 private:
  // Rank 0's partition, or its failure, on every rank.
  void adopt(const std::function<std::vector<int>()>& partition);

  Ranks ranks_;
  std::vector<int> owner_;
  std::uint64_t migrations_ = 0;
};

}  // namespace cosim::tracker
