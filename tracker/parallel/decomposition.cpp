#include "tracker/parallel/decomposition.hpp"

#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/partition.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cosim::tracker {

Decomposition::Decomposition(const Mesh& mesh, Ranks ranks)
    : ranks_(ranks), owner_(static_cast<std::size_t>(mesh.cell_count()), 0) {
  if (ranks_.size() > 1) adopt([&] { return partition_cells(mesh, ranks_.size()); });
}

void Decomposition::repartition(const Mesh& mesh, std::span<const double> particles) {
  if (ranks_.size() == 1) return;
  adopt([&] {
    // Scaled down if need be: METIS adds the weights in 32-bit integers.
    double total = 0;
    for (const double n : particles) total += n;
    const double scale = std::min(1.0, 1.0e9 / std::max(total, 1.0));
    std::vector<int> weight;
    weight.reserve(particles.size());
    for (const double n : particles) weight.push_back(1 + static_cast<int>(std::lround(n * scale)));
    return partition_cells(mesh, ranks_.size(), weight);
  });
}

void Decomposition::adopt(const std::function<std::vector<int>()>& partition) {
  // METIS is deterministic for a fixed seed, but only rank 0's answer is certain to be the
  // same everywhere: one broadcast settles it for good (a rank with another METIS build).
  // Rank 0 says first whether it has one: if METIS fails there, every rank throws alike
  // instead of the others waiting for owners that never come.
  std::string failure;
  if (ranks_.lead()) {
    try {
      owner_ = partition();
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  int failed = failure.empty() ? 0 : 1;
  MPI_Bcast(&failed, 1, MPI_INT, 0, ranks_.comm());
  if (failed) throw std::runtime_error(ranks_.lead() ? failure : "rank 0 could not partition the mesh");
  MPI_Bcast(owner_.data(), static_cast<int>(owner_.size()), MPI_INT, 0, ranks_.comm());
}

void Decomposition::set_owners(std::vector<int> owners) {
  if (owners.size() != owner_.size() ||
      std::any_of(owners.begin(), owners.end(), [&](int r) { return r < 0 || r >= ranks_.size(); }))
    throw std::invalid_argument("owners: one rank of " + std::to_string(ranks_.size()) + " per cell of " +
                                std::to_string(owner_.size()));
  owner_ = std::move(owners);
}

std::size_t Decomposition::migrate(Swarm& swarm) { return tracker::migrate(swarm, owner_, ranks_, migrations_++); }

}  // namespace cosim::tracker
