// One gas over several ranks: which rank owns each cell (partition.hpp, computed on rank 0
// and broadcast, again with the particles as weights when the loads drift apart), and the
// step's migration of particles to the owners of their cells (migration.hpp). Every rank
// keeps the whole mesh; a rank holds the particles in its own cells once they migrated.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "tracker/parallel/migration.hpp"
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
  // returns how many left this rank. `numbering`: the swarm's cells are a part's.
  std::size_t migrate(Swarm& swarm, const Numbering& numbering = {});
  // Collective: the moves handed over go on to their cells' owners, and the handover holds
  // those that came here; returns how many left.
  std::size_t hand_over(Handover& handover, const Numbering& numbering);
  // Collective: owners for a partition balanced by particles (`particles`: per cell, the
  // same on every rank), as rank 0's METIS gives it with every cell weighted by its
  // particles (and 1 % of the mean weight, so empty cells still spread), its parts numbered
  // after the ranks that hold most of their particles now. Changes nothing here.
  std::vector<int> proposal(const Mesh& mesh, std::span<const double> particles) const;
  // New owners (a proposal, or those a state saved; the same on every rank):
  // std::invalid_argument unless one rank in range per cell. The particles stay where they
  // are until the next migrate().
  void set_owners(std::vector<int> owners);

 private:
  // Rank 0's partition, or its failure, on every rank.
  std::vector<int> agreed(const std::function<std::vector<int>()>& partition) const;

  Ranks ranks_;
  std::vector<int> owner_;
  std::uint64_t migrations_ = 0;
};

}  // namespace cosim::tracker
