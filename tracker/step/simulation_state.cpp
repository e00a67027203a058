// Simulation::state and restore: everything a checkpoint or a repeated window needs, as one
// array of doubles (state_array.hpp).
#include <stdexcept>
#include <string>
#include <vector>

#include "tracker/step/simulation.hpp"
#include "tracker/step/state_array.hpp"
#include "tracker/step/tally_numbers.hpp"

namespace cosim::tracker::step {
namespace {

// Bumped when the layout changes, so an old checkpoint is refused, not misread.
constexpr double kStateVersion = 7;

template <typename Tally>
void put_tallies(StateWriter& out, const std::vector<Tally>& tallies) {
  for (const Tally& t : tallies) {
    detail::each_count(t, [&](long long n) { out.put(n); });
    detail::each_value(t, [&](double x) { out.put(x); });
  }
}

template <typename Tally>
void get_tallies(StateReader& in, std::vector<Tally>& tallies) {
  for (Tally& t : tallies) {
    detail::each_count(t, [&](long long& n) { in.get(n); });
    detail::each_value(t, [&](double& x) { in.get(x); });
  }
}

}  // namespace

std::vector<double> Simulation::state() const {
  const parallel::Ranks& ranks = decomposition_.ranks();
  const int objects = setup_.obstacles.count();
  StateWriter out;
  out.put(kStateVersion, ranks.size(), ranks.rank(), objects, whole_cells_);
  out.put(steps_, seeded_, injected_, migrated_, collisions_, rebalances_, balance_floor_);
  // The partition may have changed since the start (balance()): rank 0 keeps it for all.
  if (ranks.size() > 1 && ranks.lead()) {
    const std::vector<int> owners = decomposition_.owners().saved();
    out.put(owners.size());
    for (const int x : owners) out.put(x);
  }
  out.put(swarm_.size());
  for (std::size_t i = 0; i < swarm_.size(); ++i) {
    const tracking::Particle p = swarm_.particle(i);
    out.put(p.x, p.v, tracked().global_cell(p.cell));
    for (csg::State s : swarm_.states(i)) out.put_bits(s);
  }
  // The pose's matrix itself: a quaternion would not give the same matrix back, and a
  // repeated window must see the very pose the first attempt saw.
  for (int o = 0; o < objects; ++o)
    for (double x : setup_.obstacles.pose(o).matrix().topRows<3>().reshaped()) out.put(x);
  put_tallies(out, tallies_);
  put_tallies(out, patch_tallies_);
  for (const tracking::MoveCounter& c : tracking::kMoveCounters) out.put(moves_.*c.count);
  // Per cell of this rank's (its part, as the owners above give it), then.
  out.put(tracked().cell_count());
  if (collider_)
    for (const dsmc::CellCollisionState& c : collider_->cells()) out.put(c.sigma_g_max, c.remainder);
  for (double x : sampler_.sums()) out.put(x);
  return out.take();
}

void Simulation::restore(std::span<const double> state) {
  // Read into copies first: a state that turns out bad changes nothing (but for a partition
  // other than the present one, which is taken before the particles are checked against it).
  const parallel::Ranks& ranks = decomposition_.ranks();
  const int objects = setup_.obstacles.count();
  StateReader in(state);
  in.expect(kStateVersion, "layout version");
  in.expect(ranks.size(), "ranks");
  in.expect(ranks.rank(), "rank");
  in.expect(objects, "obstacles");
  in.expect(whole_cells_, "cells");
  std::uint64_t steps = 0, rebalances = 0;
  std::size_t seeded = 0, injected = 0, migrated = 0;
  std::int64_t collisions = 0;
  double balance_floor = 0.0;
  in.get(steps, seeded, injected, migrated, collisions, rebalances, balance_floor);
  std::vector<int> owners;
  const bool partitioned = ranks.size() > 1;
  if (partitioned && ranks.lead()) {
    const auto n = in.get<std::size_t>();
    if (n > static_cast<std::size_t>(whole_cells_)) throw std::runtime_error("tracker state: owners too long");
    owners.resize(n);
    for (int& x : owners) in.get(x);
  }
  tracking::Swarm swarm(objects);
  std::vector<csg::State> states(static_cast<std::size_t>(objects));
  for (auto n = in.get<std::size_t>(); n > 0; --n) {
    tracking::Particle p;
    in.get(p.x, p.v, p.cell);  // the cell in the whole mesh
    if (p.cell < 0 || p.cell >= whole_cells_) throw std::runtime_error("tracker state: a particle in no cell");
    for (csg::State& s : states) s = in.get_bits();
    swarm.add(p, states);
  }
  std::vector<Eigen::Isometry3d> poses(static_cast<std::size_t>(objects), Eigen::Isometry3d::Identity());
  for (Eigen::Isometry3d& pose : poses)
    for (double& x : pose.matrix().topRows<3>().reshaped()) in.get(x);
  std::vector<tracking::ObstacleTally> tallies(tallies_.size());
  get_tallies(in, tallies);
  std::vector<tracking::SurfaceTally> patch_tallies(patch_tallies_.size());
  get_tallies(in, patch_tallies);
  tracking::MoveTally moves;
  for (const tracking::MoveCounter& c : tracking::kMoveCounters) in.get(moves.*c.count);
  const auto part_cells = in.get<std::size_t>();
  if (part_cells > static_cast<std::size_t>(whole_cells_))
    throw std::runtime_error("tracker state: " + std::to_string(part_cells) + " cells on a rank");
  std::vector<dsmc::CellCollisionState> cells(collider_ ? part_cells : 0);
  for (dsmc::CellCollisionState& c : cells) in.get(c.sigma_g_max, c.remainder);
  std::vector<double> sums(1 + part_cells * tracking::CellSampler::kSumsPerCell);
  for (double& x : sums) in.get(x);
  in.finish();

  if (partitioned) {
    // Every rank restores at once (participant/mpi_team.hpp); a rank that threw above ends
    // the job (MPI_Abort) rather than leave the others waiting here.
    std::vector<int> size{static_cast<int>(owners.size())};
    ranks.broadcast(size);
    owners.resize(static_cast<std::size_t>(size[0]));
    ranks.broadcast(owners);
    if (owners != decomposition_.owners().saved()) {
      try {
        decomposition_.set_owners(
            parallel::Owners::restored(owners, decomposition_.owners(), whole_cells_, ranks.size()));
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(std::string("tracker state: ") + e.what());
      }
      if (part_) {
        take_part();
        sampler_ = tracking::CellSampler(*part_);
      }
    }
  }
  if (part_cells != static_cast<std::size_t>(tracked().cell_count()))
    throw std::runtime_error("tracker state: " + std::to_string(part_cells) + " cells on rank " +
                             std::to_string(ranks.rank()) + ", its part has " + std::to_string(tracked().cell_count()));
  if (part_) {
    swarm.renumber_cells([&](Index c) { return part_cells_->local(c); });
    for (std::size_t i = 0; i < swarm.size(); ++i)
      if (swarm.cell(i) < 0) throw std::runtime_error("tracker state: a particle in a cell of another rank's");
  }
  for (int o = 0; o < objects; ++o) setup_.obstacles.place(o, poses[static_cast<std::size_t>(o)]);
  sampler_.set_sums(sums);
  if (collider_) collider_->set_cells(std::move(cells));
  swarm_ = std::move(swarm);
  strays_ = true;  // the state does not say whether some are in ghosts: a migration finds out
  tallies_ = std::move(tallies);
  patch_tallies_ = std::move(patch_tallies);
  moves_ = moves;
  steps_ = steps;
  seeded_ = seeded;
  injected_ = injected;
  migrated_ = migrated;
  collisions_ = collisions;
  rebalances_ = rebalances;
  balance_floor_ = balance_floor;
}

}  // namespace cosim::tracker::step
