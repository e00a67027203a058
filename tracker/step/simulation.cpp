#include "tracker/step/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "tracker/mesh/box_part.hpp"
#include "tracker/parallel/bricks.hpp"
#include "tracker/step/cell_volumes.hpp"
#include "tracker/step/seed_particles.hpp"
#include "tracker/step/tally_numbers.hpp"

namespace cosim::tracker::step {
namespace {

template <typename Tally>
std::vector<Tally> summed(std::vector<Tally> tallies, const parallel::Ranks& ranks) {
  std::vector<long long> counts;
  std::vector<double> numbers;
  for (const Tally& t : tallies) {
    detail::each_count(t, [&](long long n) { counts.push_back(n); });
    detail::each_value(t, [&](double x) { numbers.push_back(x); });
  }
  ranks.sum(counts);
  ranks.sum(numbers);
  const long long* n = counts.data();
  const double* x = numbers.data();
  for (Tally& t : tallies) {
    detail::each_count(t, [&](long long& count) { count = *n++; });
    detail::each_value(t, [&](double& value) { value = *x++; });
  }
  return tallies;
}

// Rank 0 draws what a one-rank run draws; another rank has a stream of its own, none of
// them its windows' (the seed sequences differ in length).
tracking::Random first_random(std::uint64_t seed, int rank) {
  if (rank == 0) return tracking::Random(seed);
  std::seed_seq own{seed, static_cast<std::uint64_t>(rank), std::uint64_t{0}, std::uint64_t{0}};
  return tracking::Random(own);
}

// The collisions' pcg64 stream of a window on a rank: rank 0's is the window's, as on one
// rank; ranks are 2^48 streams apart, more windows than any run has.
std::uint64_t collision_stream(std::uint64_t window, int rank) {
  return window + (static_cast<std::uint64_t>(rank) << 48);
}

// Bricks for a box, METIS's parts of any other mesh.
parallel::Decomposition decompose(const GasSetup& setup, parallel::Ranks ranks) {
  if (!setup.box) return parallel::Decomposition(*setup.mesh, ranks);
  return parallel::Decomposition(parallel::box_bricks(*setup.box, ranks.size()), ranks);
}

// Per-cell numbers of a rank's cells (`width` a cell) as records: the cell in the whole
// mesh, then its numbers; cells whose numbers are all 0 are left out.
void put_cells(std::vector<double>& records, const mesh::Mesh& cells, Index c, std::span<const double> numbers) {
  if (std::all_of(numbers.begin(), numbers.end(), [](double x) { return x == 0.0; })) return;
  records.push_back(cells.global_cell(c));
  records.insert(records.end(), numbers.begin(), numbers.end());
}

std::vector<std::byte> bytes_of(std::span<const double> values) {
  std::vector<std::byte> bytes(values.size_bytes());
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());  // memcpy of null: undefined
  return bytes;
}

std::vector<double> doubles_of(std::span<const std::byte> bytes) {
  std::vector<double> values(bytes.size() / sizeof(double));
  if (!values.empty()) std::memcpy(values.data(), bytes.data(), values.size() * sizeof(double));
  return values;
}

// put_cells()'s records by rank, as the sparse exchange sends them.
parallel::Messages messages_of(const std::map<int, std::vector<double>>& records) {
  parallel::Messages out;
  for (const auto& [rank, values] : records) out[rank] = bytes_of(values);
  return out;
}

// Each record that came (its cell in the whole mesh, then `width` numbers), in order.
template <typename Take>
void for_each_record(const parallel::Messages& in, std::size_t width, const Take& take) {
  for (const auto& [rank, bytes] : in) {
    const std::vector<double> values = doubles_of(bytes);
    for (std::size_t at = 0; at < values.size(); at += 1 + width)
      take(static_cast<Index>(values[at]), std::span(values).subspan(at + 1, width));
  }
}

}  // namespace

