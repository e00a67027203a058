#include "tracker/parallel/decomposition.hpp"

#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/partition.hpp"

#include <stdexcept>
#include <string>

namespace cosim::tracker {

Decomposition::Decomposition(const Mesh& mesh, Ranks ranks)
    : ranks_(ranks), owner_(static_cast<std::size_t>(mesh.cell_count()), 0) {
  if (ranks_.size() == 1) return;
  // METIS is deterministic for a fixed seed, but only rank 0's answer is certain to be the
  // same everywhere: one broadcast settles it for good (a rank with another METIS build).
  // Rank 0 says first whether it has one: if METIS fails there, every rank throws alike
  // instead of the others waiting for owners that never come.
  std::string failure;
  if (ranks_.lead()) {
    try {
      owner_ = partition_cells(mesh, ranks_.size());
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  int failed = failure.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, ranks_.comm());
  if (failed) throw std::runtime_error(ranks_.lead() ? failure : "rank 0 could not partition the mesh");
  MPI_Bcast(owner_.data(), static_cast<int>(owner_.size()), MPI_INT, 0, ranks_.comm());
}

std::size_t Decomposition::migrate(Swarm& swarm) { return tracker::migrate(swarm, owner_, ranks_, migrations_++); }

}  // namespace cosim::tracker
