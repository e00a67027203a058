// Migration on any number of ranks (ctest runs it on 4), and rank 0's gathering: rounds of particles in random
// cells, with ranks that fall behind each other at random, every particle reaching its
// cell's owner with its states, none lost, duplicated or early, and the arrivals in the
// senders' rank order (a run repeats itself whatever order the messages come in).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/parallel/bricks.hpp"
#include "tracker/parallel/decomposition.hpp"

namespace cosim::tracker::parallel {
namespace {

TEST(Migration, RoundsAfterRoundsOnEveryRankCount) {
  const mesh::Mesh mesh = mesh::box_mesh(mesh::cube(8));
  Decomposition d(mesh, Ranks(MPI_COMM_WORLD));
  const int rank = d.ranks().rank(), ranks = d.ranks().size();
  std::mt19937_64 random(static_cast<std::uint64_t>(rank) + 11);
  std::uniform_int_distribution<Index> cell(0, mesh.cell_count() - 1);
  std::uniform_int_distribution<int> pause(0, 3);
  tracking::Swarm swarm(1);
  long long made = 0, elsewhere = 0, early = 0, moved = 0, unordered = 0;
  for (int round = 0; round < 40; ++round) {
    // Every fourth round the odd ranks have nothing to send: they keep what they hold.
    if (round % 4 != 3 || rank % 2 == 0) {
      // The ones here moved to random cells, and new ones in random cells: ids unique over
      // the ranks (rank, round, i) as their state.
      for (std::size_t i = 0; i < swarm.size(); i += 3) {
        tracking::Particle p = swarm.particle(i);
        p.cell = cell(random);
        p.x = mesh.centroid[p.cell];
        swarm.set(i, p);
      }
      for (std::uint64_t i = 0; i < 200; ++i) {
        const Index c = cell(random);
        const std::uint64_t id =
            (static_cast<std::uint64_t>(rank) << 40) | (static_cast<std::uint64_t>(round) << 20) | i;
        swarm.add({mesh.centroid[c], {0, 0, 0}, c}, std::vector<csg::State>{id});
      }
      made += 200;
    }
    // The holder in the velocity: what arrives must be in the senders' rank order, after
    // what stayed, whatever order the messages came in.
    for (std::size_t i = 0; i < swarm.size(); ++i) {
      tracking::Particle p = swarm.particle(i);
      p.v.x() = rank;
      swarm.set(i, p);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(pause(random)));
    d.migrate(swarm);
    for (std::size_t i = 1; i < swarm.size(); ++i) {
      const auto holder = [&](std::size_t k) {
        const double v = swarm.particle(k).v.x();
        return v == rank ? -1.0 : v;
      };
      unordered += holder(i) < holder(i - 1);
    }
    // Counted, not asserted: a rank that left the loop early would leave the others waiting.
    for (std::size_t i = 0; i < swarm.size(); ++i) {
      elsewhere += !d.owns(swarm.cell(i));
      // Nothing of a later round, which a rank ahead may already have sent.
      early += static_cast<int>(swarm.states(i)[0] >> 20 & 0xfffff) > round;
      moved += swarm.particle(i).x != mesh.centroid[swarm.cell(i)];
    }
  }
  EXPECT_EQ(elsewhere, 0);
  EXPECT_EQ(early, 0);
  EXPECT_EQ(moved, 0);
  EXPECT_EQ(unordered, 0);
  // Every id once.
  long long here = static_cast<long long>(swarm.size());
  EXPECT_EQ(d.ranks().sum(here), d.ranks().sum(made)) << "particles lost or duplicated on " << ranks << " ranks";
  std::vector<csg::State> ids;
  for (std::size_t i = 0; i < swarm.size(); ++i) ids.push_back(swarm.states(i)[0]);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
}

// The bricks of a re-partition are the same on every rank, and the same as one process cuts
// from every cell's particles, though each rank gives only its own particles' cells: most
// of them in a corner of a box of tetrahedra that is another for each rank.
TEST(Bricks, ARepartitionAddsUpTheRanksParticlesSlabBySlab) {
  const std::array<int, 3> hexahedra{12, 10, 8};
  const int per_hex = 6;
  const Decomposition d(Bricks(hexahedra, per_hex, Ranks(MPI_COMM_WORLD).size(), {}), Ranks(MPI_COMM_WORLD));
  const Ranks& ranks = d.ranks();
  if (ranks.size() == 1) GTEST_SKIP() << "one rank keeps its brick";
  const Index cells = hexahedra[0] * hexahedra[1] * hexahedra[2] * per_hex;
  std::mt19937_64 random(static_cast<std::uint64_t>(ranks.rank()) + 5);
  std::uniform_int_distribution<Index> anywhere(0, cells - 1);
  std::uniform_int_distribution<int> corner(0, 2);
  const int x = 3 * (ranks.rank() % 4);
  std::vector<Index> mine;
  for (int i = 0; i < 3000 + 500 * ranks.rank(); ++i)
    mine.push_back(i % 4 == 0
                       ? anywhere(random)
                       : mesh::box_cell_index({{x + corner(random), corner(random), corner(random)}, corner(random)},
                                              hexahedra, per_hex));
  const std::vector<int> cuts = d.proposal(mine).bricks()->cuts();
  std::vector<int> lead = cuts;
  ranks.broadcast(lead);
  EXPECT_EQ(cuts, lead) << "rank " << ranks.rank();

  const std::vector<double> all = ranks.gather(std::vector<double>(mine.begin(), mine.end()));
  if (!ranks.lead()) return;
  std::vector<double> weight(static_cast<std::size_t>(cells), 0.01 * static_cast<double>(all.size()) / cells);
  for (const double c : all) weight[static_cast<std::size_t>(c)] += 1.0;
  const Bricks whole(hexahedra, per_hex, ranks.size(), weight);
  EXPECT_EQ(cuts, whole.cuts());
  EXPECT_NE(cuts, Bricks(hexahedra, per_hex, ranks.size(), {}).cuts());  // the particles moved the cuts
}

// Rank 0 takes each rank's values whole and in rank order, one rank at a time, whatever
// their sizes (none too); gather() is their concatenation.
TEST(Ranks, RankZeroTakesEachRanksValuesInTurn) {
  const Ranks ranks(MPI_COMM_WORLD);
  const int rank = ranks.rank();
  std::vector<double> mine(static_cast<std::size_t>(rank == 2 ? 0 : 1000 * rank + 3));
  for (std::size_t k = 0; k < mine.size(); ++k) mine[k] = rank + 1e-6 * static_cast<double>(k);
  std::this_thread::sleep_for(std::chrono::milliseconds(10 * (ranks.size() - rank)));  // the last rank sends first
  std::vector<std::vector<double>> taken;
  ranks.gather_each(mine, [&](std::span<const double> some) { taken.emplace_back(some.begin(), some.end()); });
  const std::vector<double> all = ranks.gather(mine);
  if (rank != 0) {
    EXPECT_TRUE(taken.empty());
    EXPECT_TRUE(all.empty());
    return;
  }
  ASSERT_EQ(taken.size(), static_cast<std::size_t>(ranks.size()));
  std::vector<double> joined;
  for (int r = 0; r < ranks.size(); ++r) {
    const auto& from = taken[static_cast<std::size_t>(r)];
    EXPECT_EQ(from.size(), r == 2 ? 0u : static_cast<std::size_t>(1000 * r + 3)) << "rank " << r;
    for (std::size_t k = 0; k < from.size(); ++k) EXPECT_EQ(from[k], r + 1e-6 * static_cast<double>(k));
    joined.insert(joined.end(), from.begin(), from.end());
  }
  EXPECT_EQ(all, joined);
}

}  // namespace
}  // namespace cosim::tracker::parallel