Simulation::Simulation(GasSetup setup, parallel::Ranks ranks)
    : setup_(std::move(setup)),
      velocity_(setup_.tracers ? setup_.tracers->velocity : std::nullopt),
      seed_(setup_.particles.seed),
      decomposition_(decompose(setup_, ranks)),
      random_(first_random(seed_, ranks.rank())),
      swarm_(setup_.obstacles.count()),
      sampler_(*setup_.mesh),
      tallies_(static_cast<std::size_t>(setup_.obstacles.count())),
      patch_tallies_(setup_.domain->boundaries.patches.size()),
      away_(setup_.obstacles.count()) {
  const CellVolumes volumes = setup_.box ? volumes_of(*setup_.box) : volumes_of(*setup_.mesh);
  whole_cells_ = volumes.cells;
  if (ranks.size() > 1 && !setup_.tracers) {
    if (setup_.mesh->partial) {  // the setup holds this rank's part of a box
      part_ = std::move(setup_.mesh);
      part_cells_ = std::make_unique<mesh::PartCells>(*part_);
    } else {
      part_ = std::make_unique<mesh::Mesh>();
      take_part();
    }
    sampler_ = tracking::CellSampler(*part_);
  }
  if (ranks.size() > 1 && ranks.lead() && setup_.box && !brick()) whole_volume_ = cell_volumes(*setup_.box);
  swarm_ = seed_particles(tracked(), setup_.obstacles, setup_.particles, decomposition_, volumes);
  seeded_ = swarm_.size();
  if (setup_.collisions) {
    // The first (sigma g)_max per cell: at the hottest temperature the scene gives.
    double hottest = setup_.particles.hottest();
    for (const tracking::Inflow& inflow : setup_.inflows) hottest = std::max(hottest, inflow.temperature());
    collider_.emplace(tracked(), *setup_.collisions, std::max(hottest, 1.0), setup_.particles.weight, seed_);
    collider_->reseed(seed_, collision_stream(0, ranks.rank()));
  }
  sampler_.sample(swarm_);
}

void Simulation::reseed(std::uint64_t stream) {
  const int rank = decomposition_.ranks().rank();
  if (rank == 0) {
    std::seed_seq walls{seed_, stream};
    random_.seed(walls);
  } else {
    std::seed_seq walls{seed_, stream, static_cast<std::uint64_t>(rank)};
    random_.seed(walls);
  }
  if (collider_) collider_->reseed(seed_, collision_stream(stream, rank));
}

void Simulation::move_obstacle(int i, const Eigen::Isometry3d& pose, double dt) {
  // Every rank moves every obstacle alike: all know that overrun particles may sit in
  // ghosts now.
  if (pose.matrix() != setup_.obstacles.pose(i).matrix()) strays_ = true;
  setup_.obstacles.set_pose(i, pose, dt, *setup_.domain, swarm_, random_, tallies_[static_cast<std::size_t>(i)]);
}

