// One gas over several ranks: which rank owns each cell (owners.hpp: bricks of a box, or
// METIS's parts of any mesh, computed on rank 0 and broadcast; again with the particles as
// weights when the loads drift apart), and the moves of particles to the owners of their
// cells (migration.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/owners.hpp"
#include "tracker/parallel/ranks.hpp"
#include "tracker/tracking/swarm.hpp"

namespace cosim::tracker::parallel {

class Decomposition {
 public:
  // Collective. METIS's parts of the mesh's cells, computed on rank 0 and broadcast; one
  // rank owns every cell (no METIS, no MPI).
  Decomposition(const mesh::Mesh& mesh, Ranks ranks);
  // Bricks of a structured box (bricks.hpp): every rank computes the same, no mesh needed.
  Decomposition(Bricks bricks, Ranks ranks) : ranks_(ranks), owners_(std::move(bricks)) {}

  const Ranks& ranks() const { return ranks_; }
  const Owners& owners() const { return owners_; }
  int owner(Index cell) const { return owners_(cell); }
  bool owns(Index cell) const { return owner(cell) == ranks_.rank(); }
  // Collective: sends the swarm's particles in other ranks' cells there (migration.hpp);
  // returns how many left this rank. `numbering`: the swarm's cells are a part's.
  std::size_t migrate(tracking::Swarm& swarm, const Numbering& numbering = {});
  // Collective: the moves handed over go on to their cells' owners, and the handover holds
  // those that came here; returns how many left.
  std::size_t hand_over(tracking::Handover& handover, const Numbering& numbering);
  // Collective: the sparse exchange of migrate(), for other records.
  Messages exchange(const Messages& out) { return parallel::exchange(out, ranks_, migrations_++); }
  // Collective: owners balanced by the particles. Bricks (the owners are bricks) cut where
  // the particles split in the ratio of the ranks: each rank gives its own particles' cells
  // (numbers in the whole mesh), added up over the ranks slab by slab as the cuts need them,
  // so no rank holds every cell's count.
  Owners proposal(std::span<const Index> particle_cells) const;
  // METIS's parts of the whole `mesh` with every cell weighted by `particles` (per cell of
  // the whole; read on rank 0 only), computed on rank 0 and broadcast, numbered after the
  // ranks that hold most of their particles now.
  // In both, every cell weighs 1 % of the mean besides its particles, so empty cells still
  // spread. Nothing changes here.
  Owners proposal(const mesh::Mesh& mesh, std::span<const double> particles) const;
  // New owners (a proposal, or those a state saved; the same on every rank). The particles
  // stay where they are until the next migrate().
  void set_owners(Owners owners) { owners_ = std::move(owners); }

 private:
  // Rank 0's numbers, or its failure, on every rank.
  std::vector<int> agreed(const std::function<std::vector<int>()>& partition) const;

  Ranks ranks_;
  Owners owners_;
  std::uint64_t migrations_ = 0;
};

}  // namespace cosim::tracker::parallel
