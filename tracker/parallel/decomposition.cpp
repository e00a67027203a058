#include "tracker/parallel/decomposition.hpp"

#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/partition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace cosim::tracker::parallel {

Decomposition::Decomposition(const mesh::Mesh& mesh, Ranks ranks)
    : ranks_(ranks), owners_(std::vector<int>(static_cast<std::size_t>(mesh.cell_count()), 0)) {
  if (ranks_.size() > 1) owners_ = Owners(agreed([&] { return partition_cells(mesh, ranks_.size()); }));
}

Owners Decomposition::proposal(std::span<const Index> particle_cells) const {
  const std::optional<Bricks>& bricks = owners_.bricks();
  if (!bricks) throw std::logic_error("Decomposition::proposal: the owners are not bricks");
  if (ranks_.size() == 1) return owners_;
  const std::array<int, 3>& hexahedra = bricks->hexahedra();
  const int per_hex = bricks->per_hex();
  // This rank's particles per hexahedron, by the hexahedron's number.
  std::vector<Index> hex;
  hex.reserve(particle_cells.size());
  for (const Index c : particle_cells) hex.push_back(c / per_hex);
  std::sort(hex.begin(), hex.end());
  using Held = std::vector<std::pair<std::array<int, 3>, long long>>;
  Held held;
  for (std::size_t i = 0; i < hex.size();) {
    std::size_t j = i;
    while (j < hex.size() && hex[j] == hex[i]) ++j;
    held.emplace_back(mesh::box_cell(hex[i], hexahedra, 1).hex, static_cast<long long>(j - i));
    i = j;
  }
  // The cuts are made depth first, each range within the last one not yet done with: the
  // hexahedra in each open range, so that each is looked at once per level.
  std::vector<std::pair<Bricks::Range, Held>> open{{Bricks::Range{{0, 0, 0}, hexahedra}, std::move(held)}};
  // Every cell 1 % of the mean besides its particles, so empty space still spreads.
  const double cells = 1.0 * hexahedra[0] * hexahedra[1] * hexahedra[2] * per_hex;
  const double floor = 0.01 * static_cast<double>(ranks_.sum(static_cast<long long>(particle_cells.size()))) / cells;
  // The slabs' particles are added up in integers: the same sums, so the same cuts, on
  // every rank.
  return Owners(Bricks::by_slabs(hexahedra, per_hex, ranks_.size(), [&](const Bricks::Range& r, int axis) {
    while (!open.back().first.holds(r)) open.pop_back();
    Held here;
    for (const auto& item : open.back().second)
      if (r.holds(item.first)) here.push_back(item);
    std::vector<long long> count(static_cast<std::size_t>(r.hi[axis] - r.lo[axis]), 0);
    for (const auto& [at, n] : here) count[static_cast<std::size_t>(at[axis] - r.lo[axis])] += n;
    open.emplace_back(r, std::move(here));
    ranks_.sum(count);
    const double per_slab = floor * static_cast<double>(r.hexahedra() / (r.hi[axis] - r.lo[axis]) * per_hex);
    std::vector<double> slab;
    for (const long long n : count) slab.push_back(static_cast<double>(n) + per_slab);
    return slab;
  }));
}

Owners Decomposition::proposal(const mesh::Mesh& mesh, std::span<const double> particles) const {
  if (ranks_.size() == 1) return owners_;
  return Owners(agreed([&] {
    // The particles' weights add up to 100 per cell on average (fewer if that passes 1e9:
    // METIS adds them in 32-bit integers), every cell 1 more.
    const double total = std::max(std::accumulate(particles.begin(), particles.end(), 0.0), 1.0);
    const double scale = std::min(1.0e9, 100.0 * static_cast<double>(particles.size())) / total;
    std::vector<int> weight;
    weight.reserve(particles.size());
    for (const double n : particles) weight.push_back(1 + static_cast<int>(std::lround(n * scale)));
    std::vector<int> part = partition_cells(mesh, ranks_.size(), weight);
    // METIS numbers its parts as it likes: each part goes to the rank holding most of its
    // particles now (greedily, the largest overlaps first), so a small shift moves few.
    const auto ranks = static_cast<std::size_t>(ranks_.size());
    std::vector<double> overlap(ranks * ranks, 0.0);  // [part][rank]
    for (std::size_t c = 0; c < part.size(); ++c)
      overlap[static_cast<std::size_t>(part[c]) * ranks + static_cast<std::size_t>(owner(static_cast<Index>(c)))] +=
          particles[c] + 1e-3;
    std::vector<std::size_t> order(overlap.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return overlap[a] > overlap[b]; });
    std::vector<int> rank_of(ranks, -1);
    std::vector<bool> taken(ranks, false);
    for (const std::size_t k : order)
      if (const std::size_t p = k / ranks, r = k % ranks; rank_of[p] < 0 && !taken[r]) {
        rank_of[p] = static_cast<int>(r);
        taken[r] = true;
      }
    for (int& p : part) p = rank_of[static_cast<std::size_t>(p)];
    return part;
  }));
}

std::vector<int> Decomposition::agreed(const std::function<std::vector<int>()>& partition) const {
  // METIS is deterministic for a fixed seed, but only rank 0's answer is certain to be the
  // same everywhere: one broadcast settles it for good (a rank with another METIS build).
  // Rank 0 says first whether it has one: if METIS fails there, every rank throws alike
  // instead of the others waiting for owners that never come.
  std::vector<int> numbers;
  std::string failure;
  if (ranks_.lead()) {
    try {
      numbers = partition();
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  long long size = failure.empty() ? static_cast<long long>(numbers.size()) : -1;
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, ranks_.comm());
  if (size < 0) throw std::runtime_error(ranks_.lead() ? failure : "rank 0 could not partition the mesh");
  numbers.resize(static_cast<std::size_t>(size));
  MPI_Bcast(numbers.data(), static_cast<int>(size), MPI_INT, 0, ranks_.comm());
  return numbers;
}

std::size_t Decomposition::migrate(tracking::Swarm& swarm, const Numbering& numbering) {
  return parallel::migrate(swarm, owners_, ranks_, migrations_++, numbering);
}

std::size_t Decomposition::hand_over(tracking::Handover& handover, const Numbering& numbering) {
  return parallel::migrate(handover, owners_, ranks_, migrations_++, numbering);
}

}  // namespace cosim::tracker::parallel