void Simulation::balance() {
  const parallel::Ranks& ranks = decomposition_.ranks();
  const auto max_over_mean = [&](const std::vector<double>& load) {
    const double mean = std::accumulate(load.begin(), load.end(), 0.0) / ranks.size();
    return *std::max_element(load.begin(), load.end()) / mean;
  };
  std::vector<double> held(static_cast<std::size_t>(ranks.size()), 0.0);
  held[static_cast<std::size_t>(ranks.rank())] = static_cast<double>(swarm_.size());
  ranks.sum(held);
  const double now = max_over_mean(held);
  if (!(now > setup_.balance.threshold && now > balance_floor_)) return;
  const auto held_in = [&] {  // the cells of this rank's particles, in the whole mesh
    std::vector<Index> cells;
    for (std::size_t i = 0; i < swarm_.size(); ++i) cells.push_back(tracked().global_cell(swarm_.cell(i)));
    return cells;
  };
  parallel::Owners owners = decomposition_.owners().bricks() ? decomposition_.proposal(held_in())
                                                             : decomposition_.proposal(*setup_.mesh, counts());
  // The loads the proposal would give: each rank counts where its particles would go.
  std::vector<double> load(held.size(), 0.0);
  for (std::size_t i = 0; i < swarm_.size(); ++i)
    load[static_cast<std::size_t>(owners(tracked().global_cell(swarm_.cell(i))))] += 1.0;
  ranks.sum(load);
  // A partition that would not help (too few particles, or cells that cannot be split
  // finer) is not taken, nor sought again until the loads drift 10 % further apart. Nor
  // one that leaves a rank no cell.
  std::vector<long long> cells(held.size(), 0);
  if (const std::optional<parallel::Bricks>& b = owners.bricks())
    for (int r = 0; r < b->parts(); ++r) cells[static_cast<std::size_t>(r)] = b->brick(r).hexahedra();
  else
    for (Index c = 0; c < whole_cells_; ++c) ++cells[static_cast<std::size_t>(owners(c))];
  const bool empty = std::find(cells.begin(), cells.end(), 0LL) != cells.end();
  if (!(max_over_mean(load) < 0.9 * now) || empty) {
    balance_floor_ = 1.1 * now;
    return;
  }
  balance_floor_ = 0.0;
  ++rebalances_;
  if (!part_) {  // tracer mode: the whole mesh everywhere, nothing kept per cell
    decomposition_.set_owners(std::move(owners));
    migrated_ += decomposition_.migrate(swarm_);
    return;
  }
  // What is kept per cell goes to the cell's new owner: its collision state (its old
  // owner's), the sampler's sums (they add up over the ranks).
  constexpr std::size_t kWidth = 2 + tracking::CellSampler::kSumsPerCell;
  const std::vector<double> samples = sampler_.sums();
  std::map<int, std::vector<double>> records;
  std::vector<double> cell(kWidth);
  for (Index c = 0; c < tracked().cell_count(); ++c) {
    const bool own = c < tracked().own_cells();
    cell[0] = collider_ && own ? collider_->cells()[static_cast<std::size_t>(c)].sigma_g_max : 0.0;
    cell[1] = collider_ && own ? collider_->cells()[static_cast<std::size_t>(c)].remainder : 0.0;
    std::copy_n(samples.begin() + 1 + static_cast<std::ptrdiff_t>(c * tracking::CellSampler::kSumsPerCell),
                tracking::CellSampler::kSumsPerCell, cell.begin() + 2);
    put_cells(records[owners(tracked().global_cell(c))], tracked(), c, cell);
  }
  const parallel::Messages in = decomposition_.exchange(messages_of(records));
  // The particles by the whole's cell numbers while the parts change.
  swarm_.renumber_cells([&](Index c) { return tracked().global_cell(c); });
  decomposition_.set_owners(std::move(owners));
  take_part();
  migrated_ += decomposition_.migrate(swarm_);
  swarm_.renumber_cells([&](Index c) { return numbering().local(c); });
  std::vector<double> sums(1 + static_cast<std::size_t>(tracked().cell_count()) * tracking::CellSampler::kSumsPerCell,
                           0.0);
  sums[0] = samples[0];
  std::vector<dsmc::CellCollisionState> states(static_cast<std::size_t>(tracked().cell_count()));
  for_each_record(in, kWidth, [&](Index global, std::span<const double> cell) {
    const auto c = static_cast<std::size_t>(numbering().local(global));
    states[c].sigma_g_max = std::max(states[c].sigma_g_max, cell[0]);
    states[c].remainder += cell[1];
    for (std::size_t k = 0; k < tracking::CellSampler::kSumsPerCell; ++k)
      sums[1 + c * tracking::CellSampler::kSumsPerCell + k] += cell[2 + k];
  });
  sampler_ = tracking::CellSampler(*part_);
  sampler_.set_sums(sums);
  if (collider_) collider_->set_cells(std::move(states));
}

void Simulation::take_part() {
  const parallel::Ranks& ranks = decomposition_.ranks();
  const auto owner = [&](Index c) { return decomposition_.owner(c); };
  if (setup_.box) {
    const parallel::Bricks::Range& mine = decomposition_.owners().bricks()->brick(ranks.rank());
    *part_ = mesh::box_part(*setup_.box, mine.lo, mine.hi, owner, ranks.rank());
  } else {
    *part_ = mesh::extract_part(*setup_.mesh, owner, ranks.rank());
  }
  part_cells_ = std::make_unique<mesh::PartCells>(*part_);
  setup_.domain = std::make_unique<const tracking::Domain>(*part_, setup_.domain->boundaries);
  setup_.obstacles = setup_.obstacles.on(*part_);
  std::vector<tracking::Inflow> inflows;
  for (const tracking::Inflow& inflow : setup_.inflows) inflows.push_back(inflow.on(*part_));
  setup_.inflows = std::move(inflows);
}

