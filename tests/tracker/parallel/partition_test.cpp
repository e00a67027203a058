// The cell partition (every cell in one part, parts balanced within METIS's default 3 %,
// the same on every call, periodic faces linking cells) and the migration records (a
// particle and its states come back bit for bit), on one process.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "tracker/mesh/box_mesh.hpp"
#include "tracker/parallel/migration.hpp"
#include "tracker/parallel/partition.hpp"

namespace cosim::tracker::parallel {
namespace {

mesh::Mesh box(std::array<int, 3> cells, bool tetrahedra = false,
               std::array<bool, 3> periodic = {false, false, false}) {
  mesh::BoxSpec spec;
  for (int a = 0; a < 3; ++a) spec.axes[static_cast<std::size_t>(a)].cells = cells[static_cast<std::size_t>(a)];
  spec.tetrahedra = tetrahedra;
  spec.periodic = periodic;
  return mesh::box_mesh(spec);
}

bool linked(const CellGraph& g, int a, int b) {
  return std::binary_search(g.neighbours.begin() + g.start[a], g.neighbours.begin() + g.start[a + 1], b);
}

TEST(CellGraph, InteriorAndPeriodicFacesLinkCellsBothWaysOnce) {
  const mesh::Mesh open = box({4, 3, 2}), periodic = box({4, 3, 2}, false, {true, false, false});
  const CellGraph a = cell_graph(open), b = cell_graph(periodic);
  ASSERT_EQ(a.start.size(), 25u);
  for (int c = 0; c < 24; ++c)
    for (int k = a.start[c]; k < a.start[c + 1]; ++k) {
      EXPECT_NE(a.neighbours[k], c);
      EXPECT_TRUE(linked(a, a.neighbours[k], c));
    }
  // Cells along x fastest: 0 and 3 are the two ends of the first row.
  EXPECT_FALSE(linked(a, 0, 3));
  EXPECT_TRUE(linked(b, 0, 3));
  EXPECT_TRUE(linked(b, 3, 0));
  EXPECT_EQ(b.neighbours.size(), a.neighbours.size() + 2 * 3 * 2);
  // Two cells along a periodic axis meet through two faces: one link.
  const CellGraph two = cell_graph(box({2, 1, 1}, false, {true, true, true}));
  EXPECT_EQ(two.neighbours, (std::vector<int>{1, 0}));
}

TEST(Partition, EveryCellInOnePartBalancedAndDeterministic) {
  for (const mesh::Mesh& mesh : {box({20, 20, 20}), box({8, 8, 8}, true, {true, true, false})}) {
    for (int parts : {2, 3, 4}) {
      const std::vector<int> part = partition_cells(mesh, parts);
      ASSERT_EQ(part.size(), static_cast<std::size_t>(mesh.cell_count()));
      std::vector<int> size(static_cast<std::size_t>(parts), 0);
      for (int p : part) {
        ASSERT_GE(p, 0);
        ASSERT_LT(p, parts);
        ++size[static_cast<std::size_t>(p)];
      }
      // METIS's default load imbalance for k-way partitioning: 1.03 (ufactor 30).
      const double even = static_cast<double>(mesh.cell_count()) / parts;
      for (int s : size) {
        EXPECT_GT(s, 0);
        EXPECT_LE(s, std::ceil(1.03 * even)) << parts << " parts of " << mesh.cell_count();
      }
      EXPECT_EQ(partition_cells(mesh, parts), part);
    }
  }
}

// Weights 20 in the cells x < 5 of a 20^3 box and 1 elsewhere: the parts hold equal
// weight, so the heavy quarter is split between more parts than its share of the cells.
TEST(Partition, WeightsBalanceTheirSumNotTheCells) {
  const mesh::Mesh mesh = box({20, 20, 20});
  std::vector<int> weight(static_cast<std::size_t>(mesh.cell_count()), 1);
  for (Index c = 0; c < mesh.cell_count(); ++c)
    if (c % 20 < 5) weight[static_cast<std::size_t>(c)] = 20;
  const long long total = std::accumulate(weight.begin(), weight.end(), 0LL);
  for (int parts : {2, 4}) {
    const std::vector<int> part = partition_cells(mesh, parts, weight);
    std::vector<long long> load(static_cast<std::size_t>(parts), 0);
    for (std::size_t c = 0; c < part.size(); ++c) load[static_cast<std::size_t>(part[c])] += weight[c];
    for (long long l : load) EXPECT_LE(static_cast<double>(l), 1.04 * static_cast<double>(total) / parts) << parts;
    EXPECT_EQ(partition_cells(mesh, parts, weight), part);
  }
  weight[3] = 0;
  EXPECT_THROW(partition_cells(mesh, 2, weight), std::invalid_argument);
  EXPECT_THROW(partition_cells(mesh, 2, std::vector<int>(5, 1)), std::invalid_argument);
}

TEST(Partition, OnePartWithoutMetisAndBadCountsRefused) {
  const mesh::Mesh mesh = box({3, 3, 3});
  EXPECT_EQ(partition_cells(mesh, 1), std::vector<int>(27, 0));
  EXPECT_THROW(partition_cells(mesh, 0), std::invalid_argument);
  EXPECT_THROW(partition_cells(mesh, 28), std::invalid_argument);
}

TEST(Migration, OneRankKeepsEveryParticle) {
  tracking::Swarm swarm(0);
  for (int i = 0; i < 10; ++i) swarm.add({{0, 0, 0}, {1, 0, 0}, i}, {});
  EXPECT_EQ(migrate(swarm, Owners(std::vector<int>(10, 0)), Ranks(), 0), 0u);
  EXPECT_EQ(swarm.size(), 10u);
}

}  // namespace
}  // namespace cosim::tracker::parallel
