#include "tracker/parallel/decomposition.hpp"

#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/partition.hpp"

namespace cosim::tracker {

Decomposition::Decomposition(const Mesh& mesh, Ranks ranks)
    : ranks_(ranks), owner_(static_cast<std::size_t>(mesh.cell_count()), 0) {
  if (ranks_.size() == 1) return;
  // METIS is deterministic for a fixed seed, but only rank 0's answer is certain to be the
  // same everywhere: one broadcast settles it for good (a rank with another METIS build).
  if (ranks_.lead()) owner_ = partition_cells(mesh, ranks_.size());
  MPI_Bcast(owner_.data(), static_cast<int>(owner_.size()), MPI_INT, 0, ranks_.comm());
}

std::size_t Decomposition::migrate(Swarm& swarm) const { return tracker::migrate(swarm, owner_, ranks_); }

}  // namespace cosim::tracker