std::vector<double> Simulation::at_lead(std::span<const double> mine, std::size_t width) const {
  const parallel::Ranks& ranks = decomposition_.ranks();
  if (ranks.size() == 1) return {mine.begin(), mine.end()};
  std::vector<double> records;
  for (Index c = 0; c < tracked().cell_count(); ++c)
    put_cells(records, tracked(), c, mine.subspan(static_cast<std::size_t>(c) * width, width));
  std::vector<double> whole(ranks.lead() ? width * static_cast<std::size_t>(whole_cells_) : 0, 0.0);
  ranks.gather_each(records, [&](std::span<const double> some) {
    for (std::size_t at = 0; at < some.size(); at += 1 + width)
      for (std::size_t k = 0; k < width; ++k) whole[static_cast<std::size_t>(some[at]) * width + k] += some[at + 1 + k];
  });
  return whole;
}

int Simulation::advance(double t0, double t1, const std::function<void(double t, double h)>& before) {
  const double span = t1 - t0;
  if (!(span > 0)) throw std::runtime_error("cannot advance over " + std::to_string(span) + " s");
  // The tolerance keeps a window that is a whole number of steps from gaining one by round-off.
  const int steps = static_cast<int>(std::max(1.0, std::ceil(span / setup_.dt - 1e-9)));
  const double h = span / steps;
  for (int k = 1; k <= steps; ++k) {
    if (before) before(t0 + k * h, h);
    step(h);
  }
  return steps;
}

std::size_t Simulation::particles() const {
  return static_cast<std::size_t>(decomposition_.ranks().sum(static_cast<long long>(swarm_.size())));
}
std::size_t Simulation::seeded() const {
  return static_cast<std::size_t>(decomposition_.ranks().sum(static_cast<long long>(seeded_)));
}
std::size_t Simulation::injected() const {
  return static_cast<std::size_t>(decomposition_.ranks().sum(static_cast<long long>(injected_)));
}
std::size_t Simulation::migrated() const {
  return static_cast<std::size_t>(decomposition_.ranks().sum(static_cast<long long>(migrated_)));
}
std::int64_t Simulation::collisions() const { return decomposition_.ranks().sum(collisions_); }

tracking::MoveTally Simulation::moves() const {
  tracking::MoveTally moves = moves_;
  std::vector<long long> counts;
  for (const tracking::MoveCounter& c : tracking::kMoveCounters) counts.push_back(moves.*c.count);
  decomposition_.ranks().sum(counts);
  for (std::size_t k = 0; const tracking::MoveCounter& c : tracking::kMoveCounters) moves.*c.count = counts[k++];
  return moves;
}

std::vector<tracking::ObstacleTally> Simulation::tallies() const { return summed(tallies_, decomposition_.ranks()); }
std::vector<tracking::SurfaceTally> Simulation::patch_tallies() const {
  return summed(patch_tallies_, decomposition_.ranks());
}

std::optional<parallel::Bricks::Range> Simulation::brick() const {
  if (!part_ || !setup_.box || setup_.box->tetrahedra) return std::nullopt;
  return decomposition_.owners().bricks()->brick(decomposition_.ranks().rank());
}

Simulation::BrickSamples Simulation::take_brick() {
  const std::optional<parallel::Bricks::Range> brick_of_rank = brick();
  if (!brick_of_rank) throw std::logic_error("take_brick: this gas's cells are not a rank's brick of a box");
  const parallel::Bricks::Range& mine = *brick_of_rank;
  std::vector<double> count = particles_per_cell();
  // What a ghost holds (its strays, their sums) goes to its owner.
  std::map<int, std::vector<double>> records;
  std::array<double, 1 + tracking::CellSampler::kSumsPerCell> held{};
  for (Index c = tracked().own_cells(); c < tracked().cell_count(); ++c) {
    held[0] = count[static_cast<std::size_t>(c)];
    const std::array<double, tracking::CellSampler::kSumsPerCell> sums = sampler_.cell_sums(c);
    std::copy(sums.begin(), sums.end(), held.begin() + 1);
    if (std::any_of(held.begin(), held.end(), [](double x) { return x != 0.0; }))
      put_cells(records[decomposition_.owner(tracked().global_cell(c))], tracked(), c, held);
  }
  for_each_record(decomposition_.exchange(messages_of(records)), held.size(),
                  [&](Index global, std::span<const double> cell) {
                    const Index c = numbering().local(global);
                    count[static_cast<std::size_t>(c)] += cell[0];
                    sampler_.add_sums(c, cell.subspan(1));
                  });
  BrickSamples taken{.brick = mine, .count = {}, .moments = {}};
  const std::vector<double> volume = cell_volumes(*setup_.box, mine.lo, mine.hi);
  taken.count.reserve(volume.size());
  taken.moments.reserve(volume.size());
  const std::array<int, 3>& hexahedra = decomposition_.owners().bricks()->hexahedra();
  // A part numbers its own cells in the whole's order (part.hpp), which within a brick is
  // the brick's order: own cell c is the brick's c-th, checked rather than looked up.
  Index c = 0;
  for (int k = mine.lo[2]; k < mine.hi[2]; ++k)
    for (int j = mine.lo[1]; j < mine.hi[1]; ++j)
      for (int i = mine.lo[0]; i < mine.hi[0]; ++i, ++c) {
        if (c >= tracked().own_cells() || tracked().global_cell(c) != mesh::box_cell_index({{i, j, k}}, hexahedra, 1))
          throw std::logic_error("take_brick: the part's own cells are not its brick in order");
        taken.count.push_back(count[static_cast<std::size_t>(c)]);
        taken.moments.push_back(tracking::CellSampler::moments(sampler_.cell_sums(c), sampler_.samples(),
                                                               volume[static_cast<std::size_t>(c)],
                                                               setup_.particles.mass, setup_.particles.weight));
      }
  sampler_.reset();
  return taken;
}

std::vector<double> Simulation::particles_per_cell() const {
  std::vector<double> count(static_cast<std::size_t>(tracked().cell_count()), 0.0);
  for (std::size_t i = 0; i < swarm_.size(); ++i) count[static_cast<std::size_t>(swarm_.cell(i))] += 1.0;
  return count;
}

std::vector<double> Simulation::counts() const { return at_lead(particles_per_cell(), 1); }

std::vector<tracking::CellMoments> Simulation::take_moments() {
  if (brick()) throw std::logic_error("a brick's moments are take_brick()'s");
  const double mass = setup_.particles.mass, weight = setup_.particles.weight;
  std::vector<tracking::CellMoments> moments;
  moments.reserve(decomposition_.ranks().lead() ? static_cast<std::size_t>(whole_cells_) : 0);
  if (decomposition_.ranks().size() == 1) {
    for (Index c = 0; c < whole_cells_; ++c) moments.push_back(sampler_.moments(c, mass, weight));
  } else {
    // A cell's sums are spread over the ranks whose particles were in it when sampled; they
    // add up. Every rank sampled at every step: the sample count (the first value) is each
    // rank's, not summed.
    const std::vector<double> sums = sampler_.sums();
    const std::vector<double> cells = at_lead(std::span(sums).subspan(1), tracking::CellSampler::kSumsPerCell);
    const std::vector<double>& volume = setup_.box ? whole_volume_ : setup_.mesh->volume;
    for (std::size_t c = 0; c < cells.size() / tracking::CellSampler::kSumsPerCell; ++c)
      moments.push_back(tracking::CellSampler::moments(
          std::span(cells).subspan(c * tracking::CellSampler::kSumsPerCell, tracking::CellSampler::kSumsPerCell),
          sampler_.samples(), volume[c], mass, weight));
  }
  sampler_.reset();
  return moments;
}

}  // namespace cosim::tracker::step
